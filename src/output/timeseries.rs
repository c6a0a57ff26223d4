//! `timeseries.csv`: one row per sample interval, taken at the first time level at or after each
//! multiple of the interval (the row records the level's actual time; sampling never moves the clock).
//!
//! Columns: `t_s` [s], `tau` [-] (`t U / l`), `mid_dx1_m`, `mid_dx2_m`, `mid_dx3_m` [m] (mid-span point
//! minus the chord midpoint), `max_tension_n` [N] (largest segment tension, the kernel's value),
//! `kinetic_j`, `elastic_j`, `potential_j` [J] (gravity and uniform load), `total_j` [J] (their sum); then
//! for each named probe `NAME_dx1_m`, `NAME_dx2_m`, `NAME_dx3_m` [m] (see [`super::probe`]); then for each
//! support `k` (fixed nodes in node order) `support{k}_f1_n`, `support{k}_f2_n`, `support{k}_f3_n` [N],
//! the force the wire applies to the support (tension plus the node's share of the loads and weight; for
//! a suspension support the force its string applies to the crossarm); then for each suspension support
//! `k` `support{k}_swing_along_deg`, `support{k}_swing_across_deg` [deg] (the string's swing from plumb:
//! along the line, positive when the clamp has moved towards `+e_l`, the horizontal direction from the
//! section's first support to its last; across it, positive towards `e_t = e3 x e_l`, to the left of the
//! line: `-x1` for a line along `+x2`) and `support{k}_arm_dx1_m`, `support{k}_arm_dx2_m` [m] (the crossarm
//! pivot's displacement; zero for a rigid crossarm); then for each span `k` of a section
//! `span{k}_max_tension_n` [N] (its largest segment tension) and, with a ground,
//! `span{k}_clearance_m` [m] (its least vertical clearance `min (x3 - h(x2))` over its nodes); then, with
//! a `[thermal]` table, `temperature_k` [K] (the mean segment temperature: the conductor's).

use std::path::Path;

use serde::Serialize;

use super::clock::{LANDING, SampleClock};
use super::probe::ProbePoint;
use super::rows::RowFile;
use crate::observer::{Control, Ending, Level, Observer, OutputError};
use crate::scheme::Ground;

/// One row of the time series (its fixed columns).
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

impl Sample {
    /// Names of the fixed columns, in the order of [`Sample::values`].
    pub const COLUMNS: [&'static str; 10] = [
        "t_s",
        "tau",
        "mid_dx1_m",
        "mid_dx2_m",
        "mid_dx3_m",
        "max_tension_n",
        "kinetic_j",
        "elastic_j",
        "potential_j",
        "total_j",
    ];

    /// The fixed columns' values, in the order of [`Sample::COLUMNS`].
    pub fn values(&self) -> [f64; 10] {
        [
            self.t_s,
            self.tau,
            self.mid_dx1_m,
            self.mid_dx2_m,
            self.mid_dx3_m,
            self.max_tension_n,
            self.kinetic_j,
            self.elastic_j,
            self.potential_j,
            self.total_j,
        ]
    }

    /// The fixed columns at a level; `mid` is the mid-span probe.
    pub fn of(level: &Level, mid: &ProbePoint) -> Sample {
        let s = level.solver;
        let d = s.level_energies();
        let m = mid.displacement(s.wire());
        Sample {
            t_s: level.t_s,
            tau: level.tau(),
            mid_dx1_m: m[0],
            mid_dx2_m: m[1],
            mid_dx3_m: m[2],
            max_tension_n: s.max_tension_n(),
            kinetic_j: d.kinetic_j,
            elastic_j: d.elastic_j,
            potential_j: d.potential_j,
            total_j: d.kinetic_j + d.elastic_j + d.potential_j,
        }
    }
}

/// What the line has that gets columns of its own: supports, strings, spans.
#[derive(Clone, Debug, Default)]
pub struct LineColumns {
    /// number of supports (fixed nodes and strings, in node order)
    pub supports: usize,
    /// each string's support index, in the order of `Wire::insulators`
    pub strings: Vec<usize>,
    /// a section's spans as (first node, last node); empty for one span
    pub spans: Vec<(usize, usize)>,
    /// the ground, for the spans' clearance
    pub ground: Option<Ground>,
    /// a `temperature_k` column (the scenario has a `[thermal]` table)
    pub temperature: bool,
}

