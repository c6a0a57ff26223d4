//! Closures of the explicit heat scheme (5.2) at the insulated ends `s = 0` and `s = 1` (zero flux).
//!
//! The interior update (5.2) gives `u_1 .. u_{N-1}` at the new level `j + 1`; a closure supplies `u_0` and
//! `u_N`. Below, `r = tau / h^2` and `f` is the source of (5.1). Only the left end is written; the right end
//! is its mirror image (`0, 1, 2 -> N, N-1, N-2`) in every closure except the literal (5.3).
//!
//! # `ZeroFlux` (conservative; the recommended closure)
//!
//! The ghost node `u_{-1} = u_1` (centred zero flux `(u_1 - u_{-1}) / 2h = 0`) in (5.2) at `i = 0`:
//! ```text
//! u_0^{j+1} = u_0 + 2 r (u_1 - u_0) + tau f_0.
//! ```
//! Equivalently the finite-volume balance of the half cell `[0, h/2]` with no flux through `s = 0`. Summing
//! the whole update with the trapezoidal weights `h/2, h, .., h, h/2` telescopes to zero, so the trapezoidal
//! mean changes only by `tau * trapezoidal mean of f`: without sources it is conserved to rounding and the
//! equalisation temperature is exact. Second order in `h` (the ghost node is a second-order Neumann
//! condition); stable for `r <= 1/2` (the iteration matrix is similar to a symmetric one with spectrum in
//! `[1 - 4r, 1]`).
//!
//! # `LagrangeQuadratic`: option 1 of the paper, re-derived
//!
//! The paper's stated idea: the flux at the end from the quadratic Lagrange polynomial through
//! `(0, u_0), (h, u_1), (2h, u_2)`, whose slope at `s = 0` is `(-3 u_0 + 4 u_1 - u_2) / (2h)` (second order).
//! Zero flux at the new level, with the interior values just computed by (5.2), gives
//! ```text
//! u_0^{j+1} = (4 u_1^{j+1} - u_2^{j+1}) / 3,     u_N^{j+1} = (4 u_{N-1}^{j+1} - u_{N-2}^{j+1}) / 3.
//! ```
//! The end value is an algebraic constraint, not a time step; sources act through the interior nodes.
//! This closure conserves exactly (to rounding) the weighted sum
//! `Q = h [3/2 u_1 + u_2 + .. + u_{N-2} + 3/2 u_{N-1}]` whenever the old level satisfies the constraint (that
//! is after the first step): the interior update changes `sum_{1}^{N-1} u_i` by `(r/3)[(u_{N-1} - u_{N-2}) -
//! (u_2 - u_1)]` and `u_1 / 2 + u_{N-1} / 2` by exactly the opposite. In general a step changes `Q` by
//! `(3 r h / 2) (d_0 + d_N)`, `d_0 = u_0 - (4 u_1 - u_2)/3` the defect of the old level. `Q` differs from the
//! trapezoidal mean by `(h/2)[(u_0 - u_1) + (u_N - u_{N-1})]`, which vanishes on a uniform field: the
//! equalisation temperature is `Q` after the first step, which equals the trapezoidal mean of initial data
//! that are flat at the ends (as in the paper's test).
//!
//! # `LagrangeQuadraticAsPrinted`: the literal (5.3)
//!
//! Rearranged, the printed update of the left end is
//! `(3 u_0^{j+1} - 4 u_1^j + u_2^j) / (2 tau) = -(u_0^j - 2 u_1^j + u_2^j) / h^2 + 3 f`, and of the right end
//! `(3 u_N^{j+1} - 4 u_{N-1}^j + u_{N-2}^j) / (2 tau) = +(u_N^j - 2 u_{N-1}^j + u_{N-2}^j) / h^2 + 3 f`, i.e.
//! ```text
//! u_0^{j+1} = (4 u_1^j - u_2^j)/3 - (2 tau / 3) u_ss,0 + 2 tau f_0,
//! u_N^{j+1} = (4 u_{N-1}^j - u_{N-2}^j)/3 + (2 tau / 3) u_ss,N + 2 tau f_N,
//! ```
//! with `u_ss` the one-sided second difference: the Lagrange slope stencil is divided by `2 tau` instead of
//! `2 h` and set equal to `-u_ss` at one end and `+u_ss` at the other, both at the old level. It is the
//! zero-flux value of the old level plus a perturbation of opposite sign at the two ends, so it is not
//! symmetric and not conservative: in the paper's test it equalises above the exact value by about
//! `r h (uL - uR)` (first order in `h`; derived in the tests from the per-step change of the sum `Q` conserved
//! by `LagrangeQuadratic`), and it is unstable for larger steps: measured at N = 50, stable at `r = 0.39`,
//! divergent at `r = 0.4`, and the paper's `alpha = 1` (`r = 1/2`) diverges within `t = 0.02`. The source term is kept as printed (`2 tau f`).
//!
//! # `Linear`: option 2 of the paper, (5.4) with its inconsistent coefficient corrected
//!
//! Printed: `u_0^{j+1} = (1 + 2r) u_0 + r (u_2 - 2 u_1) + tau f_0`. Its coefficients sum to `1 + r`, not 1,
//! so a uniform field is not a solution: the end value grows by the factor `1 + r` per step on a uniform
//! field (a source `u_0 / h^2` in the continuous limit), and the scheme diverges for every `r > 0`. The one
//! coefficient change that makes it consistent is `1 + 2r -> 1 + r`:
//! ```text
//! u_0^{j+1} = u_0 + r (u_0 - 2 u_1 + u_2) + tau f_0,
//! ```
//! the heat equation at the end node with `u_ss(0)` taken as the one-sided three-point second difference,
//! i.e. `u_ss` extrapolated linearly (it is centred at `s = h`), or equally (5.2) with the ghost value
//! `u_{-1} = 3 u_0 - 3 u_1 + u_2` extrapolated from the quadratic through the first three nodes. This closure
//! never uses the zero-flux condition: heat crosses the ends during the transient, so the equalisation
//! temperature drifts. Per step the trapezoidal mean changes by
//! `(h/2)(du_0 + du_N) + tau [(u_0 - u_1) + (u_N - u_{N-1})] / h`: to leading order the closure conserves
//! `h (u_1 + .. + u_{N-1})`, leaving out the end nodes' half cells, and the drift is about
//! `(h/2)` times the total change of the two end temperatures: first order in `h`, nearly independent of
//! `r`. For data odd about `s = 1/2` (the paper's two halves) the two ends cancel and the exact value is
//! reached.
//!
//! # `LinearAsPrinted`: the literal (5.4)
//!
//! Kept only to show that, as printed, option 2 diverges (see above).

