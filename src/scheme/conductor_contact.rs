//! Contact between conductors in the explicit line scheme: the penalty of [`crate::line::contact`] at each
//! time level, from the positions `x^n` and the half-step velocities `v^{n-1/2}` (as the links'
//! dampers), added to the conductors' point forces.
//!
//! Order. The spring is second order in `w_c dt` (an undamped clash keeps its energy to `O((w_c dt)^2)`);
//! with damping the clash is first order: the dashpot's force jumps from 0 to `c' v` at the onset of
//! contact, which falls anywhere within a step (a linear spring-dashpot's force is discontinuous there).
//! Reading the closing speed extrapolated to the level instead of at the half step was tried and changes
//! nothing measurable (tests/conductor_contact.rs).
//!
//! For every pair `(A, B)` and each direction (contact points of `A` against segments of `B`, then the
//! reverse), a point's nearest segment is found by a walk from the one found at the previous level (at the first, the
//! segment at the same fraction of the conductor): step to the neighbouring segment while it is closer.
//! Conductors that run side by side keep their nearest segment within a step or two, so a level costs
//! `O(N)` per pair, not `O(N^2)`. The walk finds a local minimum of the distance; for a conductor that
//! folds back on itself it can miss a nearer segment (module doc of [`crate::line::contact`]).

use super::explicit::Explicit;
use crate::element::pair::point_segment;
use crate::line::contact::ConductorContact;

/// The first contact of a run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FirstContact {
    /// time of the level [s]
    pub time_s: f64,
    /// the two conductors (the contact point's, the segment's)
    pub conductors: (usize, usize),
    /// the segment of the first that touched
    pub segment: usize,
}

/// The state of the contact during a run.
#[derive(Clone, Debug)]
pub struct ContactState {
    spec: ConductorContact,
    /// per pair: `k'` [N/m^2] and `c'` [N s/m^2], both already halved (each direction carries half)
    coeff: Vec<(f64, f64)>,
    /// per pair and direction, per contact point: its nearest segment at the last level
    hint: Vec<[Vec<usize>; 2]>,
    /// elastic energy of the penalty springs at the evaluated level [J]
    energy_j: f64,
    /// contact points in contact at the evaluated level
    touching: usize,
    first: Option<FirstContact>,
}

/// Contact points per segment: the midpoints of its thirds, each carrying a third of its rest length.
const SAMPLES: usize = 3;
const SAMPLE_AT: [f64; SAMPLES] = [1.0 / 6.0, 0.5, 5.0 / 6.0];

/// Linear density of a conductor: its mass over its rest length [kg/m].
fn linear_density(w: &crate::wire::Wire) -> f64 {
    let m: f64 = w.segment_mass.iter().sum();
    let l: f64 = w.rest_length.iter().sum();
    m / l
}

/// The reduced linear density `mu_A mu_B / (mu_A + mu_B)` of conductors `a` and `b` [kg/m].
fn reduced_density(conductors: &[Explicit], a: usize, b: usize) -> f64 {
    let (ma, mb) = (linear_density(conductors[a].wire()), linear_density(conductors[b].wire()));
    ma * mb / (ma + mb)
}

/// The largest step [s] at which a contact of given stiffness `k'` keeps `w_c dt <= stiffness_dt`, `w_c =
/// sqrt(k' / mu)` over its pairs; `None` for a penalty scaled to the step, or without pairs.
pub fn contact_step_limit_s(spec: &ConductorContact, conductors: &[Explicit]) -> Option<f64> {
    let k = spec.stiffness_n_per_m2?;
    spec.pairs
        .iter()
        .map(|p| spec.stiffness_dt / (k / reduced_density(conductors, p.a, p.b)).sqrt())
        .min_by(f64::total_cmp)
}

impl ContactState {
    /// The state for `spec` on `conductors` with the line's nominal step `dt` [s]. The spec is checked by
    /// the caller ([`ConductorContact::check`]).
    pub fn new(spec: ConductorContact, conductors: &[Explicit], dt: f64) -> Self {
        let zeta = spec.damping_ratio();
        let w_c = spec.stiffness_dt / dt;
        let coeff = spec
            .pairs
            .iter()
            .map(|p| {
                let mu = reduced_density(conductors, p.a, p.b);
                let k = spec.stiffness_n_per_m2.unwrap_or(mu * w_c * w_c);
                (0.5 * k, 0.5 * 2.0 * zeta * (k * mu).sqrt())
            })
            .collect();
        let hint: Vec<[Vec<usize>; 2]> = spec
            .pairs
            .iter()
            .map(|p| {
                let (wa, wb) = (conductors[p.a].wire(), conductors[p.b].wire());
                let guess = |from: &crate::wire::Wire, to: &crate::wire::Wire| -> Vec<usize> {
                    let (sf, st) = (from.segments(), to.segments());
                    (0..sf * SAMPLES).map(|h| ((h / SAMPLES * st) / sf.max(1)).min(st.saturating_sub(1))).collect()
                };
                [guess(wa, wb), guess(wb, wa)]
            })
            .collect();
        ContactState { spec, coeff, hint, energy_j: 0.0, touching: 0, first: None }
    }

