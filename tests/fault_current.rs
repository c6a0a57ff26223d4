//! Issue 25, the fault current (`ohl::shortcircuit::current`): the peak of the worst-case waveform
//! against its exact value (the root of di/dt = 0) and against IEC 60909-0's `kappa sqrt(2) I''k`, the
//! Joule integral against its closed form, the three-phase currents' sum, the line-to-line currents'
//! opposition, the reclose's intervals, `kappa`'s inverse and the typed errors.

use ohl::shortcircuit::current::{CurrentError, FaultCurrent, FaultCurrentSpec, FaultKind, Reclose};
use std::f64::consts::{PI, SQRT_2};

use crate::common::gauss_legendre as gl;

fn spec(kind: FaultKind, r_over_x: f64, angle: Option<f64>) -> FaultCurrentSpec {
    FaultCurrentSpec {
        kind,
        initial_current_a: 31_500.0,
        frequency_hz: 50.0,
        r_over_x,
        inception_angle_deg: angle,
        start_s: 0.1,
        duration_s: 0.5,
        reclose: None,
    }
}

/// The exact peak of `e^(-t/tau) - cos(w t)` (the full d.c. offset) per unit `sqrt(2) I''k`, and its time
/// after inception: the root of `w sin(w t) = e^(-t/tau) / tau` in `(T/4, T/2)`, by bisection.
fn full_offset_peak(r_over_x: f64, f: f64) -> (f64, f64) {
    let w = 2.0 * PI * f;
    let tau = 1.0 / (w * r_over_x);
    let g = |t: f64| w * (w * t).sin() - (-t / tau).exp() / tau;
    let (mut a, mut b) = (0.5 * PI / w, PI / w);
    assert!(g(a) > 0.0 && g(b) < 0.0);
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if g(m) > 0.0 { a = m } else { b = m }
    }
    ((-a / tau).exp() - (w * a).cos(), a)
}

/// Worst case: the loop current of a line-to-line fault has the full d.c. offset, so its peak is the
/// exact peak of `sqrt(2) I''k (e^(-t/tau) - cos w t)` (to 1e-12: the same function evaluated two ways),
/// reached at the root of di/dt = 0 (no sample of the first cycle is higher). IEC 60909-0's `kappa =
/// 1.02 + 0.98 e^(-3R/X)` is a fit of the largest peak over all inception angles, which for R/X > 0 is
/// reached slightly off the full offset: measured here, `kappa` is within 0.6 % of that largest peak for
/// R/X in [0.05, 1] (the test scans the angle in 0.05 deg steps), and the full-offset peak is below the
/// largest by at most 2.5 % (at R/X = 1; 0.1 % at R/X = 0.05).
#[test]
fn worst_case_peak_is_the_exact_peak_and_near_kappa() {
    for &rx in &[0.05, 0.07, 0.1, 0.2, 0.5, 1.0] {
        for kind in [FaultKind::LineToLine, FaultKind::LineToEarth, FaultKind::ThreePhase] {
            let c = FaultCurrent::new(spec(kind, rx, None)).unwrap();
            let phase = if kind == FaultKind::ThreePhase { 1 } else { 0 };
            let amp = SQRT_2 * 31_500.0;
            let (p, tp) = full_offset_peak(rx, 50.0);
            let at = c.phase_currents_a(0.1 + tp)[phase].abs();
            assert!((at - p * amp).abs() < 1e-12 * amp, "{kind:?} R/X {rx}: {at} vs {}", p * amp);
            let sampled = (0..4000).map(|j| c.phase_currents_a(0.1 + j as f64 * 5e-6)[phase].abs()).fold(0.0, f64::max);
            assert!(sampled <= p * amp * (1.0 + 1e-12) && sampled > p * amp * (1.0 - 1e-6), "{kind:?} {rx}");
        }
        // The largest peak over inception angles against kappa.
        let w = 2.0 * PI * 50.0;
        let (tau, phi) = (1.0 / (w * rx), 1f64.atan2(rx));
        let mut best = 0.0_f64;
        for g in 0..7200 {
            let a = (g as f64 * 0.05).to_radians() - phi;
            for j in 0..2000 {
                let t = j as f64 * 1e-5;
                best = best.max((w * t + a).sin() - a.sin() * (-t / tau).exp());
            }
        }
        let c = FaultCurrent::new(spec(FaultKind::LineToLine, rx, None)).unwrap();
        let kappa = c.peak_factor();
        let (p, _) = full_offset_peak(rx, 50.0);
        eprintln!(
            "R/X {rx}: kappa {kappa:.5}, largest peak {best:.5} ({:+.3e}), full offset {p:.5} ({:+.3e})",
            kappa / best - 1.0,
            p / best - 1.0
        );
        assert!((kappa / best - 1.0).abs() < 6e-3, "kappa {kappa} vs {best}");
        assert!(p <= best * (1.0 + 1e-9) && p > best * (1.0 - 0.025), "{p} vs {best}");
    }
}

