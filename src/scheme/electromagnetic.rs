//! The electromagnetic load of a short circuit in the explicit line scheme ([`super::line::LineExplicit`]):
//! the evaluation of [`crate::line::electromagnetic`]'s model at each time level.
//!
//! At level `n` (time `t_n`), if some current flows ([`crate::shortcircuit::FaultCurrent::is_flowing`]):
//!
//! ```text
//! G_bp(r) = sum over source chords a of phase p (a != b, a not next to b on one carrier) of
//!           share_a (F, M)(a -> b, unit currents, r)                         (recomputed every M steps)
//! (F_b, M_b)(t_n) = share_b i_{L(b)}(t_n) sum_p i_p(t_n) G_bp(t_n)           (every step)
//! f_j += w_F(j) F_b + w_M(j) M_b    for the mechanical nodes j of chord b
//! ```
//!
//! (`F` the force on chord `b`, `M` its first moment, [`crate::element::em_force`]; `G_bp(t_n)` the last
//! evaluation or, with `extrapolate`, the line through the last two). The nodal forces enter each
//! carrier's node pass as its prescribed nodal force ([`Explicit::nodal_force_slot`]), which the segment
//! pass does not read, so the level's segment pass stays valid. With no current flowing nothing is
//! evaluated and no nodal force is set: the step is the one without the load, bit for bit.
//!
//! Work. The work of the electromagnetic forces is accumulated by the trapezoidal rule over each drift,
//! `W += (f^n + f^{n+1}) / 2 . (x^{n+1} - x^n)`, `x^{n+1} - x^n = dt v^{n+1/2}`: the half with `f^n` after
//! the step, the half with `f^{n+1}` when level `n + 1` is evaluated, so that at an evaluated level the
//! energy budget `E^n - E^0 = W^n` closes to the scheme's `O(dt^2)` (no damping).
//!
//! Near field. Two carriers of one phase (the sub-conductors of a bundle) are not evaluated by chords and
//! refreshed factors but segment by segment at every level, each target segment against the source
//! segments within a window around its own place (`NEAR_SEGMENTS`, `NEAR_DISTANCES`): the pinch pulls
//! them together until they touch, where the chords' error (chords much longer than the distance) is
//! unbounded.
//!
//! A pair of chords that intersect (a clash of two carriers, [`crate::element::em_force::EmForceError`])
//! contributes nothing; the first such event is kept ([`EmState::intersection`]) for the caller to report.

// Units in brackets, `[N]`, `[m]`, `[A]`, would otherwise be taken for intra-doc links.
#![allow(rustdoc::broken_intra_doc_links)]

use super::explicit::Explicit;
use crate::element::em_force::{EmForceError, pair_force};
use crate::line::electromagnetic::Electromagnetic;

/// Two carriers' chords met (their filaments intersect): the pair is left out of the force.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EmIntersection {
    /// time of the level [s]
    pub time_s: f64,
    /// conductor of the source chord and its first node
    pub source: (usize, usize),
    /// conductor of the target chord and its first node
    pub target: (usize, usize),
    /// least distance between the chords [m]
    pub distance_m: f64,
}

/// The meeting of two filaments (source and target: conductor and first node) at `t_s` [s].
fn meeting(e: EmForceError, t_s: f64, source: (usize, usize), target: (usize, usize)) -> EmIntersection {
    let distance_m = match e {
        EmForceError::Intersecting { distance_m } => distance_m,
        EmForceError::Degenerate => 0.0,
    };
    EmIntersection { time_s: t_s, source, target, distance_m }
}

#[derive(Clone, Copy, Debug)]
struct Chord {
    /// index into the carriers
    carrier: usize,
    /// the chord's index along its carrier
    index: usize,
    /// first and last mechanical node
    n0: usize,
    n1: usize,
    phase: usize,
    share: f64,
    core_m: f64,
    /// its spreading weights: `spread[w0..w1]`
    w0: usize,
    w1: usize,
}

