//! `snapshots.csv`: the wire's shape at each snapshot time, one row per node.
//!
//! Columns: `t_s` [s], `tau` [-], `node` [-], `s_m` [m] (Lagrangian coordinate: stress-free length from
//! the left support), `x1_m`, `x2_m`, `x3_m` [m] (position), `v1_m_per_s`, `v2_m_per_s`, `v3_m_per_s`
//! [m/s] (velocity at the last half step), `tension_n` [N] (mean of the adjacent intact segments).

use std::fs::File;
use std::io::BufWriter;
use std::path::Path;

use serde::Serialize;

use crate::scheme::Explicit;

#[derive(Serialize)]
struct Row {
    t_s: f64,
    tau: f64,
    node: usize,
    s_m: f64,
    x1_m: f64,
    x2_m: f64,
    x3_m: f64,
    v1_m_per_s: f64,
    v2_m_per_s: f64,
    v3_m_per_s: f64,
    tension_n: f64,
}

/// Writes `snapshots.csv`, flushing after every snapshot.
pub struct SnapshotWriter {
    w: csv::Writer<BufWriter<File>>,
    tension: Vec<f64>,
}

impl SnapshotWriter {
    /// Create the file.
    pub fn create(path: &Path, segments: usize) -> std::io::Result<Self> {
        Ok(SnapshotWriter {
            w: csv::Writer::from_writer(BufWriter::new(File::create(path)?)),
            tension: vec![0.0; segments],
        })
    }

    /// Append the current shape of `solver` at dimensionless time `tau`.
    pub fn write(&mut self, solver: &Explicit, tau: f64) -> std::io::Result<()> {
        let w = &solver.wire;
        let n = w.segments();
        for (j, t) in self.tension.iter_mut().enumerate() {
            *t = solver.segment_tension(j);
        }
        let mut s = 0.0;
        for i in 0..=n {
            let (mut sum, mut cnt) = (0.0, 0.0);
            if i > 0 {
                sum += self.tension[i - 1] * w.intact[i - 1];
                cnt += w.intact[i - 1];
            }
            if i < n {
                sum += self.tension[i] * w.intact[i];
                cnt += w.intact[i];
            }
            let row = Row {
                t_s: solver.time_s,
                tau,
                node: i,
                s_m: s,
                x1_m: w.x[0][i],
                x2_m: w.x[1][i],
                x3_m: w.x[2][i],
                v1_m_per_s: w.v[0][i],
                v2_m_per_s: w.v[1][i],
                v3_m_per_s: w.v[2][i],
                tension_n: if cnt > 0.0 { sum / cnt } else { 0.0 },
            };
            self.w.serialize(row).map_err(std::io::Error::other)?;
            if i < n {
                s += w.reference_length[i];
            }
        }
        self.w.flush()
    }
}
