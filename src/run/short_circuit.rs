//! The outputs of a line run with `[short_circuit]` (issue 25), tracked at every time level of the line
//! (not at samples): `short_circuit.csv` and the `short_circuit` block of `summary.json`
//! (docs/short_circuit.md, "Outputs", where the definitions are argued against IEC 60865-1).
//!
//! Per phase (a bundle summed over its sub-conductors, as IEC's force of a main conductor) and per end of
//! its section (`start`: the first support, `end`: the last), with `T(t)` the sum of the members' end
//! segment tensions:
//!
//! - `F_t`: the largest `T` from fault inception to the first maximum of the swing-out angle `delta(t)`
//!   (the angle of the mid-span point about the chord of the span's ends, from the vertical, in the plane
//!   across the line): IEC 60865-1 clause 6.2.3, the tensile force during the short circuit, caused by the
//!   swing-out;
//! - `F_f`: the largest `T` after that first maximum: clause 6.2.6, the force when the span falls back;
//! - `F_pi` (bundles): the largest `T` from inception to the end of the sub-conductors' first contraction
//!   (the least distance between two members at mid-span passes its minimum and rises again by 10 % of
//!   its initial value) or the end of the first current flow, whichever comes first;
//! - `b_h`: the largest horizontal displacement of the mid-span point across the line (clause 6.2.5);
//! - `a_min`: the least distance between two phases (the line's clearance tracker, every level).
//!
//! A maximum of `delta` counts once `delta` has fallen below it by `max(0.5 deg, 5 %)` (the hysteresis
//! keeps a ripple of the 100 Hz force from ending the swing-out).

use std::path::Path;

use serde::Serialize;

use crate::output::rows::RowFile;
use crate::scheme::LineExplicit;

use super::OutputError;

/// A value and when [s].
#[derive(Clone, Copy, Debug, Default, Serialize, PartialEq)]
pub struct Timed {
    /// the value (N, m or deg)
    pub value: f64,
    /// when [s]
    pub time_s: f64,
}

impl Timed {
    fn raise(&mut self, value: f64, time_s: f64) {
        if value > self.value {
            *self = Timed { value, time_s };
        }
    }
}

/// The forces at one end of a phase's section.
#[derive(Clone, Copy, Debug, Default, Serialize, PartialEq)]
pub struct EndForces {
    /// the tension at the start of the fault [N]
    pub static_n: f64,
    /// `F_t` [N]: the largest during the swing-out
    pub f_t: Timed,
    /// `F_f` [N]: the largest after the first maximum of the swing-out; none before that maximum
    pub f_f: Option<Timed>,
    /// `F_pi` [N]: the largest during the first contraction of a bundle; none for a single conductor
    pub f_pi: Option<Timed>,
}

/// One phase's short-circuit results.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct PhaseShortCircuit {
    /// the conductor (group) name
    pub name: String,
    /// L1, L2 or L3
    pub phase: String,
    /// at the first support, at the last
    pub ends: [EndForces; 2],
    /// the first maximum of the swing-out angle [deg] (absent until it is passed)
    pub swing_out_max_deg: Option<Timed>,
    /// `b_h`: the largest horizontal displacement across the line at mid-span [m]
    pub b_h: Timed,
    /// the end of the first contraction of a bundle [s] (absent for one conductor, or not reached)
    pub contraction_end_s: Option<f64>,
}

/// The `short_circuit` block of `summary.json`.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct ShortCircuitSummary {
    /// fault inception [s]
    pub start_s: f64,
    /// end of the last current flow [s]
    pub end_s: f64,
    /// the inception angle used [deg] (the worst case when the file gives none)
    pub inception_angle_deg: f64,
    /// the peak factor `kappa` of the current [-]
    pub peak_factor: f64,
    /// per phase
    pub phases: Vec<PhaseShortCircuit>,
    /// `a_min`: the least distance between two phases over the run [m], with its time and the pair
    pub a_min: Option<Timed>,
    /// the two phases of `a_min`
    pub a_min_between: Option<[String; 2]>,
    /// work of the electromagnetic forces over the run [J]
    pub em_work_j: f64,
}

/// Tracks one phase.
#[derive(Clone, Debug)]
struct Phase {
    name: String,
    members: Vec<usize>,
    across: [f64; 2],
    mid0: [f64; 3],
    out: PhaseShortCircuit,
    /// swing: running max of |delta| and when; whether the first maximum is passed
    delta_max: Timed,
    swung: bool,
    /// largest tension per end since the running maximum of delta was last raised
    since_peak: [Timed; 2],
    /// largest tension per end from inception
    from_start: [Timed; 2],
    /// contraction: the initial least member distance, its running minimum, whether it ended
    gap0: f64,
    gap_min: f64,
    contracted: bool,
}

