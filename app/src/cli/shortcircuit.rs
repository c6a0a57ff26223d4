//! `ohl shortcircuit CASE.toml [--out DIR]`: a line scenario with `[short_circuit]` by the IEC 60865-1
//! simplified method and by the dynamic simulation, side by side (`ohl::run::shortcircuit_case`): one table
//! of quantity, symbol, IEC equation, IEC value, dynamic value and their difference. Writes the run's files
//! (as `ohl run`, with `short_circuit.csv`) and `shortcircuit.json` (the mapped input, both sets of
//! numbers, the table) into DIR.
//!
//! Where the method cannot take the line (a line-to-earth fault, a span above its range, ...) the message
//! says why on stderr and the dynamic part still runs.
//!
//! Exit codes: 0 written; 1 the run went unstable or a file could not be written; 2 the case is invalid
//! (file, field, value and allowed range named) or has no `[short_circuit]`.

use std::path::PathBuf;
use std::process::ExitCode;

use ohl::run::shortcircuit_case::{CompareError, Comparison, compare, to_json};
use ohl::scenario;
use ohl::shortcircuit::iec60865::Mounting;

/// Arguments of `ohl shortcircuit`.
#[derive(clap::Args)]
pub struct ShortCircuitArgs {
    /// a line scenario (TOML, SI units) with a [short_circuit] table (docs/short_circuit.md)
    case: PathBuf,
    /// output directory (created if missing): the run's files, short_circuit.csv, shortcircuit.json
    #[arg(long, default_value = "out")]
    out: PathBuf,
}

/// Run the command.
pub fn main(args: ShortCircuitArgs) -> ExitCode {
    let file = args.case.display().to_string();
    let parsed = scenario::read_text(&args.case).and_then(|t| scenario::line::parse(&t, &file));
    let (s, plan) = match parsed.and_then(|s| scenario::line::plan(&s, &file).map(|p| (s, p))) {
        Ok(x) => x,
        Err(e) => {
            err!("error: {e}");
            return ExitCode::from(2);
        }
    };
    if s.short_circuit.is_none() {
        err!("error: {file}: {}", CompareError::NoShortCircuit);
        return ExitCode::from(2);
    }
    // The scenario's warnings (a step set by a string or by the contact, doubtful values), as `ohl run`
    // prints them.
    for (p, name) in plan.plans.iter().zip(plan.line.names()) {
        for w in &p.warnings {
            err!("warning: {file}: {name}: {w}");
        }
    }
    let work = ohl::run::line::LineWorkEstimate::of(&plan);
    if let Err(refusal) = work.check() {
        err!("error: {file}: {refusal}");
        return ExitCode::from(2);
    }
    let c = match compare(&s, plan, Some(&args.out)) {
        Ok(c) => c,
        Err(e) => {
            err!("error: {file}: {e}");
            return ExitCode::from(1);
        }
    };
    match &c.mapped {
        Err(e) => err!("warning: {file}: the IEC 60865-1 simplified method cannot take this line: {e}"),
        Ok(_) => {
            if let Some(Err(e)) = &c.iec {
                err!("warning: {file}: the IEC 60865-1 simplified method refuses: {e}");
            }
        }
    }
    print(&s.name.clone().unwrap_or_default(), &c);
    let path = args.out.join("shortcircuit.json");
    let text = serde_json::to_string_pretty(&to_json(&c)).expect("serialises") + "\n";
    if let Err(e) = std::fs::write(&path, text) {
        err!("error: {}: {e}", path.display());
        return ExitCode::from(1);
    }
    out!("written: {}/shortcircuit.json, short_circuit.csv, summary.json", args.out.display());
    ExitCode::SUCCESS
}

fn value(x: Option<f64>) -> String {
    // Small values (the stiffness norm N, 1e-7 1/N) in exponent form, so that they do not print as 0.
    x.map_or("-".into(), |v| if v != 0.0 && v.abs() < 1e-2 { format!("{v:.4e}") } else { format!("{v:.4}") })
}

fn print(name: &str, c: &Comparison) {
    out!("{name}: main conductor {} (IEC 60865-1 simplified method | dynamic run)", c.main);
    if let Ok(m) = &c.mapped {
        let i = &m.input;
        let mounting = match i.mounting {
            Mounting::Slack => "slack".to_string(),
            Mounting::Strained { insulator_chain_length_m } => format!("strained, l_i = {insulator_chain_length_m} m"),
        };
        out!(
            "span l = {:.3} m ({mounting}), a = {:.3} m, n = {}, m'_s = {} kg/m, m_c = {:.3} kg, A_s = {:.4e} m^2, \
             E = {:.4e} Pa, d = {} m, F_st = {:.1} N, S = {:.4e} N/m, I = {} A, T_k1 = {} s",
            i.span_m,
            i.phase_distance_m,
            i.subconductors,
            i.mass_per_length_kg_per_m,
            i.concentrated_mass_kg,
            i.area_m2,
            i.young_modulus_pa,
            i.diameter_m,
            i.static_tension_n,
            i.spring_constant_n_per_m,
            i.fault.current_a(),
            i.first_duration_s
        );
        for n in &m.notes {
            out!("  note: {n}");
        }
    }
    out!("");
    out!("{:<36} {:<8} {:<10} {:>14} {:>14} {:>10}", "quantity", "symbol", "IEC eq.", "IEC", "dynamic", "diff");
    for r in &c.rows {
        out!(
            "{:<36} {:<8} {:<10} {:>14} {:>14} {:>10}",
            format!("{} [{}]", r.quantity, r.unit),
            r.symbol,
            r.equation,
            value(r.iec),
            value(r.dynamic),
            r.difference().map_or("-".into(), |d| format!("{:+.1} %", 100.0 * d))
        );
    }
    let s = &c.outcome.summary;
    out!("");
    out!(
        "run: {} at t = {:.4} s after {} steps of {:.4e} s, wall {:.2} s",
        s.status,
        s.final_time_s,
        s.steps,
        s.dt_s,
        s.wall_time_s
    );
    out!(
        "fault: inception angle {:.2} deg, kappa {:.4}, flow {} s to {} s; EM work {:.4e} J",
        c.dynamic.inception_angle_deg,
        c.dynamic.peak_factor,
        c.dynamic.start_s,
        c.dynamic.end_s,
        c.dynamic.em_work_j
    );
}
