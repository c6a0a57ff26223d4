//! The static solver (`ohl::statics`) on the paper's test wire (sections 4.1-4.3): span 160 m,
//! `EA = 80734 g` N, `rho0 = 1 kg/m`, `g = 9.81 m/s^2`; wind `q d = rho_air U^2 d / 2` with
//! `rho_air = 1.225 kg/m^3`, `U = 20 m/s`, `d = 0.01553 m`, `c_n = 1.8446`, `c_tau = 0.0554`.
//!
//! Tolerances: a converged solve must reach the solver's default tolerance, `max(1e-10 f_max, 32 R)`
//! with `f_max` the largest nodal load and `R = (EA / l0) X eps` the rounding floor of the residual
//! (positions of size `X` known to `X eps`, turned into force by the axial stiffness): on these grids
//! `32 R` governs, `1e-7` to `6e-5` of the nodal weight, and no double-precision iteration can go lower.

use ohl::element::aero::{Aerodynamic, SegmentLoad};
use ohl::element::tension::LawKind;
use ohl::exact::ElasticCatenary;
use ohl::scheme::{Explicit, Loads, StepParams, WindGate, WindLoad};
use ohl::statics::{self, StaticError, StaticOptions, StaticReport};
use ohl::wire::{Conductor, Wire};

const EA_N: f64 = 80734.0 * 9.81;
const SPAN_M: f64 = 160.0;
const G: f64 = 9.81;
const RHO: f64 = 1.0;
const QD: f64 = 0.5 * 1.225 * 20.0 * 20.0 * 0.01553;

/// How the iteration starts.
#[derive(Clone, Copy, Debug)]
enum Start {
    /// nodes evenly on the chord
    Straight,
    /// nodes on a parabola through the supports, mid-span sag `span / 20` below the chord
    Parabola,
}

/// The paper's wire on `n` segments of total unstretched length `l0_m` between `(0, 0, 0)` and
/// `(0, 160, h_m)`.
fn wire(n: usize, l0_m: f64, h_m: f64, law: LawKind, start: Start) -> Wire {
    let conductor = Conductor { axial_stiffness_n: EA_N, internal_friction_n_s: 0.0, law };
    let mut x = [vec![0.0; n + 1], vec![0.0; n + 1], vec![0.0; n + 1]];
    for i in 0..=n {
        let s = i as f64 / n as f64;
        x[1][i] = s * SPAN_M;
        x[2][i] = s * h_m;
        if let Start::Parabola = start {
            x[2][i] -= 4.0 * s * (1.0 - s) * SPAN_M / 20.0;
        }
    }
    Wire::new(conductor, x, vec![l0_m / n as f64; n], RHO)
}

fn solver(w: Wire, wind: Option<WindLoad>) -> Explicit {
    let loads = Loads {
        gravity_m_per_s2: G,
        uniform_load_n_per_m: [0.0; 3],
        wind,
        wind_scale: 1.0,
        wind_gate: WindGate::Always,
    };
    let params = StepParams { dt_s: 1e-4, smoothing: 0.0, mass_damping_per_s: 0.0, max_speed_m_per_s: 1e3 };
    Explicit::new(w, loads, params)
}

fn paper_wind() -> WindLoad {
    WindLoad::Aerodynamic(Aerodynamic {
        direction: [1.0, 0.0, 0.0],
        qd_cn: QD * 1.8446,
        qd_ct: QD * 0.0554,
        mu_over_u: 0.0,
    })
}

/// The local orders of the terminal iterations: for consecutive residuals normalised by the nodal load,
/// `rho_k = r_k / f`, with `rho_k < 1e-2` (the asymptotic range) and `r_{k+1}` above 10 times the
/// rounding floor (below that rounding, not the method, sets the residual), `p = ln rho_{k+1} / ln
/// rho_k`. Quadratic convergence `rho_{k+1} = C rho_k^2` gives `p = 2 + ln C / ln rho_k`, at least 1.5
/// for any `C <= 10`; a linear rate of 0.1 at `rho_k = 1e-3` gives 1.33.
fn terminal_orders(rep: &StaticReport, floor: f64, load: f64) -> Vec<f64> {
    rep.residual_history
        .windows(2)
        .filter(|w| w[0] < 1e-2 * load && w[1] > 10.0 * floor)
        .map(|w| (w[1] / load).ln() / (w[0] / load).ln())
        .collect()
}

