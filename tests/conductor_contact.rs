//! Contact between conductors (`ohl::line::contact`, evaluated by `ohl::scheme::conductor_contact` in
//! `LineExplicit`), against closed forms of the penalty it is:
//!
//! - pressed together by equal and opposite uniform loads `f'`, two parallel conductors come to rest at the
//!   penetration `delta = f' / k'` exactly (`k' = mu w_c^2`, `mu` the reduced linear density);
//! - a clash of two free parallel conductors is the impact of a linear spring-dashpot of damping ratio
//!   `zeta` that cannot pull: the rebound velocity ratio `e_c` follows in closed form (below); the explicit
//!   scheme approaches it at second order in `w_c dt` (the penalty is scaled to the step, so `w_c dt` is the
//!   only discretisation parameter);
//! - without damping (`e = 1`) the kinetic energy after the clash equals the one before, to the same order;
//! - nothing is evaluated without contact: a line with contact pairs that never touch steps bitwise as
//!   without them.

use ohl::element::tension::LawKind;
use ohl::line::contact::{ConductorContact, ContactError, ContactPair};
use ohl::line::{LineConductor, Model, Role};
use ohl::scheme::{LineExplicit, Loads, StepParams};
use ohl::wire::{Conductor, Constraint, Wire};

/// Linear density [kg/m] and axial stiffness [N] (ACSR Drake, as tests/line.rs).
const RHO: f64 = 1.628;
const EA: f64 = 2.9e7;
/// 20 m conductors of 20 segments.
const LEN: f64 = 20.0;
const N: usize = 20;
/// Conductor radius [m]: gap 2 r between the axes.
const RADIUS: f64 = 0.015;

/// A straight, unstressed wire along `x2` at `x1 = x`, every node free (no supports: it moves as a body).
fn free_wire(x: f64) -> Wire {
    let xs: [Vec<f64>; 3] = [vec![x; N + 1], (0..=N).map(|i| LEN * i as f64 / N as f64).collect(), vec![0.0; N + 1]];
    let c = Conductor { axial_stiffness_n: EA, internal_friction_n_s: 0.0, law: LawKind::TensionOnly };
    let mut w = Wire::new(c, xs, vec![LEN / N as f64; N], RHO);
    w.set_constraint(0, Constraint::Free);
    w.set_constraint(N, Constraint::Free);
    w
}

fn line(a: Wire, b: Wire, dt: f64, damping_per_s: f64, contact: ConductorContact) -> LineExplicit {
    let mut m = Model::new();
    for (k, wire) in [a, b].into_iter().enumerate() {
        m.add_conductor(LineConductor {
            name: format!("C{k}"),
            role: Role::Phase,
            wire,
            loads: Loads::gravity_only(0.0),
        });
    }
    let p = StepParams { dt_s: dt, smoothing: 0.0, mass_damping_per_s: damping_per_s, max_speed_m_per_s: 1e3 };
    let mut l = LineExplicit::new(&m, p).unwrap();
    l.set_contact(Some(contact)).unwrap();
    l
}

fn contact(restitution: f64, stiffness_dt: f64) -> ConductorContact {
    ConductorContact {
        pairs: vec![ContactPair { a: 0, b: 1, gap_m: 2.0 * RADIUS }],
        restitution,
        stiffness_dt,
        stiffness_n_per_m2: None,
    }
}

/// The penetration at rest of two conductors pressed together by `f'` [N/m] each, with `spec`, at the step
/// `dt` [s] (the line may lower it); returns (penetration [m], the line's step [s], contact points touching).
fn rest_penetration(spec: ConductorContact, dt: f64, f: f64) -> (f64, f64, usize) {
    let mut l = line(free_wire(0.0), free_wire(2.0 * RADIUS), dt, 200.0, spec);
    let nodal = |sign: f64| -> [Vec<f64>; 3] {
        let ds = LEN / N as f64;
        let per = (0..=N).map(|i| sign * f * if i == 0 || i == N { 0.5 * ds } else { ds }).collect();
        [per, vec![0.0; N + 1], vec![0.0; N + 1]]
    };
    l.conductor_mut(0).set_nodal_force(Some(nodal(1.0)));
    l.conductor_mut(1).set_nodal_force(Some(nodal(-1.0)));
    let dt = l.params().dt_s;
    // 40 damping times (1 / 200 s each) whatever the step.
    for _ in 0..(2.0 / dt).ceil() as usize {
        l.step(dt).unwrap();
    }
    l.evaluate_forces();
    let (xa, _) = mean_x_v(&l, 0);
    let (xb, _) = mean_x_v(&l, 1);
    (2.0 * RADIUS - (xb - xa), dt, l.contact().unwrap().touching())
}

