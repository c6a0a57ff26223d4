//! A line scenario with `[short_circuit]` as the input of the IEC 60865-1 simplified method
//! ([`crate::shortcircuit::iec60865::Input`]): the one span of the standard, read off the line the dynamic
//! run simulates (`ohl shortcircuit`, docs/short_circuit.md, "The mapping").
//!
//! The main conductor is the phase L1 (`short_circuit.phases[0]`): for a three-phase fault in a flat
//! arrangement an outer phase, the one eq. (19a) is written for (the factor 0.75 is the time average of
//! the force on an outer conductor, `i1 (i2 / a + i3 / 2a)` with `<i1 i2> = <i1 i3> = -I^2 / 2`; the centre
//! conductor's average is zero); for a line-to-line fault a phase that carries current. Its section must
//! be one span between two dead-ends.
//!
//! - `l`: the distance between the section's two dead-end points (the portals' string points);
//! - `a`: the distance between the dead-end points of L1 and L2 at the first support (three-phase: the
//!   smaller of L1-L2 and L2-L3, the larger force);
//! - `l_i`: the tension strings' unstretched length (both ends must have one: strained; neither: slack);
//! - `n`, `m'_s`, `d`: the bundle's sub-conductor count and the conductor's linear density and diameter;
//! - `m_c`: the spacers' masses in the span;
//! - `A_s`: `short_circuit.conductor_area_m2`, else the catalogue entry's total area; `E = EA / A_s` with
//!   the line's own `EA` (so `n E A_s` is the axial stiffness the dynamic run uses);
//! - `F_st`: the horizontal tension of the main conductor in the initial state of the run (the sum over a
//!   bundle's sub-conductors; per sub-conductor the tension of its middle segment times the horizontal
//!   share of its direction);
//! - `S`: `short_circuit.spring_constant_n_per_m`, else the towers holding the two tension strings, elastic
//!   along the line with `k_1`, `k_2`, as two springs in series, `S = k_1 k_2 / (k_1 + k_2)` (one rigid:
//!   the other's `k`);
//! - the fault, `T_k1`, `c_th`, `f`, `kappa` from `[short_circuit]`; bundles: `a_s` the distance of two
//!   adjacent sub-conductors, `D sin(180 deg / n)` (twin: the bundle's diameter), `l_s = l_c / (spacers + 1)`,
//!   the mean subspan;
//! - `g_n`: the scenario's gravity (`loads.gravity_m_per_s2`), so that both halves take the same weight.

use super::line::{LinePlan, LineScenario};
use super::schema::SupportSpec;
use super::short_circuit::FaultKindSpec;
use crate::shortcircuit::iec60865::{Bundle, Fault, Input, Mounting};

/// Why a line scenario cannot be read as the standard's span.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MappingError {
    /// The scenario has no `[short_circuit]`.
    #[error("the scenario has no [short_circuit] table")]
    NoShortCircuit,
    /// The line is not what the method describes, or an input it needs is missing.
    #[error("field `{field}` = {value}: {reason}")]
    Unsupported {
        /// the field as written in the file
        field: String,
        /// its value
        value: String,
        /// why the method cannot take it, and what to give
        reason: String,
    },
}

/// The standard's input and what the mapping chose.
#[derive(Clone, Debug, PartialEq)]
pub struct Mapped {
    /// the input of [`crate::shortcircuit::iec60865::evaluate`]
    pub input: Input,
    /// the main conductor's name
    pub main: String,
    /// where each value came from where a choice was made (one line each)
    pub notes: Vec<String>,
}

fn unsupported(field: impl Into<String>, value: impl Into<String>, reason: impl Into<String>) -> MappingError {
    MappingError::Unsupported { field: field.into(), value: value.into(), reason: reason.into() }
}

fn distance(a: [f64; 3], b: [f64; 3]) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

/// The horizontal tension of a conductor of the line in its current state [N]: the tension of its middle
/// segment times the horizontal share of the segment's direction.
pub fn horizontal_tension_n(solver: &crate::scheme::Explicit) -> f64 {
    let w = solver.wire();
    let j = w.segments() / 2;
    let (p, q) = (w.position(j), w.position(j + 1));
    let h = ((q[0] - p[0]).powi(2) + (q[1] - p[1]).powi(2)).sqrt();
    solver.segment_tension(j) * h / distance(p, q)
}

