//! The verification harness of the `ohl` wire solver.
//!
//! Each study is one module under [`studies`] registered by one line in [`studies::STUDIES`]; a study
//! runs its computations, writes its CSV tables and its PNG + SVG plots under the output directory
//! (`figures/verification/` by default) and returns a [`report::StudyReport`] with its checks and a
//! pass/fail verdict. `verify all` collects them in `REPORT.md`.
//!
//! Shared machinery: [`setup`] (the paper's test wire and loads), [`convergence`] (least-squares order,
//! Richardson extrapolation, Grid Convergence Index), [`implicit`] (Newmark integrators, for one conductor and
//! for a whole line, on the library's Jacobian and sparse LU, `ohl::statics`), [`report`].
//! Independent exact references: [`exact_section`] (static equilibrium of a section on suspension strings),
//! [`exact_line`] (three-dimensional statics of a bundle with spacers and of phases on a shared elastic tower top).

pub mod convergence;
pub mod exact_line;
pub mod exact_section;
pub mod implicit;
pub mod report;
pub mod setup;
pub mod studies;
