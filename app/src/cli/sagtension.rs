//! `ohl sagtension CASE.toml --out DIR`: the sag-tension table of a span or ruling span as line
//! designers read it. For each condition (a weather) and each state of the conductor (initial, after
//! creep, after the heavy load, final: the longer of the two) the horizontal tension, the mid-span sag,
//! the larger support tension and its share of the rated tensile strength, the aluminium and core
//! stresses and whether the knee is passed (the aluminium slack: the core carries the span); then the
//! knee-point temperature of each state and the temperature at which the case's sag or clearance limit is
//! reached. Writes `DIR/sagtension.csv`, `DIR/sagtension.json` and `DIR/sag_vs_temperature.png`/`.svg`.
//! The file's schema is [`ohl::scenario::sagtension::SagTensionCase`] (docs/sagtension_cases.md).
//!
//! Exit codes: 0 written; 1 the solver found no solution (the message says for what) or a file could not
//! be written; 2 the case is invalid (file, field, value and allowed range named).

use std::path::PathBuf;
use std::process::ExitCode;

use ohl::sagtension::State;
use ohl::scenario::sagtension::{self, LawKind, Resolved};
use ohl::scenario::sagtension_table::{self, Found, Table};
use ohl::scenario::temperature::ZERO_CELSIUS_K as C;
use ohl_app::sagtension as files;

/// Arguments of `ohl sagtension`.
#[derive(clap::Args)]
pub struct SagTensionArgs {
    /// the sag-tension case (TOML, SI units; temperatures in kelvin `_k` or degrees Celsius `_c`):
    /// [conductor] catalog, [span] or [ruling_span], [stringing], optional [creep] and [heavy_load],
    /// [[condition]] and/or a [conditions] range, optional [clearance] (docs/sagtension_cases.md)
    case: PathBuf,
    /// output directory (created if missing): sagtension.csv, sagtension.json, sag_vs_temperature.png/.svg
    #[arg(long, default_value = "out")]
    out: PathBuf,
}

/// Run the command.
pub fn main(args: SagTensionArgs) -> ExitCode {
    let file = args.case.display().to_string();
    let (case, resolved) = match sagtension::load(&args.case) {
        Ok(c) => c,
        Err(e) => {
            err!("error: {e}");
            return ExitCode::from(2);
        }
    };
    let table = match sagtension_table::solve(&resolved) {
        Ok(t) => t,
        Err(e) => {
            err!("error: {file}: {e}");
            return ExitCode::from(1);
        }
    };
    print(&case.name, &resolved, &table);
    let write = || -> Result<(), String> {
        std::fs::create_dir_all(&args.out).map_err(|e| format!("{}: {e}", args.out.display()))?;
        files::write_csv(&args.out, &resolved, &table)?;
        files::write_json(&args.out, &case, &resolved, &table)?;
        files::figure(&args.out, &case, &resolved, &table)
    };
    match write() {
        Ok(()) => {
            out!("written: {}/sagtension.csv, sagtension.json, sag_vs_temperature.png, .svg", args.out.display());
            ExitCode::SUCCESS
        }
        Err(e) => {
            err!("error: {file}: {e}");
            ExitCode::from(1)
        }
    }
}

fn weather_text(w: &sagtension::Weather) -> String {
    let mut t = format!("{:.2} C", w.temperature_k - C);
    if w.ice_thickness_m > 0.0 {
        t += &format!(", {:.1} mm ice", w.ice_thickness_m * 1e3);
    }
    if w.wind_pressure_pa > 0.0 {
        t += &format!(", {:.1} Pa wind", w.wind_pressure_pa * w.drag_coefficient);
    }
    if w.constant_n_per_m > 0.0 {
        t += &format!(", K {:.2} N/m", w.constant_n_per_m);
    }
    if w.is_bare() { t + ", bare" } else { t }
}

/// The state's name in the table: `final` says which state it is.
pub fn state_label(state: State, history_of: State) -> String {
    if state == State::Final { format!("final={}", history_of.name()) } else { state.name().to_string() }
}

fn found_text(f: &Found) -> String {
    match f {
        Ok(k) => format!("{:.2} C", k - C),
        Err(e) => format!("none ({e})"),
    }
}

fn print(name: &Option<String>, r: &Resolved, t: &Table) {
    let law = match t.law {
        LawKind::TwoMaterial => "two-material stress-strain law",
        LawKind::SingleModulus => "single-modulus law (no stress-strain data in the catalogue entry)",
    };
    out!("{}: {} ({law})", name.as_deref().unwrap_or("sag-tension"), r.conductor.name);
    if r.lengths_m.len() > 1 {
        let spans: Vec<String> = r.lengths_m.iter().map(|l| format!("{l}")).collect();
        out!("section of {} spans [{}] m: ruling span {:.3} m", r.lengths_m.len(), spans.join(", "), t.span_m);
    } else {
        out!("span {} m, rise {} m", t.span_m, r.rise_m);
    }
    let strung = match (r.stringing_target, r.stringing_sag_m) {
        (_, Some(d)) => format!("sag {d} m"),
        (Some(h), None) => format!("H = {:.3} kN", h / 1e3),
        _ => String::new(),
    };
    out!("strung: {strung} at {}, {}", weather_text(&r.stringing), r.stringing_state.name());
    out!("creep: 10 years at {}", weather_text(&r.creep));
    match &r.heavy_load {
        Some(w) => out!("heavy load: {} ({})", w.label, weather_text(w)),
        None => out!("heavy load: none given"),
    }
    out!("final state = {} (the longer conductor of after creep and after load)", t.final_is.name());
    out!("");
    out!(
        "{:<40} {:<22} {:>9} {:>8} {:>10} {:>6} {:>9} {:>9} {:>5}",
        "condition",
        "state",
        "H [kN]",
        "sag [m]",
        "T_sup [kN]",
        "%RTS",
        "Al [MPa]",
        "core[MPa]",
        "knee"
    );
    let per = t.states.len();
    for (k, row) in t.rows.iter().enumerate() {
        let label = if k % per == 0 { r.conditions[k / per].label.as_str() } else { "" };
        out!(
            "{:<40} {:<22} {:>9.3} {:>8.3} {:>10.3} {:>6.2} {:>9.2} {:>9.2} {:>5}",
            label,
            state_label(row.state, row.history_of),
            row.horizontal_tension_n / 1e3,
            row.sag_midspan_m,
            files::support_tension_n(row) / 1e3,
            100.0 * row.max_tension_fraction_rts,
            row.outer_stress_pa / 1e6 + 0.0, // -0 (a slack layer) prints as 0
            row.core_stress_pa / 1e6 + 0.0,
            if row.knee_passed { "yes" } else { "no" }
        );
    }
    out!("");
    for (state, k) in &t.knee_k {
        out!("knee-point temperature, {}: {}", state.name(), found_text(k));
    }
    if let Some(limit) = t.sag_limit_m {
        let what = match sagtension_table::longest_of_section(r) {
            Some(l) => format!("sag limit {limit:.3} m of the longest span ({l} m, at the ruling span's H)"),
            None => format!("sag limit {limit:.3} m"),
        };
        for (state, k) in &t.limit_k {
            out!("{what} reached, {}: {}", state.name(), found_text(k));
        }
    }
}
