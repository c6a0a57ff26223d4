//! The two-material law of a real conductor (src/conductor) in the explicit kernel and the static solver
//! (src/wire/material.rs), against independent expectations:
//!
//! - two LINEAR materials: the law is piecewise linear, so a span below the knee point is Irvine's elastic
//!   catenary with `EA = K_o + K_c` and the stiffness-weighted thermal strain, above it the core's alone;
//!   the static finite-difference solution converges to it at the observed order 2 (sag and H);
//! - Drake's published stress-strain polynomials (Aluminum Association form, OTLS-Models fixture,
//!   docs/conductor_data.md): a taut wire in the explicit kernel loaded then unloaded follows the virgin
//!   curve up, the final-modulus line down, and carries nothing exactly below the closed-form permanent
//!   set `m - C(m) / K_u`;
//! - a span iced then de-iced (static stretch solves, and the explicit kernel settling with damping)
//!   hangs afterwards exactly as the elastic catenary of the unloaded law: each material on its
//!   unloading line from the largest strain it reached, i.e. a linear wire whose stress-free length is
//!   the virgin one plus the closed-form permanent set.

use ohl::conductor::{Component, Curve, CurveKind, TwoMaterial};
use ohl::element::tension::LawKind;
use ohl::exact::ElasticCatenary;
use ohl::scheme::{Explicit, Loads, StepParams};
use ohl::statics::{self, StaticOptions};
use ohl::wire::{Conductor, Wire};

const G: f64 = 9.81;
/// Drake's mass per length [kg/m] (1.094 lb/ft)
const RHO: f64 = 1.094 * 0.45359237 / 0.3048;
/// the polynomials' reference temperature [K] (70 F)
const THETA_REF: f64 = 294.261;
const PSI: f64 = 6894.757;
/// Drake's total area [m^2] (0.7264 in^2), on which the published stresses are given
const AREA: f64 = 0.7264 * 6.4516e-4;

/// Drake's final (unloading) stiffnesses `K_u` [N]: 64000 and 37000 psi per % strain on the total area.
fn k_final() -> [f64; 2] {
    [64000.0 * PSI * 100.0 * AREA, 37000.0 * PSI * 100.0 * AREA]
}

/// Drake's expansion coefficients [1/K] (12.8e-6 and 6.4e-6 per F).
const ALPHA: [f64; 2] = [12.8e-6 * 1.8, 6.4e-6 * 1.8];

/// Drake's published initial polynomials (psi on the total area vs strain in %) and their limits [psi].
const AL_INITIAL: ([f64; 5], f64) = ([-1213.0, 44308.1, -14004.4, -37618.0, 30676.0], 20252.0);
const ST_INITIAL: ([f64; 5], f64) = ([-69.3, 38629.0, 3998.1, -45713.0, 27892.0], 19154.0);

/// The published polynomial evaluated directly: force [N] at the mechanical strain `e` [-] (inside the
/// fitted range; the independent closed form the kernel's law is compared with).
fn published(p: ([f64; 5], f64), e: f64) -> f64 {
    let x = 100.0 * e;
    let a = p.0;
    (a[0] + a[1] * x + a[2] * x * x + a[3] * x.powi(3) + a[4] * x.powi(4)) * PSI * AREA
}

fn drake_component(p: ([f64; 5], f64), k: f64, alpha: f64, area: f64) -> Component {
    let curve = Curve::from_percent(p.0.map(|x| x * PSI), AREA, Some(p.1 * PSI)).unwrap();
    Component {
        area_m2: area,
        expansion_per_k: alpha,
        initial: curve,
        creep: None,
        unloading_stiffness_n: k,
        compression_stiffness_n: 0.0,
    }
}

/// Drake (ACSR 26/7) with its published initial curves and final moduli.
pub(crate) fn drake() -> TwoMaterial {
    let k = k_final();
    TwoMaterial {
        outer: drake_component(AL_INITIAL, k[0], ALPHA[0], 4.0283e-4),
        core: Some(drake_component(ST_INITIAL, k[1], ALPHA[1], 6.560e-5)),
        reference_temperature_k: THETA_REF,
    }
}

