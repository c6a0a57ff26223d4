//! Velocity smoothing, eq. (3.3), in its mass-weighted (momentum-conserving) form:
//!
//! ```text
//! vbar_i = v_i + b [ w+_i (v_{i+1} - v_i) - w-_i (v_i - v_{i-1}) ],    w-_i = m_{i-1/2} / m_i,
//!                                                                       w+_i = m_{i+1/2} / m_i,
//! ```
//!
//! with `b = beta / ds^2` the per-step coefficient, `m_{i+1/2}` the segment masses and `m_i` the lumped
//! node mass (half of each adjacent segment plus any point mass). On a uniform wire `m_i = m_{i+1/2}`,
//! both weights are 1 and this *is* the paper's `vbar_i = v_i + b (v_{i+1} - 2 v_i + v_{i-1})`; the
//! kernel then takes that unweighted path and reproduces the paper's scheme bit for bit. Where masses
//! differ (an insulator clamp of 100 kg among 2.6 kg conductor nodes, an iced range, spans of different
//! conductors) the weighted form is the one that conserves momentum: the exchange across segment
//! `i+1/2` is `b m_{i+1/2} (v_{i+1} - v_i)`, given to one node and taken from the other, so
//! `sum m_i vbar_i = sum m_i v_i` over free nodes (a support absorbs what crosses into it), and the
//! kinetic energy can only decrease. The unweighted form changed a heavy clamp's velocity as fast as a
//! conductor node's, a force from nowhere, which made the broken-conductor peak of a section depend on
//! the grid (docs/architecture.md, "Velocity smoothing on a section").
//!
//! The smoothed velocity *replaces* `v` for the position update (3.6) and for the next step (the
//! "damping" reading of docs/paper_notes.md). At a free end (after a break) the ghost node of (3.5)
//! copies the end velocity, so the difference across a broken segment is zero; supports have `v = 0`.
//! Stable for `0 <= b <= 1/4` (the explicit diffusion limit: by Gershgorin the weighted operator's
//! eigenvalues are at most `2 (w-_i + w+_i) <= 4`, since `m_i >= (m_{i-1/2} + m_{i+1/2}) / 2`). Per unit
//! time this is a numerical viscosity of about `b ds^2 / dt`, which scales like `ds` at a fixed Courant
//! number: transients computed with it converge at first order (docs/paper_notes.md).
//!
//! Stencil over the padded difference array `D_k = intact_{k-1} (v_k - v_{k-1})`, `k = 1..=N`,
//! `D_0 = D_{N+1} = 0`: `vbar_i = v_i + b free_i (w+_i D_{i+1} - w-_i D_i)`.

/// First half of (3.3): the padded differences `diff[k] = intact[k-1] (v[k] - v[k-1])`, `k = 1..=N`, and
/// `diff[0] = diff[N+1] = 0`, for one velocity component `v` (length `N + 1`); `diff` has length `N + 2`.
#[inline(always)]
pub fn differences(v: &[f64], diff: &mut [f64], intact: &[f64]) {
    let n = intact.len();
    let v = &v[..n + 1];
    let diff = &mut diff[..n + 2];
    diff[0] = 0.0;
    diff[n + 1] = 0.0;
    let (lo, hi) = (&v[..n], &v[1..n + 1]);
    let d = &mut diff[1..n + 1];
    for j in 0..n {
        d[j] = intact[j] * (hi[j] - lo[j]);
    }
}

/// Second half of (3.3) at node `i`: `v_i + (b free_i) (D_{i+1} - D_i)`, where `b_free = b free_i` and
/// `below = D_i`, `above = D_{i+1}` are the differences of [`differences`] on either side. The explicit
/// kernel fuses this with the drift (3.6).
#[inline(always)]
pub fn smoothed(v: f64, b_free: f64, below: f64, above: f64) -> f64 {
    v + b_free * (above - below)
}

/// Second half of the mass-weighted (3.3) at node `i`: `v_i + (b free_i) (w+_i D_{i+1} - w-_i D_i)`,
/// with `below = D_i`, `above = D_{i+1}`, `left = w-_i` and `right = w+_i`
/// ([`crate::wire::Wire::smoothing_weight`]).
#[inline(always)]
pub fn smoothed_weighted(v: f64, b_free: f64, below: f64, above: f64, left: f64, right: f64) -> f64 {
    v + b_free * (right * above - left * below)
}

