//! The scalars of a run's summary, each under the path it has in `summary.json`
//! (`supports[1].peaks.components[1].value_n`, `spans[2].final_sag_m`, `peak_max_tension_time_s`): the
//! quantities a convergence study pairs across its levels. Times of peaks are quantities too.
//!
//! Left out are the numbers that describe the discretisation or the machine rather than the solution (the
//! segments, step, steps, Courant number, wave speed, wall and CPU time, throughput, node indices), the inputs
//! the run repeats (positions of supports and probes, the start of the peaks, the events' times, the
//! static solve's tolerance and iterations), the dimensionless times `tau` (the times in seconds are
//! kept) and the warnings; a null (an absent value: a broken span's sag, a clearance without ground) is
//! no quantity on that level.

use serde_json::Value;

/// Keys whose numbers are not solution quantities (module doc).
const NOT_QUANTITIES: &[&str] = &[
    "segments",
    "dt_s",
    "steps",
    "courant",
    "wave_speed_m_per_s",
    "wall_time_s",
    "node_steps_per_second",
    "cpu_time_s",
    "cpu_node_steps_per_second",
    "node",
    "nodes",
    "span",
    "position_m",
    "at_fraction",
    "peaks_from_s",
    "tau",
    "final_tau",
    "initial_equilibrium",
    "warnings",
    "events",
    "start_up",
    "instability",
    "clearance_levels_measured",
    "count",
    "link",
];

/// Every scalar quantity of `summary` (a serialised summary) with its path, in the summary's order.
pub fn scalars(summary: &Value) -> Vec<(String, f64)> {
    let mut out = Vec::new();
    walk(summary, String::new(), &mut out);
    out
}

fn walk(v: &Value, path: String, out: &mut Vec<(String, f64)>) {
    match v {
        Value::Number(n) => {
            if let Some(x) = n.as_f64() {
                out.push((path, x));
            }
        }
        Value::Array(a) => {
            for (k, x) in a.iter().enumerate() {
                walk(x, format!("{path}[{k}]"), out);
            }
        }
        Value::Object(m) => {
            for (key, x) in m {
                if NOT_QUANTITIES.contains(&key.as_str()) {
                    continue;
                }
                let p = if path.is_empty() { key.clone() } else { format!("{path}.{key}") };
                walk(x, p, out);
            }
        }
        Value::Null | Value::Bool(_) | Value::String(_) => {}
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths_skip_discretisation_and_nulls() {
        let v: Value = serde_json::json!({
            "segments": 40, "dt_s": 0.01, "peak_max_tension_n": 12.5, "peak_max_tension_time_s": 0.3,
            "spans": [{"span": 0, "nodes": [0, 40], "final_sag_m": null, "peaks": {"max_tension": {"value_n": 9.0, "tau": 1.0}}}],
            "name": "x", "settled": true
        });
        let s = scalars(&v);
        let paths: Vec<&str> = s.iter().map(|(p, _)| p.as_str()).collect();
        assert_eq!(paths, ["peak_max_tension_n", "peak_max_tension_time_s", "spans[0].peaks.max_tension.value_n"]);
        assert_eq!(s[2].1, 9.0);
    }
}