/// Mean `x1` of a conductor's nodes [m] and its mean `v1` [m/s].
fn mean_x_v(l: &LineExplicit, c: usize) -> (f64, f64) {
    let w = l.conductors()[c].wire();
    let n = w.nodes() as f64;
    (w.x[0].iter().sum::<f64>() / n, w.v[0].iter().sum::<f64>() / n)
}

/// The rebound velocity ratio of the impact of `mu d'' = -k d - c d'` (`d` the penetration, `zeta = c /
/// (2 sqrt(k mu))`, `w^2 = k / mu`) with the force `k d + c d'` never negative: from `d(0) = 0`,
/// `d'(0) = v0`, `d = v0/w_d e^(-zeta w t) sin(w_d t)`; the force vanishes when `tan(w_d t) = -2 zeta
/// sqrt(1 - zeta^2) / (1 - 2 zeta^2)` (past the peak), and the bodies separate with the velocity then:
/// `e_c = e^(-zeta w t_r) |cos(w_d t_r) - zeta w / w_d sin(w_d t_r)|`, a function of `zeta` alone.
fn clamped_restitution(zeta: f64) -> f64 {
    let s = (1.0 - zeta * zeta).sqrt();
    // w = 1: w_d = s; the release angle in (pi/2, pi].
    let phase = std::f64::consts::PI - (2.0 * zeta * s).atan2(1.0 - 2.0 * zeta * zeta);
    let t = phase / s;
    (-zeta * t).exp() * (phase.cos() - zeta / s * phase.sin()).abs()
}

/// Pressed by `f'` [N/m] on each (towards the other), with mass damping, the two come to rest at `gap -
/// f' / k'`. `k' = mu w_c^2`, `mu = RHO / 2`: the relation is exact at rest (every node carries `l_i` of the
/// load and of the penalty; points face points, so the reactions fall on the facing points), so the only
/// error is the residual motion after 40 damping times: the tolerance 1e-9 of the penetration. (The
/// contact points of a segment, at the midpoints of its thirds, give each node exactly its `l_i` share of
/// a uniform penetration's force.)
#[test]
fn pressed_conductors_rest_at_the_penalty_penetration() {
    let (dt, f) = (1.0e-4, 300.0); // s, N/m
    let spec = contact(0.5, 0.25);
    let k = 0.5 * RHO * (spec.stiffness_dt / dt).powi(2);
    let expected = f / k;
    let (delta, _, touching) = rest_penetration(spec, dt, f);
    println!("penetration {delta:.9e} m, f'/k' = {expected:.9e} m (k' = {k:.4e} N/m^2)");
    assert!((delta - expected).abs() < 1e-9 * expected.max(1e-3), "{delta} vs {expected}");
    // Every contact point touches, in both directions.
    assert_eq!(touching, 2 * 3 * N);
}

