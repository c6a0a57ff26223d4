//! Tests of the heat rod against the paper's test 5.4, the exact Fourier solution, an exact
//! Dirichlet-Neumann series (held nodes) and the conservation laws derived in `boundary`.
//! Run with `--nocapture` to see the measured numbers.

use super::*;
use crate::exact::heat::two_halves;
use std::f64::consts::PI;

/// Paper 5.4: 473.15 K and 268.15 K scaled by 273.15 K (printed 1.7322 and 0.9817).
const UL: f64 = 473.15 / 273.15;
const UR: f64 = 268.15 / 273.15;
/// The exact equalisation temperature (printed 1.35695).
const U_EQ: f64 = 0.5 * (UL + UR);

/// Runs until the spread of the nodal temperatures is below `tol`, diverges (`spread > 10`), or `t_max` passes.
/// Returns the time taken, or `None` on divergence.
fn run_to_spread(rod: &mut HeatRod, dt: f64, tol: f64, t_max: f64) -> Option<f64> {
    while rod.spread() >= tol && rod.time() < t_max {
        rod.step(dt);
        if rod.spread() > 10.0 {
            return None;
        }
    }
    Some(rod.time())
}

fn node_average(rod: &HeatRod) -> f64 {
    rod.temperatures().iter().sum::<f64>() / rod.temperatures().len() as f64
}

/// Least-squares slope of `log e` against `log h`.
fn slope(h: &[f64], e: &[f64]) -> f64 {
    let x: Vec<f64> = h.iter().map(|v| v.ln()).collect();
    let y: Vec<f64> = e.iter().map(|v| v.ln()).collect();
    let n = x.len() as f64;
    let (mx, my) = (x.iter().sum::<f64>() / n, y.iter().sum::<f64>() / n);
    let sxy: f64 = x.iter().zip(&y).map(|(a, b)| (a - mx) * (b - my)).sum();
    let sxx: f64 = x.iter().map(|a| (a - mx) * (a - mx)).sum();
    sxy / sxx
}

#[test]
fn paper_test_5_4_all_options() {
    // N = 50 as in the paper; r = 1/2 is the paper's alpha = 1, r = 1/4 its alpha = 1/2.
    // "Equalised" here means a spread below 1e-6 (the paper does not say when it stopped); the final value is
    // the average of the nodes, which then lie within 1e-6 of each other.
    let n = 50;
    let h = 1.0 / n as f64;
    println!("paper test 5.4, N = {n}, exact equalisation {U_EQ:.7} (paper: option 1 1.36058, option 2 1.35689)");
    for r in [0.5, 0.25] {
        for boundary in [
            HeatBoundary::ZeroFlux,
            HeatBoundary::LagrangeQuadratic,
            HeatBoundary::Linear,
            HeatBoundary::LagrangeQuadraticAsPrinted,
            HeatBoundary::LinearAsPrinted,
        ] {
            let mut rod = HeatRod::two_halves(n, UL, UR, boundary);
            assert!((rod.mean() - U_EQ).abs() < 1e-15, "the initial trapezoidal mean is the exact value");
            let dt = r * h * h;
            let outcome = run_to_spread(&mut rod, dt, 1e-6, 10.0);
            match outcome {
                Some(t) => println!(
                    "  r = {r:<4} {boundary:<27?} equalised to {:.7} (error {:+.2e}) at t = {t:.4}",
                    node_average(&rod),
                    node_average(&rod) - U_EQ
                ),
                None => println!("  r = {r:<4} {boundary:<27?} diverges (spread > 10 at t = {:.4})", rod.time()),
            }
            match boundary {
                // Conservative: the mean stays exact to rounding, hence so does the equalisation value.
                // The slowest mode a_1 cos(pi s) e^{-pi^2 t}, a_1 = 2 (uL - uR) / pi, spans 2 |a_1| e^{-pi^2 t}:
                // below 1e-6 at t = ln(2 |a_1| / 1e-6) / pi^2 = 1.395, to within a step.
                HeatBoundary::ZeroFlux => {
                    let t = outcome.expect("ZeroFlux is stable for r <= 1/2");
                    // Rounding bound as in `conservation_with_asymmetric_data`.
                    assert!((rod.mean() - U_EQ).abs() < 5e-12, "mean drifted by {:e}", rod.mean() - U_EQ);
                    assert!((node_average(&rod) - U_EQ).abs() < 5e-12);
                    let t_eq = crate::exact::heat::equalisation_time(UL, UR, 1e-6);
                    assert!((t - t_eq).abs() < 2e-3, "equalised at {t}, slowest mode predicts {t_eq}");
                }
                // The data are odd about s = 1/2 and both closures are mirror-symmetric: the centre node, and so
                // the equalisation value, stay at the mean to rounding.
                HeatBoundary::LagrangeQuadratic | HeatBoundary::Linear => {
                    outcome.expect("stable at r <= 1/2");
                    assert!((node_average(&rod) - U_EQ).abs() < 5e-12);
                }
                // A step changes the sum Q conserved by LagrangeQuadratic by (3 r h / 2)(d_0 + d_N), d the defect
                // of the old level from the Lagrange closure (boundary.rs). For the literal (5.3) the closure is
                // taken from the previous level and perturbed: d_0 ~ -tau u_t(0) - (2 tau/3) u_ss(0) and
                // d_N ~ -tau u_t(1) + (2 tau/3) u_ss(1). With u_ss = u_t and summed over the steps,
                // drift ~ -(3 r h/2)(D_0 + D_N) + r h (D_N - D_0), D the total change of an end temperature.
                // Two halves: D_0 = -D_N = -(uL - uR)/2, so drift ~ r h (uL - uR), up to relative O(h)
                // (0.8 h measured).
                HeatBoundary::LagrangeQuadraticAsPrinted => {
                    if r == 0.5 {
                        assert!(outcome.is_none(), "the literal (5.3) was expected to diverge at r = 1/2");
                    } else {
                        outcome.expect("the literal (5.3) is stable at r = 1/4");
                        let drift = node_average(&rod) - U_EQ;
                        let predicted = r * h * (UL - UR);
                        assert!((drift / predicted - 1.0).abs() < 0.05, "drift {drift:e}, predicted {predicted:e}");
                    }
                }
                // Coefficients summing to 1 + r: a growing end value for every r.
                HeatBoundary::LinearAsPrinted => {
                    assert!(outcome.is_none(), "the literal (5.4) was expected to diverge");
                    assert!(rod.time() < 0.05);
                }
            }
        }
    }
}

