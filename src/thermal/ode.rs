//! The classical fourth-order Runge-Kutta step for the small ODE systems of the thermal models (the
//! conductor's heat balance `m c dT/dt = q_J + q_S - q_c - q_r`, the de-icing of an ice shell):
//!
//! ```text
//! k1 = f(t, y),  k2 = f(t + h/2, y + h k1/2),  k3 = f(t + h/2, y + h k2/2),  k4 = f(t + h, y + h k3),
//! y(t + h) = y + h (k1 + 2 k2 + 2 k3 + k4) / 6,
//! ```
//!
//! fourth order in `h` for a smooth right-hand side (the transient study observes it). A right-hand side
//! with a kink inside the step (a current step, the start of melting) lowers the order unless the caller
//! lands a step on the kink, which the thermal solvers do.
//!
//! The step is also kept inside RK4's stability interval ([`stable_step`]): linearised about the current
//! state, `dy/dt = lambda (y - y_eq)` with `lambda = df/dy < 0`, one step multiplies `y - y_eq` by
//! `R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24`, `z = h lambda`, and `|R(z)| <= 1` on the real axis only for
//! `-2.785 <= z <= 0` (the classical method's stability interval). A step `h <= 2 / |lambda|` keeps
//! `R(-2) = 1/3` positive (no overshoot). Without the cap a step beyond the interval amplifies rounding at
//! every step until the state is NaN (a fuzzer finding, `tests/fuzz_scenarios.rs`).

/// One RK4 step of `dy/dt = f(t, y)` from `(t, y)` over `h`; returns `y(t + h)`.
pub fn rk4_step<const M: usize>(f: impl Fn(f64, &[f64; M]) -> [f64; M], t: f64, y: &[f64; M], h: f64) -> [f64; M] {
    let add = |a: &[f64; M], b: &[f64; M], s: f64| -> [f64; M] { std::array::from_fn(|i| a[i] + s * b[i]) };
    let k1 = f(t, y);
    let k2 = f(t + 0.5 * h, &add(y, &k1, 0.5 * h));
    let k3 = f(t + 0.5 * h, &add(y, &k2, 0.5 * h));
    let k4 = f(t + h, &add(y, &k3, h));
    std::array::from_fn(|i| y[i] + h * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]) / 6.0)
}

/// The longest stable RK4 step of a scalar `dy/dt = f(y)` at `y` (module doc): `2 / |df/dy|`, the slope a
/// central difference over `y +- dy`; infinite where `f` does not fall with `y` (or the slope is NaN).
pub fn stable_step(f: impl Fn(f64) -> f64, y: f64, dy: f64) -> f64 {
    let slope = (f(y + dy) - f(y - dy)) / (2.0 * dy);
    if slope < 0.0 { 2.0 / -slope } else { f64::INFINITY }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fourth_order_on_exponential_decay() {
        // y' = -y, y(0) = 1: error at t = 1 with n steps falls like n^-4 (local error h^5 / 120 per step).
        let err = |n: usize| {
            let h = 1.0 / n as f64;
            let mut y = [1.0];
            for k in 0..n {
                y = rk4_step(|_, y| [-y[0]], k as f64 * h, &y, h);
            }
            (y[0] - (-1.0f64).exp()).abs()
        };
        let order = (err(10) / err(20)).log2();
        assert!((order - 4.0).abs() < 0.1, "observed order {order}");
    }
}
