//! Errors of the IEC 60865-1 simplified method.

/// Why the method could not be applied to an [`super::Input`].
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum Iec60865Error {
    /// A field outside its physical range.
    #[error("{field} = {value} is out of range: allowed {range}")]
    OutOfRange {
        /// the field as named in [`super::Input`]
        field: &'static str,
        /// the value given
        value: f64,
        /// the allowed range, in words
        range: &'static str,
    },
    /// A bundle (`n >= 2`) without sub-conductor geometry.
    #[error("subconductors = {subconductors} needs the bundle data (subconductor_distance_m, spacer_distance_m)")]
    MissingBundle {
        /// `n`
        subconductors: u32,
    },
    /// Physically valid, but outside the range in which the standard states the simplified method.
    #[error("{quantity} = {value} is outside the range of the IEC 60865-1 simplified method: {limit}")]
    OutsideMethod {
        /// the input or derived quantity
        quantity: &'static str,
        /// its value
        value: f64,
        /// the stated limit and where
        limit: &'static str,
    },
    /// The root of the `psi` equation was not found (cannot happen for valid input: the bracket is exact).
    #[error("psi: no root in [0, 1] for phi = {phi}, zeta = {zeta}")]
    Psi {
        /// `phi`
        phi: f64,
        /// `zeta`
        zeta: f64,
    },
    /// Clause 6.4.2: a root of Annex A not found, or the radicand of `nu_e` negative.
    #[error("pinch force (clause 6.4.2): no solution of Annex A for this bundle")]
    Pinch,
}