#[test]
fn printed_option_1_drift_scales_with_r_h() {
    // The literal (5.3) at three (N, r): the drift of the equalisation value against r h (uL - uR).
    for (n, r) in [(25, 0.25), (50, 0.1), (100, 0.25)] {
        let h = 1.0 / n as f64;
        let mut rod = HeatRod::two_halves(n, UL, UR, HeatBoundary::LagrangeQuadraticAsPrinted);
        run_to_spread(&mut rod, r * h * h, 1e-8, 10.0).expect("stable for r <= 1/4");
        let drift = node_average(&rod) - U_EQ;
        let predicted = r * h * (UL - UR);
        println!("  literal (5.3), N = {n:>3}, r = {r}: drift {drift:.4e}, r h (uL - uR) = {predicted:.4e}");
        // Relative O(h) correction, measured 0.8 h: 3.2 % at N = 25.
        assert!((drift / predicted - 1.0).abs() < 0.05);
    }
    // Asymmetric data, a hot left quarter: D_0 = -(3/4)(uL - uR), D_N = (uL - uR)/4, so the same estimate
    // gives drift ~ (3/4 + 1) r h (uL - uR) (measured 1.734 at N = 80, r = 1/4).
    let (n, r) = (80, 0.25);
    let h = 1.0 / n as f64;
    let u0: Vec<f64> = (0..=n)
        .map(|i| {
            if 4 * i < n {
                UL
            } else if 4 * i == n {
                U_EQ
            } else {
                UR
            }
        })
        .collect();
    let mut rod = HeatRod::new(u0, HeatBoundary::LagrangeQuadraticAsPrinted);
    let m0 = rod.mean();
    run_to_spread(&mut rod, r * h * h, 1e-9, 10.0).expect("stable for r <= 1/4");
    let drift = node_average(&rod) - m0;
    let predicted = 1.75 * r * h * (UL - UR);
    println!("  literal (5.3), hot quarter, N = {n}, r = {r}: drift {drift:.4e}, 1.75 r h (uL - uR) = {predicted:.4e}");
    assert!((drift / predicted - 1.0).abs() < 0.05);
}