/// The observer of a run with a short circuit ([module doc](self)).
pub struct ShortCircuitTracker {
    start_s: f64,
    first_end_s: f64,
    end_s: f64,
    phases: Vec<Phase>,
    file: Option<RowFile>,
    path: Option<std::path::PathBuf>,
}

fn mean(points: impl Iterator<Item = [f64; 3]>) -> [f64; 3] {
    let (mut s, mut n) = ([0.0; 3], 0.0);
    for p in points {
        for k in 0..3 {
            s[k] += p[k];
        }
        n += 1.0;
    }
    s.map(|v| v / n)
}

fn mid_node(line: &LineExplicit, c: usize) -> usize {
    line.conductors()[c].wire().segments() / 2
}

impl ShortCircuitTracker {
    /// A tracker of the phases `phases` (names of the line's conductor groups `names`/`groups`) of the
    /// fault in `line`; writes `short_circuit.csv` into `out_dir` if given.
    pub fn new(
        line: &LineExplicit,
        phases: &[String],
        names: &[String],
        groups: &[Vec<usize>],
        out_dir: Option<&Path>,
    ) -> Result<Self, OutputError> {
        let em = line.electromagnetic().expect("a short circuit has its electromagnetic load");
        let current = &em.current;
        let spec = current.spec();
        let mut tracked = Vec::new();
        for (j, name) in phases.iter().enumerate() {
            let Some(g) = names.iter().position(|n| n == name) else { continue };
            let members = groups[g].clone();
            let w = line.conductors()[members[0]].wire();
            let (a, z) = (w.position(0), w.position(w.nodes() - 1));
            let h = [z[0] - a[0], z[1] - a[1]];
            let hn = (h[0] * h[0] + h[1] * h[1]).sqrt().max(f64::MIN_POSITIVE);
            let mid0 = mean(members.iter().map(|&m| line.conductors()[m].wire().position(mid_node(line, m))));
            let gap0 = least_gap(line, &members);
            let bundle = members.len() > 1;
            tracked.push(Phase {
                name: name.clone(),
                members,
                across: [-h[1] / hn, h[0] / hn],
                mid0,
                out: PhaseShortCircuit {
                    name: name.clone(),
                    phase: format!("L{}", j + 1),
                    ends: [EndForces { f_pi: bundle.then(Timed::default), ..EndForces::default() }; 2],
                    swing_out_max_deg: None,
                    b_h: Timed::default(),
                    contraction_end_s: None,
                },
                delta_max: Timed::default(),
                swung: false,
                since_peak: [Timed::default(); 2],
                from_start: [Timed::default(); 2],
                gap0,
                gap_min: gap0,
                contracted: !bundle,
            });
        }
        let (file, path) = match out_dir {
            Some(d) => {
                let path = d.join("short_circuit.csv");
                let mut head: Vec<String> = vec!["t_s".into(), "i_l1_a".into(), "i_l2_a".into(), "i_l3_a".into()];
                for p in &tracked {
                    let n = super::line::slug(&p.name);
                    head.push(format!("f_{n}_across_n_per_m"));
                    head.push(format!("f_{n}_n_per_m"));
                }
                (Some(RowFile::create(&path, &head).map_err(OutputError::at(&path))?), Some(path))
            }
            None => (None, None),
        };
        Ok(ShortCircuitTracker {
            start_s: spec.start_s,
            first_end_s: spec.start_s + spec.duration_s,
            end_s: current.end_s(),
            phases: tracked,
            file,
            path,
        })
    }