/// `int i^2 dt` over one flow against its closed form. With `a = g - phi`, `i = sqrt(2) I (sin(wt + a) -
/// sin a e^(-t/tau))`:
///
/// ```text
/// int_0^T i^2 = 2 I^2 [ T/2 - (sin(2wT + 2a) - sin 2a) / (4w)
///                       - 2 sin a (e^(-T/tau) (-sin(wT + a)/tau - w cos(wT + a)) + sin a / tau + w cos a) / (1/tau^2 + w^2)
///                       + sin^2 a tau/2 (1 - e^(-2T/tau)) ]
/// ```
///
/// (`int e^(ct) sin(wt + a) = e^(ct) (c sin(wt + a) - w cos(wt + a)) / (c^2 + w^2)`, `c = -1/tau`). The
/// numerical integral: composite 8-point Gauss-Legendre, 400 panels per flow (a smooth integrand: error far
/// below 1e-12 relative); tolerance 1e-10 relative.
#[test]
fn joule_integral_matches_its_closed_form() {
    let closed = |i: f64, f: f64, rx: f64, a: f64, t: f64| {
        let w = 2.0 * PI * f;
        let tau = 1.0 / (w * rx);
        let e = ((-t / tau).exp() * (-(w * t + a).sin() / tau - w * (w * t + a).cos()) + a.sin() / tau + w * a.cos())
            / (1.0 / (tau * tau) + w * w);
        2.0 * i
            * i
            * (0.5 * t - ((2.0 * w * t + 2.0 * a).sin() - (2.0 * a).sin()) / (4.0 * w) - 2.0 * a.sin() * e
                + a.sin().powi(2) * 0.5 * tau * (1.0 - (-2.0 * t / tau).exp()))
    };
    for &(rx, angle) in &[(0.07, None), (0.1, Some(0.0)), (0.3, Some(47.0)), (0.05, Some(-130.0))] {
        for kind in [FaultKind::ThreePhase, FaultKind::LineToLine, FaultKind::LineToEarth] {
            let mut s = spec(kind, rx, angle);
            s.reclose = Some(Reclose { dead_time_s: 0.3, duration_s: 0.25 });
            let c = FaultCurrent::new(s).unwrap();
            let phi = c.impedance_angle_deg().to_radians();
            let gamma = c.inception_angle_deg().to_radians();
            let deg = PI / 180.0;
            let (shift, sign): ([f64; 3], [f64; 3]) = match kind {
                FaultKind::ThreePhase => ([0.0, -120.0 * deg, 120.0 * deg], [1.0; 3]),
                FaultKind::LineToLine => ([30.0 * deg; 3], [1.0, 1.0, 0.0]),
                FaultKind::LineToEarth => ([0.0; 3], [1.0, 0.0, 0.0]),
            };
            for l in 0..3 {
                let f = |t: f64| c.phase_currents_a(t)[l].powi(2);
                let num = gl(&f, 0.1, 0.6, 400) + gl(&f, 0.9, 1.15, 200);
                let a = gamma + shift[l] - phi;
                let want = sign[l] * (closed(31_500.0, 50.0, rx, a, 0.5) + closed(31_500.0, 50.0, rx, a, 0.25));
                if want == 0.0 {
                    assert_eq!(num, 0.0);
                    continue;
                }
                assert!((num / want - 1.0).abs() < 1e-10, "{kind:?} R/X {rx} L{}: {num} vs {want}", l + 1);
            }
        }
    }
}