#[test]
fn conservation_with_asymmetric_data() {
    // A hot left quarter (no symmetry to hide a drift). Exact equalisation: the initial trapezoidal mean.
    for n in [40, 80] {
        let h = 1.0 / n as f64;
        let u0: Vec<f64> = (0..=n)
            .map(|i| match (4 * i).cmp(&n) {
                std::cmp::Ordering::Less => UL,
                std::cmp::Ordering::Equal => U_EQ,
                std::cmp::Ordering::Greater => UR,
            })
            .collect();
        let m0 = HeatRod::new(u0.clone(), HeatBoundary::ZeroFlux).mean();
        let mut drifts = Vec::new();
        for boundary in [HeatBoundary::ZeroFlux, HeatBoundary::LagrangeQuadratic, HeatBoundary::Linear] {
            let mut rod = HeatRod::new(u0.clone(), boundary);
            run_to_spread(&mut rod, 0.5 * h * h, 1e-12, 10.0).expect("stable");
            let drift = rod.mean() - m0;
            println!("  hot quarter, N = {n}, {boundary:?}: equalisation - initial mean = {drift:+.3e}");
            drifts.push(drift);
        }
        // ZeroFlux conserves the trapezoidal mean; LagrangeQuadratic conserves Q (boundary.rs), which equals
        // the trapezoidal mean for data flat at the ends, and the trapezoidal mean of a uniform field (to the
        // final spread 1e-12). Rounding: ~1e-16 per node and step, summed over up to 26000 steps of 81 nodes
        // as a random walk, ~1e-16 * sqrt(2e6) = 1.5e-13 (measured up to 5.7e-13); bound 5e-12.
        assert!(drifts[0].abs() < 5e-12 && drifts[1].abs() < 5e-12, "{drifts:?}");
        // Linear: the trapezoidal mean changes per step by (h/2)(du_0 + du_N) + tau [(u_0 - u_1) + (u_N - u_{N-1})] / h
        // (boundary.rs); the first part dominates, so the drift is first order, about (h/2) times the total
        // change of the two end temperatures, (h/2)[(m0 - uL) + (m0 - uR)] = -(h/4)(uL - uR) here. The rest is
        // relative O(h) (measured 2.6 % at N = 40, 1.3 % at N = 80).
        let predicted = 0.5 * h * ((m0 - UL) + (m0 - UR));
        assert!((drifts[2] / predicted - 1.0).abs() < 0.05, "Linear drift {:e}, predicted {predicted:e}", drifts[2]);
    }
}

#[test]
fn zero_flux_converges_at_second_order_to_the_fourier_solution() {
    // r = 1/4 fixed (r = 1/6 would cancel the leading error, r = 1/2 leaves the sawtooth mode undamped),
    // compared at t = 0.1 in the max norm over the nodes. With N = 25 (odd) the jump falls mid-segment, not
    // on a node, and the leading errors of the initial data and of the scheme nearly cancel (measured 2.4e-6
    // against 8.7e-5 at N = 50): the order is fitted to the three even N only.
    let (r, t_end) = (0.25, 0.1);
    let ns = [25usize, 50, 100, 200];
    let mut report = String::new();
    for boundary in [HeatBoundary::ZeroFlux, HeatBoundary::LagrangeQuadratic, HeatBoundary::Linear] {
        let (mut hs, mut errs) = (Vec::new(), Vec::new());
        for &n in &ns {
            let mut rod = HeatRod::two_halves(n, UL, UR, boundary);
            let steps = (t_end * (n * n) as f64 / r).round() as usize;
            let dt = t_end / steps as f64;
            for _ in 0..steps {
                rod.step(dt);
            }
            let h = rod.spacing();
            let err = rod
                .temperatures()
                .iter()
                .enumerate()
                .map(|(i, u)| (u - two_halves(UL, UR, i as f64 * h, t_end)).abs())
                .fold(0.0, f64::max);
            hs.push(h);
            errs.push(err);
        }
        let p = slope(&hs[1..], &errs[1..]);
        let listed: Vec<String> = errs.iter().map(|e| format!("{e:.3e}")).collect();
        report += &format!("  {boundary:?}: max errors {listed:?} for N = {ns:?}; order (last three) {p:.3}\n");
        if boundary == HeatBoundary::ZeroFlux {
            assert!((p - 2.0).abs() < 0.1, "{report}");
        }
    }
    println!("{report}");
}

