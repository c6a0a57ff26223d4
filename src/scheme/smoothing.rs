//! Velocity smoothing, eq. (3.3):
//!
//! ```text
//! vbar_i = v_i + b (v_{i+1} - 2 v_i + v_{i-1}),        b = beta / ds^2 (the per-step coefficient),
//! ```
//!
//! applied to every free node after the velocity update of (3.1); the smoothed velocity *replaces* `v`
//! for the position update (3.6) and for the next step (the "damping" reading of docs/paper_notes.md). At a free
//! end (after a break) the ghost node of (3.5) copies the end velocity, so the difference across a
//! broken segment is zero; supports have `v = 0`. Stable for `0 <= b <= 1/4` (the explicit diffusion
//! limit). Per unit time this is a numerical viscosity of about `b ds^2 / dt`, which scales like `ds` at a
//! fixed Courant number: transients computed with it converge at first order (docs/paper_notes.md).
//!
//! Stencil over the padded difference array `D_k = intact_{k-1} (v_k - v_{k-1})`, `k = 1..=N`,
//! `D_0 = D_{N+1} = 0`: `vbar_i = v_i + b free_i (D_{i+1} - D_i)`.

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
/// `diff` holds the differences of [`differences`]. The explicit kernel fuses this with the drift (3.6).
#[inline(always)]
pub fn smoothed(v: f64, b_free: f64, diff: &[f64], i: usize) -> f64 {
    v + b_free * (diff[i + 1] - diff[i])
}

/// Apply (3.3) to one velocity component `v` (length `N + 1`) with coefficient `b`, using `diff`
/// (length `N + 2`) as scratch. `intact` (length `N`) marks unbroken segments, `free` (length `N + 1`)
/// free nodes. (The kernel uses the two halves [`differences`] and [`smoothed`] directly.)
pub fn smooth(v: &mut [f64], diff: &mut [f64], intact: &[f64], free: &[f64], b: f64) {
    let n = intact.len();
    differences(v, diff, intact);
    let diff = &diff[..n + 2];
    for (i, (vi, f)) in v[..n + 1].iter_mut().zip(&free[..n + 1]).enumerate() {
        *vi = smoothed(*vi, b * f, diff, i);
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
        smooth(&mut v, &mut d, &intact, &free, 0.02);
        for i in 1..5 {
            let e = orig[i] + 0.02 * (orig[i + 1] - 2.0 * orig[i] + orig[i - 1]);
            assert!((v[i] - e).abs() < 1e-15);
        }
        assert_eq!((v[0], v[5]), (0.0, 0.0));
        // Break segment 2 (between nodes 2 and 3): ghost copies, so node 2 sees v_3 := v_2.
        let mut v = orig.clone();
        intact[2] = 0.0;
        smooth(&mut v, &mut d, &intact, &free, 0.02);
        let e2 = orig[2] + 0.02 * (orig[2] - 2.0 * orig[2] + orig[1]);
        let e3 = orig[3] + 0.02 * (orig[4] - 2.0 * orig[3] + orig[3]);
        assert!((v[2] - e2).abs() < 1e-15 && (v[3] - e3).abs() < 1e-15);
    }
}