fn check_converges(n: usize, l0: f64, h: f64, law: LawKind, start: Start, wind: Option<WindLoad>) -> StaticReport {
    let mut s = solver(wire(n, l0, h, law, start), wind);
    let floor = statics::rounding_floor_n(&s);
    let load = RHO * G * SPAN_M / n as f64;
    let rep = statics::solve(&mut s, &StaticOptions::default())
        .unwrap_or_else(|e| panic!("N={n} L0={l0} h={h} {law:?} {start:?}: {e}"));
    let hist: Vec<String> = rep.residual_history.iter().map(|r| format!("{r:.1e}")).collect();
    let p = terminal_orders(&rep, floor, load);
    println!(
        "N={n} L0={l0} h={h} {law:?} {start:?} wind={}: {} it, residual {:.2e} N (tol {:.2e}, floor {:.2e}), orders {p:?}\n  history {}\n  steps {:?}",
        wind.is_some(),
        rep.iterations,
        rep.residual_n,
        rep.tolerance_n,
        floor,
        hist.join(" "),
        rep.step_factors
    );
    assert!(rep.residual_n <= rep.tolerance_n && rep.tolerance_n <= 32.0 * floor + 1e-10 * 2.0 * load);
    // The last iterations are Newton's: quadratic (order 2; 1.6 allows for the shape of the constant).
    assert!(p.iter().all(|&p| p >= 1.5), "terminal orders {p:?}");
    rep
}

#[test]
fn converges_from_straight_and_parabola_for_slack_and_taut_wires() {
    for law in [LawKind::TensionOnly, LawKind::Linear] {
        for l0 in [160.0, 165.0, 159.9] {
            for start in [Start::Straight, Start::Parabola] {
                for n in [100, 1000] {
                    check_converges(n, l0, 0.0, law, start, None);
                }
            }
        }
    }
}

#[test]
fn converges_with_wind_and_weight_and_unequal_supports() {
    for start in [Start::Straight, Start::Parabola] {
        for (l0, h) in [(160.0, 0.0), (165.0, 20.0), (161.5, -30.0)] {
            check_converges(200, l0, h, LawKind::TensionOnly, start, Some(paper_wind()));
            check_converges(200, l0, h, LawKind::TensionOnly, start, None);
        }
    }
}

/// Largest distance [m] between the nodes and the exact elastic catenary at `s_i = i l0 / N`.
fn catenary_error(n: usize) -> f64 {
    let mut s = solver(wire(n, SPAN_M, 0.0, LawKind::TensionOnly, Start::Parabola), None);
    statics::solve(&mut s, &StaticOptions::default()).unwrap_or_else(|e| panic!("N={n}: {e}"));
    let exact = ElasticCatenary::solve([0.0; 3], [0.0, SPAN_M, 0.0], SPAN_M, [0.0, 0.0, -RHO * G], EA_N)
        .unwrap_or_else(|e| panic!("exact catenary: {e}"));
    (0..=n)
        .map(|i| {
            let (p, q) = (s.wire().position(i), exact.position(i as f64 * SPAN_M / n as f64));
            ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt()
        })
        .fold(0.0, f64::max)
}

#[test]
fn agrees_with_the_elastic_catenary_to_second_order() {
    // The lumped-mass chain is a second-order discretisation of the string: the nodal error is O(ds^2).
    // Least-squares slope of ln(error) against ln(N) over the three finest grids.
    let ns = [25usize, 50, 100, 200];
    let errs: Vec<f64> = ns.iter().map(|&n| catenary_error(n)).collect();
    println!("N {ns:?}: largest nodal error [m] {errs:?}");
    let pts: Vec<(f64, f64)> = ns[1..].iter().zip(&errs[1..]).map(|(&n, &e)| ((n as f64).ln(), e.ln())).collect();
    let (mx, my) = (pts.iter().map(|p| p.0).sum::<f64>() / 3.0, pts.iter().map(|p| p.1).sum::<f64>() / 3.0);
    let slope =
        pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum::<f64>() / pts.iter().map(|p| (p.0 - mx).powi(2)).sum::<f64>();
    println!("observed order {:.4}", -slope);
    assert!((-slope - 2.0).abs() < 0.1, "observed order {}", -slope);
    // And the error itself is small against the sag (about 7 m): below 1e-3 of it on N = 200.
    assert!(errs[3] < 7e-3, "error {} m at N = 200", errs[3]);
}