/// Geometric factors of one target chord: per source phase, the force (0..3) and first moment (3..6)
/// [N/A^2].
/// Chords of one carrier closer in index than this are left out of its self-force: the chord itself and
/// its two neighbours (they share a node with it). Including the neighbours with the core cut instead was
/// measured (docs/short_circuit.md): it changes the force totals by 0.1 % to 0.4 % on the swinging span of
/// the tests, with no consistent gain in the chord error.
const EXCLUDE: usize = 1;
type Factors = [[f64; 6]; 3];
/// The near field of two carriers of one phase (a bundle's sub-conductors, a few centimetres to decimetres
/// apart, which the pinch pulls together until they touch) covers at least this many segments on each
/// side of the target segment's place...
const NEAR_SEGMENTS: usize = 2;
/// ... and at least this many times their initial distance at mid-span. Beyond it the sibling's force is
/// left out: for parallel conductors at `d` the part beyond `D` is the fraction `1 - D / sqrt(D^2 + d^2)
/// ~ d^2 / (2 D^2)` of the force per length, 0.5 % at `D = 10 d` (less as the pinch closes them). Chords
/// longer than the distance between the carriers misplace the force (docs/short_circuit.md): when the
/// sub-conductors met under the pinch, the chords of 4 segments refreshed every 8 steps let them pass
/// through the contact penalty (tests/short_circuit_contact.rs); segment by segment at every level they
/// do not.
const NEAR_DISTANCES: f64 = 10.0;

/// The state of the electromagnetic load during a run.
#[derive(Clone, Debug)]
pub struct EmState {
    em: Electromagnetic,
    /// every carrier's conductor index
    conductor: Vec<usize>,
    chords: Vec<Chord>,
    /// (node, w_F, w_M) per chord, chord after chord
    spread: Vec<(usize, f64, f64)>,
    /// chord end points at the last refresh (scratch)
    ends: Vec<[[f64; 3]; 2]>,
    geom: Vec<Factors>,
    geom_prev: Vec<Factors>,
    /// the factors used at this level (scratch)
    geom_now: Vec<Factors>,
    t_geom: f64,
    t_prev: f64,
    have_geom: bool,
    have_prev: bool,
    last_refresh: u64,
    /// nodal forces per carrier at the evaluated level [N]
    forces: Vec<[Vec<f64>; 3]>,
    /// spare nodal-force buffers per carrier while no current flows (moved into the conductors while it
    /// flows)
    spare: Vec<Option<[Vec<f64>; 3]>>,
    /// the forces of the evaluated level are those of a flowing current
    level_flowing: bool,
    /// work since t = 0 [J]
    work_j: f64,
    /// the step count at whose level the second half of the work was added
    half_added: Option<u64>,
    intersection: Option<EmIntersection>,
    /// refreshes of the geometric factors so far
    refreshes: u64,
    /// near pairs (target carrier, source carrier): two carriers of one phase (a bundle's sub-conductors),
    /// evaluated segment by segment at every level within `window` segments, not by chords
    near: Vec<(usize, usize)>,
    /// half-width of the near field [segments]
    window: usize,
}

/// The spreading weights of a chord over its nodes with rest-length fractions `u` (module docs of
/// [`crate::line::electromagnetic`]): `int phi_j q`, `q = F (4 - 6u) + M (12u - 6)`.
fn chord_weights(u: &[f64], out: &mut Vec<(usize, f64, f64)>, n0: usize) {
    let len = u.len() - 1;
    if len == 1 {
        out.push((n0, 1.0, -1.0));
        out.push((n0 + 1, 0.0, 1.0));
        return;
    }
    let g_f = |x: f64| 4.0 - 6.0 * x;
    let g_m = |x: f64| 12.0 * x - 6.0;
    for m in 0..=len {
        let (mut wf, mut wm) = (0.0, 0.0);
        if m > 0 {
            let h = u[m] - u[m - 1];
            wf += h * (g_f(u[m - 1]) / 6.0 + g_f(u[m]) / 3.0);
            wm += h * (g_m(u[m - 1]) / 6.0 + g_m(u[m]) / 3.0);
        }
        if m < len {
            let h = u[m + 1] - u[m];
            wf += h * (g_f(u[m]) / 3.0 + g_f(u[m + 1]) / 6.0);
            wm += h * (g_m(u[m]) / 3.0 + g_m(u[m + 1]) / 6.0);
        }
        out.push((n0 + m, wf, wm));
    }
}