/// Three-phase currents sum to zero at every instant (to rounding of their size); line-to-line currents
/// are exactly opposite with L3 at zero; line-to-earth flows in L1 only.
#[test]
fn phase_currents_sum_and_oppose() {
    for &angle in &[None, Some(0.0), Some(73.0), Some(-200.0)] {
        let c3 = FaultCurrent::new(spec(FaultKind::ThreePhase, 0.08, angle)).unwrap();
        let c2 = FaultCurrent::new(spec(FaultKind::LineToLine, 0.08, angle)).unwrap();
        let c1 = FaultCurrent::new(spec(FaultKind::LineToEarth, 0.08, angle)).unwrap();
        for j in 0..3000 {
            let t = j as f64 * 2.3e-4;
            let i = c3.phase_currents_a(t);
            let size = i.iter().map(|x| x.abs()).fold(0.0, f64::max);
            assert!((i[0] + i[1] + i[2]).abs() <= 1e-12 * size.max(1.0), "t {t}: {i:?}");
            let i = c2.phase_currents_a(t);
            assert!(i[0] == -i[1] && i[2] == 0.0, "{i:?}");
            let i = c1.phase_currents_a(t);
            assert!(i[1] == 0.0 && i[2] == 0.0);
        }
    }
}

/// The flow intervals: `[0.1, 0.6)`, then after 0.3 s of dead time `[0.9, 1.15)`; zero outside, and the
/// second flow starts again from zero current with the same inception angle (the same waveform, to
/// the rounding of `t - t_inception`).
#[test]
fn reclose_intervals() {
    let mut s = spec(FaultKind::LineToLine, 0.1, None);
    s.reclose = Some(Reclose { dead_time_s: 0.3, duration_s: 0.25 });
    let c = FaultCurrent::new(s).unwrap();
    let want = [(0.1, 0.6), (0.9, 1.15)];
    assert_eq!(c.intervals_s().len(), 2);
    for (&(a, b), (wa, wb)) in c.intervals_s().iter().zip(want) {
        assert!((a - wa).abs() < 1e-15 && (b - wb).abs() < 1e-15, "{:?}", c.intervals_s());
    }
    assert!((c.end_s() - 1.15).abs() < 1e-15);
    for (t, on) in [
        (0.0, false),
        (0.0999, false),
        (0.1, true),
        (0.5999, true),
        (0.6, false),
        (0.8, false),
        (0.9, true),
        (1.1499, true),
        (1.15, false),
        (2.0, false),
    ] {
        assert_eq!(c.is_flowing(t), on, "t {t}");
        if !on {
            assert_eq!(c.phase_currents_a(t), [0.0; 3]);
        }
    }
    assert!(c.phase_currents_a(0.1).iter().all(|&i| i == 0.0), "the current starts from zero");
    for j in 0..100 {
        let tp = j as f64 * 2.1e-3;
        // the same waveform (t - t_inception differs by the rounding of the interval's start)
        let (a, b) = (c.phase_currents_a(0.1 + tp)[0], c.phase_currents_a(c.intervals_s()[1].0 + tp)[0]);
        assert!((a - b).abs() < 1e-9 * 31_500.0, "{a} vs {b}");
    }
    let once = FaultCurrent::new(spec(FaultKind::LineToLine, 0.1, None)).unwrap();
    assert_eq!(once.end_s(), 0.6);
    assert!(!once.is_flowing(0.9));
}

