//! The errors of the sag-tension solver: an input out of its physical range, or a condition the span
//! cannot reach (a load it cannot carry, a knee it never passes in the searched range).

/// An error of [`super`] with the quantity concerned.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SagTensionError {
    /// an input out of its range
    #[error("invalid {what}: {value} (allowed: {allowed})")]
    Invalid {
        /// the quantity, with its unit
        what: &'static str,
        /// the value given
        value: f64,
        /// the allowed range
        allowed: &'static str,
    },
    /// no equilibrium, or an iteration that did not converge
    #[error("no solution for the {what}: {detail}")]
    NoSolution {
        /// what was being solved
        what: &'static str,
        /// why, with the numbers
        detail: String,
    },
    /// the searched temperature range holds no root
    #[error("no {what} between {low_k} K and {high_k} K: {detail}")]
    NotInRange {
        /// what was searched
        what: &'static str,
        /// lower end [K]
        low_k: f64,
        /// upper end [K]
        high_k: f64,
        /// the values at the ends
        detail: String,
    },
    /// a state that needs a stretch condition the problem does not give
    #[error("state {0} needs its stretch condition (`creep` for after-creep, `heavy_load` for after-load)")]
    MissingStretch(&'static str),
}