impl EmState {
    /// The state for a checked load on the conductors' wires.
    pub(crate) fn new(em: Electromagnetic, conductors: &[Explicit]) -> Self {
        let k = em.numerics.chord_segments;
        let mut chords = Vec::new();
        let mut spread = Vec::new();
        let mut forces = Vec::new();
        let mut u = Vec::new();
        for (ci, c) in em.carriers.iter().enumerate() {
            let w = conductors[c.conductor].wire();
            let n = w.segments();
            let mut n0 = 0;
            let mut index = 0;
            while n0 < n {
                let n1 = (n0 + k).min(n);
                u.clear();
                let total: f64 = w.rest_length[n0..n1].iter().sum();
                let mut s = 0.0;
                u.push(0.0);
                for j in n0..n1 {
                    s += w.rest_length[j];
                    u.push(if j + 1 == n1 { 1.0 } else { s / total });
                }
                let w0 = spread.len();
                chord_weights(&u, &mut spread, n0);
                chords.push(Chord {
                    carrier: ci,
                    index,
                    n0,
                    n1,
                    phase: c.phase,
                    share: c.share,
                    core_m: c.core_radius_m,
                    w0,
                    w1: spread.len(),
                });
                n0 = n1;
                index += 1;
            }
            let nodes = w.nodes();
            forces.push([vec![0.0; nodes], vec![0.0; nodes], vec![0.0; nodes]]);
        }
        let nc = chords.len();
        let spare = forces.iter().map(|f| Some(f.clone())).collect();
        let mut near = Vec::new();
        let mut window = NEAR_SEGMENTS;
        for (b, cb) in em.carriers.iter().enumerate() {
            for (a, ca) in em.carriers.iter().enumerate() {
                if a != b && ca.phase == cb.phase {
                    near.push((b, a));
                    let (wa, wb) = (conductors[ca.conductor].wire(), conductors[cb.conductor].wire());
                    let (pa, pb) = (wa.position(wa.nodes() / 2), wb.position(wb.nodes() / 2));
                    let d = ((pa[0] - pb[0]).powi(2) + (pa[1] - pb[1]).powi(2) + (pa[2] - pb[2]).powi(2)).sqrt();
                    let ds = wb.total_rest_length() / wb.segments() as f64;
                    let w = (NEAR_DISTANCES * d / ds).ceil();
                    if w.is_finite() && w > window as f64 {
                        window = (w as usize).min(wb.segments());
                    }
                }
            }
        }
        EmState {
            conductor: em.carriers.iter().map(|c| c.conductor).collect(),
            em,
            chords,
            spread,
            ends: vec![[[0.0; 3]; 2]; nc],
            geom: vec![[[0.0; 6]; 3]; nc],
            geom_prev: vec![[[0.0; 6]; 3]; nc],
            geom_now: vec![[[0.0; 6]; 3]; nc],
            t_geom: 0.0,
            t_prev: 0.0,
            have_geom: false,
            have_prev: false,
            last_refresh: 0,
            forces,
            spare,
            level_flowing: false,
            work_j: 0.0,
            half_added: None,
            intersection: None,
            refreshes: 0,
            near,
            window,
        }
    }

    /// The near field's half-width [segments] (0 sub-conductor pairs: its least value).
    pub fn near_window(&self) -> usize {
        self.window
    }

    /// The load.
    pub fn load(&self) -> &Electromagnetic {
        &self.em
    }

    /// Nodal forces of conductor `c` at the evaluated level [N], if it carries current (zero while none
    /// flows).
    pub fn force_n(&self, conductor: usize) -> Option<&[Vec<f64>; 3]> {
        self.conductor.iter().position(|&c| c == conductor).map(|k| &self.forces[k])
    }

    /// Work of the electromagnetic forces since t = 0 [J] (to the evaluated level).
    pub fn work_j(&self) -> f64 {
        self.work_j
    }

    /// The first intersection of two carriers' chords met, if any.
    pub fn intersection(&self) -> Option<EmIntersection> {
        self.intersection
    }

    /// How many times the geometric factors were evaluated.
    pub fn refreshes(&self) -> u64 {
        self.refreshes
    }

    /// Remove the load's nodal forces from the conductors (the load is replaced or removed).
    pub(crate) fn detach(&mut self, conductors: &mut [Explicit]) {
        for (k, &c) in self.conductor.iter().enumerate() {
            if let Some(f) = conductors[c].nodal_force_slot().take() {
                self.spare[k] = Some(f);
            }
        }
    }

