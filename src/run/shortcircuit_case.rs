//! `ohl shortcircuit`: a line scenario with `[short_circuit]` evaluated twice, by the IEC 60865-1
//! simplified method on the span the line describes ([`crate::scenario::short_circuit_iec`]) and by the
//! dynamic run of the same [`LinePlan`] as `ohl run` ([`super::line`], [`super::short_circuit`]), side by
//! side: one [`Row`] per quantity with its IEC equation number.
//!
//! The IEC half may be refused (a line the method does not describe, a span outside its range): the
//! dynamic half still runs, and the refusal is kept as text.

use std::path::Path;

use super::line::{LineOutcome, LineRunError, LineRunOptions, run_line_observed};
use super::short_circuit::{EndForces, ShortCircuitSummary};
use crate::scenario::line::{LinePlan, LineScenario};
use crate::scenario::short_circuit_iec::{Mapped, map};
use crate::shortcircuit::iec60865::{Output, Pinch, evaluate};

/// One quantity, both ways.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Row {
    /// what it is
    pub quantity: &'static str,
    /// IEC 60865-1's symbol
    pub symbol: &'static str,
    /// IEC 60865-1's equation number
    pub equation: &'static str,
    /// the unit of both values
    pub unit: &'static str,
    /// the simplified method's value (absent: refused, or not asked for by the clause)
    pub iec: Option<f64>,
    /// the dynamic run's value (absent: not defined for the run)
    pub dynamic: Option<f64>,
}

impl Row {
    /// `(dynamic - iec) / iec` [-], where both exist.
    pub fn difference(&self) -> Option<f64> {
        match (self.iec, self.dynamic) {
            (Some(i), Some(d)) if i != 0.0 => Some((d - i) / i),
            _ => None,
        }
    }
}

/// Both halves.
#[derive(Debug)]
pub struct Comparison {
    /// the standard's input read off the line, or why the line is not the method's span
    pub mapped: Result<Mapped, String>,
    /// the method's output, or why it refused (none where the mapping failed)
    pub iec: Option<Result<Output, String>>,
    /// the dynamic run (its summary has the `short_circuit` block)
    pub outcome: LineOutcome,
    /// the dynamic run's short-circuit results
    pub dynamic: ShortCircuitSummary,
    /// the main conductor whose numbers are compared
    pub main: String,
    /// the table
    pub rows: Vec<Row>,
}