/// A level span of `span` [m] on `n` segments with total reference length `length` [m], hanging on a
/// parabola of sag `span / 30` to start, following `law` at the temperature `theta` [K].
fn span_wire(n: usize, span: f64, length: f64, law: TwoMaterial, theta: f64) -> Wire {
    let mut x = [vec![0.0; n + 1], vec![0.0; n + 1], vec![0.0; n + 1]];
    for i in 0..=n {
        let s = i as f64 / n as f64;
        x[1][i] = s * span;
        x[2][i] = -4.0 * s * (1.0 - s) * span / 30.0;
    }
    let c = Conductor { axial_stiffness_n: 1.0, internal_friction_n_s: 0.0, law: LawKind::TensionOnly };
    let mut w = Wire::new(c, x, vec![length / n as f64; n], RHO);
    w.set_two_material(law, CurveKind::Initial);
    w.set_temperature(0..n, theta);
    w
}

fn solver(w: Wire, dt: f64, damping: f64) -> Explicit {
    let loads = Loads::gravity_only(G);
    Explicit::new(
        w,
        loads,
        StepParams { dt_s: dt, smoothing: 0.0, mass_damping_per_s: damping, max_speed_m_per_s: 1e3 },
    )
}

/// Mid-span sag [m] (the middle node below the chord of a level span, `n` even) and the horizontal
/// tension `H` [N] (segment 0's tension times its tangent's `x2`; constant along a level span under
/// vertical loads, node by node).
fn sag_and_h(s: &Explicit) -> (f64, f64) {
    let w = s.wire();
    let n = w.segments();
    let sag = -w.x[2][n / 2];
    let d = [w.x[0][1] - w.x[0][0], w.x[1][1] - w.x[1][0], w.x[2][1] - w.x[2][0]];
    let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    (sag, s.segment_tension(0) * d[1] / len)
}

/// Least-squares slope of log(error) against log(1/N) [-].
fn fitted_order(ns: &[usize], errors: &[f64]) -> f64 {
    let xs: Vec<f64> = ns.iter().map(|&n| -(n as f64).ln()).collect();
    let ys: Vec<f64> = errors.iter().map(|e| e.ln()).collect();
    let (mx, my) = (xs.iter().sum::<f64>() / xs.len() as f64, ys.iter().sum::<f64>() / ys.len() as f64);
    let num: f64 = xs.iter().zip(&ys).map(|(x, y)| (x - mx) * (y - my)).sum();
    let den: f64 = xs.iter().map(|x| (x - mx).powi(2)).sum();
    num / den
}

