//! `ohl thermal CASE.toml --out DIR`: the heat balance of a conductor in a weather (IEEE Std 738-2012 or
//! CIGRE TB 601): steady temperatures for currents, steady ampacities for maximum temperatures, a
//! transient after current steps, and de-icing (time to shed, current to shed in time). Prints a table and
//! writes `DIR/thermal.json`, `DIR/transient.csv` and `DIR/deicing.csv` (the de-icing of the first
//! current). The file's schema is [`ohl::scenario::thermal::ThermalCase`].

use std::path::PathBuf;
use std::process::ExitCode;

use ohl::scenario::thermal::{self, ThermalCase};
use ohl::scenario::{self};
use ohl::thermal::deicing::DeicingOptions;
use ohl::thermal::transient::{CurrentSchedule, Transient, time_to_reach};
use ohl::thermal::{HeatBalance, Model, steady};
use serde_json::json;

/// Arguments of `ohl thermal`.
#[derive(clap::Args)]
pub struct ThermalArgs {
    /// the thermal case (TOML, SI units; temperatures in kelvin `_k` or degrees Celsius `_c`)
    case: PathBuf,
    /// output directory (created if missing)
    #[arg(long, default_value = "out")]
    out: PathBuf,
}

/// 0 C in kelvin: a temperature `T` [K] is `T - C` degrees Celsius.
const C: f64 = ohl::scenario::temperature::ZERO_CELSIUS_K;

/// Run the command; exit 0 on success, 1 if a computation failed, 2 on invalid input.
pub fn main(args: ThermalArgs) -> ExitCode {
    let file = args.case.display().to_string();
    let case = match scenario::read_text(&args.case).and_then(|t| thermal::parse_case(&t, &file)) {
        Ok(c) => c,
        Err(e) => {
            err!("error: {e}");
            return ExitCode::from(2);
        }
    };
    for w in thermal::unused_weather_inputs("weather", &case.weather, case.standard) {
        err!("warning: {file}: {w}");
    }
    match evaluate(&case, &args.out) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            err!("error: {file}: {e}");
            ExitCode::from(1)
        }
    }
}

fn terms_json(model: &Model, t: f64, i: f64) -> serde_json::Value {
    let q = model.terms(t, i);
    json!({
        "joule_w_per_m": q.joule_w_per_m, "solar_w_per_m": q.solar_w_per_m,
        "convection_w_per_m": q.convection_w_per_m, "radiation_w_per_m": q.radiation_w_per_m,
    })
}