#[test]
fn support_reactions_balance_the_weight_and_the_wind() {
    for wind in [None, Some(paper_wind())] {
        let (n, l0) = (200, 165.0);
        let mut s = solver(wire(n, l0, 20.0, LawKind::TensionOnly, Start::Straight), wind);
        statics::solve(&mut s, &StaticOptions::default()).unwrap_or_else(|e| panic!("{e}"));
        // The total external load, independently of the residual: the weight rho0 l0 g, and the wind on
        // each segment from the law itself at the final shape.
        let mut load = [0.0, 0.0, -RHO * l0 * G];
        if let Some(WindLoad::Aerodynamic(a)) = wind {
            for j in 0..n {
                let (p, q) = (s.wire().position(j), s.wire().position(j + 1));
                let d = [q[0] - p[0], q[1] - p[1], q[2] - p[2]];
                let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
                let f = a.force([d[0] / len, d[1] / len, d[2] / len], len, [0.0; 3]);
                (0..3).for_each(|k| load[k] += f[k]);
            }
        }
        let reactions = statics::support_reactions(&mut s);
        assert_eq!(reactions.iter().map(|r| r.0).collect::<Vec<_>>(), vec![0, n]);
        let sum: Vec<f64> = (0..3).map(|k| reactions.iter().map(|r| r.1[k]).sum::<f64>() + load[k]).collect();
        let scale = load.iter().map(|c| c * c).sum::<f64>().sqrt();
        let gap = sum.iter().map(|c| c * c).sum::<f64>().sqrt() / scale;
        println!("wind {}: load {load:?} N, reactions {reactions:?}, imbalance {gap:.2e}", wind.is_some());
        // Free-node residuals sum to at most N tol ~ 2e-4 N against 1.6e3 N; rounding of the sums ~1e-13.
        assert!(gap < 1e-9, "imbalance {gap:e}");
    }
}

#[test]
fn unsupported_cases_give_typed_errors() {
    let mut s = solver(wire(50, SPAN_M, 0.0, LawKind::TensionOnly, Start::Parabola), Some(paper_wind()));
    s.loads_mut().wind_gate = WindGate::Downwind;
    assert_eq!(statics::solve(&mut s, &StaticOptions::default()), Err(StaticError::DownwindGate));
    // Segments 7 and 20 broken: nodes 8 to 20 hang from nothing.
    let mut s = solver(wire(50, SPAN_M, 0.0, LawKind::TensionOnly, Start::Parabola), None);
    s.wire_mut().break_segment(7);
    s.wire_mut().break_segment(20);
    assert_eq!(statics::solve(&mut s, &StaticOptions::default()), Err(StaticError::BrokenSegment { node: 8 }));
    let mut s = solver(wire(50, SPAN_M, 0.0, LawKind::TensionOnly, Start::Parabola), None);
    s.wire_mut().x[2][10] = f64::NAN;
    assert_eq!(statics::solve(&mut s, &StaticOptions::default()), Err(StaticError::NonFinite { iteration: 0 }));
    // Two coincident nodes: the tangent is 0/0.
    let mut s = solver(wire(50, SPAN_M, 0.0, LawKind::TensionOnly, Start::Straight), None);
    s.wire_mut().x[1][11] = s.wire().x[1][10];
    assert!(matches!(statics::solve(&mut s, &StaticOptions::default()), Err(StaticError::NonFinite { .. })));
    // An unreachable tolerance: NotConverged, with the residual reached.
    let mut s = solver(wire(50, SPAN_M, 0.0, LawKind::TensionOnly, Start::Parabola), None);
    let opts = StaticOptions { tolerance_n: Some(1e-30), max_iterations: 8 };
    assert!(matches!(statics::solve(&mut s, &opts), Err(StaticError::NotConverged { iterations: 8, .. })));
}

#[test]
fn jacobian_replica_matches_the_kernel() {
    // Wind with damping, internal friction and velocities: every term of the replica is exercised.
    let mut w = wire(40, 161.0, 5.0, LawKind::TensionOnly, Start::Parabola);
    w.internal_friction_n_s.fill(50.0);
    for i in 1..40 {
        w.v[0][i] = 0.3 * (i as f64).sin();
        w.v[2][i] = 0.2 * (i as f64).cos();
    }
    let mut s = solver(
        w,
        Some(WindLoad::Aerodynamic(Aerodynamic {
            direction: [1.0, 0.0, 0.0],
            qd_cn: QD * 1.8446,
            qd_ct: QD * 0.0554,
            mu_over_u: 0.2 / 20.0,
        })),
    );
    let gap = statics::jacobian::replica_gap(&mut s);
    // Forces of order EA e ~ 5e3 N: rounding ~1e-12 of it.
    println!("replica gap {gap:.2e} N");
    assert!(gap < 1e-8, "gap {gap:e} N");
}

