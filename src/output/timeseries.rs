//! `timeseries.csv`: one row per sample interval.
//!
//! Columns: `t_s` [s], `tau` [-] (`t U / l`), `mid_dx1_m`, `mid_dx2_m`, `mid_dx3_m` [m] (mid-span point
//! minus the chord midpoint), `max_tension_n` [N], `kinetic_j`, `elastic_j`, `potential_j` [J]
//! (gravity and uniform load), `total_j` [J] (their sum).

use std::fs::File;
use std::io::BufWriter;
use std::path::Path;

use serde::Serialize;

/// One row of the time series.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Sample {
    /// time `t` [s]
    pub t_s: f64,
    /// dimensionless time `tau = t U / l` [-]
    pub tau: f64,
    /// mid-span displacement from the chord midpoint, `x1` [m]
    pub mid_dx1_m: f64,
    /// mid-span displacement from the chord midpoint, `x2` [m]
    pub mid_dx2_m: f64,
    /// mid-span displacement from the chord midpoint, `x3` [m]
    pub mid_dx3_m: f64,
    /// largest segment tension [N]
    pub max_tension_n: f64,
    /// kinetic energy [J]
    pub kinetic_j: f64,
    /// elastic energy [J]
    pub elastic_j: f64,
    /// potential energy of gravity and the uniform load [J]
    pub potential_j: f64,
    /// kinetic + elastic + potential [J]
    pub total_j: f64,
}

/// Writes `timeseries.csv`, flushing after every row.
pub struct TimeseriesWriter {
    w: csv::Writer<BufWriter<File>>,
}

impl TimeseriesWriter {
    /// Create the file (with its header, written with the first row).
    pub fn create(path: &Path) -> std::io::Result<Self> {
        Ok(TimeseriesWriter { w: csv::Writer::from_writer(BufWriter::new(File::create(path)?)) })
    }

    /// Append a row.
    pub fn write(&mut self, s: &Sample) -> std::io::Result<()> {
        self.w.serialize(s).map_err(std::io::Error::other)?;
        self.w.flush()
    }
}
