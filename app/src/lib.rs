//! `ohl_app`: the applications of the `ohl` wire model, which the library itself does not carry.
//!
//! - [`paper`]: the paper's cases of `paper_cases/` (the `[paper]` checks of a case file, the heat-case
//!   file format, running, extracting, references, tables and figures);
//! - [`plot`]: PNG and SVG charts (plotters);
//! - [`cases`]: the line-section cases of `cases/` (runs, load figures, peak-to-residual tables);
//! - [`bench`]: the kernel benchmark (measurements, machine description, CSV tables, throughput plot);
//! - [`progress`]: the terminal progress bar of `ohl run`, an observer of the library's run loop.
//!
//! The binary `ohl` (`src/main.rs`, `src/cli/`) is the command line over these.

pub mod bench;
pub mod cases;
pub mod paper;
pub mod plot;
pub mod progress;
