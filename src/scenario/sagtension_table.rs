//! The table of a sag-tension case (`ohl sagtension`, `ohl.sagtension`): the case's conductor strung once
//! ([`crate::sagtension::Problem::string`]), then every condition solved in every state of the strung
//! conductor (initial, after creep, after load, final), the knee-point temperature of each state and the
//! temperature at which each state reaches the case's sag limit. The same problem with the single-modulus
//! law of the catalogue entry gives the comparison curve of the figure. The model and its equations are
//! the solver's ([`crate::sagtension`], docs/sagtension.md); this module only orders its answers.

use super::sagtension::{LawKind, Resolved};
use crate::sagtension::search::{TEMPERATURE_RANGE_K, illinois};
use crate::sagtension::{Row, SagTensionError, Span, State, Strung, Weather};

/// A value the solver may not find (a knee outside the searched temperatures): the value, or why not.
pub type Found = Result<f64, String>;

/// The table of a case.
#[derive(Clone, Debug)]
pub struct Table {
    /// the conductor's law
    pub law: LawKind,
    /// the length of the span the solver sees [m] (the ruling span of a section)
    pub span_m: f64,
    /// the states of the table, in order
    pub states: Vec<State>,
    /// the state the final one stands for
    pub final_is: State,
    /// the rows: for each condition (in the case's order) one row per state of [`Table::states`]
    pub rows: Vec<Row>,
    /// for each row, the mid-span sag of each span of the case [m]: one span's own; a section's spans each
    /// at the ruling span's horizontal tension ([`Strung::section_span`])
    pub span_sags_m: Vec<Vec<f64>>,
    /// the knee-point temperature of each state [K]
    pub knee_k: Vec<(State, Found)>,
    /// the temperature at which each state reaches the sag limit [K] (empty without a limit): the span's, or
    /// for a section its longest span's at the ruling span's horizontal tension
    pub limit_k: Vec<(State, Found)>,
    /// the sag limit of the span, or of the longest span of a section [m]
    pub sag_limit_m: Option<f64>,
}

/// The strung conductor of the case with the law `law`.
pub fn strung(r: &Resolved, law: crate::conductor::TwoMaterial) -> Result<Strung, SagTensionError> {
    r.problem(law)?.string()
}

/// Solve the case's table.
pub fn solve(r: &Resolved) -> Result<Table, SagTensionError> {
    let (law, kind) = r.law();
    let s = strung(r, law)?;
    let states = s.states();
    let mut rows = Vec::with_capacity(r.conditions.len() * states.len());
    let mut span_sags_m = Vec::with_capacity(rows.capacity());
    for w in &r.conditions {
        let w = w.to_solver();
        for &state in &states {
            let row = s.solve(&w, state)?;
            span_sags_m.push(if r.lengths_m.len() == 1 {
                vec![row.sag_midspan_m]
            } else {
                r.lengths_m
                    .iter()
                    .map(|&l| Ok(s.section_span(&w, state, Span::level(l))?.sag_midspan_m))
                    .collect::<Result<Vec<f64>, SagTensionError>>()?
            });
            rows.push(row);
        }
    }
    let knee_k = states.iter().map(|&st| (st, s.knee_temperature_k(st).map_err(|e| e.to_string()))).collect();
    let sag_limit_m = r.sag_limit_m;
    let limit_k = match sag_limit_m {
        Some(d) => states
            .iter()
            .map(|&st| {
                let t = match longest_of_section(r) {
                    None => s.temperature_at_sag_k(st, d),
                    Some(l) => section_temperature_at_sag_k(&s, st, l, d),
                };
                (st, t.map_err(|e| e.to_string()))
            })
            .collect(),
        None => Vec::new(),
    };
    Ok(Table {
        law: kind,
        span_m: s.problem.span.length_m,
        final_is: s.histories.final_is,
        states,
        rows,
        span_sags_m,
        knee_k,
        limit_k,
        sag_limit_m,
    })
}

/// The longest span of a section [m] (`None` for a single span).
pub fn longest_of_section(r: &Resolved) -> Option<f64> {
    (r.lengths_m.len() > 1).then(|| r.lengths_m.iter().fold(0.0_f64, |m, l| m.max(*l)))
}

/// The mid-span sag [m] of the bare conductor in `state` at `temperature_k` [K]: of the span, or of the
/// span `section_span_m` of a section, at the ruling span's horizontal tension ([`Strung::section_span`]).
pub fn sag_at(
    s: &Strung,
    state: State,
    temperature_k: f64,
    section_span_m: Option<f64>,
) -> Result<f64, SagTensionError> {
    let w = Weather::bare(temperature_k);
    Ok(match section_span_m {
        None => s.solve(&w, state)?.sag_midspan_m,
        Some(l) => s.section_span(&w, state, Span::level(l))?.sag_midspan_m,
    })
}

/// The temperature [K] at which the span `span_m` of a section reaches the mid-span sag `sag_m` [m], bare, in
/// `state`: the root of `sag_m - sag(theta)` (increasing in `theta`) in the solver's searched range
/// ([`TEMPERATURE_RANGE_K`]) by its Illinois search, to 1e-10 K.
pub fn section_temperature_at_sag_k(s: &Strung, state: State, span_m: f64, sag_m: f64) -> Result<f64, SagTensionError> {
    let g = |t: f64| -> Result<f64, SagTensionError> { Ok(sag_m - sag_at(s, state, t, Some(span_m))?) };
    let (lo, hi) = TEMPERATURE_RANGE_K;
    let (g_lo, g_hi) = (g(lo)?, g(hi)?);
    if g_lo < 0.0 || g_hi > 0.0 {
        return Err(SagTensionError::NotInRange {
            what: "temperature at that sag of the longest span",
            low_k: lo,
            high_k: hi,
            detail: format!("the sag is {:.3} m and {:.3} m there", sag_m - g_lo, sag_m - g_hi),
        });
    }
    illinois(g, lo, hi, g_lo, g_hi, 1e-10)
}

/// The mid-span sag [m] of the bare conductor in `state` at each temperature of `temperatures_k` [K]
/// ([`sag_at`]).
pub fn sag_curve(
    s: &Strung,
    state: State,
    temperatures_k: &[f64],
    section_span_m: Option<f64>,
) -> Result<Vec<(f64, f64)>, SagTensionError> {
    temperatures_k.iter().map(|&t| Ok((t, sag_at(s, state, t, section_span_m)?))).collect()
}
