//! A line of several conductors (`ohl::line`, `ohl::scheme::line`): phases, an earth wire and bundles on
//! shared supports.
//!
//! Checks, each against an independent expectation:
//! - uncoupled: three Drake phases and a steel earth wire, each a two-span section on its own strings, in
//!   a cross wind with each conductor's own drag, give bit for bit the results of four single-conductor
//!   runs; hung from one shared rigid tower top (offsets), they agree to rounding;
//! - the least distance between two conductors (an iced phase above a bare one) converges to the exact
//!   distance of their elastic catenaries at observed order 2;
//! - a symmetric twin bundle: the spacer arms carry exactly nothing and each sub-conductor is bit for bit
//!   an independent conductor;
//! - undamped, with spacers, strings and a shared elastic tower top: the total energy is conserved to the
//!   leapfrog's `O(dt^2)` (its drift falls by about 4 when the step is halved);
//! - a step above the stable step of a stiff attachment is refused, naming the node.
//!
//! Data: ACSR Drake 795 kcmil 26/7 (28.1 mm, 1.628 kg/m: the catalogue `data/conductors.toml`; EA =
//! 2.9e7 N, E about 70 GPa on 402 mm^2, as `tests/section.rs` and the cases a-d, where the catalogue has
//! the final modulus's 3.607e7 N); the earth wire a 3/8 in. extra-high-strength galvanised steel strand, 7 x
//! 3.05 mm (9.5 mm, 0.407 kg/m, RTS 68.5 kN, EA = 186 GPa x 51.1 mm^2 = 9.5e6 N: ASTM A475 table values
//! as we know them, not checked against a copy); strings 3.5 m, 100 kg, EA 5e7 N (as `tests/section.rs`);
//! the earth wire's suspension clamp a 0.3 m link of 1.7e7 N/m (100 kg with its hardware); spacer arms 1e6 N/m (a rigid spacer frame of the order of 1e6-1e7 N/m; the static results do not
//! depend on it beyond millimetres).

use ohl::element::LinkLaw;
use ohl::element::aero::Aerodynamic;
use ohl::element::tension::LawKind;
use ohl::line::build::{Attach, BundleSpec, add_bundle, add_section_conductor};
use ohl::line::clearance::{Scratch, least_distance};
use ohl::line::{ElasticSupport, Endpoint, Link, LinkKind, Model, NodeRef, Role, Support};
use ohl::scheme::{Explicit, LineError, LineExplicit, Loads, StepParams, WindGate, WindLoad};
use ohl::statics::{self, StaticOptions};
use ohl::wire::Conductor;
use ohl::wire::section::{self, Section, Span, Stringing, Support as SectionSupport};

const G: f64 = 9.81;

#[derive(Clone, Copy)]
struct Material {
    ea: f64,
    rho: f64,
    diameter: f64,
}

const DRAKE: Material = Material { ea: 2.9e7, rho: 1.628, diameter: 0.0281 };
const EHS_38: Material = Material { ea: 9.5e6, rho: 0.407, diameter: 0.0095 };
/// Suspension string of a phase: length [m], axial stiffness EA [N].
const STRING: (f64, f64) = (3.5, 5.0e7);
/// The earth wire's suspension clamp: a short link (0.3 m, EA 5e6 N: 1.7e7 N/m).
const EW_CLAMP: (f64, f64) = (0.3, 5.0e6);

fn loads(m: Material, wind_m_per_s: f64) -> Loads {
    // q d c_n with c_n = 1.0, c_tau = 0 (the codes' drag, docs/examples.md), air 1.225 kg/m^3.
    let q = 0.5 * 1.225 * wind_m_per_s * wind_m_per_s;
    let wind = (wind_m_per_s > 0.0).then_some(WindLoad::Aerodynamic(Aerodynamic {
        direction: [1.0, 0.0, 0.0],
        qd_cn: q * m.diameter,
        qd_ct: 0.0,
        mu_over_u: 1.0 / wind_m_per_s,
    }));
    Loads { gravity_m_per_s2: G, uniform_load_n_per_m: [0.0; 3], wind, wind_scale: 1.0, wind_gate: WindGate::Always }
}

/// A two-span section along +x2 at across-position `x1`: dead-ends at heights `z`, a suspension string
/// (length `string_m`) in the middle from a pivot at `z + 4`, strung at `h0` [N].
fn two_spans(m: Material, x1: f64, z: f64, h0: f64, segments: usize, string: (f64, f64)) -> Section {
    let span = Span {
        conductor: Conductor { axial_stiffness_n: m.ea, internal_friction_n_s: 0.0, law: LawKind::TensionOnly },
        linear_density_kg_per_m: m.rho,
        segments,
        stringing: Stringing::HorizontalTension(h0),
    };
    Section {
        supports: vec![
            SectionSupport::DeadEnd { point_m: [x1, 0.0, z] },
            SectionSupport::Suspension {
                pivot_m: [x1, 380.0, z + 4.0],
                length_m: string.0,
                mass_kg: 100.0,
                stiffness_n: string.1,
                crossarm: None,
            },
            SectionSupport::DeadEnd { point_m: [x1, 800.0, z + 2.0] },
        ],
        spans: vec![span; 2],
        gravity_m_per_s2: G,
    }
}

