//! `snapshots.csv`: the wire's shape at each snapshot time, one row per node, taken at the first time
//! level at or after the time (the rows record the level's actual time; snapshots never move the clock),
//! and always once more at the end of a run that did not go unstable (the final state).
//!
//! Columns: `t_s` [s], `tau` [-], `node` [-], `s_m` [m] (Lagrangian coordinate: unstretched length from
//! the first node), `x1_m`, `x2_m`, `x3_m` [m] (position), `v1_m_per_s`, `v2_m_per_s`, `v3_m_per_s`
//! [m/s] (velocity at the last half step), `tension_n` [N] (mean of the adjacent intact segments).
//! Rows reach the file a page at a time and always whole ([`super::rows`]): a run killed mid-snapshot
//! leaves a file of whole rows, ending possibly within a snapshot.

use std::path::Path;

use super::clock::{LANDING, ListClock};
use super::rows::RowFile;
use crate::run::{Control, Ending, Level, Observer, OutputError};
use crate::scheme::Explicit;

/// Writes `snapshots.csv`.
pub struct Snapshots {
    file: RowFile,
    clock: ListClock,
    tension: Vec<f64>,
    last_t_s: Option<f64>,
}

impl Snapshots {
    /// Create `path` for snapshots at `times_s` [s].
    pub fn create(path: &Path, times_s: Vec<f64>) -> Result<Self, OutputError> {
        let header = [
            "t_s",
            "tau",
            "node",
            "s_m",
            "x1_m",
            "x2_m",
            "x3_m",
            "v1_m_per_s",
            "v2_m_per_s",
            "v3_m_per_s",
            "tension_n",
        ]
        .map(String::from);
        let file = RowFile::create(path, &header).map_err(OutputError::at(path))?;
        Ok(Snapshots { file, clock: ListClock::new(times_s), tension: Vec::new(), last_t_s: None })
    }

    fn write(&mut self, solver: &Explicit, t_s: f64, tau: f64) -> Result<(), OutputError> {
        let w = &solver.wire();
        let n = w.segments();
        self.tension.clear();
        self.tension.extend((0..n).map(|j| solver.segment_tension(j)));
        let f = &mut self.file;
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
            f.number(t_s);
            f.number(tau);
            f.integer(i as u64);
            for x in [s, w.x[0][i], w.x[1][i], w.x[2][i], w.v[0][i], w.v[1][i], w.v[2][i]] {
                f.number(x);
            }
            f.number(if cnt > 0.0 { sum / cnt } else { 0.0 });
            f.end_row();
            if i < n {
                s += w.reference_length[i];
            }
        }
        self.last_t_s = Some(t_s);
        f.commit().map_err(OutputError::at(f.path()))
    }
}

impl Observer for Snapshots {
    fn observe(&mut self, level: &Level) -> Result<Control, OutputError> {
        if self.clock.due(level.t_s, LANDING * level.solver.params().dt_s) {
            self.write(level.solver, level.t_s, level.tau())?;
        }
        Ok(Control::Continue)
    }

    fn finish(&mut self, level: &Level, ending: &Ending) -> Result<(), OutputError> {
        if !matches!(ending, Ending::Unstable(_)) && self.last_t_s != Some(level.t_s) {
            self.write(level.solver, level.t_s, level.tau())?;
        }
        let f = &mut self.file;
        f.finish().map_err(OutputError::at(f.path()))
    }
}