/// Read the line scenario `s`, built into `plan`, as the standard's span.
pub fn map(s: &LineScenario, plan: &LinePlan) -> Result<Mapped, MappingError> {
    let sc = s.short_circuit.as_ref().ok_or(MappingError::NoShortCircuit)?;
    let mut notes = Vec::new();
    let fault = match sc.kind {
        FaultKindSpec::ThreePhase => Fault::ThreePhase { current_a: sc.initial_current_a },
        FaultKindSpec::LineToLine => Fault::LineToLine { current_a: sc.initial_current_a },
        FaultKindSpec::LineToEarth => {
            return Err(unsupported(
                "short_circuit.kind",
                "\"line_to_earth\"",
                "IEC 60865-1 clause 6 gives the swing-out of a span for three-phase and line-to-line faults only",
            ));
        }
    };
    let spec_of = |name: &str| s.line.conductors.iter().position(|c| c.name == name);
    let phase = |j: usize| -> Result<usize, MappingError> {
        let name = sc.phases.get(j).ok_or_else(|| {
            unsupported("short_circuit.phases", format!("{:?}", sc.phases), "the method needs the phases L1 and L2")
        })?;
        spec_of(name)
            .ok_or_else(|| unsupported(format!("short_circuit.phases[{j}]"), format!("{name:?}"), "not a conductor"))
    };
    let main_k = phase(0)?;
    let main = &s.line.conductors[main_k];
    let f = |name: &str| format!("line.conductors[{main_k}].{name}");
    let sec = &main.section;
    if sec.supports.len() != 2 {
        return Err(unsupported(
            f("section.supports"),
            format!("{} supports", sec.supports.len()),
            "the simplified method is for one span between two supports: give the main conductor a section of one span",
        ));
    }
    let point = |c: &super::line::LineConductorSpec, j: usize, field: String| match c.section.supports.get(j) {
        Some(SupportSpec::DeadEnd { point_m }) => Ok(*point_m),
        _ => Err(unsupported(
            field,
            "a suspension",
            "the method's span ends at dead-ends (tension strings or fixed points)",
        )),
    };
    let (p0, p1) = (point(main, 0, f("section.supports[0]"))?, point(main, 1, f("section.supports[1]"))?);
    let span_m = distance(p0, p1);
    // The phase distance at the first support.
    let l2 = phase(1)?;
    let q2 = point(&s.line.conductors[l2], 0, format!("line.conductors[{l2}].section.supports[0]"))?;
    let a12 = distance(q2, p0);
    let mut phase_distance_m = a12;
    if sc.kind == FaultKindSpec::ThreePhase {
        let l3 = phase(2)?;
        let a23 = distance(point(&s.line.conductors[l3], 0, format!("line.conductors[{l3}].section.supports[0]"))?, q2);
        if (a23 - a12).abs() > 1e-9 * a12.max(a23) {
            notes.push(format!("a: L1-L2 {a12} m and L2-L3 {a23} m differ; the smaller is taken (the larger force)"));
        }
        phase_distance_m = a12.min(a23);
    }
    let mounting = match main.tension_strings.as_slice() {
        [] => Mounting::Slack,
        [x, y] => {
            if x.length_m != y.length_m {
                notes.push(format!(
                    "l_i: the two tension strings are {} m and {} m; their mean is taken",
                    x.length_m, y.length_m
                ));
            }
            Mounting::Strained { insulator_chain_length_m: 0.5 * (x.length_m + y.length_m) }
        }
        _ => {
            return Err(unsupported(
                f("tension_strings"),
                "1 string",
                "the method's strained span has a tension string at both ends (l_c = l - 2 l_i); give both, or none (slack)",
            ));
        }
    };
    let n = main.bundle.as_ref().map_or(1, |b| b.sub_conductors);
    let cd = &main.conductor;
    let diameter_m = cd.diameter_m.ok_or_else(|| {
        unsupported(f("conductor.diameter_m"), "(missing)", "the method needs the sub-conductor's diameter d")
    })?;
    let area_m2 = match (sc.conductor_area_m2, &cd.catalog) {
        (Some(a), _) => a,
        (None, Some(name)) => {
            let k = crate::thermal::catalog::find(name).map_err(|e| {
                unsupported("short_circuit.conductor_area_m2", "(missing)", format!("no catalogue area: {e}"))
            })?;
            notes.push(format!("A_s: the catalogue's total area of {name}"));
            k.total_area_m2()
        }
        (None, None) => {
            return Err(unsupported(
                "short_circuit.conductor_area_m2",
                "(missing)",
                "the method needs the sub-conductor's cross-section A_s: give it, or a catalogue conductor",
            ));
        }
    };
    let ea = match (cd.axial_stiffness_n, cd.youngs_modulus_pa) {
        (Some(ea), _) => ea,
        (None, Some(e)) => e * std::f64::consts::PI * diameter_m * diameter_m / 4.0,
        (None, None) => {
            return Err(unsupported(f("conductor.axial_stiffness_n"), "(missing)", "the method needs E A_s"));
        }
    };
    // The members of the main conductor in the line and their horizontal tensions at t = 0.
    let group =
        plan.group_names.iter().position(|g| g == &main.name).ok_or_else(|| {
            unsupported(f("name"), format!("{:?}", main.name), "not a conductor group of the built line")
        })?;
    let static_tension_n: f64 =
        plan.groups[group].iter().map(|&m| horizontal_tension_n(&plan.line.conductors()[m])).sum();
    let spring = |t: &str| s.line.towers.iter().find(|x| x.name == t).and_then(|x| x.elastic).map(|e| e.along_n_per_m);
    let spring_constant_n_per_m = match sc.spring_constant_n_per_m {
        Some(k) => k,
        None => {
            let ks: Vec<Option<f64>> = (0..2).map(|j| main.towers.get(j).and_then(|t| spring(t))).collect();
            match (ks[0], ks[1]) {
                (Some(a), Some(b)) => a * b / (a + b),
                (Some(k), None) | (None, Some(k)) => k,
                (None, None) => {
                    return Err(unsupported(
                        "short_circuit.spring_constant_n_per_m",
                        "(missing)",
                        "the portals are rigid (S infinite): give the resultant spring constant S of both supports, \
                         or hang the tension strings on towers with `elastic` springs",
                    ));
                }
            }
        }
    };
    let l_c = match mounting {
        Mounting::Slack => span_m,
        Mounting::Strained { insulator_chain_length_m } => span_m - 2.0 * insulator_chain_length_m,
    };
    let (concentrated_mass_kg, bundle) = match &main.bundle {
        Some(b) => {
            let spacers = b.spacers.len();
            let a_s = b.diameter_m * (std::f64::consts::PI / n as f64).sin();
            if n > 2 {
                notes.push(format!(
                    "a_s: the distance of two adjacent sub-conductors, {a_s} m (IEC 60865-1 defines an effective a_s \
                     for n > 2, not applied)"
                ));
            }
            let bundle = Bundle {
                subconductor_distance_m: a_s,
                spacer_distance_m: l_c / (spacers as f64 + 1.0),
                frequency_hz: sc.frequency_hz,
                peak_factor: sc.kappa(),
            };
            (b.spacer_mass_kg * spacers as f64, Some(bundle))
        }
        None => (0.0, None),
    };
    if sc.reclose.is_some() {
        notes.push("T_k1: the first flow only; the simplified method has no auto-reclose".into());
    }
    let input = Input {
        span_m,
        phase_distance_m,
        mounting,
        subconductors: n as u32,
        mass_per_length_kg_per_m: cd.linear_density_kg_per_m,
        concentrated_mass_kg,
        area_m2,
        young_modulus_pa: ea / area_m2,
        diameter_m,
        static_tension_n,
        spring_constant_n_per_m,
        fault,
        first_duration_s: sc.duration_s,
        thermal_constant_m4_per_a2s: sc.thermal_constant_m4_per_a2s,
        gravity_m_per_s2: s.loads.gravity_m_per_s2,
        bundle,
    };
    Ok(Mapped { input, main: main.name.clone(), notes })
}