#[test]
fn two_linear_materials_hang_as_the_elastic_catenary_below_and_above_the_knee_at_order_two() {
    // Drake's final stiffnesses as two linear materials (no compression): below the knee
    // T = K_o (e - a_o d) + K_c (e - a_c d) = K (e - a d), K = K_o + K_c, a = (K_o a_o + K_c a_c) / K;
    // above it T = K_c (e - a_c d). With the strain on the reference length L, T = K (e - a d) is Irvine's
    // elastic catenary of unstretched length L (1 + a d), stiffness K (1 + a d) and weight rho g / (1 + a d)
    // per unit of that length (module doc of src/exact/catenary.rs).
    let k = k_final();
    let law = TwoMaterial {
        outer: Component::linear(4.0283e-4, k[0] / 4.0283e-4, ALPHA[0]),
        core: Some(Component::linear(6.560e-5, k[1] / 6.560e-5, ALPHA[1])),
        reference_temperature_k: THETA_REF,
    };
    let (span, length) = (300.0, 300.25);
    // 20 C below the reference (both carry), and 250 K above it (the aluminium slack: the knee of this
    // span is near 120 K above the reference).
    for (d, above) in [(-20.0, false), (250.0, true)] {
        let theta = THETA_REF + d;
        let (kk, a) =
            if above { (k[1], ALPHA[1]) } else { (k[0] + k[1], (k[0] * ALPHA[0] + k[1] * ALPHA[1]) / (k[0] + k[1])) };
        let f = 1.0 + a * d;
        let exact =
            ElasticCatenary::solve([0.0; 3], [0.0, span, 0.0], length * f, [0.0, 0.0, -RHO * G / f], kk * f).unwrap();
        let (sag_x, h_x) = (-exact.midspan_displacement_m()[2], exact.horizontal_tension_n());
        let ns = [10, 20, 40, 80];
        let (mut es, mut eh) = (vec![], vec![]);
        for &n in &ns {
            let mut s = solver(span_wire(n, span, length, law, theta), 1e-4, 0.0);
            statics::solve(&mut s, &StaticOptions::default()).unwrap();
            // Every segment on the branch the closed form assumes (the knee strain is a_o d).
            let knee = ALPHA[0] * d;
            for j in 0..n {
                let e = s.wire().strain(j);
                assert!(if above { e < knee } else { e > knee }, "segment {j} at d = {d}: e {e} vs knee {knee}");
            }
            let (sag, h) = sag_and_h(&s);
            es.push((sag - sag_x).abs());
            eh.push((h - h_x).abs());
        }
        let (ps, ph) = (fitted_order(&ns[1..], &es[1..]), fitted_order(&ns[1..], &eh[1..]));
        eprintln!("d = {d} K: sag {sag_x:.6} m, H {h_x:.3} N; errors sag {es:?} H {eh:?}; orders {ps:.3} {ph:.3}");
        assert!((ps - 2.0).abs() <= 0.1 && (ph - 2.0).abs() <= 0.1, "orders {ps} {ph}");
    }
}

/// Closed form of one material of the test: force [N] at mechanical strain `e` with largest strain `m`
/// on the published curve `p`, unloading stiffness `k` (no compression).
fn closed_form(p: ([f64; 5], f64), k: f64, e: f64, m: f64) -> f64 {
    if e >= m { published(p, e) } else { (published(p, m) + k * (e - m)).max(0.0) }
}