fn params(dt_s: f64, smoothing: f64, damping: f64) -> StepParams {
    StepParams { dt_s, smoothing, mass_damping_per_s: damping, max_speed_m_per_s: 4.0e3 }
}

/// Courant step of `m` on segments of `ds` [m] [s].
fn courant_step(m: Material, ds: f64, c: f64) -> f64 {
    c * ds / (m.ea / m.rho).sqrt()
}

/// The horizontal configuration: three Drake phases 7 m apart and the earth wire 8 m above the middle one.
fn horizontal(segments: usize) -> Vec<(Material, Section)> {
    vec![
        (DRAKE, two_spans(DRAKE, -7.0, 20.0, 28_000.0, segments, STRING)),
        (DRAKE, two_spans(DRAKE, 0.0, 20.0, 28_000.0, segments, STRING)),
        (DRAKE, two_spans(DRAKE, 7.0, 20.0, 28_000.0, segments, STRING)),
        (EHS_38, two_spans(EHS_38, 0.0, 28.0, 13_700.0, segments, EW_CLAMP)),
    ]
}

/// Add each section as a conductor; every support point its own rigid support at that point (offset 0),
/// or, with `shared`, the suspension strings of all four on one rigid tower top at the middle phase's pivot.
fn line_of(sections: &[(Material, Section)], wind: f64, shared: bool) -> Model {
    let mut model = Model::new();
    let tower = shared.then(|| {
        let SectionSupport::Suspension { pivot_m, .. } = sections[1].1.supports[1] else { unreachable!() };
        model.add_support(Support::rigid("tower 1", pivot_m))
    });
    for (i, (m, sec)) in sections.iter().enumerate() {
        let attach: Vec<Attach> = sec
            .supports
            .iter()
            .enumerate()
            .map(|(k, s)| match *s {
                SectionSupport::DeadEnd { point_m } => {
                    Attach::Fixed { support: model.add_support(Support::rigid(format!("c{i} s{k}"), point_m)) }
                }
                SectionSupport::Suspension { pivot_m, .. } => {
                    let support =
                        tower.unwrap_or_else(|| model.add_support(Support::rigid(format!("c{i} s{k}"), pivot_m)));
                    Attach::String { support, damping_n_s: 0.0 }
                }
            })
            .collect();
        let role = if i == 3 { Role::EarthWire } else { Role::Phase };
        add_section_conductor(&mut model, format!("c{i}"), role, sec, &attach, loads(*m, wind)).unwrap();
    }
    model
}

/// The step every conductor can take at Courant 0.8 (the shortest of their Courant steps).
fn common_step(sections: &[(Material, Section)], segments: usize) -> f64 {
    sections.iter().map(|(m, _)| courant_step(*m, 380.0 / segments as f64, 0.8)).fold(f64::INFINITY, f64::min)
}

#[test]
fn uncoupled_conductors_are_bitwise_single_runs() {
    let n = 24;
    let sections = horizontal(n);
    let dt = common_step(&sections, n);
    let p = params(dt, 0.02, 0.0);
    let mut line = LineExplicit::new(&line_of(&sections, 25.0, false), p).unwrap();
    let mut singles: Vec<Explicit> =
        sections.iter().map(|(m, sec)| Explicit::new(section::build(sec).unwrap().0, loads(*m, 25.0), p)).collect();
    for step in 0..600 {
        let h = if step % 9 == 4 { 0.43 * dt } else { dt };
        line.step(h).unwrap();
        for s in &mut singles {
            s.step(h).unwrap();
        }
    }
    for (i, s) in singles.iter().enumerate() {
        let (a, b) = (line.conductors()[i].wire(), s.wire());
        for k in 0..3 {
            for j in 0..a.nodes() {
                assert_eq!(a.x[k][j].to_bits(), b.x[k][j].to_bits(), "conductor {i} x{k}[{j}]");
                assert_eq!(a.v[k][j].to_bits(), b.v[k][j].to_bits(), "conductor {i} v{k}[{j}]");
            }
        }
    }
    // The wind moved them (the comparison is not of resting wires): the phases swung by metres.
    let mid = line.conductors()[0].wire().position(n / 2);
    assert!(mid[0] > -7.0 + 0.05, "phase 0 mid-span x1 = {}", mid[0]);

    // The same conductors on one shared rigid tower top (their pivots as offsets from its reference
    // point): the same run up to the rounding of (pivot - p) + p, amplified by the undamped dynamics.
    let mut shared = LineExplicit::new(&line_of(&sections, 25.0, true), p).unwrap();
    let mut line = LineExplicit::new(&line_of(&sections, 25.0, false), p).unwrap();
    for _ in 0..600 {
        shared.step(dt).unwrap();
        line.step(dt).unwrap();
    }
    let mut worst = 0.0_f64;
    for i in 0..4 {
        let (a, b) = (shared.conductors()[i].wire(), line.conductors()[i].wire());
        for k in 0..3 {
            for j in 0..a.nodes() {
                worst = worst.max((a.x[k][j] - b.x[k][j]).abs());
            }
        }
    }
    assert!(worst < 1e-9, "shared tower top vs separate supports: {worst:e} m");
    // The tower top carries the four strings: its resultant is the sum of their forces.
    shared.evaluate_forces();
    let r = shared.support_resultant_n(0);
    let mut sum = [0.0; 3];
    for (l, link) in shared.links().iter().enumerate() {
        if matches!(link.a, Endpoint::Support { support: 0, .. }) {
            let f = shared.link_force_n(l);
            for k in 0..3 {
                sum[k] -= f[k];
            }
        }
    }
    assert_eq!(r, sum);
    assert!(r[2] < -4.0 * 100.0 * G, "the tower top is pulled down by four strings: {r:?}");
}