/// Apply the mass-weighted (3.3) to one velocity component `v` (length `N + 1`) with coefficient `b`,
/// using `diff` (length `N + 2`) as scratch. `intact` (length `N`) marks unbroken segments, `free`
/// (length `N + 1`) free nodes, `weight` the node weights `[w-, w+]` (each length `N + 1`). (The kernel
/// uses the halves [`differences`], [`smoothed`] and [`smoothed_weighted`] directly.)
pub fn smooth(v: &mut [f64], diff: &mut [f64], intact: &[f64], free: &[f64], weight: &[Vec<f64>; 2], b: f64) {
    let n = intact.len();
    differences(v, diff, intact);
    let diff = &diff[..n + 2];
    for (i, (vi, f)) in v[..n + 1].iter_mut().zip(&free[..n + 1]).enumerate() {
        *vi = smoothed_weighted(*vi, b * f, diff[i], diff[i + 1], weight[0][i], weight[1][i]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matches_the_three_point_formula_and_honours_breaks() {
        let mut v = vec![0.0, 1.0, 4.0, 9.0, 16.0, 0.0];
        let free = [0.0, 1.0, 1.0, 1.0, 1.0, 0.0];
        let mut intact = [1.0; 5];
        let mut d = vec![0.0; 7];
        let orig = v.clone();
        let ones = [vec![1.0; 6], vec![1.0; 6]];
        smooth(&mut v, &mut d, &intact, &free, &ones, 0.02);
        for i in 1..5 {
            let e = orig[i] + 0.02 * (orig[i + 1] - 2.0 * orig[i] + orig[i - 1]);
            assert!((v[i] - e).abs() < 1e-15);
        }
        assert_eq!((v[0], v[5]), (0.0, 0.0));
        // Break segment 2 (between nodes 2 and 3): ghost copies, so node 2 sees v_3 := v_2.
        let mut v = orig.clone();
        intact[2] = 0.0;
        smooth(&mut v, &mut d, &intact, &free, &ones, 0.02);
        let e2 = orig[2] + 0.02 * (orig[2] - 2.0 * orig[2] + orig[1]);
        let e3 = orig[3] + 0.02 * (orig[4] - 2.0 * orig[3] + orig[3]);
        assert!((v[2] - e2).abs() < 1e-15 && (v[3] - e3).abs() < 1e-15);
    }

    /// The weighted form conserves momentum `sum m_i v_i` over free nodes when no support is adjacent,
    /// loses kinetic energy, and leaves a heavy node's velocity nearly unchanged.
    #[test]
    fn weighted_form_conserves_momentum_and_damps_energy() {
        // Six segments with masses 1..6 kg; a 100 kg point mass at node 3; ends free (a piece in flight).
        let seg = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0];
        let n = seg.len();
        let point = [0.0, 0.0, 0.0, 100.0, 0.0, 0.0, 0.0];
        let m: Vec<f64> = (0..=n)
            .map(|i| 0.5 * (if i > 0 { seg[i - 1] } else { 0.0 } + if i < n { seg[i] } else { 0.0 }) + point[i])
            .collect();
        let weight = [
            (0..=n).map(|i| if i > 0 { seg[i - 1] / m[i] } else { 0.0 }).collect::<Vec<_>>(),
            (0..=n).map(|i| if i < n { seg[i] / m[i] } else { 0.0 }).collect::<Vec<_>>(),
        ];
        let v0 = vec![0.3, -1.0, 2.0, 0.5, -0.7, 1.1, 0.0];
        let mut v = v0.clone();
        let mut d = vec![0.0; n + 2];
        smooth(&mut v, &mut d, &[1.0; 6], &[1.0; 7], &weight, 0.25);
        let p = |v: &[f64]| v.iter().zip(&m).map(|(v, m)| v * m).sum::<f64>();
        let e = |v: &[f64]| v.iter().zip(&m).map(|(v, m)| 0.5 * m * v * v).sum::<f64>();
        // Rounding: a sum of 7 terms of size <= 100 kg m/s.
        assert!((p(&v) - p(&v0)).abs() < 1e-13, "momentum {} -> {}", p(&v0), p(&v));
        assert!(e(&v) < e(&v0));
        // The clamp (m_3 = 103.5 kg) moves by b (m_{7/2} (v_4 - v_3) - m_{5/2} (v_3 - v_2)) / m_3.
        let clamp = v0[3] + 0.25 * (4.0 * (v0[4] - v0[3]) - 3.0 * (v0[3] - v0[2])) / 103.5;
        assert!((v[3] - clamp).abs() < 1e-15 && (v[3] - v0[3]).abs() < 1e-3);
    }
}
