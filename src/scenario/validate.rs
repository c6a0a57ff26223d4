//! Validation of a parsed scenario: every field is checked before anything runs, and each problem
//! names the field, its value and what is allowed. Nothing here panics on any input.

use std::fmt;

use super::events::EventSpec;
use super::schema::{Scenario, ShapeSpec, WindLawSpec};
use crate::scheme::courant;

/// One invalid field.
#[derive(Clone, Debug, PartialEq)]
pub struct Problem {
    /// dotted path of the field, e.g. `numerics.courant`
    pub field: String,
    /// the value found, as written
    pub value: String,
    /// what is allowed
    pub allowed: String,
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "field `{}` = {} is not allowed: {}", self.field, self.value, self.allowed)
    }
}

/// Collects problems (also used by the validators of the files the applications read).
#[derive(Debug, Default)]
pub struct Check(pub Vec<Problem>);

impl Check {
    /// Record that `field` = `value` is not allowed, with what is.
    pub fn fail(&mut self, field: &str, value: impl fmt::Display, allowed: &str) {
        self.0.push(Problem { field: field.into(), value: value.to_string(), allowed: allowed.into() });
    }
    /// `x` finite and `> 0`.
    pub fn positive(&mut self, field: &str, x: f64) -> bool {
        let ok = x.is_finite() && x > 0.0;
        if !ok {
            self.fail(field, x, "must be a finite number > 0");
        }
        ok
    }
    /// `x` finite and `>= 0`.
    pub fn non_negative(&mut self, field: &str, x: f64) -> bool {
        let ok = x.is_finite() && x >= 0.0;
        if !ok {
            self.fail(field, x, "must be a finite number >= 0");
        }
        ok
    }
    /// `lo <= x <= hi`.
    pub fn within(&mut self, field: &str, x: f64, lo: f64, hi: f64, allowed: &str) -> bool {
        let ok = x.is_finite() && x >= lo && x <= hi;
        if !ok {
            self.fail(field, x, allowed);
        }
        ok
    }
    fn finite3(&mut self, field: &str, v: [f64; 3]) -> bool {
        let ok = v.iter().all(|c| c.is_finite());
        if !ok {
            self.fail(field, format!("{v:?}"), "all three components must be finite numbers");
        }
        ok
    }
}

/// Largest number of segments accepted (memory and run time stay sane).
pub const MAX_SEGMENTS: usize = 10_000_000;

/// All problems of a scenario; empty when it is valid.
pub fn validate(s: &Scenario) -> Vec<Problem> {
    check(s).0
}

/// The quantities validation derives on the way, each `None` where its inputs were invalid. The builder
/// uses these and derives none of them again.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Derived {
    /// axial stiffness `EA` [N]
    pub ea_n: Option<f64>,
    /// chord length `|B - A|` [m]
    pub chord_m: Option<f64>,
    /// unstretched length `S` [m]
    pub length_m: Option<f64>,
    /// wave speed `c` [m/s]
    pub wave_speed_m_per_s: Option<f64>,
    /// nominal time step (3.7) [s]
    pub dt_s: Option<f64>,
}