#[test]
fn held_nodes_match_the_dirichlet_neumann_series() {
    // Hold s in [0, 0.1] at u = 2 with the rest starting at u = 1. On x = s - 0.1 in [0, L], L = 0.9, the
    // deficit v = 2 - u solves v_t = v_xx, v(0) = 0, v_x(L) = 0, v(x, 0) = 1: v = sum_m b_m sin(l_m x)
    // exp(-l_m^2 t), l_m = (m + 1/2) pi / L, b_m = 2 / (L l_m).
    let exact = |s: f64, t: f64| {
        let (x, l) = (s - 0.1, 0.9);
        if x <= 0.0 {
            return 2.0;
        }
        let v: f64 = (0..2000)
            .map(|m| {
                let lm = (m as f64 + 0.5) * PI / l;
                2.0 / (l * lm) * (lm * x).sin() * (-lm * lm * t).exp()
            })
            .sum();
        2.0 - v
    };
    let t_end = 0.05;
    let mut errs = Vec::new();
    for n in [50usize, 100] {
        let mut rod = HeatRod::new(vec![1.0; n + 1], HeatBoundary::ZeroFlux);
        let held = 0..n / 10 + 1; // the nodes with s <= 0.1
        rod.hold(held.clone(), 2.0);
        assert!((rod.mean() - (1.0 + 0.1 + 0.5 / n as f64)).abs() < 1e-14, "hold sets the nodes at once");
        let steps = (t_end * (n * n) as f64 / 0.25).round() as usize;
        let dt = t_end / steps as f64;
        for _ in 0..steps {
            rod.step(dt);
            assert!(rod.temperatures()[held.clone()].iter().all(|&u| u == 2.0), "held nodes moved");
        }
        let u = rod.temperatures();
        // Heat spreads from the held range: monotone decrease away from it, everywhere above the initial 1.
        assert!(u.windows(2).all(|w| w[1] <= w[0]) && u[n] > 1.0);
        let h = rod.spacing();
        let err = u.iter().enumerate().map(|(i, &ui)| (ui - exact(i as f64 * h, t_end)).abs()).fold(0.0, f64::max);
        println!("  hold, N = {n}: max error against the series {err:.3e}");
        errs.push(err);
        // After release the ZeroFlux rod conserves its mean again.
        rod.release();
        let m = rod.mean();
        for _ in 0..100 {
            rod.step(dt);
        }
        assert!((rod.mean() - m).abs() < 1e-14);
        assert!(rod.temperatures()[0] < 2.0, "released nodes evolve");
    }
    // Second order: the error falls by 4 when h halves (3.5 allows for the O(h^3) remainder).
    assert!(errs[0] / errs[1] > 3.5, "error ratio {}", errs[0] / errs[1]);
}

#[test]
fn a_uniform_source_heats_a_uniform_rod_uniformly() {
    // f = 2 on a uniform rod: u = u0 + 2 t exactly for every closure but the literal ones (whose printed
    // source terms are 2 tau f and whose coefficients do not sum to one).
    for boundary in [HeatBoundary::ZeroFlux, HeatBoundary::LagrangeQuadratic, HeatBoundary::Linear] {
        let mut rod = HeatRod::new(vec![1.5; 21], boundary);
        let f = vec![2.0; 21];
        let dt = rod.max_stable_step();
        for _ in 0..200 {
            rod.step_with_source(dt, &f);
        }
        let want = 1.5 + 2.0 * rod.time();
        assert!(rod.temperatures().iter().all(|u| (u - want).abs() < 1e-12), "{boundary:?}");
    }
    // ZeroFlux with a non-uniform source: the mean grows by tau * trapezoidal mean of f per step.
    let mut rod = HeatRod::two_halves(20, UL, UR, HeatBoundary::ZeroFlux);
    let f: Vec<f64> = (0..=20).map(|i| (i as f64 * 0.3).sin()).collect();
    let f_mean = HeatRod::new(f.clone(), HeatBoundary::ZeroFlux).mean();
    let dt = 0.5 * rod.max_stable_step();
    for _ in 0..400 {
        rod.step_with_source(dt, &f);
    }
    assert!((rod.mean() - (U_EQ + rod.time() * f_mean)).abs() < 1e-13);
}

#[test]
fn segment_temperatures_average_the_end_nodes() {
    let rod = HeatRod::new(vec![1.0, 3.0, 4.0, 8.0], HeatBoundary::ZeroFlux);
    let mut out = [0.0; 3];
    rod.segment_temperatures(&mut out);
    assert_eq!(out, [2.0, 3.5, 6.0]);
    assert_eq!(rod.spread(), 7.0);
    assert_eq!(rod.max_stable_step(), 0.5 / 9.0);
}

#[test]
fn an_overflowed_temperature_is_an_error_not_a_panic() {
    // A temperature over a tiny scale (u = T / T_s) overflows: try_new says so, new would panic.
    let u: f64 = 473.15 / 1.0e-308;
    assert!(u.is_infinite());
    let e = HeatRod::try_new(vec![1.0, u, 1.0], HeatBoundary::ZeroFlux).unwrap_err();
    assert!(e.contains("u[1] = inf is not finite"), "{e}");
    assert!(HeatRod::try_new(vec![1.0, 2.0], HeatBoundary::ZeroFlux).unwrap_err().contains("at least 3 nodes"));
    assert!(HeatRod::try_new(vec![1.0, 2.0, 3.0], HeatBoundary::ZeroFlux).is_ok());
}
