//! The outputs of `ohl sagtension`: the table as CSV and JSON, and the figure of sag against temperature
//! (initial and final states of the case's conductor; for a section its longest span at the ruling span's
//! horizontal tension; its knee points marked, and the single-modulus
//! conductor of the same catalogue entry strung alike, dashed, for comparison). The numbers are the
//! library's ([`ohl::scenario::sagtension_table`]).

use std::path::Path;

use ohl::sagtension::{Row, State, Strung};
use ohl::scenario::sagtension::{Resolved, SagTensionCase};
use ohl::scenario::sagtension_table::{self, Table};
use ohl::scenario::temperature::ZERO_CELSIUS_K as C;
use serde_json::json;

use crate::plot::{Chart, PlotError, Series, Style, render_titled};

/// The columns of `sagtension.csv`, in order.
pub const CSV_COLUMNS: [&str; 19] = [
    "condition",
    "label",
    "temperature_c",
    "ice_thickness_m",
    "wind_pressure_pa",
    "constant_n_per_m",
    "load_n_per_m",
    "state",
    "history_of",
    "horizontal_tension_n",
    "sag_m",
    "sag_max_m",
    "support_tension_n",
    "tension_percent_rts",
    "aluminium_stress_pa",
    "core_stress_pa",
    "knee_passed",
    "strain",
    "conductor_length_m",
];

/// The larger support tension of a row [N].
pub fn support_tension_n(r: &Row) -> f64 {
    r.support_tension_a_n.max(r.support_tension_b_n)
}

/// Write `dir/sagtension.csv`.
pub fn write_csv(dir: &Path, resolved: &Resolved, table: &Table) -> Result<(), String> {
    let path = dir.join("sagtension.csv");
    let err = |e: csv::Error| format!("{}: {e}", path.display());
    let mut w = csv::Writer::from_path(&path).map_err(err)?;
    w.write_record(CSV_COLUMNS).map_err(err)?;
    let per = table.states.len();
    for (k, r) in table.rows.iter().enumerate() {
        let c = &resolved.conditions[k / per];
        let num = |x: f64| x.to_string();
        w.write_record([
            (k / per).to_string(),
            c.label.clone(),
            num(c.temperature_k - C),
            num(c.ice_thickness_m),
            num(c.wind_pressure_pa * c.drag_coefficient),
            num(c.constant_n_per_m),
            num(r.load_n_per_m),
            r.state.name().into(),
            r.history_of.name().into(),
            num(r.horizontal_tension_n),
            num(r.sag_midspan_m),
            num(r.sag_max_m),
            num(support_tension_n(r)),
            num(100.0 * r.max_tension_fraction_rts),
            num(r.outer_stress_pa),
            num(r.core_stress_pa),
            r.knee_passed.to_string(),
            num(r.strain_max),
            num(r.length_m),
        ])
        .map_err(err)?;
    }
    w.flush().map_err(|e| format!("{}: {e}", path.display()))
}

fn found_json(f: &[(State, sagtension_table::Found)]) -> serde_json::Value {
    let mut m = serde_json::Map::new();
    for (s, v) in f {
        m.insert(
            s.name().into(),
            match v {
                Ok(k) => json!({"temperature_k": k, "temperature_c": k - C}),
                Err(e) => json!({"not_found": e}),
            },
        );
    }
    serde_json::Value::Object(m)
}

/// Write `dir/sagtension.json`: the case as resolved, the states, the knee and limit temperatures, the rows.
pub fn write_json(dir: &Path, case: &SagTensionCase, resolved: &Resolved, table: &Table) -> Result<(), String> {
    let per = table.states.len();
    let rows: Vec<serde_json::Value> = table
        .rows
        .iter()
        .enumerate()
        .map(|(k, r)| {
            json!({
                "condition": k / per, "state": r.state.name(), "history_of": r.history_of.name(),
                "load_n_per_m": r.load_n_per_m, "horizontal_tension_n": r.horizontal_tension_n,
                "sag_m": r.sag_midspan_m, "sag_max_m": r.sag_max_m,
                "support_tension_a_n": r.support_tension_a_n, "support_tension_b_n": r.support_tension_b_n,
                "tension_percent_rts": 100.0 * r.max_tension_fraction_rts,
                "aluminium_stress_pa": r.outer_stress_pa, "core_stress_pa": r.core_stress_pa,
                "aluminium_stress_total_area_pa": r.outer_stress_total_area_pa,
                "core_stress_total_area_pa": r.core_stress_total_area_pa,
                "knee_passed": r.knee_passed, "strain": r.strain_max, "conductor_length_m": r.length_m,
                "unstressed_length_m": r.unstressed_length_m,
                "span_sags_m": table.span_sags_m[k],
            })
        })
        .collect();
    let doc = json!({
        "name": case.name, "conductor": resolved.conductor.name, "law": table.law,
        "spans_m": resolved.lengths_m, "rise_m": resolved.rise_m, "span_m": table.span_m,
        "stringing": {"weather": resolved.stringing, "horizontal_tension_n": resolved.stringing_target,
                      "sag_m": resolved.stringing_sag_m, "state": resolved.stringing_state.name()},
        "creep": resolved.creep, "heavy_load": resolved.heavy_load,
        "conditions": resolved.conditions,
        "states": table.states.iter().map(|s| s.name()).collect::<Vec<_>>(), "final_is": table.final_is.name(),
        "knee_point": found_json(&table.knee_k),
        "sag_limit_m": table.sag_limit_m, "sag_limit_reached": found_json(&table.limit_k),
        "rows": rows,
    });
    let path = dir.join("sagtension.json");
    let text = serde_json::to_string_pretty(&doc).map_err(|e| e.to_string())?;
    std::fs::write(&path, text).map_err(|e| format!("{}: {e}", path.display()))
}