/// The clash of two free conductors approaching at 2 m/s: the rebound ratio against the closed form
/// `e_c(zeta)` at `w_c dt` = 0.5 (the default), 0.2, 0.1, 0.05. The error falls at FIRST order: the
/// dashpot's force jumps from 0 to `c' v0` at the onset, which falls anywhere within a step (the spring
/// alone is second order: `undamped_clash_keeps_the_kinetic_energy`). Measured at the default: 6.7e-2
/// (12 % of e_c) for e = 0.5, the clash more dissipative than asked (reading the closing speed extrapolated
/// to the level instead of at the half step was tried and changed nothing measurable). Asserted: the
/// observed order of the last pair within 1 +- 0.2, and the error at the default below 15 % of `e_c` for e
/// = 0.5 and 40 % for e = 0.2 (measured 34 %; the restitution of clashing conductors is itself an assumption,
/// docs/short_circuit.md).
#[test]
fn clash_rebound_matches_the_clamped_spring_dashpot() {
    for e in [0.5, 0.2] {
        let spec0 = contact(e, 0.25);
        let zeta = spec0.damping_ratio();
        let e_c = clamped_restitution(zeta);
        let mut errs = vec![];
        let rates = [0.5, 0.2, 0.1, 0.05];
        for &wdt in &rates {
            let dt = 1.0e-4;
            let mut l = line(free_wire(0.0), free_wire(0.1), dt, 0.0, contact(e, wdt));
            let v0 = 1.0;
            for c in 0..2 {
                let s = if c == 0 { v0 } else { -v0 };
                l.conductor_mut(c).wire_mut().v[0].fill(s);
            }
            // Approach (0.1 - 0.03) / 2 m/s = 35 ms, then the contact lasts about pi / w_c.
            let t_end = 0.035 + 3.0 * std::f64::consts::PI * dt / wdt + 0.01;
            let steps = (t_end / dt).ceil() as usize;
            for _ in 0..steps {
                l.step(dt).unwrap();
            }
            l.evaluate_forces();
            assert_eq!(l.contact().unwrap().touching(), 0, "still in contact at the end");
            let (_, va) = mean_x_v(&l, 0);
            let (_, vb) = mean_x_v(&l, 1);
            let ratio = (vb - va) / (2.0 * v0);
            let err = (ratio - e_c).abs();
            println!("e = {e}: w_c dt = {wdt}: rebound ratio {ratio:.8}, closed form {e_c:.8}, error {err:.3e}");
            errs.push(err);
        }
        let bound = if e == 0.5 { 0.15 } else { 0.4 };
        assert!(errs[0] < bound * e_c, "e = {e}: error {} at the default", errs[0]);
        let p = (errs[2] / errs[3]).ln() / 2f64.ln();
        println!("e = {e}: order of the last pair {p:.3}");
        assert!((p - 1.0).abs() < 0.2, "e = {e}: order {p}");
    }
}

/// Without damping the clash is elastic: the kinetic energy after it equals the one before (both bodies
/// move as rigid bodies before and after), to second order in `w_c dt`.
#[test]
fn undamped_clash_keeps_the_kinetic_energy() {
    let mut errs = vec![];
    for &wdt in &[0.2, 0.1] {
        let dt = 1.0e-4;
        let mut l = line(free_wire(0.0), free_wire(0.1), dt, 0.0, contact(1.0, wdt));
        for c in 0..2 {
            l.conductor_mut(c).wire_mut().v[0].fill(if c == 0 { 1.0 } else { -1.0 });
        }
        l.evaluate_forces();
        let e0 = l.energies();
        let steps = ((0.035 + 3.0 * std::f64::consts::PI * dt / wdt + 0.01) / dt).ceil() as usize;
        for _ in 0..steps {
            l.step(dt).unwrap();
        }
        l.evaluate_forces();
        let e1 = l.energies();
        let rel = ((e1.kinetic_j + e1.elastic_j) - (e0.kinetic_j + e0.elastic_j)).abs() / e0.kinetic_j;
        println!("w_c dt = {wdt}: relative energy change {rel:.3e}");
        errs.push(rel);
    }
    assert!(errs[0] < 1e-2, "{errs:?}");
    assert!(errs[1] < errs[0] / 3.0, "{errs:?}");
}

/// Pairs that never touch change nothing: bitwise the run without contact.
#[test]
fn no_touch_no_change() {
    let dt = 1.0e-4;
    let run = |with: bool| {
        let mut l = line(free_wire(0.0), free_wire(0.5), dt, 0.0, contact(0.5, 0.25));
        if !with {
            l.set_contact(None).unwrap();
        }
        l.conductor_mut(0).wire_mut().v[0].fill(0.3);
        l.conductor_mut(0).wire_mut().v[2][N / 2] = 0.2;
        for _ in 0..500 {
            l.step(dt).unwrap();
        }
        l.conductors()[0].wire().x.clone()
    };
    assert_eq!(run(true), run(false));
}