#[test]
fn symmetric_twin_bundle_is_two_independent_conductors() {
    let n = 20;
    let sec = two_spans(DRAKE, 0.0, 20.0, 28_000.0, n, STRING);
    let mut model = Model::new();
    let attach: Vec<Attach> = sec
        .supports
        .iter()
        .enumerate()
        .map(|(k, _)| {
            let s = model.add_support(Support::rigid(format!("s{k}"), [0.0, 400.0 * k as f64, 24.0]));
            if k == 1 { Attach::String { support: s, damping_n_s: 0.0 } } else { Attach::Fixed { support: s } }
        })
        .collect();
    let spec = BundleSpec::regular(2, 0.4, vec![(0, 0.3), (0, 0.7), (1, 0.25), (1, 0.5), (1, 0.75)], 1.0e6);
    let (members, _) = add_bundle(&mut model, "A", 0, &sec, &attach, loads(DRAKE, 0.0), &spec).unwrap();
    assert_eq!(members.len(), 2);
    let dt = courant_step(DRAKE, 380.0 / n as f64, 0.8);
    let p = params(dt, 0.0, 0.0);
    let mut line = LineExplicit::new(&model, p).unwrap();
    // The independent conductor: the sub-conductor's own section, alone.
    let shifted = |dx: f64| {
        let mut s = sec.clone();
        for sup in &mut s.supports {
            match sup {
                SectionSupport::DeadEnd { point_m } => point_m[0] += dx,
                SectionSupport::Suspension { pivot_m, .. } => pivot_m[0] += dx,
            }
        }
        s
    };
    let mut alone: Vec<Explicit> =
        [-0.2, 0.2].map(|dx| Explicit::new(section::build(&shifted(dx)).unwrap().0, loads(DRAKE, 0.0), p)).into();
    for _ in 0..800 {
        line.step(dt).unwrap();
        for a in &mut alone {
            a.step(dt).unwrap();
        }
    }
    line.evaluate_forces();
    for (l, link) in line.links().iter().enumerate() {
        if link.kind == LinkKind::Spacer {
            assert_eq!(line.link_tension_n(l), 0.0, "spacer arm {l}");
        }
    }
    // Which sub-conductor is at x1 = -0.2: e_t = e3 x e_l = -x1 for a line along +x2, so offset +0.2
    // (index 0) is at x1 = -0.2.
    for (i, a) in alone.iter().enumerate() {
        let w = line.conductors()[members[i]].wire();
        for k in 0..3 {
            for j in 0..w.nodes() {
                assert_eq!(w.x[k][j].to_bits(), a.wire().x[k][j].to_bits(), "sub-conductor {i} x{k}[{j}]");
            }
        }
    }
}

