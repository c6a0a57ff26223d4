//! What a run produces. Each output is an observer of the run loop ([`crate::observer::Observer`]), one per
//! file:
//!
//! - [`timeseries`]: `timeseries.csv`, a row per sample interval (probes and support forces included);
//! - [`snapshots`]: `snapshots.csv`, the whole wire at the snapshot times and at the end;
//! - [`peaks`]: peaks of tension, probe displacements and support forces, every time level, per phase;
//! - [`recorder`]: the same samples and shapes in memory;
//! - [`summary`]: `summary.json`, written whole at the end;
//! - [`spans`]: a span's sag, horizontal tension, largest tension and clearance at one level;
//! - [`start_up`]: which peaks come from the start (a wind's onset) rather than from the design load;
//!
//! with their building blocks: [`clock`] (when an output acts, without moving the clock), [`probe`]
//! (Lagrangian points), [`rows`] (CSV files that only ever hold whole rows) and [`cpu_time`] (the
//! thread's CPU time, for the throughput).

pub mod clock;
pub mod cpu_time;
pub mod peaks;
pub mod probe;
pub mod recorder;
pub mod rows;
pub mod snapshots;
pub mod spans;
pub mod start_up;
pub mod summary;
pub mod timeseries;

pub use peaks::{Peak, Peaks};
pub use probe::ProbePoint;
pub use recorder::{Probe, Recorder, Shape};
pub use snapshots::Snapshots;
pub use summary::Summary;
pub use timeseries::{Sample, Timeseries};
