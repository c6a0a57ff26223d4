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
use crate::wire::Wire;

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

/// Whether the AVX2 copy of [`ContactState::evaluate`] may run: the processor reports AVX2 and
/// `OHL_NO_AVX2` is not set (read once).
#[cfg(target_arch = "x86_64")]
fn avx2() -> bool {
    static AVX2: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    *AVX2.get_or_init(super::avx2_available)
}

/// The walk to the segment of `wt` nearest to the point `x` from segment `hint`: step to the neighbouring
/// segment while it is closer (`(distance^2, u)` of [`point_segment`], the pair element's closest points
/// with `x` as a segment of zero length). The first step's three segments `j - 1, j, j + 1` are computed
/// side by side ([`three_segments`], the same operations per lane) where all three exist and `x` is
/// finite, and compared in the walk's order (`j - 1`, then `j + 1` against the best so far); further steps
/// (rare: the segment found at the last level is nearly always still the nearest) one at a time.
#[inline(always)]
fn nearest_segment(x: [f64; 3], wt: &Wire, hint: usize) -> (usize, (f64, f64)) {
    let st = wt.segments();
    let seg = |j: usize| -> (f64, f64) { point_segment(x, wt.position(j), wt.position(j + 1)) };
    let mut j = hint.min(st - 1);
    let mut best;
    let finite = x[0].is_finite() && x[1].is_finite() && x[2].is_finite();
    if finite && j >= 1 && j + 1 < st {
        let three = three_segments(x, wt, j);
        best = three[1];
        let start = j;
        if three[0].0 < best.0 {
            best = three[0];
            j = start - 1;
        }
        if three[2].0 < best.0 {
            best = three[2];
            j = start + 1;
        }
        if j == start {
            return (j, best);
        }
    } else {
        best = seg(j);
    }
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
            return (j, best);
        }
    }
}