/// `kappa` and its inverse: round trip, the limits (R/X = 0 gives kappa = 2, no decay), and the worst
/// angles resolved as the module docs state.
#[test]
fn peak_factor_inverse_and_worst_angles() {
    for &rx in &[0.0, 0.01, 0.07, 0.3, 1.0, 3.0] {
        let c = FaultCurrent::new(spec(FaultKind::ThreePhase, rx, None)).unwrap();
        let back = FaultCurrent::r_over_x_from_peak_factor(c.peak_factor()).unwrap();
        assert!((back - rx).abs() < 1e-12 * (1.0 + rx), "{rx}: {back}");
        let phi = c.impedance_angle_deg();
        assert!((c.inception_angle_deg() - (phi + 30.0)).abs() < 1e-12);
        let ll = FaultCurrent::new(spec(FaultKind::LineToLine, rx, None)).unwrap();
        assert!((ll.inception_angle_deg() - (phi - 120.0)).abs() < 1e-12);
        let le = FaultCurrent::new(spec(FaultKind::LineToEarth, rx, None)).unwrap();
        assert!((le.inception_angle_deg() - (phi - 90.0)).abs() < 1e-12);
    }
    // R = 0: no decay; at gamma = 0 (phi = 90 deg) the full offset, i = sqrt(2) I (1 - cos w t'), whose
    // peak 2 sqrt(2) I = kappa sqrt(2) I recurs every period.
    let mut s = spec(FaultKind::LineToEarth, 0.0, Some(0.0));
    s.duration_s = 2.0;
    let c = FaultCurrent::new(s).unwrap();
    assert_eq!(c.peak_factor(), 2.0);
    let i = c.phase_currents_a(0.1 + 1.01)[0];
    assert!((i / (2.0 * SQRT_2 * 31_500.0) - 1.0).abs() < 1e-12, "{i}");
    for bad in [1.02, 1.0, 2.0001, f64::NAN] {
        assert!(matches!(
            FaultCurrent::r_over_x_from_peak_factor(bad),
            Err(CurrentError::Value { field: "kappa", .. })
        ));
    }
}

/// Every field out of range is a typed error naming it, its value and the allowed range; no NaN passes.
#[test]
fn bad_values_are_typed_errors() {
    type Set = Box<dyn Fn(&mut FaultCurrentSpec)>;
    let cases: Vec<(&str, Set)> = vec![
        ("initial_current_a", Box::new(|s| s.initial_current_a = 0.0)),
        ("initial_current_a", Box::new(|s| s.initial_current_a = f64::NAN)),
        ("frequency_hz", Box::new(|s| s.frequency_hz = -50.0)),
        ("r_over_x", Box::new(|s| s.r_over_x = -0.1)),
        ("r_over_x", Box::new(|s| s.r_over_x = f64::INFINITY)),
        ("inception_angle_deg", Box::new(|s| s.inception_angle_deg = Some(f64::NAN))),
        ("start_s", Box::new(|s| s.start_s = -1.0)),
        ("duration_s", Box::new(|s| s.duration_s = 0.0)),
        ("reclose.dead_time_s", Box::new(|s| s.reclose = Some(Reclose { dead_time_s: 0.0, duration_s: 0.1 }))),
        ("reclose.duration_s", Box::new(|s| s.reclose = Some(Reclose { dead_time_s: 0.3, duration_s: f64::NAN }))),
    ];
    for (field, set) in cases {
        let mut s = spec(FaultKind::ThreePhase, 0.1, None);
        set(&mut s);
        match FaultCurrent::new(s) {
            Err(e @ CurrentError::Value { field: f, .. }) => {
                assert_eq!(f, field);
                let msg = e.to_string();
                assert!(msg.starts_with(field) && msg.contains("must be"), "{msg}");
            }
            other => panic!("{field}: {other:?}"),
        }
    }
}