/// The least distance between an iced phase above a bare one (vertical configuration, 1 m apart across),
/// from the discrete equilibria (the library's Newton per conductor), against the exact elastic
/// catenaries: the iced upper conductor sags more, so the least distance is at mid-span, between the two
/// curves' mid-span points. Error fitted over N = 32, 64, 128: order 2 +- 0.1.
#[test]
fn clearance_converges_at_order_two_to_the_exact_catenaries() {
    let ice = 1.5; // kg/m of glaze on the upper conductor
    let (lo_a, lo_b) = ([0.0, 0.0, 20.0], [0.0, 400.0, 20.0]);
    let (up_a, up_b) = ([1.0, 0.0, 27.0], [1.0, 400.0, 27.0]);
    let l0 = section::length_for_tension(lo_a, lo_b, 28_000.0, DRAKE.rho * G, DRAKE.ea).unwrap();
    let exact = |a: [f64; 3], b: [f64; 3], rho: f64| {
        ohl::exact::catenary::ElasticCatenary::solve(a, b, l0, [0.0, 0.0, -rho * G], DRAKE.ea)
            .unwrap()
            .position(0.5 * l0)
    };
    let (pl, pu) = (exact(lo_a, lo_b, DRAKE.rho), exact(up_a, up_b, DRAKE.rho + ice));
    let d_exact = ((pu[0] - pl[0]).powi(2) + (pu[1] - pl[1]).powi(2) + (pu[2] - pl[2]).powi(2)).sqrt();
    assert!(d_exact < 7.0 - 0.5, "the iced conductor comes closer at mid-span: {d_exact}");
    let mut errors = Vec::new();
    let ns = [16, 32, 64, 128];
    for &n in &ns {
        let settled = |a: [f64; 3], b: [f64; 3], rho: f64| {
            let xs: [Vec<f64>; 3] =
                std::array::from_fn(|k| (0..=n).map(|i| a[k] + (b[k] - a[k]) * i as f64 / n as f64).collect());
            let c = Conductor { axial_stiffness_n: DRAKE.ea, internal_friction_n_s: 0.0, law: LawKind::TensionOnly };
            let w = ohl::wire::Wire::new(c, xs, vec![l0 / n as f64; n], rho);
            let mut s = Explicit::new(w, loads(DRAKE, 0.0), params(1e-3, 0.0, 0.0));
            statics::solve(&mut s, &StaticOptions::default()).unwrap();
            s.wire().clone()
        };
        let (wl, wu) = (settled(lo_a, lo_b, DRAKE.rho), settled(up_a, up_b, DRAKE.rho + ice));
        let c = least_distance(&wl, &wu, &mut Scratch::default()).unwrap();
        assert!((c.arc_fraction_a(&wl) - 0.5).abs() < 1.0 / n as f64, "closest point at mid-span");
        errors.push((c.distance_m - d_exact).abs());
    }
    let order = fitted_order(&ns[1..].iter().map(|&n| n as f64).collect::<Vec<_>>(), &errors[1..]);
    eprintln!("clearance: exact {d_exact:.9} m, errors {errors:?}, fitted order {order:.3}");
    assert!((order - 2.0).abs() < 0.1, "order {order}, errors {errors:?}");
}

/// Least-squares slope of log(error) against log(1/N) [-].
fn fitted_order(ns: &[f64], errors: &[f64]) -> f64 {
    let xs: Vec<f64> = ns.iter().map(|n| -n.ln()).collect();
    let ys: Vec<f64> = errors.iter().map(|e| e.ln()).collect();
    let (mx, my) = (xs.iter().sum::<f64>() / xs.len() as f64, ys.iter().sum::<f64>() / ys.len() as f64);
    let num: f64 = xs.iter().zip(&ys).map(|(x, y)| (x - mx) * (y - my)).sum();
    let den: f64 = xs.iter().map(|x| (x - mx).powi(2)).sum();
    num / den
}

/// An elastic tower top under the middle pivots of `two_spans` (x2 = 380 m, 24 m up; the pivots are offsets
/// from it), 800 kg, springs `k_along` and `k_across` [N/m], damping `c` [N s/m].
fn elastic_tower(model: &mut Model, k_along: f64, k_across: f64, c: f64) -> usize {
    model.add_support(Support {
        name: "tower".into(),
        position_m: [0.0, 380.0, 24.0],
        elastic: Some(ElasticSupport {
            along: [0.0, 1.0, 0.0],
            along_n_per_m: k_along,
            across_n_per_m: k_across,
            mass_kg: 800.0,
            damping_n_s_per_m: c,
        }),
    })
}

/// The attachments of `two_spans` at `x1`: its dead-ends on rigid supports of their own, its string on
/// `tower` with axial damping `ba` [N s].
fn on_tower(model: &mut Model, x1: f64, tower: usize, ba: f64) -> Vec<Attach> {
    (0..3)
        .map(|k| {
            if k == 1 {
                Attach::String { support: tower, damping_n_s: ba }
            } else {
                let p = [x1, 400.0 * k as f64, 20.0 + k as f64];
                Attach::Fixed { support: model.add_support(Support::rigid("dead-end", p)) }
            }
        })
        .collect()
}