#[test]
fn a_taut_wire_loaded_then_unloaded_returns_along_the_modulus_line_to_the_permanent_set() {
    // Drake's aluminium alone, at its reference temperature, 4 segments of 10 m along x2, no gravity: the
    // right end pulled out to 0.3 % strain and back to zero over 2 s each, slowly (the longitudinal
    // period is 2 * 40 m / 3.6 km/s = 0.02 s) and with damping, so the wire stays nearly uniform.
    let k = k_final()[0];
    let law = TwoMaterial {
        outer: drake_component(AL_INITIAL, k, ALPHA[0], 4.0283e-4),
        core: None,
        reference_temperature_k: THETA_REF,
    };
    let n = 4;
    let x = [vec![0.0; n + 1], (0..=n).map(|i| 10.0 * i as f64).collect(), vec![0.0; n + 1]];
    let c = Conductor { axial_stiffness_n: 1.0, internal_friction_n_s: 0.0, law: LawKind::TensionOnly };
    let mut w = Wire::new(c, x, vec![10.0; n], RHO);
    w.set_two_material(law, CurveKind::Initial);
    w.set_temperature(0..n, THETA_REF);
    let ez = law.outer.initial.zero_strain();
    let dt = 0.5 * 10.0 / (w.axial_stiffness_n[0] / RHO).sqrt();
    let mut s = Explicit::new(
        w,
        Loads::gravity_only(0.0),
        StepParams { dt_s: dt, smoothing: 0.0, mass_damping_per_s: 20.0, max_speed_m_per_s: 1e3 },
    );
    let (peak, t_ramp) = (0.003, 2.0);
    let steps = (2.0 * t_ramp / dt).ceil() as usize;
    let mut m = vec![ez; n];
    let (mut slack_seen, mut checked) = (0, 0);
    let scale = published(AL_INITIAL, peak);
    for step in 0..steps {
        let t = step as f64 * dt;
        let end = 40.0 * (1.0 + peak * if t < t_ramp { t / t_ramp } else { 2.0 - t / t_ramp });
        s.wire_mut().x[1][n] = end;
        // The level the step advances: its strains join the history (Material::advance).
        for (j, mj) in m.iter_mut().enumerate() {
            *mj = mj.max(s.wire().strain(j));
        }
        s.step(dt).unwrap();
        let hist = &s.wire().material.as_ref().unwrap().max_strain[0];
        assert_eq!(hist, &m, "the kernel's history is the largest strain reached, bit for bit");
        for j in 0..n {
            let e = s.wire().strain(j);
            let tension = s.segment_tension(j);
            let expect = closed_form(AL_INITIAL, k, e, m[j]);
            // The same polynomial in two evaluation orders (Horner on the fraction vs powers of the
            // percentage): rounding of a few ulps of the largest term, 1e-12 of the peak force.
            assert!((tension - expect).abs() <= 1e-12 * scale, "step {step} segment {j}: {tension} vs {expect}");
            let permanent = m[j] - published(AL_INITIAL, m[j]) / k;
            if t > t_ramp && e < m[j] {
                checked += 1;
                // Carries exactly above the closed-form permanent set, nothing at or below it.
                assert_eq!(tension > 0.0, e > permanent, "step {step} segment {j}: e {e}, permanent set {permanent}");
                if tension == 0.0 {
                    slack_seen += 1;
                }
            }
        }
    }
    let hist = &s.wire().material.as_ref().unwrap().max_strain[0];
    let sets: Vec<f64> = hist.iter().map(|&mj| mj - published(AL_INITIAL, mj) / k).collect();
    eprintln!(
        "virgin slack {ez:.6e}, largest strains {hist:?}, permanent sets {sets:?}; {checked} unloading checks, {slack_seen} slack"
    );
    assert!(slack_seen > 0 && checked > 1000);
    assert!(
        sets.iter().all(|&p| p > ez + 1e-4),
        "loading to 0.3 % leaves a permanent set well beyond the virgin slack"
    );
}

/// The linear wire equivalent to a two-material wire unloaded from its history: each material on its
/// unloading line `F_k = K_k (e - a_k d - e_pk)`, `e_pk = m_k - C_k(m_k) / K_k` (closed form from the
/// published curve), so `T = K (e - e_0)` with `K = K_o + K_c`, `e_0 = sum K_k (e_pk + a_k d) / K`: a
/// linear-law segment of stress-free length `L (1 + e_0)` and stiffness `K (1 + e_0)`. Also returns the
/// strain range each segment must stay in for the equivalence (above both slack strains, below both
/// largest strains). Its nodes start from `start`'s (so that its solve finds the equilibrium itself).
fn unloaded_equivalent(two: &Wire, start: &Wire, theta: f64) -> (Wire, Vec<(f64, f64)>) {
    let k = k_final();
    let mat = two.material.as_ref().unwrap();
    let d = theta - THETA_REF;
    let n = two.segments();
    let c = Conductor { axial_stiffness_n: 1.0, internal_friction_n_s: 0.0, law: LawKind::Linear };
    let mut w = Wire::new(c, start.x.clone(), two.reference_length.clone(), RHO);
    let mut range = Vec::new();
    for j in 0..n {
        let (mo, mc) = (mat.max_strain[0][j], mat.max_strain[1][j]);
        let ep = [mo - published(AL_INITIAL, mo) / k[0], mc - published(ST_INITIAL, mc) / k[1]];
        let e0 = (k[0] * (ep[0] + ALPHA[0] * d) + k[1] * (ep[1] + ALPHA[1] * d)) / (k[0] + k[1]);
        w.rest_length[j] = two.reference_length[j] * (1.0 + e0);
        w.axial_stiffness_n[j] = (k[0] + k[1]) * (1.0 + e0);
        let lo = (ep[0] + ALPHA[0] * d).max(ep[1] + ALPHA[1] * d);
        let hi = (mo + ALPHA[0] * d).min(mc + ALPHA[1] * d);
        range.push((lo, hi));
    }
    (w, range)
}