/// A span broken at segment 7 leaves two pieces hanging from the supports. The discrete equilibrium is
/// known exactly: each piece hangs straight down from its support, segment `j` carrying the weight of
/// the nodes below it, `T_j = g sum m_i`, stretched to `l0 (1 + T_j / EA)` (the broken segment's mass
/// stays lumped on its two end nodes). Newton starts from the parabola, far from the vertical pieces.
/// Tolerance: the solve stops at a residual of about 1e-10 of the nodal weight; over segments of
/// stiffness EA / l0 = 2.5e5 N/m that moves a node by far less than 1e-9 m; asserted at 1e-8 m.
///
/// Start: each piece on a straight line 10 degrees off the vertical, unstretched. From the parabola the
/// solver does not converge (residual 35 N after 100 iterations: a piece must swing through 90 degrees,
/// far outside Newton's basin), which is why a broken section's residual state is solved from pieces
/// re-hung below their supports (`ohl_app::cases`).
#[test]
fn a_broken_span_hangs_straight_down_from_its_supports() {
    let n = 50;
    let mut s = solver(wire(n, SPAN_M, 0.0, LawKind::TensionOnly, Start::Straight), None);
    s.wire_mut().break_segment(7);
    let (l0, tilt) = (SPAN_M / n as f64, 10f64.to_radians());
    for i in 0..=n {
        let (top, d) = if i <= 7 { (0, i) } else { (n, n - i) };
        let y = s.wire().x[1][top] + if top == 0 { 1.0 } else { -1.0 } * d as f64 * l0 * tilt.sin();
        s.wire_mut().x[1][i] = y;
        s.wire_mut().x[2][i] = -(d as f64) * l0 * tilt.cos();
    }
    let report = statics::solve(&mut s, &StaticOptions::default()).unwrap();
    let w = s.wire();
    let hang = |top: usize, nodes: Vec<usize>| -> f64 {
        // `nodes` from the support down; returns the largest position error [m].
        let mut z = w.x[2][top];
        let mut worst: f64 = 0.0;
        for pair in nodes.windows(2) {
            let (a, b) = (pair[0], pair[1]);
            let j = a.min(b);
            let below: f64 = nodes.iter().skip_while(|&&i| i != b).map(|&i| w.mass[i]).sum();
            let t = G * below;
            z -= w.rest_length[j] * (1.0 + t / EA_N);
            let horizontal = (w.x[0][b] - w.x[0][top]).hypot(w.x[1][b] - w.x[1][top]);
            worst = worst.max((w.x[2][b] - z).abs()).max(horizontal);
        }
        worst
    };
    let left = hang(0, (0..=7).collect());
    let right = hang(n, (8..=n).rev().collect());
    println!(
        "broken at segment 7: {} iterations; largest error {left:.2e} m (left piece), {right:.2e} m (right)",
        report.iterations
    );
    assert!(left < 1e-8 && right < 1e-8, "{left} {right}");
}

