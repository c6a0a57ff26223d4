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
use crate::observer::{Control, Ending, Level, Observer, OutputError};
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
        let f = &mut self.file;
        node_rows(solver, &mut self.tension, |r| {
            f.number(t_s);
            f.number(tau);
            f.integer(r.node as u64);
            for x in [r.s_m, r.x_m[0], r.x_m[1], r.x_m[2], r.v_m_per_s[0], r.v_m_per_s[1], r.v_m_per_s[2]] {
                f.number(x);
            }
            f.number(r.tension_n);
            f.end_row();
        });
        self.last_t_s = Some(t_s);
        f.commit().map_err(OutputError::at(f.path()))
    }
}

/// One node of a snapshot, as a row of `snapshots.csv` has it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NodeRow {
    /// node index [-]
    pub node: usize,
    /// Lagrangian coordinate: unstretched length from the first node [m]
    pub s_m: f64,
    /// position [m]
    pub x_m: [f64; 3],
    /// velocity at the last half step [m/s]
    pub v_m_per_s: [f64; 3],
    /// mean tension of the adjacent intact segments (0 if none) [N]
    pub tension_n: f64,
}

/// The rows of a snapshot of `solver`'s current state, node by node (`tension` is scratch space): the
/// numbers `snapshots.csv` holds, for the file and for in-memory records alike.
pub fn node_rows(solver: &Explicit, tension: &mut Vec<f64>, mut each: impl FnMut(NodeRow)) {
    let w = &solver.wire();
    let n = w.segments();
    tension.clear();
    tension.extend((0..n).map(|j| solver.segment_tension(j)));
    let mut s = 0.0;
    for i in 0..=n {
        let (mut sum, mut cnt) = (0.0, 0.0);
        if i > 0 {
            sum += tension[i - 1] * w.intact[i - 1];
            cnt += w.intact[i - 1];
        }
        if i < n {
            sum += tension[i] * w.intact[i];
            cnt += w.intact[i];
        }
        each(NodeRow {
            node: i,
            s_m: s,
            x_m: [w.x[0][i], w.x[1][i], w.x[2][i]],
            v_m_per_s: [w.v[0][i], w.v[1][i], w.v[2][i]],
            tension_n: if cnt > 0.0 { sum / cnt } else { 0.0 },
        });
        if i < n {
            s += w.reference_length[i];
        }
    }
}

impl Observer for Snapshots {
    fn observe(&mut self, level: &Level) -> Result<Control, OutputError> {
        let tol = LANDING * level.solver.params().dt_s;
        if self.clock.due(level.t_s, tol) {
            self.write(level.solver, level.t_s, level.tau())?;
        }
        Ok(Control::QuietUntil(self.clock.quiet_until_s(tol)))
    }

    fn finish(&mut self, level: &Level, ending: &Ending) -> Result<(), OutputError> {
        if !matches!(ending, Ending::Unstable(_)) && self.last_t_s != Some(level.t_s) {
            self.write(level.solver, level.t_s, level.tau())?;
        }
        let f = &mut self.file;
        f.finish().map_err(OutputError::at(f.path()))
    }
}
