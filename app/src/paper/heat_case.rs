//! Running a heat case ([`crate::paper::heat_spec`]): the paper's test 5.4, an insulated rod whose
//! halves start at different temperatures, advanced by (5.2) with each of the case's boundary closures
//! until it equalises (spread of the nodal temperatures below the case's threshold), diverges, or reaches
//! the time cap; then the thermal expansion (5.5)-(5.6) of the equalised wire.
//!
//! References: the exact equalisation temperature is the mean of the halves (heat is conserved by
//! insulated ends); the exact time to equalise follows from the slowest Fourier mode of the exact
//! solution ([`ohl::exact::heat::equalisation_time`]); the figure draws the exact profiles `u(s, t)`
//! beside the computed ones.
//!
//! Time here is the dimensionless `t = kappa t_phys / l^2` of (5.1); the figure and the notes state the
//! physical time of one unit ([`ohl::heat::scale`]).

use std::io::Write;
use std::path::Path;
use std::time::Instant;

use super::table::Row;
use super::{CaseReport, PaperError};
use crate::paper::heat_spec::{self, HeatCase, HeatExtractKind, HeatReferenceKind, RunSpec};
use crate::paper::spec::UnitSpec;
use crate::plot::{Chart, Series, Style, render_titled};
use ohl::exact::heat::{equalisation_time, slowest_mode_spread, two_halves};
use ohl::heat::HeatRod;
use ohl::heat::expansion::{thermal_force, thermal_strain};
use ohl::heat::scale::{conduction_time_scale_s, thermal_diffusivity};

/// How a run ended.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Ending {
    /// the spread fell below the threshold at this dimensionless time; the mean nodal value then [-]
    Equalised {
        /// dimensionless time
        t: f64,
        /// arithmetic mean of the nodal temperatures (all within the threshold of each other) [-]
        value: f64,
    },
    /// the spread exceeded the divergence threshold at this dimensionless time
    Diverged {
        /// dimensionless time
        t: f64,
    },
    /// the time cap was reached first
    Capped {
        /// dimensionless time
        t: f64,
    },
}

/// One sample of a run's history.
#[derive(Clone, Copy, Debug)]
pub struct HeatSample {
    /// dimensionless time
    pub t: f64,
    /// temperature of the left end node `u_0` [-]
    pub u_left: f64,
    /// temperature of the right end node `u_N` [-]
    pub u_right: f64,
    /// trapezoidal mean [-] (conserved exactly by the zero-flux closure)
    pub mean: f64,
    /// largest minus smallest nodal temperature [-]
    pub spread: f64,
}

/// What one run produced.
#[derive(Clone, Debug)]
pub struct HeatRun {
    /// its specification
    pub spec: RunSpec,
    /// how it ended
    pub ending: Ending,
    /// history, about 400 samples plus the last
    pub history: Vec<HeatSample>,
    /// profiles `(t, u_0..u_N)` at the first steps at or after the case's profile times
    pub profiles: Vec<(f64, Vec<f64>)>,
}