/// Every problem of a scenario, and what was derived from its valid parts.
pub(crate) fn check(s: &Scenario) -> (Vec<Problem>, Derived) {
    let mut c = Check(Vec::new());
    let mut derived = Derived::default();

    // Conductor.
    let cd = &s.conductor;
    let rho_ok = c.positive("conductor.linear_density_kg_per_m", cd.linear_density_kg_per_m);
    c.within(
        "conductor.thermal_expansion_per_k",
        cd.thermal_expansion_per_k,
        0.0,
        1.0e-3,
        "must be in [0, 1e-3] 1/K (aluminium: 23.8e-6, section 5.4)",
    );
    c.within(
        "conductor.reference_temperature_k",
        cd.reference_temperature_k,
        f64::MIN_POSITIVE,
        5000.0,
        "must be in (0, 5000] K",
    );
    if let Some(d) = cd.diameter_m {
        c.positive("conductor.diameter_m", d);
    }
    let ea = match (cd.axial_stiffness_n, cd.youngs_modulus_pa) {
        (Some(_), Some(e)) => {
            c.fail(
                "conductor.youngs_modulus_pa",
                e,
                "give either conductor.axial_stiffness_n or conductor.youngs_modulus_pa, not both",
            );
            None
        }
        (Some(ea), None) => c.positive("conductor.axial_stiffness_n", ea).then_some(ea),
        (None, Some(e)) => {
            let e_ok = c.positive("conductor.youngs_modulus_pa", e);
            match cd.diameter_m {
                None => {
                    c.fail("conductor.diameter_m", "(missing)", "required with conductor.youngs_modulus_pa");
                    None
                }
                Some(d) if e_ok && d.is_finite() && d > 0.0 => Some(e * std::f64::consts::PI * d * d / 4.0),
                Some(_) => None,
            }
        }
        (None, None) => {
            c.fail(
                "conductor.axial_stiffness_n",
                "(missing)",
                "give conductor.axial_stiffness_n [N], or conductor.youngs_modulus_pa [Pa] with conductor.diameter_m [m]",
            );
            None
        }
    };

    // Geometry.
    let g = &s.geometry;
    let a_ok = c.finite3("geometry.left_support_m", g.left_support_m);
    let b_ok = c.finite3("geometry.right_support_m", g.right_support_m);
    let mut chord = None;
    if a_ok && b_ok {
        let d: f64 = (0..3).map(|k| (g.right_support_m[k] - g.left_support_m[k]).powi(2)).sum::<f64>().sqrt();
        if d > 1.0e-6 {
            chord = Some(d);
        } else {
            c.fail(
                "geometry.right_support_m",
                format!("{:?}", g.right_support_m),
                "the supports must be at least 1e-6 m apart (it coincides with geometry.left_support_m)",
            );
        }
    }
    let n_ok = g.segments >= 2 && g.segments <= MAX_SEGMENTS;
    if !n_ok {
        c.fail("geometry.segments", g.segments, &format!("must be an integer in [2, {MAX_SEGMENTS}]"));
    }
    if let Some(l) = g.unstretched_length_m {
        c.positive("geometry.unstretched_length_m", l);
    }

    // Initial shape.
    let ini = &s.initial;
    let mut shape_length = chord;
    match (ini.shape, ini.sag_m) {
        (ShapeSpec::Straight, Some(f)) => c.fail("initial.sag_m", f, "only with initial.shape = \"parabola\""),
        (ShapeSpec::Straight, None) => {}
        (ShapeSpec::Parabola, None) => {
            c.fail("initial.sag_m", "(missing)", "required with initial.shape = \"parabola\"")
        }
        (ShapeSpec::Equilibrium, None) => {}
        (ShapeSpec::Parabola | ShapeSpec::Equilibrium, Some(f)) => {
            let hi = chord.unwrap_or(f64::INFINITY);
            if c.within("initial.sag_m", f, f64::MIN_POSITIVE, hi, "must be > 0 and at most the chord length") {
                shape_length = chord.map(|l| super::build::parabola_length(l, f));
            }
        }
    }

    // Loads.
    let ld = &s.loads;
    c.within("loads.gravity_m_per_s2", ld.gravity_m_per_s2, 0.0, 100.0, "must be in [0, 100] m/s^2");
    c.finite3("loads.uniform_load_n_per_m", ld.uniform_load_n_per_m);
    if let Some(w) = &ld.wind {
        if c.finite3("loads.wind.direction", w.direction) {
            let norm: f64 = w.direction.iter().map(|x| x * x).sum::<f64>().sqrt();
            if norm < 1.0e-12 {
                c.fail("loads.wind.direction", format!("{:?}", w.direction), "must be a non-zero vector");
            }
        }
        c.positive("loads.wind.speed_m_per_s", w.speed_m_per_s);
        c.positive("loads.wind.air_density_kg_per_m3", w.air_density_kg_per_m3);
        c.non_negative("loads.wind.normal_coefficient", w.normal_coefficient);
        c.non_negative("loads.wind.tangential_coefficient", w.tangential_coefficient);
        c.non_negative("loads.wind.initial_scale", w.initial_scale);
        match (w.law, w.pressure_n_per_m) {
            (WindLawSpec::UniformNormal, Some(p)) => {
                c.non_negative("loads.wind.pressure_n_per_m", p);
            }
            (WindLawSpec::UniformNormal, None) => {
                c.fail("loads.wind.pressure_n_per_m", "(missing)", "required with loads.wind.law = \"uniform_normal\"")
            }
            (WindLawSpec::Aerodynamic, Some(p)) => {
                c.fail("loads.wind.pressure_n_per_m", p, "only with loads.wind.law = \"uniform_normal\"")
            }
            (WindLawSpec::Aerodynamic, None) => {
                if cd.diameter_m.is_none() {
                    c.fail("conductor.diameter_m", "(missing)", "required with loads.wind.law = \"aerodynamic\"");
                }
            }
        }
    }

    // Numerics.
    let nm = &s.numerics;
    let courant_ok = c.within("numerics.courant", nm.courant, f64::MIN_POSITIVE, 1.0, "must be in (0, 1]");
    c.within("numerics.smoothing", nm.smoothing, 0.0, 0.25, "must be in [0, 0.25] (stability of (3.3))");
    c.within("numerics.mu", nm.mu, 0.0, 1.0, "must be in [0, 1] (paper section 3: 0.1 to 0.2)");
    let eta_ok = c.non_negative("numerics.eta_n_s", nm.eta_n_s);
    let zeta_ok = c.non_negative("numerics.mass_damping_per_s", nm.mass_damping_per_s);
    if let Some(v) = nm.max_speed_m_per_s {
        c.positive("numerics.max_speed_m_per_s", v);
    }
    // Stability limits need EA, rho0, the segment length: check them only when those are valid.
    let length = g.unstretched_length_m.or(shape_length);
    derived.ea_n = ea;
    derived.chord_m = chord;
    derived.length_m = length.filter(|l| l.is_finite() && *l > 0.0);
    if let (Some(ea), true, true, Some(len)) = (ea, rho_ok, n_ok, length)
        && len.is_finite()
        && len > 0.0
    {
        let cw = courant::wave_speed(ea, cd.linear_density_kg_per_m);
        let ds = len / g.segments as f64;
        derived.wave_speed_m_per_s = Some(cw);
        if courant_ok && eta_ok {
            let z = courant::friction_number(ea, nm.eta_n_s, cw, ds);
            let limit = courant::stable_courant(z);
            if nm.courant > limit {
                c.fail(
                    "numerics.courant",
                    nm.courant,
                    &format!(
                        "must be at most sqrt(1 + z^2) - z = {limit:.6} for internal friction eta = {} N s \
                         (z = eta c / (EA ds) = {z:.4e}): the explicit Kelvin-Voigt term lowers the stable step",
                        nm.eta_n_s
                    ),
                );
            }
            let dt = courant::time_step(nm.courant, ds, cw);
            derived.dt_s = Some(dt);
            if zeta_ok && nm.mass_damping_per_s * dt >= 1.0 {
                c.fail(
                    "numerics.mass_damping_per_s",
                    nm.mass_damping_per_s,
                    &format!("must satisfy zeta dt < 1 (dt = {dt:.4e} s), i.e. zeta < {:.4e} 1/s", 1.0 / dt),
                );
            }
        }
    }

    // Duration.
    let du = &s.duration;
    let end = match (du.end_time_s, &du.until_settled) {
        (Some(t), None) => c.positive("duration.end_time_s", t).then_some(t),
        (None, Some(st)) => {
            c.within(
                "duration.until_settled.kinetic_energy_fraction",
                st.kinetic_energy_fraction,
                f64::MIN_POSITIVE,
                1.0 - f64::EPSILON,
                "must be in (0, 1)",
            );
            c.positive("duration.until_settled.window_s", st.window_s);
            c.positive("duration.until_settled.max_time_s", st.max_time_s).then_some(st.max_time_s)
        }
        (Some(t), Some(_)) => {
            c.fail("duration.end_time_s", t, "give either duration.end_time_s or duration.until_settled, not both");
            None
        }
        (None, None) => {
            c.fail("duration", "(empty)", "give duration.end_time_s [s] or duration.until_settled");
            None
        }
    };

    // Output.
    let out = &s.output;
    c.positive("output.sample_interval_s", out.sample_interval_s);
    c.positive("output.tau_speed_m_per_s", out.tau_speed_m_per_s);
    for (k, &t) in out.snapshot_times_s.iter().enumerate() {
        let hi = end.unwrap_or(f64::INFINITY);
        c.within(
            &format!("output.snapshot_times_s[{k}]"),
            t,
            0.0,
            hi,
            "must be in [0, end time] (duration.end_time_s or duration.until_settled.max_time_s)",
        );
    }
    for (k, p) in out.probes.iter().enumerate() {
        let field = |f: &str| format!("output.probes[{k}].{f}");
        let name_ok = !p.name.is_empty()
            && p.name.chars().all(|ch| ch.is_ascii_alphanumeric() || ch == '_')
            && p.name != crate::output::probe::MIDSPAN;
        if !name_ok {
            c.fail(&field("name"), format!("{:?}", p.name), "must be letters, digits and _ only, and not \"mid\"");
        }
        if out.probes[..k].iter().any(|q| q.name == p.name) {
            c.fail(&field("name"), format!("{:?}", p.name), "must differ from the names of the earlier probes");
        }
        c.within(&field("at_fraction"), p.at_fraction, 0.0, 1.0, "must be a fraction of the span in [0, 1]");
    }
    if let Some(t) = out.peaks_from_s {
        c.within("output.peaks_from_s", t, 0.0, end.unwrap_or(f64::INFINITY), "must be in [0, end time] [s]");
    }
    check_ground_and_events(&mut c, s, end);
    (c.0, derived)
}