    /// Observe the evaluated level at `t_s` (after [`LineExplicit::evaluate_forces`]).
    pub fn observe(&mut self, line: &LineExplicit, t_s: f64) -> Result<(), OutputError> {
        let em = line.electromagnetic().expect("a short circuit has its electromagnetic load");
        let i = em.current.phase_currents_a(t_s);
        if let Some(f) = self.file.as_mut() {
            f.number(t_s);
            for v in i {
                f.number(v);
            }
        }
        let started = t_s >= self.start_s;
        for p in &mut self.phases {
            let cs = line.conductors();
            let ends = [
                p.members.iter().map(|&m| cs[m].segment_tension(0)).sum::<f64>(),
                p.members.iter().map(|&m| cs[m].segment_tension(cs[m].wire().segments() - 1)).sum::<f64>(),
            ];
            // The EM force per unit length at mid-span, summed over the members.
            let mut q = [0.0; 3];
            for &m in &p.members {
                let k = mid_node(line, m);
                let w = cs[m].wire();
                let len = 0.5 * (w.rest_length[k - 1] + w.rest_length[k]);
                if let Some(f) = line.em_force_n(m) {
                    for d in 0..3 {
                        q[d] += f[d][k] / len;
                    }
                }
            }
            if let Some(f) = self.file.as_mut() {
                f.number(q[0] * p.across[0] + q[1] * p.across[1]);
                f.number((q[0] * q[0] + q[1] * q[1] + q[2] * q[2]).sqrt());
            }
            if !started {
                p.out.ends[0].static_n = ends[0];
                p.out.ends[1].static_n = ends[1];
                continue;
            }
            // Mid-span: displacement across and the swing-out angle about the chord of the ends.
            let mid = mean(p.members.iter().map(|&m| cs[m].wire().position(mid_node(line, m))));
            let chord = mean(p.members.iter().flat_map(|&m| {
                let w = cs[m].wire();
                [w.position(0), w.position(w.nodes() - 1)]
            }));
            let across = |v: [f64; 3]| v[0] * p.across[0] + v[1] * p.across[1];
            let u = across([mid[0] - p.mid0[0], mid[1] - p.mid0[1], 0.0]);
            p.out.b_h.raise(u.abs(), t_s);
            let r = [mid[0] - chord[0], mid[1] - chord[1], mid[2] - chord[2]];
            let delta = across(r).atan2(-r[2]).to_degrees().abs();
            if !p.swung {
                if delta > p.delta_max.value {
                    p.delta_max = Timed { value: delta, time_s: t_s };
                    for e in 0..2 {
                        p.out.ends[e].f_t = p.out.ends[e].f_t.max_with(p.since_peak[e]);
                        p.since_peak[e] = Timed::default();
                    }
                } else if delta < p.delta_max.value - (0.5f64).max(0.05 * p.delta_max.value) {
                    p.swung = true;
                    p.out.swing_out_max_deg = Some(p.delta_max);
                    for e in 0..2 {
                        p.out.ends[e].f_f = Some(p.since_peak[e]);
                    }
                }
            }
            for e in 0..2 {
                p.from_start[e].raise(ends[e], t_s);
                if p.swung {
                    if let Some(f) = p.out.ends[e].f_f.as_mut() {
                        f.raise(ends[e], t_s);
                    }
                } else {
                    p.since_peak[e].raise(ends[e], t_s);
                }
            }
            // The first contraction of a bundle.
            if !p.contracted {
                let gap = least_gap(line, &p.members);
                p.gap_min = p.gap_min.min(gap);
                if gap > p.gap_min + 0.1 * p.gap0 || t_s > self.first_end_s {
                    p.contracted = true;
                    p.out.contraction_end_s = Some(t_s);
                } else {
                    for e in 0..2 {
                        if let Some(f) = p.out.ends[e].f_pi.as_mut() {
                            f.raise(ends[e], t_s);
                        }
                    }
                }
            }
        }
        if let Some(f) = self.file.as_mut() {
            f.end_row();
            let path = self.path.clone().unwrap_or_default();
            f.commit().map_err(OutputError::at(&path))?;
        }
        Ok(())
    }

    /// The summary at the end of the run; `a_min` from the line's clearances (`least` between phases by
    /// name, `[a, b]`, the least distance and its time).
    pub fn finish(
        mut self,
        line: &LineExplicit,
        clearances: &[([String; 2], f64, f64)],
    ) -> Result<ShortCircuitSummary, OutputError> {
        if let (Some(f), Some(path)) = (self.file.as_mut(), self.path.as_ref()) {
            f.finish().map_err(OutputError::at(path))?;
        }
        let names: Vec<&String> = self.phases.iter().map(|p| &p.name).collect();
        let between = clearances
            .iter()
            .filter(|(pair, _, _)| names.contains(&&pair[0]) && names.contains(&&pair[1]))
            .min_by(|a, b| a.1.total_cmp(&b.1));
        let em = line.electromagnetic().expect("a short circuit has its electromagnetic load");
        let phases = self
            .phases
            .into_iter()
            .map(|mut p| {
                if !p.swung {
                    // The swing-out has not passed its first maximum: F_t is the largest so far.
                    for e in 0..2 {
                        p.out.ends[e].f_t = p.out.ends[e].f_t.max_with(p.since_peak[e]);
                    }
                }
                p.out
            })
            .collect();
        Ok(ShortCircuitSummary {
            start_s: self.start_s,
            end_s: self.end_s,
            inception_angle_deg: em.current.inception_angle_deg(),
            peak_factor: em.current.peak_factor(),
            phases,
            a_min: between.map(|b| Timed { value: b.1, time_s: b.2 }),
            a_min_between: between.map(|b| b.0.clone()),
            em_work_j: line.em_work_j(),
        })
    }
}

impl Timed {
    fn max_with(self, other: Timed) -> Timed {
        if other.value > self.value { other } else { self }
    }
}

/// The least distance between two members of a bundle at their mid-span nodes [m] (infinite for one).
fn least_gap(line: &LineExplicit, members: &[usize]) -> f64 {
    let mut least = f64::INFINITY;
    for (a, &m) in members.iter().enumerate() {
        for &n in &members[a + 1..] {
            let p = line.conductors()[m].wire().position(mid_node(line, m));
            let q = line.conductors()[n].wire().position(mid_node(line, n));
            least = least.min(((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt());
        }
    }
    least
}