/// Run one closure until it equalises, diverges or reaches the cap.
pub fn run_rod(case: &HeatCase, spec: &RunSpec) -> HeatRun {
    let ts = case.rod.temperature_scale_k;
    let (ul, ur) = (case.rod.left_temperature_k / ts, case.rod.right_temperature_k / ts);
    let mut rod = HeatRod::two_halves(case.rod.segments, ul, ur, spec.boundary.closure());
    let h = rod.spacing();
    let dt = spec.step_ratio * h * h;
    // About 400 samples up to the exact equalisation time (a diverging run stops earlier, a run past the
    // cap later: the history then has fewer or more samples).
    let t_expected = equalisation_time(ul, ur, case.stop.spread).clamp(dt, case.stop.max_time);
    let every = ((t_expected / dt / 400.0) as usize).max(1);
    let mut profile_times: Vec<f64> = case.profile_times.clone();
    profile_times.sort_by(f64::total_cmp);
    let mut next_profile = 0;
    let sample = |rod: &HeatRod| {
        let u = rod.temperatures();
        HeatSample { t: rod.time(), u_left: u[0], u_right: u[u.len() - 1], mean: rod.mean(), spread: rod.spread() }
    };
    let mut history = vec![sample(&rod)];
    let mut profiles = Vec::new();
    let mut steps = 0usize;
    let ending = loop {
        while next_profile < profile_times.len() && rod.time() >= profile_times[next_profile] - 1e-12 {
            profiles.push((rod.time(), rod.temperatures().to_vec()));
            next_profile += 1;
        }
        let spread = rod.spread();
        if spread > case.stop.divergence_spread {
            break Ending::Diverged { t: rod.time() };
        }
        if spread < case.stop.spread {
            let u = rod.temperatures();
            break Ending::Equalised { t: rod.time(), value: u.iter().sum::<f64>() / u.len() as f64 };
        }
        if rod.time() >= case.stop.max_time {
            break Ending::Capped { t: rod.time() };
        }
        rod.step(dt);
        steps += 1;
        if steps.is_multiple_of(every) {
            history.push(sample(&rod));
        }
    };
    if history.last().is_none_or(|s| s.t < rod.time()) {
        history.push(sample(&rod));
    }
    HeatRun { spec: spec.clone(), ending, history, profiles }
}

/// Run a heat case from its TOML text; with `out_dir`, write `<out_dir>/<name>.png`, `.svg`, `.csv` and
/// `<name>_profiles.csv`.
pub fn run_heat_case(text: &str, file: &str, name: &str, out_dir: Option<&Path>) -> Result<CaseReport, PaperError> {
    let started = Instant::now();
    let case = heat_spec::parse(text, file)?;
    let runs: Vec<HeatRun> = case.runs.iter().map(|r| run_rod(&case, r)).collect();
    let ts = case.rod.temperature_scale_k;
    let (ul, ur) = (case.rod.left_temperature_k / ts, case.rod.right_temperature_k / ts);
    let m = &case.material;
    let u_exact = 0.5 * (ul + ur);
    let by_label = |label: &str| runs.iter().find(|r| r.spec.label == label).expect("labels are validated");
    let expansion = |u: f64, force: bool| {
        let eps = thermal_strain(m.thermal_expansion_per_k, u * ts - m.reference_temperature_k);
        if force { thermal_force(m.youngs_modulus_pa, eps, m.diameter_m) } else { eps }
    };
    let rows: Vec<Row> = case
        .paper
        .checks
        .iter()
        .map(|ch| {
            let run = by_label(&ch.extract.run);
            let si = match (ch.extract.kind, run.ending) {
                (HeatExtractKind::EqualisedTemperature, Ending::Equalised { value, .. }) => value,
                (HeatExtractKind::EqualisationTime, Ending::Equalised { t, .. }) => t,
                (HeatExtractKind::DivergenceTime, Ending::Diverged { t }) => t,
                (HeatExtractKind::ThermalStrain, Ending::Equalised { value, .. }) => expansion(value, false),
                (HeatExtractKind::ThermalForce, Ending::Equalised { value, .. }) => expansion(value, true),
                _ => f64::NAN,
            };
            let exact = ch.reference.map(|k| match k {
                HeatReferenceKind::ExactEqualisation => u_exact,
                HeatReferenceKind::SlowestModeTime => equalisation_time(ul, ur, case.stop.spread),
                HeatReferenceKind::ThermalStrain => expansion(u_exact, false),
                HeatReferenceKind::ThermalForce => expansion(u_exact, true),
            });
            let conv = |v: f64| if ch.unit == UnitSpec::Kn { v / 1e3 } else { v };
            Row::from_check(name, ch, conv(si), exact.map(conv))
        })
        .collect();

    let kappa = thermal_diffusivity(m.thermal_conductivity_w_per_m_k, m.density_kg_per_m3, m.specific_heat_j_per_kg_k);
    let unit_s = conduction_time_scale_s(m.span_m, kappa);
    let mut notes = case.paper.notes.clone();
    for r in &runs {
        let what = match r.ending {
            Ending::Equalised { t, value } => format!("equalised to u = {value:.7} at t = {t:.4}"),
            Ending::Diverged { t } => format!("diverged (spread > {}) at t = {t:.5}", case.stop.divergence_spread),
            Ending::Capped { t } => format!("not equalised by the cap t = {t:.3}"),
        };
        notes.push(format!("{}: {what}", r.spec.label));
    }
    notes.push(format!(
        "time is the dimensionless t = kappa t_phys / l^2 of (5.1): kappa = k / (rho c) = {kappa:.4e} m^2/s, one unit = l^2 / kappa = {unit_s:.4e} s ({:.1} years) for l = {} m",
        unit_s / (365.25 * 86400.0),
        m.span_m
    ));
    let mut figure = None;
    if let Some(dir) = out_dir {
        let stem = dir.join(name);
        let charts = charts(&case, &runs, ul, ur, unit_s);
        let heading = format!(
            "{name}: {} | wire d = {:.2} mm, E = {:.0} GPa, span {} m",
            case.paper.title,
            m.diameter_m * 1e3,
            m.youngs_modulus_pa / 1e9,
            m.span_m
        );
        render_titled(&charts, 2, (680, 440), &heading, &stem).map_err(|e| PaperError::Output(e.to_string()))?;
        write_csv(&runs, &stem).map_err(|e| PaperError::Output(format!("{}: {e}", stem.display())))?;
        figure = Some(stem);
    }
    let equalised = runs.iter().filter(|r| matches!(r.ending, Ending::Equalised { .. })).count();
    Ok(CaseReport {
        name: name.to_string(),
        section: case.paper.section.clone(),
        title: case.paper.title.clone(),
        rows,
        notes,
        events: Vec::new(),
        status: format!("{} runs, {equalised} equalised", runs.len()),
        wall_s: started.elapsed().as_secs_f64(),
        figure,
        estimate: None,
    })
}