fn range_ok(c: &mut Check, field: &str, r: [f64; 2]) -> bool {
    let ok = r.iter().all(|x| x.is_finite()) && 0.0 <= r[0] && r[0] < r[1] && r[1] <= 1.0;
    if !ok {
        c.fail(field, format!("{r:?}"), "must be [a, b] with 0 <= a < b <= 1 (fractions of the unstretched length)");
    }
    ok
}

/// `[ground]` and `[[events]]`.
fn check_ground_and_events(c: &mut Check, s: &Scenario, end: Option<f64>) {
    let g = &s.geometry;
    if let Some(gr) = &s.ground {
        let low = g.left_support_m[2].min(g.right_support_m[2]);
        if !(gr.height_m.is_finite() && gr.height_m < low) {
            c.fail(
                "ground.height_m",
                gr.height_m,
                &format!("must be a finite height below both supports (the lower support is at x3 = {low} m)"),
            );
        }
        c.within("ground.restitution", gr.restitution, 0.0, 1.0, "must be in [0, 1] (0.6 returns 36 % of the energy)");
    }
    let hi = end.unwrap_or(f64::INFINITY);
    // Ice: the linear density of every part of the span, as the events change it in time order.
    let mut order: Vec<usize> = (0..s.events.len()).collect();
    order.sort_by(|&a, &b| s.events[a].time_s().total_cmp(&s.events[b].time_s()));
    let mut ice: Vec<(f64, f64, f64)> = Vec::new(); // (a, b, delta) applied so far
    for k in order {
        let e = &s.events[k];
        let f = |name: &str| format!("events[{k}].{name}");
        c.within(
            &f("time_s"),
            e.time_s(),
            0.0,
            hi,
            "must be in [0, end time] (duration.end_time_s or duration.until_settled.max_time_s)",
        );
        let needs_wind = matches!(e, EventSpec::Wind { .. } | EventSpec::Gust { .. });
        if needs_wind && s.loads.wind.is_none() {
            c.fail(&f("action"), format!("\"{}\"", e.action()), "needs a wind load ([loads.wind]) to switch");
        }
        match *e {
            EventSpec::Break { at_fraction, .. } => {
                c.within(&f("at_fraction"), at_fraction, f64::MIN_POSITIVE, 1.0 - f64::EPSILON, "must be in (0, 1)");
            }
            EventSpec::Ice { linear_density_kg_per_m: d, range, .. } => {
                if range_ok(c, &f("range"), range)
                    && c.within(
                        &f("linear_density_kg_per_m"),
                        d,
                        -1.0e6,
                        1.0e6,
                        "must be a finite change of linear density [kg/m]",
                    )
                {
                    ice.push((range[0], range[1], d));
                    // The least density anywhere: check at the midpoints between all range ends.
                    let mut ends: Vec<f64> = ice.iter().flat_map(|r| [r.0, r.1]).collect();
                    ends.sort_by(f64::total_cmp);
                    let least = ends
                        .windows(2)
                        .filter(|w| w[1] > w[0])
                        .map(|w| {
                            let m = 0.5 * (w[0] + w[1]);
                            ice.iter().filter(|r| r.0 <= m && m <= r.1).map(|r| r.2).sum::<f64>()
                        })
                        .fold(0.0_f64, f64::min);
                    if least < 0.0 {
                        c.fail(
                            &f("linear_density_kg_per_m"),
                            d,
                            &format!(
                                "would leave part of the span {:.6} kg/m below conductor.linear_density_kg_per_m \
                                 (ice can only be dropped down to the bare wire, for which the time step is set)",
                                -least
                            ),
                        );
                    }
                }
            }
            EventSpec::Wind { scale, .. } => {
                c.non_negative(&f("scale"), scale);
            }
            EventSpec::Gust { period_s, amplitude, .. } => {
                c.positive(&f("period_s"), period_s);
                c.non_negative(&f("amplitude"), amplitude);
            }
            EventSpec::Temperature { temperature_k, range, ramp_s, .. } => {
                c.within(&f("temperature_k"), temperature_k, f64::MIN_POSITIVE, 5000.0, "must be in (0, 5000] K");
                range_ok(c, &f("range"), range);
                c.non_negative(&f("ramp_s"), ramp_s);
            }
            EventSpec::HeatConduction { hold_range, hold_temperature_k, heat_time_per_s, .. } => {
                range_ok(c, &f("hold_range"), hold_range);
                c.within(
                    &f("hold_temperature_k"),
                    hold_temperature_k,
                    f64::MIN_POSITIVE,
                    5000.0,
                    "must be in (0, 5000] K",
                );
                c.within(&f("heat_time_per_s"), heat_time_per_s, f64::MIN_POSITIVE, 1.0e3, "must be in (0, 1000] 1/s");
            }
            EventSpec::HeatConductionOff { .. } => {}
            EventSpec::Ground { .. } => {
                if s.ground.is_none() {
                    c.fail(&f("action"), "\"ground\"", "needs a [ground] section (height_m, restitution)");
                }
            }
        }
    }
}