/// The same broken span above a level, frictionless ground 12 m below its supports
/// (`statics::solve_on_ground`): each piece hangs straight down from its support as long as it is above
/// the ground, and the rest of it lies on the ground. The discrete equilibrium is known exactly: with
/// segments of 3.2 m, three nodes hang below each support (at 3.2, 6.4, 9.6 m, stretched by at most
/// 1.2e-4), the fourth would be 12.8 m down and lies on the ground, joined to the last hanging node by a
/// slack segment (2.4 m of drop, 3.2 m long), so the ground holds no tension: each support carries the
/// weight of its own node and the three hanging ones, `g (m_0 + m_1 + m_2 + m_3)`, and no horizontal
/// load, and the hanging nodes are at the heights of the previous test. Tolerances: positions 1e-8 m as
/// there; the reactions to 1e-8 of the weight they carry (the solve's residual is about 1e-10 of a nodal
/// weight); the lying nodes sink by their weight over the contact's stiffness `max EA / l0` (31.4 N over
/// 2.5e5 N/m = 1.3e-4 m), asserted to rounding.
///
/// Start: the pieces hang 10 degrees off the vertical down to the ground and lie on it towards their free
/// ends (as `ohl_app::cases` re-hangs them): from there the hanging part swings to the vertical and the
/// lying part slides 2 to 3 m along the ground.
#[test]
fn a_broken_span_hangs_to_a_frictionless_ground_and_lies_on_it() {
    let n = 50;
    let ground_m = -12.0;
    let mut s = solver(wire(n, SPAN_M, 0.0, LawKind::TensionOnly, Start::Straight), None);
    s.wire_mut().break_segment(7);
    s.set_ground(Some(ohl::scheme::Ground::level(ground_m, 0.6, 0.0)));
    let (l0, tilt) = (SPAN_M / n as f64, 10f64.to_radians());
    for (top, nodes) in [(0, (1..=7).collect::<Vec<_>>()), (n, (8..n).rev().collect())] {
        let side = if top == 0 { 1.0 } else { -1.0 };
        let (mut y, mut z) = (s.wire().x[1][top], 0.0);
        for i in nodes {
            if z - l0 * tilt.cos() > ground_m {
                (y, z) = (y + side * l0 * tilt.sin(), z - l0 * tilt.cos());
            } else {
                (y, z) = (y + side * l0, ground_m);
            }
            s.wire_mut().x[1][i] = y;
            s.wire_mut().x[2][i] = z;
        }
    }
    let report = statics::solve_on_ground(&mut s, &StaticOptions::default()).unwrap();
    assert!(s.ground().is_some(), "the ground stays on the solver");
    let w = s.wire();
    let k_contact = statics::jacobian::max_axial_stiffness_n_per_m(&s);
    let mut worst: f64 = 0.0;
    for (top, hanging, lying) in [(0, vec![1, 2, 3], 4..=7), (n, vec![49, 48, 47], 8..=46)] {
        let mut z = 0.0;
        for (d, &i) in hanging.iter().enumerate() {
            let below: f64 = hanging[d..].iter().map(|&b| w.mass[b]).sum();
            z -= l0 * (1.0 + G * below / EA_N);
            worst = worst.max((w.x[2][i] - z).abs()).max((w.x[1][i] - w.x[1][top]).abs()).max(w.x[0][i].abs());
        }
        for i in lying {
            let sink = w.mass[i] * G / k_contact;
            assert!((w.x[2][i] - (ground_m - sink)).abs() < 1e-12, "node {i} at {}", w.x[2][i]);
        }
    }
    let reactions = statics::support_reactions(&mut s);
    for (node, r) in &reactions {
        let nodes = if *node == 0 { [0, 1, 2, 3] } else { [n, n - 1, n - 2, n - 3] };
        let carried = G * nodes.iter().map(|&i| s.wire().mass[i]).sum::<f64>();
        println!("support {node}: reaction {r:?} N, hanging weight {carried:.9} N");
        assert!((r[2] - carried).abs() < 1e-8 * carried && r[0].abs().max(r[1].abs()) < 1e-8 * carried, "{r:?}");
    }
    println!("{} iterations; largest position error of the hanging nodes {worst:.2e} m", report.iterations);
    assert!(worst < 1e-8, "{worst}");
}

