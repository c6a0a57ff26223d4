//! Sag-tension: the spans of a line design as line designers tabulate them (issue 24). A conductor with
//! its real axial law ([`crate::conductor`]: two materials, stress-strain polynomials, creep, permanent
//! set, the knee point) is strung at one condition and solved at a list of others, in the states
//! initial, after creep, after a heavy load and final. docs/sagtension.md describes the model, the
//! conventions and the comparisons with published tables.
//!
//! - [`catenary`]: the exact catenary of a span with a nonlinear law, by quadrature (Irvine's
//!   equations with `e(T)` from the law);
//! - [`weather`]: a condition's load per length (ice, wind, NESC constant) and the conductor;
//! - [`span`]: a span or the ruling span of a section;
//! - [`problem`]: the stringing condition, the states and the change of state;
//! - [`row`]: what one table row reports;
//! - [`search`]: the knee-point temperature and the temperature of a given sag;
//! - [`error`]: the typed errors.
//!
//! The public entry points are [`solve_table`], [`knee_temperature_k`] and [`temperature_at_sag_k`]
//! (each strings the conductor once: [`Problem::string`]; use [`Strung`] to ask several questions).

// Units in brackets, `[N]`, `[m]`, are not intra-doc links.
#![allow(rustdoc::broken_intra_doc_links)]

pub mod catenary;
pub mod error;
pub mod problem;
pub mod row;
pub mod search;
pub mod span;
pub mod weather;

pub use error::SagTensionError;
pub use problem::{Histories, Problem, State, StretchPoint, Stringing, StringingTarget, Strung};
pub use row::Row;
pub use span::Span;
pub use weather::{STANDARD_GRAVITY_M_PER_S2, SagConductor, Weather};

/// The table: one row per weather and state, the weathers in the order given, for each the states
/// [`Strung::states`] (initial, after creep and after load where their conditions are given, final).
pub fn solve_table(problem: &Problem, weathers: &[Weather]) -> Result<Vec<Row>, SagTensionError> {
    let strung = problem.string()?;
    let mut rows = Vec::with_capacity(weathers.len() * 4);
    for w in weathers {
        for state in strung.states() {
            rows.push(strung.solve(w, state)?);
        }
    }
    Ok(rows)
}

/// The knee-point temperature [K] of the bare span in `state` ([`Strung::knee_temperature_k`]).
pub fn knee_temperature_k(problem: &Problem, state: State) -> Result<f64, SagTensionError> {
    problem.string()?.knee_temperature_k(state)
}

/// The temperature [K] at which the bare span in `state` sags `sag_m` [m] at mid-span
/// ([`Strung::temperature_at_sag_k`]).
pub fn temperature_at_sag_k(problem: &Problem, state: State, sag_m: f64) -> Result<f64, SagTensionError> {
    problem.string()?.temperature_at_sag_k(state, sag_m)
}
