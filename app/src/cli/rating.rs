//! `ohl rating SCENARIO.toml --out DIR`: the thermal rating of a span or section by ground clearance or
//! sag ([`ohl::scenario::rating`]): the temperature at which the line reaches the limit, the steady
//! ampacity there (and for the conductor's maximum temperature), and the time to reach the governing
//! temperature after a current step. Prints them and writes `DIR/rating.json`.

use std::path::PathBuf;
use std::process::ExitCode;

use ohl::scenario::rating::{RatingError, rate};
use ohl::scenario::{self};
use serde_json::json;

/// Arguments of `ohl rating`.
#[derive(clap::Args)]
pub struct RatingArgs {
    /// the scenario (TOML, SI units) with `[thermal]` and `[rating]` tables
    scenario: PathBuf,
    /// output directory (created if missing)
    #[arg(long, default_value = "out")]
    out: PathBuf,
}

/// 0 C in kelvin: a temperature `T` [K] is `T - C` degrees Celsius.
const C: f64 = ohl::scenario::temperature::ZERO_CELSIUS_K;

/// Run the command; exit 0 on success, 1 if a solve failed, 2 on invalid input.
pub fn main(args: RatingArgs) -> ExitCode {
    let file = args.scenario.display().to_string();
    let s = match scenario::load(&args.scenario) {
        Ok(s) => s,
        Err(e) => {
            err!("error: {e}");
            return ExitCode::from(2);
        }
    };
    let r = match rate(&s, &file) {
        Ok(r) => r,
        Err(RatingError::Input(e)) => {
            err!("error: {e}");
            return ExitCode::from(2);
        }
        Err(e) => {
            err!("error: {file}: {e}");
            return ExitCode::from(1);
        }
    };
    let name = s.name.clone().unwrap_or_else(|| "rating".into());
    let unit = if r.quantity == "clearance" { "least clearance" } else { "largest sag" };
    out!("{name}: rating by {} (limit {} m)", r.quantity, r.limit_m);
    out!("  {unit} at the air temperature: {:.3} m", r.at_air_m);
    match r.limit_temperature_k {
        Some(t) => out!("  the limit is reached at a conductor temperature of {:.3} C", t - C),
        None => out!("  the limit is not reached below the maximum temperature"),
    }
    if let Some(a) = r.clearance_ampacity_a {
        out!("  steady ampacity for the {}: {a:.1} A", r.quantity);
    }
    if let Some(a) = r.temperature_ampacity_a {
        out!("  steady ampacity for the maximum temperature: {a:.1} A");
    }
    out!(
        "  rating: {:.1} A (governing temperature {:.3} C, {unit} there {:.3} m; {} static solves)",
        r.rating_a,
        r.governing_temperature_k - C,
        r.at_rating_m,
        r.solves
    );
    if let Some(o) = &r.other {
        let what = if o.quantity == "temperature" { "maximum temperature" } else { o.quantity };
        match (o.temperature_k, &o.failed) {
            (Some(t), _) => out!(
                "  margin: the {what} limit is reached at {:.3} C{}",
                t - C,
                o.current_a.map_or_else(|| " (no steady ampacity there)".to_string(), |a| format!(", at {a:.1} A"))
            ),
            (None, Some(why)) => out!("  margin: the {what} limit was not found: {why}"),
            (None, None) => out!(
                "  margin: the {what} stays within its limit up to {:.2} C",
                ohl::scenario::range::RATING_TEMPERATURE_K.hi - C
            ),
        }
    }
    if let Some((from, to, start, when)) = r.step {
        match when {
            Some(t) => out!(
                "  after a step {from} A -> {to} A (from {:.2} C): reaches {:.2} C after {t:.0} s ({:.1} min)",
                start - C,
                r.governing_temperature_k - C,
                t / 60.0
            ),
            // The first current's steady temperature is above the limit already: the question is moot.
            None if start > r.governing_temperature_k => out!(
                "  after a step {from} A -> {to} A: starts at {:.2} C, already above the limit {:.2} C ({from} A exceeds the rating)",
                start - C,
                r.governing_temperature_k - C
            ),
            None => out!("  after a step {from} A -> {to} A: does not reach the limit within 24 h"),
        }
    }
    let doc = json!({
        "name": name, "quantity": r.quantity, "limit_m": r.limit_m,
        "limit_temperature_k": r.limit_temperature_k, "at_air_temperature_m": r.at_air_m,
        "clearance_ampacity_a": r.clearance_ampacity_a, "temperature_ampacity_a": r.temperature_ampacity_a,
        "rating_a": r.rating_a, "governing_temperature_k": r.governing_temperature_k, "at_rating_m": r.at_rating_m,
        "step": r.step.map(|(from, to, start, when)| json!({"from_a": from, "to_a": to, "initial_temperature_k": start,
            "initial_temperature_c": start - C, "time_to_limit_s": when})),
        "static_solves": r.solves,
        "limit_temperature_c": r.limit_temperature_k.map(|t| t - C),
        "governing_temperature_c": r.governing_temperature_k - C,
        "other_limit": r.other.as_ref().map(|o| json!({"quantity": o.quantity, "temperature_k": o.temperature_k,
            "temperature_c": o.temperature_k.map(|t| t - C), "current_a": o.current_a, "static_solves": o.solves,
            "failed": o.failed})),
    });
    if let Err(e) = std::fs::create_dir_all(&args.out).and_then(|_| {
        std::fs::write(args.out.join("rating.json"), serde_json::to_string_pretty(&doc).unwrap_or_default())
    }) {
        err!("error: {}: {e}", args.out.display());
        return ExitCode::from(1);
    }
    out!("  written to {}", args.out.display());
    ExitCode::SUCCESS
}