/// The columns of `timeseries.csv`: their names, and their values at a time level. The file writer
/// ([`Timeseries`]) and in-memory records of the same table (the Python package) share it, so both hold
/// the same numbers.
pub struct Columns {
    header: Vec<String>,
    mid: ProbePoint,
    probes: Vec<ProbePoint>,
    forces: Vec<(usize, [f64; 3])>,
    strings: bool,
    spans: Vec<(usize, usize)>,
    ground: Option<Ground>,
    temperature: bool,
}

impl Columns {
    /// The columns of the mid-span probe `mid`, the other `probes` and what `line` has.
    pub fn new(mid: ProbePoint, probes: Vec<ProbePoint>, line: LineColumns) -> Self {
        let LineColumns { supports, strings: suspensions, spans, ground, temperature } = line;
        let mut header: Vec<String> = Sample::COLUMNS.map(String::from).into();
        for p in &probes {
            header.extend((1..=3).map(|k| format!("{}_dx{k}_m", p.name)));
        }
        for s in 0..supports {
            header.extend((1..=3).map(|k| format!("support{s}_f{k}_n")));
        }
        for s in &suspensions {
            header.extend(
                ["swing_along_deg", "swing_across_deg", "arm_dx1_m", "arm_dx2_m"].map(|c| format!("support{s}_{c}")),
            );
        }
        for k in 0..spans.len() {
            header.push(format!("span{k}_max_tension_n"));
            if ground.is_some() {
                header.push(format!("span{k}_clearance_m"));
            }
        }
        if temperature {
            header.push("temperature_k".into());
        }
        let strings = !suspensions.is_empty();
        Columns { header, mid, probes, forces: Vec::new(), strings, spans, ground, temperature }
    }

    /// The column names, in the order of [`Columns::values`].
    pub fn header(&self) -> &[String] {
        &self.header
    }

    /// The row of `level`: one call of `push` per column, in the order of [`Columns::header`].
    pub fn values(&mut self, level: &Level, mut push: impl FnMut(f64)) {
        let s = Sample::of(level, &self.mid);
        for x in s.values() {
            push(x);
        }
        for p in &self.probes {
            for x in p.displacement(level.solver.wire()) {
                push(x);
            }
        }
        level.solver.support_forces(&mut self.forces);
        for (_, force) in &self.forces {
            for x in force {
                push(*x);
            }
        }
        if self.strings {
            let w = level.solver.wire();
            for ins in &w.insulators {
                let [along, across] = ins.swing(w.position(ins.node));
                let d = ins.pivot_displacement_m();
                for x in [along.to_degrees(), across.to_degrees(), d[0], d[1]] {
                    push(x);
                }
            }
        }
        for &(first, last) in &self.spans {
            let s = level.solver;
            let w = s.wire();
            push(s.max_tension_in(first..last));
            if let Some(g) = &self.ground {
                push(g.least_clearance_m(&w.x, first..=last));
            }
        }
        if self.temperature {
            let t = &level.solver.wire().temperature_k;
            push(t.iter().sum::<f64>() / t.len() as f64);
        }
    }
}

/// Writes `timeseries.csv` (rows reach the file a page at a time, always whole: [`super::rows`]).
pub struct Timeseries {
    file: RowFile,
    clock: SampleClock,
    columns: Columns,
}

impl Timeseries {
    /// Create `path` for samples every `interval_s` [s] of the mid-span probe `mid`, the other `probes`
    /// and `supports` supports.
    pub fn create(
        path: &Path,
        interval_s: f64,
        mid: ProbePoint,
        probes: Vec<ProbePoint>,
        line: LineColumns,
    ) -> Result<Self, OutputError> {
        Self::with_columns(path, interval_s, Columns::new(mid, probes, line))
    }

    /// Create `path` for samples of `columns` every `interval_s` [s].
    pub fn with_columns(path: &Path, interval_s: f64, columns: Columns) -> Result<Self, OutputError> {
        let file = RowFile::create(path, columns.header()).map_err(OutputError::at(path))?;
        Ok(Timeseries { file, clock: SampleClock::new(interval_s), columns })
    }
}

impl Observer for Timeseries {
    fn observe(&mut self, level: &Level) -> Result<Control, OutputError> {
        let tol = LANDING * level.solver.params().dt_s;
        if self.clock.due(level.t_s, tol) {
            let f = &mut self.file;
            self.columns.values(level, |x| f.number(x));
            f.end_row();
            f.commit().map_err(OutputError::at(f.path()))?;
        }
        Ok(Control::QuietUntil(self.clock.quiet_until_s(tol)))
    }

    fn finish(&mut self, _level: &Level, _ending: &Ending) -> Result<(), OutputError> {
        let f = &mut self.file;
        f.finish().map_err(OutputError::at(f.path()))
    }
}