    /// The contact as given.
    pub fn spec(&self) -> &ConductorContact {
        &self.spec
    }

    /// Elastic energy of the penalty at the evaluated level [J].
    pub fn energy_j(&self) -> f64 {
        self.energy_j
    }

    /// Contact points in contact at the evaluated level (3 per segment and direction).
    pub fn touching(&self) -> usize {
        self.touching
    }

    /// The first contact of the run, if any.
    pub fn first(&self) -> Option<FirstContact> {
        self.first
    }

    /// Evaluate the contact forces of the level at time `t_s` [s] and push them onto `points` (per
    /// conductor, `(node, F)` [N]).
    pub fn evaluate(&mut self, conductors: &[Explicit], t_s: f64, points: &mut [Vec<(usize, [f64; 3])>]) {
        self.energy_j = 0.0;
        self.touching = 0;
        for (k, p) in self.spec.pairs.iter().enumerate() {
            let (kk, cc) = self.coeff[k];
            for dir in 0..2 {
                let (from, to) = if dir == 0 { (p.a, p.b) } else { (p.b, p.a) };
                let (wf, wt) = (conductors[from].wire(), conductors[to].wire());
                let hints = &mut self.hint[k][dir];
                let st = wt.segments();
                if st == 0 {
                    continue;
                }
                for (h, hint) in hints.iter_mut().enumerate() {
                    // Sample point h: segment i of `from` at the fraction s (the midpoints of its thirds).
                    let (i, s) = (h / SAMPLES, SAMPLE_AT[h % SAMPLES]);
                    if wf.intact[i] == 0.0 {
                        continue;
                    }
                    let (p0, p1) = (wf.position(i), wf.position(i + 1));
                    let x = [0, 1, 2].map(|c| p0[c] + s * (p1[c] - p0[c]));
                    // The nearest point of segment j to x: the pair element's closest points with x as a
                    // segment of zero length (`point_segment`: the same bits, without the zero segment's
                    // arithmetic).
                    let seg = |j: usize| -> (f64, f64) { point_segment(x, wt.position(j), wt.position(j + 1)) };
                    // Walk to the nearest segment from the last level's.
                    let mut j = (*hint).min(st - 1);
                    let mut best = seg(j);
                    loop {
                        let mut moved = false;
                        for c in [j.wrapping_sub(1), j + 1] {
                            if c < st {
                                let s = seg(c);
                                if s.0 < best.0 {
                                    best = s;
                                    j = c;
                                    moved = true;
                                }
                            }
                        }
                        if !moved {
                            break;
                        }
                    }
                    *hint = j;
                    let (d2, u) = best;
                    if d2 >= p.gap_m * p.gap_m || d2 <= 0.0 || wt.intact[j] == 0.0 {
                        continue;
                    }
                    let d = d2.sqrt();
                    let (q0, q1) = (wt.position(j), wt.position(j + 1));
                    let q = [0, 1, 2].map(|c| q0[c] + u * (q1[c] - q0[c]));
                    let nrm = [0, 1, 2].map(|c| (x[c] - q[c]) / d);
                    let vx = [0, 1, 2].map(|c| (1.0 - s) * wf.v[c][i] + s * wf.v[c][i + 1]);
                    let vq = [0, 1, 2].map(|c| (1.0 - u) * wt.v[c][j] + u * wt.v[c][j + 1]);
                    let closing = (0..3).map(|c| (vx[c] - vq[c]) * nrm[c]).sum::<f64>();
                    let (li, delta) = (wf.rest_length[i] / SAMPLES as f64, p.gap_m - d);
                    let f = (kk * li * delta - cc * li * closing).max(0.0);
                    self.energy_j += 0.5 * kk * li * delta * delta;
                    self.touching += 1;
                    if self.first.is_none() {
                        self.first = Some(FirstContact { time_s: t_s, conductors: (from, to), segment: i });
                    }
                    let g = nrm.map(|c| f * c);
                    points[from].push((i, [0, 1, 2].map(|c| (1.0 - s) * g[c])));
                    points[from].push((i + 1, [0, 1, 2].map(|c| s * g[c])));
                    points[to].push((j, [0, 1, 2].map(|c| -(1.0 - u) * g[c])));
                    points[to].push((j + 1, [0, 1, 2].map(|c| -u * g[c])));
                }
            }
        }
    }
}