impl HeatRun {
    fn ending_time(&self) -> f64 {
        match self.ending {
            Ending::Equalised { t, .. } | Ending::Diverged { t } | Ending::Capped { t } => t,
        }
    }
}

fn charts(case: &HeatCase, runs: &[HeatRun], ul: f64, ur: f64, unit_s: f64) -> Vec<Chart> {
    let ts = case.rod.temperature_scale_k;
    let u_label = format!("u = T / {ts} K [-]");
    let t_label = format!("t = kappa t_phys / l^2 [-]   (1 = {unit_s:.3e} s)");
    let mut out = Vec::new();

    // (a) Profiles of the chosen run against the exact solution.
    let pr = runs.iter().find(|r| r.spec.label == case.paper.profile_run).expect("validated label");
    let mut a = Chart {
        title: format!("profiles u(s, t): {} (markers) and exact (lines)", pr.spec.label),
        x_label: "s = x / l [-]".into(),
        y_label: u_label.clone(),
        ..Default::default()
    };
    for (k, (t, u)) in pr.profiles.iter().enumerate() {
        let n = u.len() - 1;
        let exact: Vec<(f64, f64)> =
            (0..=400).map(|j| j as f64 / 400.0).map(|s| (s, two_halves(ul, ur, s, *t))).collect();
        a.series.push(Series::new(format!("exact, t = {t:.4}"), exact, Style::Line, k));
        let pts = u.iter().enumerate().map(|(i, v)| (i as f64 / n as f64, *v)).collect();
        a.series.push(Series::new(String::new(), pts, Style::Markers, k));
    }
    out.push(a);

    // (b) Spread against time, all runs, with the slowest exact mode.
    let mut b = Chart {
        title: "spread max u - min u of the nodes (log scale)".into(),
        x_label: t_label.clone(),
        y_label: "spread [-]".into(),
        log_y: true,
        ..Default::default()
    };
    let t_end = runs.iter().map(HeatRun::ending_time).fold(0.0, f64::max);
    let slow: Vec<(f64, f64)> =
        (1..=200).map(|j| t_end * j as f64 / 200.0).map(|t| (t, slowest_mode_spread(ul, ur, t))).collect();
    b.series.push(Series::new("exact slowest mode 2|a1| exp(-pi^2 t)", slow, Style::Dashed, 7));
    for (k, r) in runs.iter().enumerate() {
        let pts =
            r.history.iter().filter(|s| s.spread.is_finite() && s.spread > 0.0).map(|s| (s.t, s.spread)).collect();
        b.series.push(Series::new(r.spec.label.clone(), pts, Style::Line, k));
    }
    out.push(b);

    // (c) Left end temperature against the exact u(0, t), runs that did not diverge.
    let stable: Vec<(usize, &HeatRun)> =
        runs.iter().enumerate().filter(|(_, r)| !matches!(r.ending, Ending::Diverged { .. })).collect();
    let mut c = Chart {
        title: "temperature of the left end u(0, t)".into(),
        x_label: t_label.clone(),
        y_label: u_label.clone(),
        ..Default::default()
    };
    let ex: Vec<(f64, f64)> =
        (0..=300).map(|j| t_end * j as f64 / 300.0).map(|t| (t, two_halves(ul, ur, 0.0, t))).collect();
    c.series.push(Series::new("exact", ex, Style::Dashed, 7));
    for (k, r) in &stable {
        c.series.push(Series::new(
            r.spec.label.clone(),
            r.history.iter().map(|s| (s.t, s.u_left)).collect(),
            Style::Line,
            *k,
        ));
    }
    out.push(c);

    // (d) Heat content: trapezoidal mean minus the exact equalisation temperature.
    let mut d = Chart {
        title: "heat balance: trapezoidal mean minus exact (u_L + u_R) / 2".into(),
        x_label: t_label,
        y_label: "mean u - exact [-]".into(),
        ..Default::default()
    };
    let u_exact = 0.5 * (ul + ur);
    for (k, r) in &stable {
        d.series.push(Series::new(
            r.spec.label.clone(),
            r.history.iter().map(|s| (s.t, s.mean - u_exact)).collect(),
            Style::Line,
            *k,
        ));
    }
    out.push(d);
    out
}