/// A contact of given stiffness `k'` is the same spring whatever the step: pressed by `f'`, the two rest at
/// `f' / k'` at two steps a factor 2 apart (tolerance as `pressed_conductors_rest_at_the_penalty_penetration`:
/// the residual motion after 40 damping times), where the step-scaled penalty's penetration falls as `dt^2`.
#[test]
fn given_stiffness_rests_at_its_penetration_at_every_step() {
    let (f, k) = (300.0, 2.0e7);
    let expected = f / k;
    for dt in [1.0e-4, 0.5e-4] {
        let spec = ConductorContact { stiffness_n_per_m2: Some(k), ..contact(0.5, 0.5) };
        let (delta, step, _) = rest_penetration(spec, dt, f);
        println!("dt = {dt:e} s (line step {step:e} s): penetration {delta:.9e} m, f'/k' = {expected:.9e} m");
        assert_eq!(step, dt, "k' = {k:e} is stable at {dt:e} s: the step is kept");
        assert!((delta - expected).abs() < 1e-9 * expected, "{delta} vs {expected}");
    }
}

/// A contact stiffer than the step allows lowers the line's step to `stiffness_dt / w_c`, `w_c = sqrt(k' /
/// mu)`, `mu = RHO / 2` (the reduced density of two equal conductors), and scales the smoothing by the same
/// ratio (the same viscosity per second); the contact is then the given spring (rest penetration exact).
#[test]
fn stiff_contact_lowers_the_step() {
    let k = 1.0e9;
    let limit = 0.5 / (k / (0.5 * RHO)).sqrt();
    let mut m = Model::new();
    for (c, x) in [0.0, 1.0].into_iter().enumerate() {
        m.add_conductor(LineConductor {
            name: format!("C{c}"),
            role: Role::Phase,
            wire: free_wire(x),
            loads: Loads::gravity_only(0.0),
        });
    }
    let p = StepParams { dt_s: 1e-4, smoothing: 0.002, mass_damping_per_s: 0.0, max_speed_m_per_s: 1e3 };
    let mut l = LineExplicit::new(&m, p).unwrap();
    l.set_contact(Some(ConductorContact { stiffness_n_per_m2: Some(k), ..contact(0.5, 0.5) })).unwrap();
    let got = *l.params();
    println!("step {:.6e} s (limit {limit:.6e} s), smoothing {:.6e}", got.dt_s, got.smoothing);
    assert_eq!(got.dt_s, limit);
    assert!((got.smoothing - 0.002 * limit / 1e-4).abs() < 1e-15);
    for c in l.conductors() {
        assert_eq!(c.params().dt_s, limit);
        assert_eq!(c.params().smoothing, got.smoothing);
    }
    let (delta, step, _) =
        rest_penetration(ConductorContact { stiffness_n_per_m2: Some(k), ..contact(0.5, 0.5) }, 1e-4, 300.0);
    assert_eq!(step, limit);
    assert!((delta - 300.0 / k).abs() < 1e-9 * (300.0 / k), "{delta}");
}

#[test]
fn refuses_bad_pairs() {
    let l = line(free_wire(0.0), free_wire(0.5), 1e-4, 0.0, ConductorContact::default());
    let mut l = l;
    let bad = ConductorContact { pairs: vec![ContactPair { a: 0, b: 2, gap_m: 0.03 }], ..ConductorContact::default() };
    assert!(matches!(l.set_contact(Some(bad)), Err(ContactError::Pair { pair: 0, .. })));
    let bad = ConductorContact { pairs: vec![ContactPair { a: 1, b: 1, gap_m: 0.03 }], ..ConductorContact::default() };
    assert!(matches!(l.set_contact(Some(bad)), Err(ContactError::Pair { .. })));
    let bad = ConductorContact { restitution: 0.0, ..ConductorContact::default() };
    assert!(matches!(l.set_contact(Some(bad)), Err(ContactError::Value { .. })));
    let bad = ConductorContact { stiffness_n_per_m2: Some(1e13), ..ConductorContact::default() };
    assert!(matches!(l.set_contact(Some(bad)), Err(ContactError::Value { .. })));
}