/// The temperatures of the figure [K]: from the coldest to the hottest of the conditions, the stringing
/// temperature and the knee points found, 121 points.
pub fn figure_temperatures_k(resolved: &Resolved, table: &Table) -> Vec<f64> {
    let knees = table.knee_k.iter().filter_map(|(_, k)| k.as_ref().ok().copied());
    let all: Vec<f64> = resolved
        .conditions
        .iter()
        .map(|w| w.temperature_k)
        .chain([resolved.stringing.temperature_k])
        .chain(knees.map(|k| k + 10.0))
        .collect();
    let lo = all.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = all.iter().copied().fold(f64::NEG_INFINITY, f64::max).max(lo + 10.0);
    (0..=120).map(|k| lo + (hi - lo) * k as f64 / 120.0).collect()
}

/// Draw `dir/sag_vs_temperature.png` and `.svg`.
pub fn figure(dir: &Path, case: &SagTensionCase, resolved: &Resolved, table: &Table) -> Result<(), String> {
    let (law, _) = resolved.law();
    let strung: Strung = sagtension_table::strung(resolved, law).map_err(|e| e.to_string())?;
    let linear = sagtension_table::strung(resolved, resolved.single_modulus_law()).map_err(|e| e.to_string())?;
    let temps = figure_temperatures_k(resolved, table);
    let to_c = |pts: Vec<(f64, f64)>| pts.into_iter().map(|(t, d)| (t - C, d)).collect::<Vec<_>>();
    let section = sagtension_table::longest_of_section(resolved);
    let curve = |s: &Strung, st: State| {
        sagtension_table::sag_curve(s, st, &temps, section).map(to_c).map_err(|e| e.to_string())
    };
    let mut series = vec![
        Series::new("initial", curve(&strung, State::Initial)?, Style::Line, 0),
        Series::new(format!("final (= {})", table.final_is.name()), curve(&strung, State::Final)?, Style::Line, 1),
        Series::new(
            "single-modulus conductor (catalogue EA and alpha), strung alike",
            curve(&linear, State::Initial)?,
            Style::Dashed,
            7,
        ),
    ];
    for (k, (state, knee)) in table.knee_k.iter().enumerate() {
        if !matches!(state, State::Initial | State::Final) {
            continue;
        }
        if let Ok(t) = knee {
            let d = sagtension_table::sag_at(&strung, *state, *t, section).map_err(|e| e.to_string())?;
            series.push(Series::new(
                format!("knee point, {} ({:.1} C)", state.name(), t - C),
                vec![(t - C, d)],
                Style::Markers,
                if k == 0 { 0 } else { 1 },
            ));
        }
    }
    if let Some(limit) = table.sag_limit_m {
        let (a, b) = (temps[0] - C, temps[temps.len() - 1] - C);
        let label = format!("sag limit {limit:.2} m");
        series.push(Series::new(label, vec![(a, limit), (b, limit)], Style::Dotted, 3));
    }
    let ruling = resolved.lengths_m.len() > 1;
    let chart = Chart {
        title: if ruling {
            format!(
                "section of {} spans (ruling span {:.1} m): its longest span at the ruling span's H",
                resolved.lengths_m.len(),
                table.span_m
            )
        } else {
            format!("span {:.1} m", table.span_m)
        },
        x_label: "conductor temperature [C]".into(),
        y_label: match section {
            Some(l) => format!("mid-span sag of the longest span, {l} m [m]"),
            None => "mid-span sag [m]".into(),
        },
        series,
        ..Default::default()
    };
    let title = format!("{}: {}", case.name.clone().unwrap_or_else(|| "sag-tension".into()), resolved.conductor.name);
    render_titled(&[chart], 1, (1000, 560), &title, &dir.join("sag_vs_temperature"))
        .map_err(|e: PlotError| e.to_string())
}