fn write_csv(runs: &[HeatRun], stem: &Path) -> std::io::Result<()> {
    let mut f = std::io::BufWriter::new(std::fs::File::create(stem.with_extension("csv"))?);
    writeln!(f, "run,boundary,step_ratio,t,u_left_end,u_right_end,trapezoidal_mean,spread")?;
    for r in runs {
        for s in &r.history {
            writeln!(
                f,
                "\"{}\",{:?},{},{:.8e},{:.15e},{:.15e},{:.15e},{:.6e}",
                r.spec.label, r.spec.boundary, r.spec.step_ratio, s.t, s.u_left, s.u_right, s.mean, s.spread
            )?;
        }
    }
    f.flush()?;
    let path =
        stem.with_file_name(format!("{}_profiles.csv", stem.file_name().and_then(|s| s.to_str()).unwrap_or("heat")));
    let mut f = std::io::BufWriter::new(std::fs::File::create(path)?);
    writeln!(f, "run,t,s,u")?;
    for r in runs {
        for (t, u) in &r.profiles {
            let n = u.len() - 1;
            for (i, v) in u.iter().enumerate() {
                writeln!(f, "\"{}\",{t:.8e},{:.6},{v:.15e}", r.spec.label, i as f64 / n as f64)?;
            }
        }
    }
    f.flush()
}
