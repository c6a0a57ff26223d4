//! Output files of a run: `timeseries.csv` ([`timeseries`]), `snapshots.csv` ([`snapshots`]) and
//! `summary.json` ([`summary`]). Writers flush as they go, so a run stopped by an instability leaves
//! readable files behind.

pub mod snapshots;
pub mod summary;
pub mod timeseries;

pub use snapshots::SnapshotWriter;
pub use summary::{Peak, Summary};
pub use timeseries::{Sample, TimeseriesWriter};