/// Largest distance between the nodes of two wires [m].
fn distance(a: &Wire, b: &Wire) -> f64 {
    (0..a.nodes()).map(|i| (0..3).map(|k| (a.x[k][i] - b.x[k][i]).powi(2)).sum::<f64>().sqrt()).fold(0.0, f64::max)
}

#[test]
fn a_span_stretched_by_ice_hangs_lower_as_the_elastic_catenary_of_its_permanent_set() {
    // Drake, 300 m level span, reference length 300.25 m (about 19 kN bare at 15 C), 40 segments; 3 kg/m
    // of ice (a radial 25 mm shell weighs 2.0 kg/m on Drake; heavier to stretch it clearly).
    let (n, span, length, theta, ice) = (40, 300.0, 300.25, 288.15, 3.0);
    let opts = StaticOptions::default();
    let mut s = solver(span_wire(n, span, length, drake(), theta), 1e-4, 0.0);
    statics::solve(&mut s, &opts).unwrap();
    let (sag0, h0) = sag_and_h(&s);
    assert_eq!(
        s.wire().material.as_ref().unwrap().max_strain,
        {
            let v = drake().virgin(CurveKind::Initial).max_strain;
            [vec![v[0]; n], vec![v[1]; n]]
        },
        "a static solve holds the history"
    );
    assert!(s.wire_mut().add_linear_density(0..n, ice));
    statics::solve(&mut s, &opts).unwrap();
    let (sag_ice, h_ice) = sag_and_h(&s);
    s.wire_mut().load_history();
    assert!(s.wire_mut().add_linear_density(0..n, -ice));
    statics::solve(&mut s, &opts).unwrap();
    let (sag1, h1) = sag_and_h(&s);
    let (mut eq, range) = unloaded_equivalent(s.wire(), &span_wire(n, span, length, drake(), theta), theta);
    for j in 0..n {
        let e = s.wire().strain(j);
        assert!(e > range[j].0 && e < range[j].1, "segment {j}: strain {e} outside {:?}", range[j]);
    }
    let mut lin = solver(std::mem::replace(&mut eq, s.wire().clone()), 1e-4, 0.0);
    statics::solve(&mut lin, &opts).unwrap();
    let (sag_eq, h_eq) = sag_and_h(&lin);
    let dist = distance(s.wire(), lin.wire());
    eprintln!(
        "static: sag {sag0:.4} m / H {h0:.1} N bare virgin, {sag_ice:.4} / {h_ice:.1} iced, {sag1:.4} / {h1:.1} after; \
         equivalent {sag_eq:.4} / {h_eq:.1}; largest node distance {dist:.3e} m"
    );
    assert!(sag1 > sag0 + 0.05, "the stretched span hangs lower");
    // Both solves converge to the default tolerance (1e-10 of the nodal load or 32 rounding floors): the
    // nodes are then within residual / stiffness ~ 1e-9 m of the exact discrete equilibria, which are the
    // same equilibrium of the same piecewise-linear law (rounding apart).
    assert!(dist < 1e-7, "{dist}");
    assert!((h1 - h_eq).abs() < 1e-6 * h_eq);

    // The same in the explicit kernel: ice applied suddenly (so the dynamic overshoot stretches further),
    // settled with mass damping, ice removed, settled again.
    let w0 = span_wire(n, span, length, drake(), theta);
    let dt = 0.8 * (span / n as f64) / (w0.axial_stiffness_n[0] / RHO).sqrt();
    let mut d = solver(w0, dt, 1.0);
    statics::solve(&mut d, &opts).unwrap();
    let settle = |d: &mut Explicit| {
        for _ in 0..(120.0 / dt) as usize {
            d.step(dt).unwrap();
        }
        let w = d.wire();
        (0..w.nodes()).map(|i| (0..3).map(|k| w.v[k][i].abs()).fold(0.0, f64::max)).fold(0.0, f64::max)
    };
    assert!(d.wire_mut().add_linear_density(0..n, ice));
    let v_ice = settle(&mut d);
    let m_dyn = d.wire().material.as_ref().unwrap().max_strain[0][0];
    assert!(d.wire_mut().add_linear_density(0..n, -ice));
    let v_end = settle(&mut d);
    let (mut eq, range) = unloaded_equivalent(d.wire(), &span_wire(n, span, length, drake(), theta), theta);
    for j in 0..n {
        let e = d.wire().strain(j);
        assert!(e > range[j].0 && e < range[j].1, "segment {j}: strain {e} outside {:?}", range[j]);
    }
    let mut lin = solver(std::mem::replace(&mut eq, d.wire().clone()), 1e-4, 0.0);
    statics::solve(&mut lin, &opts).unwrap();
    let (sag_d, _) = sag_and_h(&d);
    let (sag_eq, _) = sag_and_h(&lin);
    let dist = distance(d.wire(), lin.wire());
    eprintln!(
        "dynamic: largest speed {v_ice:.2e} m/s iced, {v_end:.2e} after; history m_o[0] {m_dyn:.6e} (static {:.6e}); \
         sag {sag_d:.4} m, equivalent {sag_eq:.4} m; largest node distance {dist:.3e} m",
        s.wire().material.as_ref().unwrap().max_strain[0][0]
    );
    assert!(sag_d > sag1, "the sudden load's overshoot stretched the span further than the static stretch");
    // Settled to speeds v: with damping zeta = 1/s the remaining force imbalance is about m v zeta per
    // node, a displacement of that over the transverse stiffness; bounded here by 1e-6 m.
    assert!(v_end < 1e-9 && dist < 1e-6, "{v_end} {dist}");
}