    /// Evaluate the forces of the level at `t_s` (after `steps` steps, the last of `dt_prev_s`) and set
    /// them on the carriers (module docs).
    pub(crate) fn evaluate(&mut self, conductors: &mut [Explicit], t_s: f64, steps: u64, dt_prev_s: f64) {
        if !self.em.current.is_flowing(t_s) {
            if self.level_flowing {
                for f in &mut self.forces {
                    for a in f.iter_mut() {
                        a.fill(0.0);
                    }
                }
                self.detach(conductors);
                self.level_flowing = false;
            }
            // A new flow starts with fresh factors (the geometry moved during the dead time).
            self.have_geom = false;
            self.have_prev = false;
            return;
        }
        let m = self.em.numerics.refresh_steps as u64;
        if !self.have_geom || steps >= self.last_refresh + m {
            self.refresh(conductors, t_s);
            self.last_refresh = steps;
        }
        // The factors at t_n.
        let extrapolate = self.em.numerics.extrapolate && self.have_prev && t_s != self.t_geom;
        let geom: &[Factors] = if extrapolate {
            let s = (t_s - self.t_geom) / (self.t_geom - self.t_prev);
            for ((now, g), p) in self.geom_now.iter_mut().zip(&self.geom).zip(&self.geom_prev) {
                for q in 0..3 {
                    for j in 0..6 {
                        now[q][j] = g[q][j] + s * (g[q][j] - p[q][j]);
                    }
                }
            }
            &self.geom_now
        } else {
            &self.geom
        };
        let i = self.em.current.phase_currents_a(t_s);
        for f in &mut self.forces {
            for a in f.iter_mut() {
                a.fill(0.0);
            }
        }
        for (b, g) in self.chords.iter().zip(geom) {
            let ib = b.share * i[b.phase];
            let mut fm = [0.0; 6];
            for (p, gp) in g.iter().enumerate() {
                let ip = ib * i[p];
                for j in 0..6 {
                    fm[j] += ip * gp[j];
                }
            }
            let out = &mut self.forces[b.carrier];
            for &(node, wf, wm) in &self.spread[b.w0..b.w1] {
                for k in 0..3 {
                    out[k][node] += wf * fm[k] + wm * fm[3 + k];
                }
            }
        }
        self.near_field(conductors, t_s, &i);
        // Into the carriers' node passes.
        for (k, &c) in self.conductor.iter().enumerate() {
            let slot = conductors[c].nodal_force_slot();
            if slot.is_none() {
                *slot = self.spare[k].take().or_else(|| Some(self.forces[k].clone()));
            }
            let dst = slot.as_mut().expect("set above");
            for d in 0..3 {
                dst[d].copy_from_slice(&self.forces[k][d]);
            }
        }
        // The second half of the last drift's work, once per level.
        if steps > 0 && self.half_added != Some(steps) {
            self.work_j += 0.5 * self.power_w(conductors) * dt_prev_s;
        }
        self.half_added = Some(steps);
        self.level_flowing = true;
    }

    /// After the step of length `dt_s` from the evaluated level: the first half of its work.
    pub(crate) fn after_step(&mut self, conductors: &[Explicit], dt_s: f64) {
        if self.level_flowing {
            self.work_j += 0.5 * self.power_w(conductors) * dt_s;
        }
    }

    /// `sum f . v` over the carriers' nodes, with the level's forces and the last half-step velocities
    /// [W].
    fn power_w(&self, conductors: &[Explicit]) -> f64 {
        let mut p = 0.0;
        for (k, &c) in self.conductor.iter().enumerate() {
            let w = conductors[c].wire();
            for d in 0..3 {
                p += self.forces[k][d].iter().zip(&w.v[d]).map(|(f, v)| f * v).sum::<f64>();
            }
        }
        p
    }