/// Two Drake phases, one a twin bundle, on one elastic tower top, with an interphase spacer, released from
/// their strung (not equilibrium) shapes with the tower top moved aside (2 cm along, 1 cm across: small
/// enough that no string goes slack, since a tension-only law switching off is not smooth and leapfrog's
/// energy error at such an event is O(dt), not O(dt^2)). With `damped`, the strings (BA 2e4 N s), the
/// spacer arms (500 N s/m), the interphase spacer (2000 N s/m) and the tower top (2e4 N s/m) have dampers.
fn coupled_line(n: usize, courant: f64, damped: bool) -> (LineExplicit, usize, f64) {
    let d = |v: f64| if damped { v } else { 0.0 };
    let mut model = Model::new();
    let tower = elastic_tower(&mut model, 4.0e5, 2.0e5, d(2.0e4));
    let mut conductors = Vec::new();
    for (x1, bundle) in [(-6.0, false), (6.0, true)] {
        let sec = two_spans(DRAKE, x1, 20.0, 28_000.0, n, STRING);
        let attach = on_tower(&mut model, x1, tower, d(2.0e4));
        if bundle {
            let mut spec = BundleSpec::regular(2, 0.45, vec![(0, 0.5), (1, 0.5)], 1.0e6);
            spec.arm_damping_n_s_per_m = d(500.0);
            let (m, _) = add_bundle(&mut model, "B", 0, &sec, &attach, loads(DRAKE, 0.0), &spec).unwrap();
            conductors.push(m[0]);
        } else {
            conductors
                .push(add_section_conductor(&mut model, "A", Role::Phase, &sec, &attach, loads(DRAKE, 0.0)).unwrap().0);
        }
    }
    model.supports[tower].position_m[0] += 0.01;
    model.supports[tower].position_m[1] += 0.02;
    // An interphase spacer at mid-span of the first spans, stretched by 1 cm (2 kN).
    let node = n / 2;
    let (pa, pb) =
        (model.conductors[conductors[0]].wire.position(node), model.conductors[conductors[1]].wire.position(node));
    let spacing = ((pa[0] - pb[0]).powi(2) + (pa[1] - pb[1]).powi(2) + (pa[2] - pb[2]).powi(2)).sqrt();
    model.add_link(Link {
        kind: LinkKind::InterphaseSpacer,
        a: Endpoint::Node(NodeRef::new(conductors[0], node)),
        b: Endpoint::Node(NodeRef::new(conductors[1], node)),
        law: LinkLaw::spring(spacing - 0.01, 2.0e5, d(2000.0)),
        intact: true,
    });
    let dt = courant_step(DRAKE, 380.0 / n as f64, courant);
    (LineExplicit::new(&model, params(dt, 0.0, 0.0)).unwrap(), tower, dt)
}

fn total_energy(e: ohl::scheme::line::LineEnergies) -> f64 {
    e.kinetic_j + e.elastic_j + e.potential_j
}

/// Undamped, the total energy (conductors, strings, spacers, tower springs and motion) is conserved to
/// O(dt^2): the relative drift stays small and falls by about 4 when the step is halved (3.0 to 5.0
/// accepted: the energy error of leapfrog oscillates, so its maximum over a window is only approximately
/// proportional to dt^2).
#[test]
fn energy_is_conserved_with_spacers_strings_and_an_elastic_tower() {
    let drift = |n: usize, courant: f64| {
        let (mut line, tower, dt) = coupled_line(n, courant, false);
        line.evaluate_forces();
        let e0 = line.energies();
        let (t0, scale) = (total_energy(e0), e0.elastic_j.abs() + e0.potential_j.abs());
        let steps = (3.0 / dt) as usize;
        let mut worst = 0.0_f64;
        for _ in 0..steps {
            line.step(dt).unwrap();
            line.evaluate_forces();
            worst = worst.max((total_energy(line.energies()) - t0).abs());
        }
        // The tower moved: the comparison is of a coupled motion.
        assert!(line.support_displacement_m(tower)[1].abs() > 1e-4);
        worst / scale
    };
    let (d1, d2, d3, d4) = (drift(16, 0.4), drift(16, 0.2), drift(16, 0.1), drift(16, 0.05));
    eprintln!(
        "energy drift: {d1:.3e}, {d2:.3e}, {d3:.3e}, {d4:.3e} at Courant 0.4, 0.2, 0.1, 0.05; ratios {:.2}, {:.2}, {:.2}",
        d1 / d2,
        d2 / d3,
        d3 / d4
    );
    assert!(d1 < 1e-5, "{d1}");
    assert!((3.0..=5.0).contains(&(d1 / d2)), "ratio {}", d1 / d2);
}