fn evaluate(case: &ThermalCase, out: &std::path::Path) -> Result<(), String> {
    let model = case.model().map_err(|e| e.to_string())?;
    std::fs::create_dir_all(out).map_err(|e| format!("{}: {e}", out.display()))?;
    let name = case.name.clone().unwrap_or_else(|| "thermal".into());
    out!(
        "{name}: {} in air at {:.2} C, wind {} m/s at {} deg",
        case.conductor.label(),
        case.weather.air_temperature_k - C,
        case.weather.wind_speed_m_per_s,
        case.weather.wind_angle_deg
    );
    let mut steady_rows = Vec::new();
    for &i in &case.current_a {
        let s = steady::temperature(&model, i).map_err(|e| e.to_string())?;
        out!(
            "  steady temperature at {i:8.1} A: {:8.3} C  (q_J {:.3}, q_S {:.3}, q_c {:.3}, q_r {:.3} W/m)",
            s.temperature_k - C,
            s.terms.joule_w_per_m,
            s.terms.solar_w_per_m,
            s.terms.convection_w_per_m,
            s.terms.radiation_w_per_m
        );
        steady_rows
            .push(json!({"current_a": i, "temperature_k": s.temperature_k, "temperature_c": s.temperature_k - C,
            "terms": terms_json(&model, s.temperature_k, i)}));
    }
    let mut ampacity_rows = Vec::new();
    for &t in &case.max_temperature_k {
        let a = steady::ampacity(&model, t).map_err(|e| e.to_string())?;
        out!("  steady ampacity at {:7.2} C: {:9.2} A", t - C, a.current_a);
        ampacity_rows.push(json!({"max_temperature_k": t, "max_temperature_c": t - C, "current_a": a.current_a,
                "terms": terms_json(&model, t, a.current_a)}));
    }
    let mut transient = serde_json::Value::Null;
    if let Some(t) = &case.transient {
        let schedule =
            CurrentSchedule::new(t.current_a.iter().map(|p| (p[0], p[1])).collect()).ok_or("transient.current_a")?;
        let t0 = match t.initial_temperature_k {
            Some(k) => k,
            None => steady::temperature(&model, schedule.initial_a()).map_err(|e| e.to_string())?.temperature_k,
        };
        let tr = Transient { model: &model, current: &schedule, step_s: t.step_s };
        let samples = tr.run(0.0, t0, t.end_time_s);
        let path = out.join("transient.csv");
        let mut w = csv::Writer::from_path(&path).map_err(|e| format!("{}: {e}", path.display()))?;
        w.write_record(["t_s", "current_a", "temperature_k"]).map_err(|e| e.to_string())?;
        for s in &samples {
            w.write_record([s.time_s, s.current_a, s.temperature_k].map(|x| x.to_string()))
                .map_err(|e| e.to_string())?;
        }
        w.flush().map_err(|e| e.to_string())?;
        let last = samples.last().map_or(t0, |s| s.temperature_k);
        let reach = t.limit_k.map(|l| time_to_reach(&tr, 0.0, t0, l, t.end_time_s));
        out!(
            "  transient: {:.3} C at t = 0, {:.3} C at {} s ({} samples in {})",
            t0 - C,
            last - C,
            t.end_time_s,
            samples.len(),
            path.display()
        );
        if let (Some(l), Some(r)) = (t.limit_k, reach) {
            match r {
                Some(s) => out!("  reaches {:.2} C at {s:.1} s ({:.2} min)", l - C, s / 60.0),
                None => out!("  does not reach {:.2} C within {} s", l - C, t.end_time_s),
            }
        }
        transient = json!({"initial_temperature_k": t0, "final_temperature_k": last, "limit_k": t.limit_k, "time_to_limit_s": reach.flatten(),
            "initial_temperature_c": t0 - C, "final_temperature_c": last - C, "limit_c": t.limit_k.map(|l| l - C)});
    }
    let mut deicing = serde_json::Value::Null;
    if let (Some(de), Some(d)) = (case.deicing().map_err(|e| e.to_string())?, &case.deicing) {
        let opts = DeicingOptions { step_s: d.step_s, record_every_s: 10.0, ..Default::default() };
        let min = de.minimum_current_a().map_err(|e| e.to_string())?;
        out!(
            "  de-icing {} mm of ice ({:.3} kg/m; {:?}): least current that melts {min:.1} A",
            d.thickness_m * 1e3,
            de.ice_mass_kg_per_m(),
            d.criterion
        );
        let mut runs = Vec::new();
        for (k, &i) in d.current_a.iter().enumerate() {
            let r = de.run(i, &opts).map_err(|e| e.to_string())?;
            let e = &r.energy;
            out!(
                "    {i:8.1} A: melting from {:.1} s, sheds at {:.1} s ({:.2} min); energy closure {:.2e} of the Joule heat",
                r.warm_time_s,
                r.shed_time_s,
                r.shed_time_s / 60.0,
                e.closure_j_per_m / e.joule_j_per_m
            );
            if k == 0 {
                let path = out.join("deicing.csv");
                let mut w = csv::Writer::from_path(&path).map_err(|e| format!("{}: {e}", path.display()))?;
                w.write_record(["t_s", "conductor_k", "surface_k", "melted_kg_per_m", "joule_w_per_m", "loss_w_per_m"])
                    .map_err(|e| e.to_string())?;
                for s in &r.series {
                    w.write_record(
                        [s.time_s, s.conductor_k, s.surface_k, s.melted_kg_per_m, s.joule_w_per_m, s.loss_w_per_m]
                            .map(|x| x.to_string()),
                    )
                    .map_err(|e| e.to_string())?;
                }
                w.flush().map_err(|e| e.to_string())?;
            }
            runs.push(json!({"current_a": i, "melting_from_s": r.warm_time_s, "shed_time_s": r.shed_time_s,
                "energy_j_per_m": {"joule": e.joule_j_per_m, "sensible": e.sensible_j_per_m, "latent": e.latent_j_per_m, "losses": e.losses_j_per_m, "closure": e.closure_j_per_m}}));
        }
        let mut within = Vec::new();
        for &t in &d.shed_within_s {
            let i = de.current_to_shed_in(t, &opts).map_err(|e| e.to_string())?;
            out!("    sheds within {t} s ({:.1} min) from {i:.1} A", t / 60.0);
            within.push(json!({"time_s": t, "current_a": i}));
        }
        deicing = json!({"ice_kg_per_m": de.ice_mass_kg_per_m(), "minimum_current_a": min, "runs": runs, "shed_within": within});
    }
    let doc = json!({
        "name": name, "conductor": case.conductor.label(), "standard": case.standard,
        "steady": steady_rows, "ampacity": ampacity_rows, "transient": transient, "deicing": deicing,
    });
    let path = out.join("thermal.json");
    std::fs::write(&path, serde_json::to_string_pretty(&doc).map_err(|e| e.to_string())?)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    out!("  written to {}", out.display());
    Ok(())
}