    /// The near field: every target segment of a near pair against the source segments within the window
    /// around the one at the same fraction, on the present geometry, with the present currents.
    fn near_field(&mut self, conductors: &[Explicit], t_s: f64, i: &[f64; 3]) {
        for &(b, a) in &self.near {
            let (cb, ca) = (&self.em.carriers[b], &self.em.carriers[a]);
            let (ib, ia) = (cb.share * i[cb.phase], ca.share * i[ca.phase]);
            let (wb, wa) = (conductors[cb.conductor].wire(), conductors[ca.conductor].wire());
            let (nb, na) = (wb.segments(), wa.segments());
            for j in 0..nb {
                let (b0, b1) = (wb.position(j), wb.position(j + 1));
                let centre = (j * na + na / 2) / nb.max(1);
                let lo = centre.saturating_sub(self.window);
                let hi = (centre + self.window + 1).min(na);
                for s in lo..hi {
                    match pair_force(wa.position(s), wa.position(s + 1), ia, b0, b1, ib, cb.core_radius_m) {
                        Ok(f) => {
                            let out = &mut self.forces[b];
                            for k in 0..3 {
                                out[k][j] += f.total_n[k] - f.at_b1_n[k];
                                out[k][j + 1] += f.at_b1_n[k];
                            }
                        }
                        Err(e) => {
                            self.intersection.get_or_insert(meeting(e, t_s, (ca.conductor, s), (cb.conductor, j)));
                        }
                    }
                }
            }
        }
    }

    /// Recompute the geometric factors on the present geometry.
    fn refresh(&mut self, conductors: &[Explicit], t_s: f64) {
        if self.have_geom {
            std::mem::swap(&mut self.geom, &mut self.geom_prev);
            self.t_prev = self.t_geom;
            self.have_prev = true;
        }
        for (e, c) in self.ends.iter_mut().zip(&self.chords) {
            let w = conductors[self.conductor[c.carrier]].wire();
            *e = [w.position(c.n0), w.position(c.n1)];
        }
        for (bi, b) in self.chords.iter().enumerate() {
            let mut g = [[0.0; 6]; 3];
            let [b0, b1] = self.ends[bi];
            for (ai, a) in self.chords.iter().enumerate() {
                if a.carrier == b.carrier && a.index.abs_diff(b.index) <= EXCLUDE {
                    continue;
                }
                if a.carrier != b.carrier && a.phase == b.phase {
                    // A near pair: segment by segment at every level (`near_field`).
                    continue;
                }
                let [a0, a1] = self.ends[ai];
                match pair_force(a0, a1, 1.0, b0, b1, 1.0, b.core_m) {
                    Ok(f) => {
                        let gp = &mut g[a.phase];
                        for k in 0..3 {
                            gp[k] += a.share * f.total_n[k];
                            gp[3 + k] += a.share * f.at_b1_n[k];
                        }
                    }
                    Err(e) => {
                        let (source, target) = ((self.conductor[a.carrier], a.n0), (self.conductor[b.carrier], b.n0));
                        self.intersection.get_or_insert(meeting(e, t_s, source, target));
                    }
                }
            }
            self.geom[bi] = g;
        }
        self.t_geom = t_s;
        self.have_geom = true;
        self.refreshes += 1;
    }
}

#[cfg(test)]
mod tests {
    use super::chord_weights;

    /// The spread keeps the chord's force and first moment: `sum_j w_F = 1`, `sum_j w_M = 0`,
    /// `sum_j u_j w_F = 0`, `sum_j u_j w_M = 1` (so `sum_j f_j = F`, `sum_j u_j f_j = M`), on uneven node
    /// fractions; and a chord of one segment is the pair element's own split, exactly.
    #[test]
    fn spread_keeps_force_and_moment() {
        let u = [0.0, 0.1, 0.35, 0.5, 0.8, 1.0];
        let mut w = Vec::new();
        chord_weights(&u, &mut w, 7);
        assert_eq!(w.iter().map(|x| x.0).collect::<Vec<_>>(), vec![7, 8, 9, 10, 11, 12]);
        let (mut f, mut m, mut uf, mut um) = (0.0, 0.0, 0.0, 0.0);
        for (j, &(_, wf, wm)) in w.iter().enumerate() {
            f += wf;
            m += wm;
            uf += u[j] * wf;
            um += u[j] * wm;
        }
        assert!((f - 1.0).abs() < 1e-14 && m.abs() < 1e-14, "{f} {m}");
        assert!(uf.abs() < 1e-14 && (um - 1.0).abs() < 1e-14, "{uf} {um}");
        let mut one = Vec::new();
        chord_weights(&[0.0, 1.0], &mut one, 3);
        assert_eq!(one, vec![(3, 1.0, -1.0), (4, 0.0, 1.0)]);
    }
}