/// With dampers on the strings, the spacer arms, the interphase spacer and the tower top, the energy budget
/// closes: the change of the total energy over 3 s equals the work of the dampers, summed step by step as
/// the damper force of each step (from the half-step velocities the kernel uses) times the step's
/// displacement of its ends. The closing error is the scheme's: it falls as the step is refined, at
/// observed order 2.
#[test]
fn energy_budget_closes_with_string_spacer_and_tower_dampers() {
    let residual = |courant: f64| {
        let (mut line, tower, dt) = coupled_line(16, courant, true);
        line.evaluate_forces();
        let e0 = total_energy(line.energies());
        let steps = (3.0 / dt) as usize;
        let mut work = 0.0;
        for _ in 0..steps {
            // The dampers' forces of this level (the damper part `BA edot` of each link's law, every
            // string taut) and the ends' positions before the step.
            let forces: Vec<[f64; 3]> = line
                .links()
                .iter()
                .map(|l| {
                    let damper = LinkLaw { axial_stiffness_n: 0.0, compression: true, ..l.law };
                    let ((ra, va), (rb, vb)) = (line.endpoint_state(&l.a), line.endpoint_state(&l.b));
                    damper.force_on_b(ra, rb, va, vb)
                })
                .collect();
            let ends: Vec<([f64; 3], [f64; 3])> =
                line.links().iter().map(|l| (line.endpoint_state(&l.a).0, line.endpoint_state(&l.b).0)).collect();
            let (p0, u) = (line.support_position_m(tower), line.support_velocity_m_per_s(tower));
            line.step(dt).unwrap();
            for (k, l) in line.links().iter().enumerate() {
                let (ra, rb) = (line.endpoint_state(&l.a).0, line.endpoint_state(&l.b).0);
                let f = forces[k];
                for c in 0..3 {
                    work += f[c] * ((rb[c] - ends[k].1[c]) - (ra[c] - ends[k].0[c]));
                }
            }
            let p1 = line.support_position_m(tower);
            for c in 0..2 {
                work += -2.0e4 * u[c] * (p1[c] - p0[c]);
            }
            line.evaluate_forces();
        }
        let e1 = total_energy(line.energies());
        assert!(work < 0.0, "the dampers take energy out: {work}");
        (((e1 - e0) - work) / work).abs()
    };
    let (r1, r2, r3) = (residual(0.4), residual(0.2), residual(0.1));
    let order = ((r1 / r2).log2() + (r2 / r3).log2()) / 2.0;
    eprintln!(
        "damped energy budget: relative closing error {r1:.3e}, {r2:.3e}, {r3:.3e} at Courant 0.4, 0.2, 0.1; order {order:.2}"
    );
    // Measured: 2.99e-2, 7.32e-3, 1.82e-3 of the dampers' work (order 2.02): the lagged damper force
    // `F(v^{n-1/2})` against the step's displacement `dt v^{n+1/2}` differs from the continuous power by
    // `O(dt^2)` per unit time, like leapfrog's energy error.
    assert!(r3 < 5e-3, "{r3}");
    assert!((order - 2.0).abs() < 0.2, "order {order}");
}

#[test]
fn a_step_above_a_stiff_spacer_limit_is_refused_naming_the_node() {
    let n = 20;
    let sec = two_spans(DRAKE, 0.0, 20.0, 28_000.0, n, STRING);
    let mut model = Model::new();
    let attach: Vec<Attach> = (0..3)
        .map(|k| {
            let s = model.add_support(Support::rigid(format!("s{k}"), [0.0, 400.0 * k as f64, 24.0]));
            if k == 1 { Attach::String { support: s, damping_n_s: 0.0 } } else { Attach::Fixed { support: s } }
        })
        .collect();
    let spec = BundleSpec::regular(2, 0.4, vec![(0, 0.5)], 1.0e10);
    add_bundle(&mut model, "A", 0, &sec, &attach, loads(DRAKE, 0.0), &spec).unwrap();
    let dt = courant_step(DRAKE, 380.0 / n as f64, 0.8);
    match LineExplicit::new(&model, params(dt, 0.0, 0.0)) {
        Err(LineError::Step { at, limit_s, .. }) => {
            assert!(at.contains("node 10"), "{at}");
            assert!(limit_s < dt);
        }
        other => panic!("expected a refusal, got {:?}", other.map(|_| ())),
    }
    // The same bundle with a spacer of 1e6 N/m runs.
    let mut model2 = Model::new();
    for k in 0..3 {
        model2.add_support(Support::rigid(format!("s{k}"), [0.0, 400.0 * k as f64, 24.0]));
    }
    let spec = BundleSpec::regular(2, 0.4, vec![(0, 0.5)], 1.0e6);
    add_bundle(&mut model2, "A", 0, &sec, &attach, loads(DRAKE, 0.0), &spec).unwrap();
    assert!(LineExplicit::new(&model2, params(dt, 0.0, 0.0)).is_ok());
}