/// The span state of `ohl run`'s summary and of `--static-after` (`ohl::output::spans::SpanState`) on
/// the solved paper wire, level and inclined (10 m), against the elastic catenary through the same
/// supports with the same unstretched length (`ohl::exact::ElasticCatenary`): its sag at the horizontal
/// middle (`ohl::wire::section::midspan_sag_m`) and its horizontal tension `H`. The discrete chain is a
/// second-order discretisation, so `H` differs from the catenary's by `C ds^2`: asserted to shrink by at
/// least 3 from N = 40 to 80 (order 2 gives 4; measured 4.0) and at N = 80 to be below 1e-3 of `H`. On
/// the level span the middle is node N/2 and the sag converges the same way (asserted likewise). On the
/// inclined span the middle falls between two nodes, whose chord is below the curve by at most
/// `kappa ds^2 / 8` (`kappa = w / H` the curvature), at a place within the segment that changes with N:
/// the sag's error is asserted below `kappa ds^2 / 4` (that interpolation bound plus as much again for
/// the chain's own error, which is 0.47 of it on the level span) and below 1e-3 of the sag at N = 80.
/// The largest tension is the largest segment tension, and no ground means no clearance.
#[test]
fn span_state_gives_the_catenarys_sag_and_horizontal_tension() {
    use ohl::output::spans::SpanState;
    for h in [0.0, 10.0] {
        let mut errors = Vec::new();
        for n in [40, 80] {
            let l0 = 165.0;
            let mut s = solver(wire(n, l0, h, LawKind::TensionOnly, Start::Parabola), None);
            statics::solve(&mut s, &StaticOptions::default()).unwrap();
            s.evaluate_forces();
            let state = SpanState::of(&s, 0, n, None);
            let (a, b) = (s.wire().position(0), s.wire().position(n));
            let cat = ElasticCatenary::solve(a, b, l0, [0.0, 0.0, -RHO * G], EA_N).unwrap();
            let sag = ohl::wire::section::midspan_sag_m(&cat, a, b);
            let (ds, dh) =
                (state.sag_m.unwrap() - sag, state.horizontal_tension_n.unwrap() - cat.horizontal_tension_n());
            println!(
                "h = {h} m, N = {n}: sag {:.6} m (catenary {sag:.6}), H {:.4} N (catenary {:.4})",
                state.sag_m.unwrap(),
                state.horizontal_tension_n.unwrap(),
                cat.horizontal_tension_n()
            );
            let largest = (0..n).map(|j| s.segment_tension(j)).fold(0.0, f64::max);
            assert!((state.max_tension_n - largest).abs() <= 1e-9 * largest);
            assert_eq!(state.least_clearance_m, None);
            let kappa = RHO * G / cat.horizontal_tension_n();
            let step = l0 / n as f64;
            assert!(ds.abs() < kappa * step * step / 4.0, "h = {h}, N = {n}: sag off by {ds} m");
            errors.push((ds.abs() / sag, dh.abs() / cat.horizontal_tension_n()));
        }
        let ((s40, h40), (s80, h80)) = (errors[0], errors[1]);
        assert!(s80 < 1e-3 && h80 < 1e-3, "h = {h}: relative errors at N = 80: sag {s80:.2e}, H {h80:.2e}");
        assert!(h40 > 3.0 * h80, "h = {h}: {errors:?}");
        if h == 0.0 {
            assert!(s40 > 3.0 * s80, "level: {errors:?}");
        }
    }
}

/// `statics::residual` re-hangs a broken span's pieces and lays them on the ground from any final state
/// (here: the intact span's equilibrium with segment 7 broken, the pieces where they were, some nodes
/// below the ground), and finds the exact equilibrium of
/// `a_broken_span_hangs_to_a_frictionless_ground_and_lies_on_it`: each support carries its node and the
/// three hanging ones; the ground carries the rest (tolerance 1e-8 of the weight, as there). The span's
/// state has no sag or horizontal tension (it is broken), and its least clearance is the lying nodes'
/// sink into the penalty contact (1.3e-4 m at most).
#[test]
fn the_residual_state_rehangs_a_broken_span_onto_the_ground() {
    let n = 50;
    let ground_m = -12.0;
    let mut s = solver(wire(n, SPAN_M, 0.0, LawKind::TensionOnly, Start::Parabola), None);
    statics::solve(&mut s, &StaticOptions::default()).unwrap();
    s.wire_mut().break_segment(7);
    s.set_ground(Some(ohl::scheme::Ground::level(ground_m, 0.6, 0.0)));
    let r = statics::residual::residual(&s, &[]).unwrap();
    let w = r.solver.wire();
    let total: f64 = G * w.mass.iter().sum::<f64>();
    let mut carried = 0.0;
    for sup in &r.supports {
        let nodes = if sup.node == 0 { [0, 1, 2, 3] } else { [n, n - 1, n - 2, n - 3] };
        let hanging = G * nodes.iter().map(|&i| w.mass[i]).sum::<f64>();
        carried += hanging;
        let f = sup.force_n;
        println!("support {}: force {f:?} N, hanging weight {hanging:.9} N", sup.node);
        assert!((f[2] + hanging).abs() < 1e-8 * hanging && f[0].abs().max(f[1].abs()) < 1e-8 * hanging, "{f:?}");
    }
    assert!((r.ground_reaction_n[2] - (total - carried)).abs() < 1e-8 * total, "{:?}", r.ground_reaction_n);
    let span = &r.spans[0];
    assert_eq!((span.span, span.nodes), (0, [0, n]));
    assert_eq!((span.state.sag_m, span.state.horizontal_tension_n), (None, None));
    let clearance = span.state.least_clearance_m.unwrap();
    assert!(clearance < 0.0 && clearance > -1.3e-4, "{clearance}");
}
