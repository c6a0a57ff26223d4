//! Solution verification of a run: how far a computed number is from the limit of its discretisation.
//!
//! - [`gci`]: Celik's three-grid procedure (observed order, Richardson extrapolate, Grid Convergence Index
//!   with Roache's factor of safety), the arithmetic behind `ohl run --converge` (the refined runs
//!   themselves are the application's, `ohl_app::converge`).

pub mod gci;