/// Why the comparison could not be made.
#[derive(Debug, thiserror::Error)]
pub enum CompareError {
    /// the scenario has no `[short_circuit]`
    #[error("the scenario has no [short_circuit] table: `ohl shortcircuit` needs one (docs/short_circuit.md)")]
    NoShortCircuit,
    /// the dynamic run failed
    #[error(transparent)]
    Run(#[from] LineRunError),
}

fn largest(ends: &[EndForces; 2], f: impl Fn(&EndForces) -> Option<f64>) -> Option<f64> {
    ends.iter().filter_map(f).reduce(f64::max)
}

/// A note when the main conductor is a bundle whose segments are too long for the pinch's transition at a
/// spacer ([`crate::shortcircuit::pinch_transition`], at the current's first peak `kappa sqrt(2) I''k / n` a
/// sub-conductor and the static tension `F_st / n`): the dynamic `F_pi` is then low.
fn pinch_resolution(input: &crate::shortcircuit::iec60865::Input, main: &str, plan: &LinePlan) -> Option<String> {
    let b = input.bundle?;
    let n = f64::from(input.subconductors);
    let i = b.peak_factor * std::f64::consts::SQRT_2 * input.fault.current_a() / n;
    let p = crate::shortcircuit::pinch_transition::pinch_transition(
        b.subconductor_distance_m,
        input.diameter_m,
        i,
        input.static_tension_n / n,
    )?;
    let g = plan.group_names.iter().position(|g| g == main)?;
    let ds = plan.groups[g]
        .iter()
        .flat_map(|&c| plan.line.conductors()[c].wire().rest_length.iter().copied())
        .fold(0.0, f64::max);
    (ds > 0.5 * p.length_m).then(|| {
        format!(
            "F_pi: the pinch's transition at a spacer is about {:.3} m long (sub-conductors {} m apart, {:.1} kA \
             each at the first peak, {:.0} N each; docs/short_circuit.md), and segments of {ds:.3} m do not \
             resolve it (less than two segments in it): the dynamic F_pi is low, rising under refinement",
            p.length_m,
            b.subconductor_distance_m,
            i / 1e3,
            input.static_tension_n / n
        )
    })
}

/// Evaluate the method on the span of `s` and run `plan` (built from `s`), writing the run's files into
/// `out_dir` if given.
pub fn compare(s: &LineScenario, plan: LinePlan, out_dir: Option<&Path>) -> Result<Comparison, CompareError> {
    let sc = s.short_circuit.as_ref().ok_or(CompareError::NoShortCircuit)?;
    let mut mapped = map(s, &plan).map_err(|e| e.to_string());
    if let Ok(m) = &mut mapped
        && let Some(note) = pinch_resolution(&m.input, &m.main, &plan)
    {
        m.notes.push(note);
    }
    let iec = mapped.as_ref().ok().map(|m| evaluate(&m.input).map_err(|e| e.to_string()));
    let main = match &mapped {
        Ok(m) => m.main.clone(),
        Err(_) => sc.phases.first().cloned().unwrap_or_default(),
    };
    let opts = LineRunOptions { out_dir: out_dir.map(Path::to_path_buf), record: false };
    let outcome = run_line_observed(plan, &opts, &mut [])?;
    let dynamic = outcome.summary.short_circuit.clone().ok_or(CompareError::NoShortCircuit)?;
    let phase = dynamic.phases.iter().find(|p| p.name == main);
    let out = iec.as_ref().and_then(|r| r.as_ref().ok());
    let input = mapped.as_ref().ok().map(|m| m.input);
    let ends = phase.map(|p| p.ends);
    let dyn_end = |f: fn(&EndForces) -> Option<f64>| ends.as_ref().and_then(|e| largest(e, f));
    let rows = vec![
        Row {
            quantity: "static tension (input)",
            symbol: "F_st",
            equation: "-",
            unit: "N",
            iec: input.map(|i| i.static_tension_n),
            dynamic: dyn_end(|e| Some(e.static_n)),
        },
        Row {
            quantity: "characteristic EM force per length",
            symbol: "F'",
            equation: "(19a)",
            unit: "N/m",
            iec: out.map(|o| o.f_prime_n_per_m),
            dynamic: None,
        },
        Row {
            quantity: "force over weight",
            symbol: "r",
            equation: "(20)",
            unit: "-",
            iec: out.map(|o| o.r),
            dynamic: None,
        },
        Row {
            quantity: "equivalent static sag",
            symbol: "b_c",
            equation: "(22)",
            unit: "m",
            iec: out.map(|o| o.b_c_m),
            dynamic: None,
        },
        Row {
            quantity: "period during the short circuit",
            symbol: "T_res",
            equation: "(24)",
            unit: "s",
            iec: out.map(|o| o.t_res_s),
            dynamic: None,
        },
        Row {
            quantity: "stiffness norm",
            symbol: "N",
            equation: "(25)",
            unit: "1/N",
            iec: out.map(|o| o.n_stiffness_per_n),
            dynamic: None,
        },
        Row {
            quantity: "stress factor",
            symbol: "zeta",
            equation: "(28)",
            unit: "-",
            iec: out.map(|o| o.zeta),
            dynamic: None,
        },
        Row {
            quantity: "swing-out at the end of the flow",
            symbol: "delta_k",
            equation: "(29)",
            unit: "deg",
            iec: out.map(|o| o.delta_k_deg),
            dynamic: None,
        },
        Row {
            quantity: "maximum swing-out angle",
            symbol: "delta_m",
            equation: "(30)",
            unit: "deg",
            iec: out.map(|o| o.delta_m_deg),
            dynamic: phase.and_then(|p| p.swing_out_max_deg.map(|d| d.value)),
        },
        Row {
            quantity: "load parameter",
            symbol: "phi",
            equation: "(32)",
            unit: "-",
            iec: out.map(|o| o.phi),
            dynamic: None,
        },
        Row {
            quantity: "factor of F_t",
            symbol: "psi",
            equation: "Annex A",
            unit: "-",
            iec: out.map(|o| o.psi),
            dynamic: None,
        },
        Row {
            quantity: "tensile force during the swing-out",
            symbol: "F_t",
            equation: "(33)",
            unit: "N",
            iec: out.map(|o| o.f_t_n),
            dynamic: dyn_end(|e| Some(e.f_t.value)),
        },
        Row {
            quantity: "tensile force at the fall",
            symbol: "F_f",
            equation: "(43)",
            unit: "N",
            iec: out.and_then(|o| o.f_f_n),
            dynamic: dyn_end(|e| e.f_f.map(|f| f.value)),
        },
        Row {
            quantity: "maximum horizontal displacement",
            symbol: "b_h",
            equation: "(44)/(45)",
            unit: "m",
            iec: out.map(|o| o.b_h_m),
            dynamic: phase.map(|p| p.b_h.value),
        },
        Row {
            quantity: "minimum air clearance",
            symbol: "a_min",
            equation: "(48)",
            unit: "m",
            iec: out.map(|o| o.a_min_m),
            dynamic: dynamic.a_min.map(|a| a.value),
        },
        Row {
            quantity: "bundle pinch force",
            symbol: "F_pi",
            equation: "(51)-(64)",
            unit: "N",
            iec: out.and_then(|o| match o.pinch {
                Some(Pinch::EffectiveClash { force_n }) => Some(force_n),
                Some(Pinch::NotClashing(c)) => Some(c.f_pi_n),
                None => None,
            }),
            dynamic: dyn_end(|e| e.f_pi.map(|f| f.value)),
        },
    ];
    Ok(Comparison { mapped, iec, outcome, dynamic, main, rows })
}

/// Both halves as `shortcircuit.json` holds them (the command's file, the Python package's dict).
pub fn to_json(c: &Comparison) -> serde_json::Value {
    let mapped = match &c.mapped {
        Ok(m) => {
            let i = &m.input;
            serde_json::json!({
                "main": m.main,
                "span_m": i.span_m,
                "phase_distance_m": i.phase_distance_m,
                "insulator_chain_length_m": match i.mounting { crate::shortcircuit::iec60865::Mounting::Slack => None, crate::shortcircuit::iec60865::Mounting::Strained { insulator_chain_length_m } => Some(insulator_chain_length_m) },
                "subconductors": i.subconductors,
                "mass_per_length_kg_per_m": i.mass_per_length_kg_per_m,
                "concentrated_mass_kg": i.concentrated_mass_kg,
                "area_m2": i.area_m2,
                "young_modulus_pa": i.young_modulus_pa,
                "diameter_m": i.diameter_m,
                "static_tension_n": i.static_tension_n,
                "spring_constant_n_per_m": i.spring_constant_n_per_m,
                "current_a": i.fault.current_a(),
                "first_duration_s": i.first_duration_s,
                "thermal_constant_m4_per_a2s": i.thermal_constant_m4_per_a2s,
                "gravity_m_per_s2": i.gravity_m_per_s2,
                "subconductor_distance_m": i.bundle.map(|b| b.subconductor_distance_m),
                "spacer_distance_m": i.bundle.map(|b| b.spacer_distance_m),
                "notes": m.notes,
            })
        }
        Err(e) => serde_json::json!({ "refused": e }),
    };
    let iec = match &c.iec {
        Some(Err(e)) => serde_json::json!({ "refused": e }),
        Some(Ok(_)) | None => serde_json::Value::Null,
    };
    let rows: Vec<serde_json::Value> = c
        .rows
        .iter()
        .map(|r| {
            serde_json::json!({
                "quantity": r.quantity, "symbol": r.symbol, "equation": r.equation, "unit": r.unit,
                "iec": r.iec, "dynamic": r.dynamic, "difference": r.difference(),
            })
        })
        .collect();
    serde_json::json!({
        "main": c.main,
        "iec_input": mapped,
        "iec_refusal": iec,
        "rows": rows,
        "dynamic": c.dynamic,
    })
}
