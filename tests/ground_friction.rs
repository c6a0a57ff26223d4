//! Coulomb friction on the ground (`Ground::friction`): a wire lying on the ground and sliding along it
//! at `v0` decelerates at `mu_g g` and stops after `v0^2 / (2 mu_g g)`, the exact result for a body
//! sliding on a plane (the wire moves as a rigid body: every node has the same velocity, so no segment
//! changes length). With restitution the node bounces by tiny amounts on every step, but the normal
//! impulse summed over the contacts still equals the weight's impulse, so the same distance holds.
//!
//! Tolerance: the contact acts once per step, so the stopping time is resolved to `dt` and the distance
//! to about `v0 dt`: 5e-3 m here for `dt = 1e-3 s`; asserted at 2 v0 dt.

use ohl::element::tension::LawKind;
use ohl::scheme::{Explicit, Ground, Loads, StepParams};
use ohl::wire::{Conductor, Constraint, Wire};

const G: f64 = 9.81;

/// A free wire of `n` unit segments lying on the ground `x3 = 0` along `x2`, sliding at `v0` [m/s].
fn lying_wire(n: usize, v0: f64, dt: f64, ground: Ground) -> Explicit {
    let x = [vec![0.0; n + 1], (0..=n).map(|i| i as f64).collect(), vec![0.0; n + 1]];
    let conductor = Conductor { axial_stiffness_n: 1.0e5, internal_friction_n_s: 0.0, law: LawKind::TensionOnly };
    let mut w = Wire::new(conductor, x, vec![1.0; n], 1.0);
    w.set_constraint(0, Constraint::Free);
    w.set_constraint(n, Constraint::Free);
    w.v[1].fill(v0);
    let loads = Loads::gravity_only(G);
    let params = StepParams { dt_s: dt, smoothing: 0.0, mass_damping_per_s: 0.0, max_speed_m_per_s: 1e3 };
    let mut s = Explicit::new(w, loads, params);
    s.set_ground(Some(ground));
    s
}

fn slide(mu: f64, restitution: f64, v0: f64, dt: f64) -> f64 {
    let mut s = lying_wire(4, v0, dt, Ground::level(0.0, restitution, mu));
    let x0 = s.wire().x[1][0];
    for _ in 0..((2.0 * v0 / (mu * G)) / dt) as usize {
        s.step(dt).unwrap();
    }
    assert!(s.wire().v[1].iter().all(|v| v.abs() < 1e-12), "still sliding: {:?}", s.wire().v[1]);
    s.wire().x[1][0] - x0
}

#[test]
fn a_sliding_wire_stops_after_the_coulomb_distance() {
    let (v0, dt) = (5.0, 1.0e-3);
    for (mu, e) in [(0.5, 0.0), (0.3, 0.0), (0.5, 0.5)] {
        let d = slide(mu, e, v0, dt);
        let exact = v0 * v0 / (2.0 * mu * G);
        println!("mu = {mu}, e = {e}: slid {d:.5} m, exact {exact:.5} m, error {:+.2e} m", d - exact);
        assert!((d - exact).abs() < 2.0 * v0 * dt, "mu = {mu}, e = {e}: {d} vs {exact}");
    }
}

#[test]
fn without_friction_it_slides_on() {
    // The frictionless ground of the paper (4.4): the velocity along the ground is kept.
    let mut s = lying_wire(2, 2.0, 1e-3, Ground::level(0.0, 0.6, 0.0));
    for _ in 0..1000 {
        s.step(1e-3).unwrap();
    }
    // Kept up to the rounding of the segment lengths as the nodes move (tiny tensions): 1e-9 m/s.
    assert!(s.wire().v[1].iter().all(|&v| (v - 2.0).abs() < 1e-9), "{:?}", s.wire().v[1]);
}