/// How the insulated ends of the rod are closed; see the module documentation for the derivations.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum HeatBoundary {
    /// Paper's option 1 re-derived: zero Lagrange-quadratic slope at the new level,
    /// `u_0 = (4 u_1 - u_2) / 3` (conserves a weighted sum, not the trapezoidal mean; second order).
    LagrangeQuadratic,
    /// Paper's option 2 (5.4) with the coefficient `1 + 2r` corrected to `1 + r`: the end node follows the
    /// heat equation with the one-sided second difference (not conservative; drift first order in `h`).
    Linear,
    /// Ghost node `u_{-1} = u_1`: conserves the trapezoidal mean to rounding; second order. Recommended.
    ZeroFlux,
    /// The literal printed (5.3) (asymmetric, non-conservative, unstable at `r = 0.4` and above for N = 50).
    LagrangeQuadraticAsPrinted,
    /// The literal printed (5.4) (inconsistent; diverges for every step).
    LinearAsPrinted,
}

impl HeatBoundary {
    /// Sets `new[0]` and `new[N]` from the old level `old` and the interior of the new level `new[1..N]`.
    /// `r = dt / h^2`; `source` is `f` at the old level (nodal, `N + 1` values) or `None` for `f = 0`.
    pub(crate) fn close(self, old: &[f64], new: &mut [f64], r: f64, dt: f64, source: Option<&[f64]>) {
        let n = old.len() - 1;
        let (f0, fn_) = source.map_or((0.0, 0.0), |f| (f[0], f[n]));
        match self {
            HeatBoundary::ZeroFlux => {
                new[0] = old[0] + 2.0 * r * (old[1] - old[0]) + dt * f0;
                new[n] = old[n] + 2.0 * r * (old[n - 1] - old[n]) + dt * fn_;
            }
            HeatBoundary::LagrangeQuadratic => {
                new[0] = (4.0 * new[1] - new[2]) / 3.0;
                new[n] = (4.0 * new[n - 1] - new[n - 2]) / 3.0;
            }
            HeatBoundary::Linear => {
                new[0] = old[0] + r * (old[0] - 2.0 * old[1] + old[2]) + dt * f0;
                new[n] = old[n] + r * (old[n] - 2.0 * old[n - 1] + old[n - 2]) + dt * fn_;
            }
            HeatBoundary::LagrangeQuadraticAsPrinted => {
                new[0] = -2.0 * r / 3.0 * old[0] + 4.0 / 3.0 * (1.0 + r) * old[1] - (1.0 + 2.0 * r) / 3.0 * old[2]
                    + 2.0 * dt * f0;
                new[n] = 2.0 * r / 3.0 * old[n] + 4.0 / 3.0 * (1.0 - r) * old[n - 1]
                    - (1.0 - 2.0 * r) / 3.0 * old[n - 2]
                    + 2.0 * dt * fn_;
            }
            HeatBoundary::LinearAsPrinted => {
                new[0] = (1.0 + 2.0 * r) * old[0] + r * (old[2] - 2.0 * old[1]) + dt * f0;
                new[n] = (1.0 + 2.0 * r) * old[n] + r * (old[n - 2] - 2.0 * old[n - 1]) + dt * fn_;
            }
        }
    }
}