#[test]
fn a_section_with_suspension_strings_stretched_by_ice_hangs_as_its_permanent_set_says() {
    // Three spans of 250, 350 and 300 m of Drake (dead-ends at 30 m, two suspension strings of 2.5 m,
    // 60 kg, EA 3e7 N, from pivots at 32.5 m), strung at 25 kN with the strings plumb (lengths from the
    // catalogue-like EA 3.6e7 N), 30 segments per span, then run with Drake's two-material law at 15 C:
    // static solve bare (virgin), 3 kg/m of ice, static stretch (Wire::load_history), ice removed, static
    // solve; then the same with the ice applied and removed in the explicit kernel with damping. The
    // result must be the equilibrium of the linear equivalent (unloaded_equivalent) solved from the
    // virgin shape, strings included.
    use ohl::wire::section::{Section, Span, Stringing, Support, build};
    let theta = 288.15;
    let suspension = |y: f64| Support::Suspension {
        pivot_m: [0.0, y, 32.5],
        length_m: 2.5,
        mass_kg: 60.0,
        stiffness_n: 3.0e7,
        crossarm: None,
    };
    let c = Conductor { axial_stiffness_n: 3.6e7, internal_friction_n_s: 0.0, law: LawKind::TensionOnly };
    let span = |_| Span {
        conductor: c,
        linear_density_kg_per_m: RHO,
        segments: 30,
        stringing: Stringing::HorizontalTension(25e3),
    };
    let sec = Section {
        supports: vec![
            Support::DeadEnd { point_m: [0.0, 0.0, 30.0] },
            suspension(250.0),
            suspension(600.0),
            Support::DeadEnd { point_m: [0.0, 900.0, 30.0] },
        ],
        spans: (0..3).map(span).collect(),
        gravity_m_per_s2: G,
    };
    let (mut virgin, layout) = build(&sec).unwrap();
    let n = virgin.segments();
    virgin.set_two_material(drake(), CurveKind::Initial);
    virgin.set_temperature(0..n, theta);
    let mids: Vec<usize> = (0..3).map(|k| (layout.first_node[k] + layout.first_node[k + 1]) / 2).collect();
    let heights = |w: &Wire| mids.iter().map(|&i| w.x[2][i]).collect::<Vec<_>>();
    let opts = StaticOptions::default();
    let linear_check = |two: &Wire, label: &str| {
        let (eq, range) = unloaded_equivalent(two, &virgin, theta);
        for j in 0..n {
            let e = two.strain(j);
            assert!(e > range[j].0 && e < range[j].1, "{label}: segment {j}: strain {e} outside {:?}", range[j]);
        }
        // Keep the strings: the equivalent is the two-material wire with the linear law per segment.
        let mut w = two.clone();
        w.law = LawKind::Linear;
        w.material = None;
        w.rest_length.copy_from_slice(&eq.rest_length);
        w.axial_stiffness_n.copy_from_slice(&eq.axial_stiffness_n);
        for k in 0..3 {
            w.x[k].copy_from_slice(&virgin.x[k]);
        }
        let mut lin = solver(w, 1e-4, 0.0);
        statics::solve(&mut lin, &opts).unwrap();
        let dist = distance(two, lin.wire());
        eprintln!(
            "{label}: mid-span heights {:?} m, equivalent {:?} m; largest node distance {dist:.3e} m",
            heights(two),
            heights(lin.wire())
        );
        dist
    };
    let mut s = solver(virgin.clone(), 1e-4, 0.0);
    statics::solve(&mut s, &opts).unwrap();
    let before = heights(s.wire());
    assert!(s.wire_mut().add_linear_density(0..n, 3.0));
    statics::solve(&mut s, &opts).unwrap();
    s.wire_mut().load_history();
    assert!(s.wire_mut().add_linear_density(0..n, -3.0));
    statics::solve(&mut s, &opts).unwrap();
    let after = heights(s.wire());
    eprintln!("static: mid-span heights bare virgin {before:?} m, after the ice {after:?} m");
    assert!(before.iter().zip(&after).all(|(b, a)| a < &(b - 0.05)), "every span hangs lower");
    // Both solves converge to the default tolerance: nodes within ~1e-9 m of the same equilibrium.
    let d_static = linear_check(s.wire(), "static");
    assert!(d_static < 1e-7, "{d_static}");

    // Explicit: from the virgin equilibrium, ice on suddenly, settle, ice off, settle (damping 1/s).
    let mut d = solver(virgin.clone(), 1.0, 1.0);
    statics::solve(&mut d, &opts).unwrap();
    // The clamps' stable step with the strings (3e7 N over 2.5 m on 60 kg plus the conductor) is below
    // the conductor's Courant step: take half of both bounds' smaller.
    let ds = 250.0 / 30.0;
    let dt = 0.4 * ds / (d.wire().axial_stiffness_n[0] / RHO).sqrt();
    d.params_mut().dt_s = dt;
    let settle = |d: &mut Explicit| {
        for _ in 0..(120.0 / dt) as usize {
            d.step(dt).unwrap();
        }
    };
    assert!(d.wire_mut().add_linear_density(0..n, 3.0));
    settle(&mut d);
    assert!(d.wire_mut().add_linear_density(0..n, -3.0));
    settle(&mut d);
    let d_dyn = linear_check(d.wire(), "dynamic");
    assert!(d_dyn < 1e-6, "{d_dyn}");
}