/// Newton on the whole line (conductors, spacer arms, strings, an elastic tower top) finds the rest state
/// of the explicit line scheme: a twin bundle with ice on one sub-conductor and a single phase hung from
/// one elastic tower top, both two-span sections. The explicit run with mass damping (dynamic relaxation,
/// which changes the path, not the equilibrium) settles to the same state; the distance between the two
/// is the settle's residual, asserted below 1e-6 m (measured 1.4e-11 m after 40 000 steps, 112 s of
/// simulated time at a damping rate of 3 /s: e^-168, at the rounding floor). The Newton
/// state is also a rest state of the explicit scheme: one step from it moves no node by more than 1e-9 m.
#[test]
fn newton_on_the_line_is_the_rest_state_of_the_explicit_line() {
    let n = 16;
    let build = |damping: f64| {
        let mut model = Model::new();
        let tower = elastic_tower(&mut model, 2.0e5, 2.0e5, 4.0e4);
        let mut members = Vec::new();
        for (x1, bundle) in [(-6.0, false), (6.0, true)] {
            let sec = two_spans(DRAKE, x1, 20.0, 28_000.0, n, STRING);
            let attach = on_tower(&mut model, x1, tower, 0.0);
            if bundle {
                let spec = BundleSpec::regular(2, 0.45, vec![(0, 0.25), (0, 0.75), (1, 0.5)], 1.0e6);
                members = add_bundle(&mut model, "B", 0, &sec, &attach, loads(DRAKE, 0.0), &spec).unwrap().0;
            } else {
                add_section_conductor(&mut model, "A", Role::Phase, &sec, &attach, loads(DRAKE, 0.0)).unwrap();
            }
        }
        // Ice (1.2 kg/m) on the first span of one sub-conductor only.
        let dt = courant_step(DRAKE, 380.0 / n as f64, 0.5);
        let mut line = LineExplicit::new(&model, params(dt, 0.0, damping)).unwrap();
        assert!(line.conductor_mut(members[0]).wire_mut().add_linear_density(0..n, 1.2));
        (line, members, tower)
    };
    let (mut newton, members, tower) = build(0.0);
    let report = statics::solve_line(&mut newton, &StaticOptions::default()).unwrap();
    eprintln!(
        "line Newton: {} iterations, residual {:.3e} N (tolerance {:.3e} N)",
        report.iterations, report.residual_n, report.tolerance_n
    );
    // Mass damping ~ twice the lowest pendulum frequency of a 400 m span (about 0.25 Hz: 1.6 rad/s).
    let (mut relaxed, _, _) = build(3.0);
    let dt = relaxed.params().dt_s;
    let (mut peak, mut ke) = (0.0_f64, f64::INFINITY);
    let mut steps = 0;
    while steps < 40_000 && (ke > 1e-28 * peak || steps < 1000) {
        relaxed.step(dt).unwrap();
        relaxed.evaluate_forces();
        ke = relaxed.energies().kinetic_j;
        peak = peak.max(ke);
        steps += 1;
    }
    let mut worst = 0.0_f64;
    for c in 0..newton.conductors().len() {
        let (a, b) = (newton.conductors()[c].wire(), relaxed.conductors()[c].wire());
        for k in 0..3 {
            for i in 0..a.nodes() {
                worst = worst.max((a.x[k][i] - b.x[k][i]).abs());
            }
        }
    }
    let dtower = (newton.support_displacement_m(tower)[1] - relaxed.support_displacement_m(tower)[1]).abs();
    eprintln!(
        "settled in {steps} steps ({:.1} s); Newton vs settled: nodes {worst:.3e} m, tower {dtower:.3e} m; tower moved {:.4e} m",
        steps as f64 * dt,
        newton.support_displacement_m(tower)[1]
    );
    assert!(worst < 1e-6 && dtower < 1e-6, "{worst} {dtower}");
    // The ice pulls the bundle's sub-conductors apart in height and the tower towards the iced span.
    let (wa, wb) = (newton.conductors()[members[0]].wire(), newton.conductors()[members[1]].wire());
    assert!(wa.x[2][n / 2] < wb.x[2][n / 2] - 0.1, "the iced sub-conductor hangs lower");
    assert!(newton.support_displacement_m(tower)[1] < -1e-4, "towards the iced span (smaller x2)");
    // A rest state of the explicit line: one step moves nothing beyond rounding-level dynamics.
    let before: Vec<_> = (0..newton.conductors().len()).map(|c| newton.conductors()[c].wire().x.clone()).collect();
    newton.step(dt).unwrap();
    let mut moved = 0.0_f64;
    for (c, x) in before.iter().enumerate() {
        for k in 0..3 {
            for (i, v) in x[k].iter().enumerate() {
                moved = moved.max((newton.conductors()[c].wire().x[k][i] - v).abs());
            }
        }
    }
    assert!(moved < 1e-9, "one step from the Newton state moved a node by {moved:e} m");
}

/// A span between two tension (dead-end) strings in line with the conductor (3 m, 60 kg, EA 8e7 N, the
/// order of a long-rod strain string): Newton on the line balances the total weight of conductor and
/// strings by the two supports' vertical loads (Newton's tolerance, 1e-10 of the nodal loads: asserted at
/// 1e-6 of the weight), the supports' horizontal loads are equal and opposite, and the explicit line
/// settles (dynamic relaxation) onto the same state.
#[test]
fn tension_strings_at_the_dead_ends_balance_the_weight() {
    let n = 20;
    let build = |damping: f64| {
        let mut model = Model::new();
        let (a, b) = ([0.0, 0.0, 30.0], [0.0, 400.0, 30.0]);
        let s0 = model.add_support(Support::rigid("strain tower 1", a));
        let s1 = model.add_support(Support::rigid("strain tower 2", b));
        let span = Span {
            conductor: Conductor { axial_stiffness_n: DRAKE.ea, internal_friction_n_s: 0.0, law: LawKind::TensionOnly },
            linear_density_kg_per_m: DRAKE.rho,
            segments: n,
            stringing: Stringing::HorizontalTension(28_000.0),
        };
        let sec = Section {
            supports: vec![SectionSupport::DeadEnd { point_m: a }, SectionSupport::DeadEnd { point_m: b }],
            spans: vec![span],
            gravity_m_per_s2: G,
        };
        let string = LinkLaw::string(3.0, 8.0e7, 0.0);
        let attach = [
            Attach::TensionString { support: s0, law: string, mass_kg: 60.0 },
            Attach::TensionString { support: s1, law: string, mass_kg: 60.0 },
        ];
        add_section_conductor(&mut model, "A", Role::Phase, &sec, &attach, loads(DRAKE, 0.0)).unwrap();
        let dt = courant_step(DRAKE, 394.0 / n as f64, 0.5);
        (LineExplicit::new(&model, params(dt, 0.0, damping)).unwrap(), dt)
    };
    let (mut line, _) = build(0.0);
    statics::solve_line(&mut line, &StaticOptions::default()).unwrap();
    line.evaluate_forces();
    let w = line.conductors()[0].wire();
    let weight = (w.total_mass() + w.point_mass_kg.iter().sum::<f64>()) * G;
    let (f0, f1) = (line.support_resultant_n(0), line.support_resultant_n(1));
    assert!((f0[2] + f1[2] + weight).abs() < 1e-6 * weight, "{} + {} vs {weight}", f0[2], f1[2]);
    assert!((f0[1] + f1[1]).abs() < 1e-6 * f0[1].abs() && f0[1] > 20_000.0, "{f0:?} {f1:?}");
    let (mut relaxed, dt) = build(2.0);
    for _ in 0..40_000 {
        relaxed.step(dt).unwrap();
    }
    let (a, b) = (line.conductors()[0].wire(), relaxed.conductors()[0].wire());
    let worst =
        (0..a.nodes()).map(|i| (0..3).map(|k| (a.x[k][i] - b.x[k][i]).abs()).fold(0.0, f64::max)).fold(0.0, f64::max);
    assert!(worst < 1e-6, "Newton vs settled: {worst:e} m");
}