/// [`point_segment`] of the finite point `x` to the segments `j - 1`, `j`, `j + 1` of `w` (`1 <= j`,
/// `j + 2 <= N`), lane by lane: the nodes `j - 1 .. j + 2` are contiguous in each coordinate.
#[inline(always)]
fn three_segments(x: [f64; 3], w: &Wire, j: usize) -> [(f64, f64); 3] {
    const L: usize = 4;
    let (mut q0, mut q1) = ([[0.0; L]; 3], [[0.0; L]; 3]);
    for k in 0..3 {
        let n: &[f64; 4] = w.x[k][j - 1..j + 3].try_into().expect("four nodes");
        // lanes: segments j - 1, j, j + 1 and j + 1 again (unused)
        q0[k] = [n[0], n[1], n[2], n[2]];
        q1[k] = [n[1], n[2], n[3], n[3]];
    }
    let (mut d2, mut u) = ([0.0; L], [0.0; L]);
    for l in 0..L {
        let dq = [q1[0][l] - q0[0][l], q1[1][l] - q0[1][l], q1[2][l] - q0[2][l]];
        let r = [x[0] - q0[0][l], x[1] - q0[1][l], x[2] - q0[2][l]];
        let e = dq[0] * dq[0] + dq[1] * dq[1] + dq[2] * dq[2];
        let f = dq[0] * r[0] + dq[1] * r[1] + dq[2] * r[2];
        let ul = if e <= 0.0 { 0.0 } else { (f / e).clamp(0.0, 1.0) };
        let g = [x[0] - (q0[0][l] + ul * dq[0]), x[1] - (q0[1][l] + ul * dq[1]), x[2] - (q0[2][l] + ul * dq[2])];
        d2[l] = g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
        u[l] = ul;
    }
    [(d2[0], u[0]), (d2[1], u[1]), (d2[2], u[2])]
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
        #[cfg(target_arch = "x86_64")]
        if avx2() {
            // SAFETY: only where the processor reports AVX2 (`avx2`).
            return unsafe { self.evaluate_avx2(conductors, t_s, points) };
        }
        self.evaluate_lanes(conductors, t_s, points)
    }

    /// [`ContactState::evaluate_lanes`] compiled for AVX2.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    fn evaluate_avx2(&mut self, conductors: &[Explicit], t_s: f64, points: &mut [Vec<(usize, [f64; 3])>]) {
        self.evaluate_lanes(conductors, t_s, points)
    }

    /// [`ContactState::evaluate`]'s body.
    #[inline(always)]
    fn evaluate_lanes(&mut self, conductors: &[Explicit], t_s: f64, points: &mut [Vec<(usize, [f64; 3])>]) {
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
                    let (j, best) = nearest_segment(x, wt, *hint);
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::element::tension::LawKind;
    use crate::wire::Conductor;

    /// The walk [`nearest_segment`] replaced: every candidate one at a time.
    fn walk_one_at_a_time(x: [f64; 3], wt: &Wire, hint: usize) -> (usize, (f64, f64)) {
        let st = wt.segments();
        let seg = |j: usize| -> (f64, f64) { point_segment(x, wt.position(j), wt.position(j + 1)) };
        let mut j = hint.min(st - 1);
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
                return (j, best);
            }
        }
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    fn nearest_segment_avx2(x: [f64; 3], wt: &Wire, hint: usize) -> (usize, (f64, f64)) {
        nearest_segment(x, wt, hint)
    }

    /// The side-by-side first step gives the walk's segment and the bits of its distance and fraction,
    /// in the baseline and the AVX2 copy (a NaN as a NaN): wavy conductors of 2 to 40 segments (with repeated nodes, and
    /// an infinite or NaN coordinate in some), points near and far (and non-finite), every hint.
    #[test]
    fn nearest_segment_is_the_walk_bit_for_bit() {
        let mut rnd = crate::test_rng::symmetric(0x2545_f491_4f6c_dd1d_u64);
        let c = Conductor { axial_stiffness_n: 1e6, internal_friction_n_s: 0.0, law: LawKind::TensionOnly };
        let mut compared = 0;
        for case in 0..400 {
            let n = 2 + case % 39;
            let wave = 3.0 * rnd();
            let mut xs = [0, 1, 2].map(|_| vec![0.0; n + 1]);
            for i in 0..=n {
                let s = i as f64 / n as f64;
                xs[0][i] = wave * (7.0 * s).sin() + 0.3 * rnd();
                xs[1][i] = 100.0 * s + 2.0 * rnd();
                xs[2][i] = 10.0 - 4.0 * s * (1.0 - s) + 0.3 * rnd();
            }
            if case % 7 == 3 {
                let i = case % n;
                for k in 0..3 {
                    xs[k][i + 1] = xs[k][i];
                }
            }
            if case % 11 == 5 {
                xs[case % 3][case % (n + 1)] = [f64::INFINITY, f64::NAN][case % 2];
            }
            let w = Wire::new(c, xs, vec![100.0 / n as f64; n], 1.0);
            for p in 0..40 {
                let mut x = [3.0 * rnd(), 50.0 + 60.0 * rnd(), 10.0 + 3.0 * rnd()];
                if p == 7 {
                    x[case % 3] = [f64::NAN, f64::NEG_INFINITY][case % 2];
                }
                for hint in [0, 1, n / 2, n.saturating_sub(2), n - 1, n, n + 5] {
                    let want = walk_one_at_a_time(x, &w, hint);
                    // A NaN's sign and payload aside (IEEE 754 leaves them open: two compilations of
                    // the same operations may differ there; every output writes a NaN as NaN).
                    let b = |v: f64| if v.is_nan() { f64::NAN.to_bits() } else { v.to_bits() };
                    let bits = |(j, (d2, u)): (usize, (f64, f64))| (j, b(d2), b(u));
                    assert_eq!(bits(nearest_segment(x, &w, hint)), bits(want), "case {case}, point {p}, hint {hint}");
                    #[cfg(target_arch = "x86_64")]
                    if std::is_x86_feature_detected!("avx2") {
                        // SAFETY: the processor reports AVX2.
                        let got = unsafe { nearest_segment_avx2(x, &w, hint) };
                        assert_eq!(bits(got), bits(want), "case {case}, point {p}, hint {hint} (AVX2)");
                    }
                    compared += 1;
                }
            }
        }
        assert_eq!(compared, 400 * 40 * 7);
    }
}