#[test]
fn a_scenario_with_the_two_material_law_iced_and_de_iced_hangs_as_its_permanent_set_says() {
    // The scenario path: conductor.catalog = "ACSR Drake" with tension_law = "two_material" (the
    // catalogue's stress-strain data), a 300 m level span at 15 C from its static equilibrium, 2 kg/m of
    // ice on at 1 s (the `ice` event), off at 40 s, mass damping 1/s, to 80 s. The end state against the
    // linear law of the closed-form permanent sets (each material's `m - C(m) / K_u`, from the
    // catalogue's curve `C` and final stiffness `K_u` and the history the run reached), solved statically
    // from the virgin equilibrium. Settled to about 1e-8 m per 10 s at the end: tolerance 1e-6 m.
    use ohl::run::{RunOptions, run};
    use ohl::scenario;
    let text = r#"
name = "two_material_ice"
[conductor]
catalog = "ACSR Drake"
tension_law = "two_material"
reference_temperature_k = 288.15
[geometry]
left_support_m = [0.0, 0.0, 30.0]
right_support_m = [0.0, 300.0, 30.0]
segments = 40
unstretched_length_m = 300.25
[initial]
shape = "equilibrium"
[numerics]
courant = 0.5
smoothing = 0.0
mass_damping_per_s = 1.0
[[events]]
time_s = 1.0
action = "ice"
linear_density_kg_per_m = 2.0
[[events]]
time_s = 40.0
action = "ice"
linear_density_kg_per_m = -2.0
[duration]
end_time_s = 80.0
"#;
    let sc = scenario::parse(text, "two_material_ice").unwrap();
    let plan = scenario::plan(&sc, "two_material_ice").unwrap();
    assert_eq!(plan.solver.wire().law, LawKind::TwoMaterial);
    let start = plan.solver.wire().clone();
    let o = run(plan, &RunOptions { out_dir: None, record: false }).unwrap();
    let two = o.solver.wire();
    let mat = two.material.as_ref().unwrap();
    let (law, theta) = (mat.law, two.temperature_k[0]);
    assert_eq!(theta, 288.15);
    let core = law.core.unwrap();
    let (ko, kc) = (law.outer.unloading_stiffness_n, core.unloading_stiffness_n);
    let d = theta - law.reference_temperature_k;
    let mut w = two.clone();
    w.law = LawKind::Linear;
    w.material = None;
    for j in 0..two.segments() {
        let (mo, mc) = (mat.max_strain[0][j], mat.max_strain[1][j]);
        let ep = [mo - law.outer.initial.force(mo) / ko, mc - core.initial.force(mc) / kc];
        let (lo, hi) = (
            (ep[0] + law.outer.expansion_per_k * d).max(ep[1] + core.expansion_per_k * d),
            (mo + law.outer.expansion_per_k * d).min(mc + core.expansion_per_k * d),
        );
        let e = two.strain(j);
        assert!(e > lo && e < hi, "segment {j}: strain {e} outside ({lo}, {hi})");
        let e0 = (ko * (ep[0] + law.outer.expansion_per_k * d) + kc * (ep[1] + core.expansion_per_k * d)) / (ko + kc);
        w.rest_length[j] = two.reference_length[j] * (1.0 + e0);
        w.axial_stiffness_n[j] = (ko + kc) * (1.0 + e0);
    }
    for k in 0..3 {
        w.x[k].copy_from_slice(&start.x[k]);
        w.v[k].fill(0.0);
    }
    let mut lin = solver(w, 1e-4, 0.0);
    lin.loads_mut().gravity_m_per_s2 = o.solver.loads().gravity_m_per_s2;
    statics::solve(&mut lin, &StaticOptions::default()).unwrap();
    let dist = distance(two, lin.wire());
    let (before, after) = (start.x[2][20], two.x[2][20]);
    eprintln!(
        "scenario: mid-span height {before:.4} m virgin, {after:.4} m after the ice; equivalent {:.4} m; largest node distance {dist:.3e} m",
        lin.wire().x[2][20]
    );
    assert!(after < before - 0.3, "the stretched span hangs lower");
    assert!(dist < 1e-6, "{dist}");
}