#[test]
fn a_line_of_two_material_conductors_steps_and_stretches_as_its_single_conductors() {
    // The horizontal configuration without wind, the three Drake phases with Drake's two-material law
    // (tests/two_material.rs) at 15 C, the earth wire as it is: the line's kernel and static solver carry
    // each conductor's history like the single-conductor runs. Dynamics: 3 kg/m of ice added suddenly,
    // 600 steps, bitwise the single runs (history included). Statics: the line's stretch (solve_line,
    // Wire::load_history, ice off, solve_line) against the single conductors' (statics::solve), each solve
    // converged to its default tolerance: nodes within ~1e-9 m of the same equilibrium.
    let n = 24;
    let sections = horizontal(n);
    let dt = common_step(&sections, n);
    let p = params(dt, 0.0, 0.5);
    let law = crate::two_material::drake();
    let mut line = LineExplicit::new(&line_of(&sections, 0.0, false), p).unwrap();
    let mut singles: Vec<Explicit> =
        sections.iter().map(|(m, sec)| Explicit::new(section::build(sec).unwrap().0, loads(*m, 0.0), p)).collect();
    let segs = singles[0].wire().segments();
    for (i, s) in singles.iter_mut().enumerate().take(3) {
        for w in [s.wire_mut(), line.conductor_mut(i).wire_mut()] {
            w.set_two_material(law, ohl::conductor::CurveKind::Initial);
            w.set_temperature(0..segs, 288.15);
            assert!(w.add_linear_density(0..segs, 3.0));
        }
    }
    let virgin = singles[0].wire().material.as_ref().unwrap().max_strain[0][0];
    for _ in 0..600 {
        line.step(dt).unwrap();
        for s in &mut singles {
            s.step(dt).unwrap();
        }
    }
    for (i, s) in singles.iter().enumerate() {
        let (a, b) = (line.conductors()[i].wire(), s.wire());
        assert_eq!(a.material, b.material, "conductor {i}: history");
        for k in 0..3 {
            for j in 0..a.nodes() {
                assert_eq!(a.x[k][j].to_bits(), b.x[k][j].to_bits(), "conductor {i} x{k}[{j}]");
            }
        }
    }
    let moved = line.conductors()[0].wire().material.as_ref().unwrap().max_strain[0][0];
    assert!(moved > virgin + 1e-4, "the iced phase was stretched: {virgin} -> {moved}");

    let opts = StaticOptions::default();
    statics::solve_line(&mut line, &opts).unwrap();
    for s in &mut singles {
        statics::solve(s, &opts).unwrap();
    }
    for i in 0..3 {
        line.conductor_mut(i).wire_mut().load_history();
        singles[i].wire_mut().load_history();
        assert!(line.conductor_mut(i).wire_mut().add_linear_density(0..segs, -3.0));
        assert!(singles[i].wire_mut().add_linear_density(0..segs, -3.0));
    }
    statics::solve_line(&mut line, &opts).unwrap();
    let mut worst = 0.0_f64;
    for (i, s) in singles.iter_mut().enumerate() {
        statics::solve(s, &opts).unwrap();
        let (a, b) = (line.conductors()[i].wire(), s.wire());
        for j in 0..a.nodes() {
            worst = worst.max((0..3).map(|k| (a.x[k][j] - b.x[k][j]).powi(2)).sum::<f64>().sqrt());
        }
    }
    eprintln!("line vs single conductors after the stretch: largest node distance {worst:.3e} m");
    assert!(worst < 1e-7, "{worst}");
}
