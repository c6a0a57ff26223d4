//! Sag-tension (issue 24, `ohl::sagtension`): the nonlinear catenary by quadrature against Irvine's closed
//! form, the knee point and the change of state against their closed forms for linear materials, the
//! permanent set of a span after a heavy load, and the published / code references of
//! docs/sagtension_references.md (D: OTLS-Models fixture, B: CRC handbook Table 14.5).

use ohl::conductor::History;
use ohl::conductor::{Component, Curve, CurveKind, TwoMaterial};
use ohl::exact::catenary::ElasticCatenary;
use ohl::exact::roots::{Options1d, solve_bracketed};
use ohl::sagtension::catenary::SpanLaw;
use ohl::sagtension::catenary::{DEFAULT_PANELS, strain_of};
use ohl::sagtension::{
    Problem, STANDARD_GRAVITY_M_PER_S2, SagConductor, SagTensionError, Span, State, StretchPoint, Stringing,
    StringingTarget, Weather, solve_table,
};

const PSI: f64 = 6894.757293168;
const LBF: f64 = 4.4482216152605;
const FT: f64 = 0.3048;
const INCH: f64 = 0.0254;
const LB_PER_FT3: f64 = 0.45359237 / (FT * FT * FT);
const PSF: f64 = LBF / (FT * FT);

/// A published table row: temperature [F], ice [in], wind [psf], K [lb/ft], final sag [ft], final tension
/// [lb], initial sag [ft], initial tension [lb].
type PublishedRow = (f64, f64, f64, f64, f64, f64, f64, f64);

/// The rows of a published table as transcribed in `tests/data/sagtension/FILE` (`expected.rows`;
/// docs/sagtension_references.md), the one copy the tests and `verify sagtension` read.
fn published(file: &str) -> Vec<PublishedRow> {
    let path = format!("{}/tests/data/sagtension/{file}", env!("CARGO_MANIFEST_DIR"));
    let doc: toml::Table = std::fs::read_to_string(&path).unwrap().parse().unwrap();
    let num = |r: &toml::Value, k: &str| {
        let v = &r[k];
        v.as_float().or_else(|| v.as_integer().map(|i| i as f64)).unwrap_or_else(|| panic!("{path}: {k}"))
    };
    doc["expected"]["rows"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| {
            (
                num(r, "temperature_degf"),
                num(r, "ice_in"),
                num(r, "wind_psf"),
                num(r, "k_lb_per_ft"),
                num(r, "final_sag_ft"),
                num(r, "final_tension_lbf"),
                num(r, "initial_sag_ft"),
                num(r, "initial_tension_lbf"),
            )
        })
        .collect()
}

fn kelvin_of_f(f: f64) -> f64 {
    (f - 32.0) / 1.8 + 273.15
}

/// Drake with the OTLS-Models polynomials (psi on the total area 0.7264 in^2 vs strain in %; reference
/// 70 F; docs/sagtension_references.md reference D), aluminium compression `compression_psi_pct`.
fn drake(compression_psi_pct: f64) -> SagConductor {
    let area = 0.7264 * INCH * INCH;
    let p = |a: [f64; 5]| a.map(|x| x * PSI);
    let curve = |a, lim: f64| Curve::from_percent(p(a), area, Some(lim * PSI)).unwrap();
    let per_pct = |m: f64| m * PSI * 100.0 * area;
    let outer = Component {
        area_m2: 4.0283e-4,
        expansion_per_k: 12.8e-6 * 1.8,
        initial: curve([-1213.0, 44308.1, -14004.4, -37618.0, 30676.0], 20252.0),
        creep: Some(curve([-544.8, 21426.8, -18842.2, 5495.0, 0.0], 7535.0)),
        unloading_stiffness_n: per_pct(64000.0),
        compression_stiffness_n: per_pct(compression_psi_pct),
    };
    let core = Component {
        area_m2: 6.560e-5,
        expansion_per_k: 6.4e-6 * 1.8,
        initial: curve([-69.3, 38629.0, 3998.1, -45713.0, 27892.0], 19154.0),
        creep: Some(curve([47.1, 36211.3, 12201.4, -72392.0, 46338.0], 22406.0)),
        unloading_stiffness_n: per_pct(37000.0),
        compression_stiffness_n: 0.0,
    };
    SagConductor {
        law: TwoMaterial { outer, core: Some(core), reference_temperature_k: kelvin_of_f(70.0) },
        diameter_m: 1.108 * INCH,
        mass_kg_per_m: 1.094 * 0.45359237 / FT,
        rated_tensile_strength_n: 31500.0 * LBF,
    }
}

fn weather_us(temp_f: f64, ice_in: f64, density_lb_ft3: f64, wind_psf: f64, k_lb_ft: f64) -> Weather {
    Weather {
        temperature_k: kelvin_of_f(temp_f),
        ice_thickness_m: ice_in * INCH,
        ice_density_kg_per_m3: density_lb_ft3 * LB_PER_FT3,
        wind_pressure_pa: wind_psf * PSF,
        constant_n_per_m: k_lb_ft * LBF / FT,
    }
}

/// A conductor of linear materials: aluminium-like outer `K_o` = 22 MN, steel-like core `K_c` = 13 MN
/// (`None`: outer only), Drake's expansion coefficients, reference 20 C.
fn linear_conductor(with_core: bool) -> SagConductor {
    let outer = Component::linear(4.0283e-4, 55e9, 23.04e-6);
    let core = with_core.then(|| Component::linear(6.560e-5, 200e9, 11.52e-6));
    SagConductor {
        law: TwoMaterial { outer, core, reference_temperature_k: 293.15 },
        diameter_m: 0.028,
        mass_kg_per_m: 1.628,
        rated_tensile_strength_n: 140e3,
    }
}

fn problem(conductor: SagConductor, span: Span, h0_n: f64, at: Weather) -> Problem {
    Problem {
        conductor,
        span,
        stringing: Stringing { target: StringingTarget::HorizontalTension(h0_n), weather: at, state: State::Initial },
        creep: None,
        heavy_load: None,
        gravity_m_per_s2: STANDARD_GRAVITY_M_PER_S2,
        stretch_point: StretchPoint::MostStrained,
    }
}

/// Irvine's closed form for a linear law `T = K (e - c)` (`c` the thermal strain, or thermal strain plus
/// permanent set): `1 + e = (1 + c)(1 + T / (K (1 + c)))`, an elastic catenary of unstressed length
/// `L0 (1 + c)`, stiffness `K (1 + c)` and load `w / (1 + c)` per unit of that length. Returns (H, V).
fn irvine(l: f64, h: f64, l0: f64, w: f64, k: f64, c: f64) -> (f64, f64) {
    let cat = ElasticCatenary::solve([0.0; 3], [0.0, l, h], l0 * (1.0 + c), [0.0, 0.0, -w / (1.0 + c)], k * (1.0 + c))
        .unwrap();
    (cat.horizontal_tension_n(), cat.reaction_a_n())
}

fn span_law<'a>(law: &'a TwoMaterial, history: History, theta: f64, w: f64, l: f64, h: f64, l0: f64) -> SpanLaw<'a> {
    SpanLaw {
        law,
        history,
        temperature_k: theta,
        load_n_per_m: w,
        span_m: l,
        rise_m: h,
        unstressed_length_m: l0,
        panels: DEFAULT_PANELS,
    }
}

/// (a) A linear law is Irvine's elastic catenary: H and V agree to 1e-10 relative. Both solve the same
/// equations to a closure residual of 1e-12 of the span; the quadrature of an analytic integrand with 4
/// panels of 12 points is exact to round-off (next test), so 1e-10 leaves a margin of 100 for the
/// conditioning of H on the closure (H ~ w l^2 / 8 f: dH/H ~ (l / f) dx/l).
#[test]
fn a_linear_law_is_irvines_elastic_catenary() {
    let c = linear_conductor(false);
    let k = c.law.outer.initial.coefficients_n[1];
    let alpha = c.law.outer.expansion_per_k;
    let h0 = c.law.virgin(CurveKind::Initial);
    // (span, rise, L0 / chord, w, temperature): level, inclined, taut (L0 shorter than the chord), slack,
    // hot and cold.
    for &(l, h, ratio, w, theta) in &[
        (300.0f64, 0.0f64, 1.002, 16.0, 293.15),
        (400.0, 60.0, 1.004, 40.0, 353.15),
        (250.0, -30.0, 0.9995, 16.0, 253.15),
        (100.0, 10.0, 1.2, 16.0, 373.15),
        (800.0, 0.0, 1.01, 60.0, 233.15),
    ] {
        let l0 = ratio * l.hypot(h);
        let s = span_law(&c.law, h0, theta, w, l, h, l0).solve().unwrap();
        let (hi, vi) = irvine(l, h, l0, w, k, alpha * (theta - 293.15));
        let dh = (s.horizontal_tension_n - hi).abs() / hi;
        let dv = (s.reaction_a_n - vi).abs() / hi.max(vi.abs());
        assert!(
            dh < 1e-10 && dv < 1e-10,
            "l {l} h {h}: H {} vs {hi} ({dh:e}), V {} vs {vi} ({dv:e})",
            s.horizontal_tension_n,
            s.reaction_a_n
        );
    }
}

/// Drake with the OTLS curves, strung at 6000 lb and 60 F over 1200 ft, after the 0 F / 0.5 in ice / 8
/// psf load (reference D's problem).
fn reference_d(conductor: SagConductor, stretch_point: StretchPoint) -> Problem {
    Problem {
        creep: Some(weather_us(60.0, 0.0, 0.0, 0.0, 0.0)),
        heavy_load: Some(weather_us(0.0, 0.5, 57.3, 8.0, 0.0)),
        stretch_point,
        ..problem(conductor, Span::level(1200.0 * FT), 6000.0 * LBF, weather_us(60.0, 0.0, 0.0, 0.0, 0.0))
    }
}

/// The composite rule converges: on Drake's polynomial law after the heavy load at 60 F and 212 F (the
/// knee passed at 212 F, so the span has kinks: both components' unloading lines, the aluminium's slack
/// point; the rule splits there) the closure integral `x(L0)` at the solved `(H, V)` with 1, 2, 4 (the
/// default) and 8 panels per piece agrees with 32 panels to 1e-14 of the span: the round-off of a sum
/// of a few hundred terms.
#[test]
fn the_quadrature_converges_to_round_off() {
    let p = reference_d(drake(1500.0), StretchPoint::MostStrained);
    let strung = p.string().unwrap();
    let (hist, _) = strung.histories.get(State::AfterLoad).unwrap();
    for theta_f in [60.0, 212.0] {
        let w = weather_us(theta_f, 0.0, 0.0, 0.0, 0.0).load_n_per_m(&p.conductor, p.gravity_m_per_s2);
        let l0 = strung.unstressed_length_m;
        let mut s = span_law(&p.conductor.law, hist, kelvin_of_f(theta_f), w, 1200.0 * FT, 0.0, l0);
        let hv = s.solve().unwrap().hv();
        let mut x = |panels: usize| {
            s.panels = panels;
            s.position(l0, hv).unwrap()[0]
        };
        let reference = x(32);
        let diffs: Vec<f64> = [1, 2, 4, 8].iter().map(|&n| ((x(n) - reference) / reference).abs()).collect();
        println!("{theta_f} F: x(L0) {reference} m, relative differences with 1, 2, 4, 8 panels: {diffs:?}");
        assert!(diffs[2] < 1e-14 && diffs[3] < 1e-14, "{diffs:?}");
    }
}

/// (b) Closed-form knee of two linear materials. At the knee the aluminium's strain is zero at the most
/// tensioned support, `e = alpha_o d`, and the whole span hangs on the core, `T = K_c (e - alpha_c d)`:
/// Irvine's catenary of the core (`c = alpha_c d`) whose support tension equals `K_c (alpha_o - alpha_c) d`.
/// That 1-D root in `d` against the solver's search: 1e-8 K (both roots converge to 1e-10 K or better;
/// the closure residual 1e-12 moves the root by less than 1e-9 K: dT/dtheta ~ 150 N/K against T ~ 1e4 N).
#[test]
fn the_knee_temperature_of_two_linear_materials_is_the_closed_form() {
    let c = linear_conductor(true);
    let core = c.law.core.unwrap();
    let (kc, ac, ao) = (core.initial.coefficients_n[1], core.expansion_per_k, c.law.outer.expansion_per_k);
    for &(l, rise, h0) in &[(300.0, 0.0, 25e3), (450.0, 40.0, 30e3)] {
        let p = problem(c, Span { length_m: l, rise_m: rise }, h0, Weather::bare(288.15));
        let strung = p.string().unwrap();
        let knee = strung.knee_temperature_k(State::Initial).unwrap();
        let l0 = strung.unstressed_length_m;
        let w = Weather::bare(300.0).load_n_per_m(&c, p.gravity_m_per_s2);
        let f = |d: f64| {
            let (hh, v) = irvine(l, rise, l0, w, kc, ac * d);
            let t_support = hh.hypot(v).max(hh.hypot(w * l0 - v));
            (t_support - kc * (ao - ac) * d, f64::NAN)
        };
        let d = solve_bracketed(f, 1.0, 500.0, Options1d { x_rel_tol: 1e-15, x_abs_tol: 1e-12, max_iterations: 400 })
            .unwrap();
        let closed = 293.15 + d;
        println!("span {l} m, H0 {h0} N: knee {knee} K, closed form {closed} K");
        assert!((knee - closed).abs() < 1e-8, "knee {knee} vs closed form {closed}");
    }
}

/// (c) Strain sharing: with linear materials the components' forces at the support are
/// `K_o (e - alpha_o d)` and `K_c (e - alpha_c d)` below the knee and `0`, `T` above it (1e-9 of the
/// tension: the force sum reproduces the inverted strain to Newton's last step).
/// (d) Change of state per material: below the knee the span is Irvine's catenary of the composite
/// (`K = K_o + K_c`, thermal strain `(K_o alpha_o + K_c alpha_c) d / K`), above it the core's
/// (`K_c`, `alpha_c d`): H to 1e-10 as in (a); the sag's slope in temperature follows: checked by
/// finite differences, 10 K apart, against the same closed forms (1e-6: the difference quotient's own
/// truncation cancels, as both sides use the same two temperatures).
#[test]
fn strain_sharing_and_change_of_state_follow_each_material_below_and_above_the_knee() {
    let c = linear_conductor(true);
    let core = c.law.core.unwrap();
    let (ko, ao) = (c.law.outer.initial.coefficients_n[1], c.law.outer.expansion_per_k);
    let (kc, ac) = (core.initial.coefficients_n[1], core.expansion_per_k);
    let p = problem(c, Span::level(300.0), 25e3, Weather::bare(288.15));
    let strung = p.string().unwrap();
    let knee = strung.knee_temperature_k(State::Initial).unwrap();
    let l0 = strung.unstressed_length_m;
    let w = Weather::bare(0.0).load_n_per_m(&c, p.gravity_m_per_s2);
    let composite = |d: f64| irvine(300.0, 0.0, l0, w, ko + kc, (ko * ao + kc * ac) * d / (ko + kc)).0;
    let core_only = |d: f64| irvine(300.0, 0.0, l0, w, kc, ac * d).0;
    for theta in [knee - 60.0, knee - 10.0, knee + 10.0, knee + 80.0] {
        let r = strung.solve(&Weather::bare(theta), State::Initial).unwrap();
        let d = theta - 293.15;
        let e = r.strain_max;
        let t = r.support_tension_a_n;
        let (fo, fc, expected_h) = if theta < knee {
            (ko * (e - ao * d), kc * (e - ac * d), composite(d))
        } else {
            (0.0, kc * (e - ac * d), core_only(d))
        };
        assert_eq!(r.knee_passed, theta > knee);
        assert!((r.outer_force_n - fo).abs() < 1e-9 * t && (r.core_force_n - fc).abs() < 1e-9 * t, "{theta}: {r:?}");
        assert!(
            (r.horizontal_tension_n - expected_h).abs() < 1e-10 * expected_h,
            "{theta}: H {} vs {expected_h}",
            r.horizontal_tension_n
        );
        // The sag-temperature slope: the solver's finite difference against the closed form's.
        let r2 = strung.solve(&Weather::bare(theta + 10.0), State::Initial).unwrap();
        let slope = (r2.sag_midspan_m - r.sag_midspan_m) / 10.0;
        let h2 = if theta < knee { composite(d + 10.0) } else { core_only(d + 10.0) };
        // level span: sag = (H / w') (cosh(w' l / 2H) - 1) + elastic part; compare dH instead of the
        // sag's formula: the slope of H is the material's.
        let dh = (r2.horizontal_tension_n - r.horizontal_tension_n) / 10.0;
        if (theta < knee) == (theta + 10.0 < knee) {
            assert!(
                (dh - (h2 - expected_h) / 10.0).abs() < 1e-6 * dh.abs(),
                "{theta}: dH/dtheta {dh} vs {}",
                (h2 - expected_h) / 10.0
            );
        }
        println!(
            "{theta:.2} K: H {:.3} N, sag {:.4} m, dsag/dtheta {slope:.6} m/K, knee passed {}",
            r.horizontal_tension_n, r.sag_midspan_m, r.knee_passed
        );
    }
}

/// The polynomial path: after the heavy load every point of a span at a lighter condition lies on both
/// components' unloading lines, `F_k = K_uk (e - alpha_k d - e_pk)` with `e_pk` the closed-form
/// permanent set `m_k - C_k(m_k) / K_uk`; so the span is Irvine's catenary with `K = K_uo + K_uc` and the
/// rest strain `(K_uo (alpha_o d + e_po) + K_uc (alpha_c d + e_pc)) / K`: H to 1e-10 (as (a)). The
/// section hangs lower after the load by exactly that permanent elongation: the after-load sag exceeds
/// the initial sag at the same condition.
#[test]
fn after_a_heavy_load_the_span_hangs_on_the_unloading_lines_with_the_closed_form_permanent_set() {
    let p = reference_d(drake(0.0), StretchPoint::MostStrained);
    let strung = p.string().unwrap();
    let (hist, _) = strung.histories.get(State::AfterLoad).unwrap();
    let law = &p.conductor.law;
    let core = law.core.unwrap();
    for theta_f in [30.0, 60.0, 90.0] {
        let weather = weather_us(theta_f, 0.0, 0.0, 0.0, 0.0);
        let r = strung.solve(&weather, State::AfterLoad).unwrap();
        let initial = strung.solve(&weather, State::Initial).unwrap();
        // the lowest-tension point still has the aluminium loaded (else the closed form changes)
        let e_low = strain_of(law, r.horizontal_tension_n, weather.temperature_k, &hist).unwrap();
        assert!(law.forces(e_low, weather.temperature_k, &hist)[0] > 0.0);
        let d = weather.temperature_k - law.reference_temperature_k;
        let epo = hist.max_strain[0] - law.outer.initial.force(hist.max_strain[0]) / law.outer.unloading_stiffness_n;
        let epc = hist.max_strain[1] - core.initial.force(hist.max_strain[1]) / core.unloading_stiffness_n;
        let (kuo, kuc) = (law.outer.unloading_stiffness_n, core.unloading_stiffness_n);
        let k = kuo + kuc;
        let c = (kuo * (law.outer.expansion_per_k * d + epo) + kuc * (core.expansion_per_k * d + epc)) / k;
        let w = weather.load_n_per_m(&p.conductor, p.gravity_m_per_s2);
        let (hh, _) = irvine(1200.0 * FT, 0.0, strung.unstressed_length_m, w, k, c);
        assert!((r.horizontal_tension_n - hh).abs() < 1e-10 * hh, "{theta_f} F: {} vs {hh}", r.horizontal_tension_n);
        assert!(
            r.sag_midspan_m > initial.sag_midspan_m + 0.1,
            "{theta_f} F: {} vs {}",
            r.sag_midspan_m,
            initial.sag_midspan_m
        );
        println!(
            "{theta_f} F: after load H {:.2} lb sag {:.3} ft; initial H {:.2} lb sag {:.3} ft; permanent set Al {epo:e} steel {epc:e}",
            r.horizontal_tension_n / LBF,
            r.sag_midspan_m / FT,
            initial.horizontal_tension_n / LBF,
            initial.sag_midspan_m / FT
        );
    }
}

/// An independent implementation of the average-tension method of SAG10-type programs and OTLS-Models
/// (docs/sagtension.md): the INEXTENSIBLE catenary of a level span with the load per unit stretched
/// length (`per_stretched`) or per unit unstressed length (`w / (1 + e)` on the stretched length,
/// iterated), the whole length strained at the average tension `T_avg = (1/L) int T ds` (closed form for
/// the catenary), `L0 = L / (1 + e(T_avg))`; H by bisection. Returns `(initial, after load, after creep)`
/// H [lb] per weather.
fn average_tension_model(c: &SagConductor, per_stretched: bool, weathers: &[Weather]) -> Vec<[f64; 3]> {
    let g = STANDARD_GRAVITY_M_PER_S2;
    let law = &c.law;
    let l = 1200.0 * FT;
    let l0_of = |h: f64, w: &Weather, hist: &History| -> (f64, f64) {
        let w0 = w.load_n_per_m(c, g);
        let mut e = 0.0;
        let mut out = (0.0, 0.0);
        for _ in 0..(if per_stretched { 1 } else { 40 }) {
            let ws = if per_stretched { w0 } else { w0 / (1.0 + e) };
            let cc = h / ws;
            let a = l / (2.0 * cc);
            let len = 2.0 * cc * a.sinh();
            let t_avg = h * h / (2.0 * ws * len) * (2.0 * a.sinh() * a.cosh() + l / cc);
            e = strain_of(law, t_avg, w.temperature_k, hist).unwrap();
            out = (len / (1.0 + e), e);
        }
        out
    };
    let h_of = |l0: f64, w: &Weather, hist: &History| {
        let (mut lo, mut hi) = (100.0, 1e6);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if l0_of(mid, w, hist).0 > l0 { lo = mid } else { hi = mid }
        }
        0.5 * (lo + hi)
    };
    let string = weather_us(60.0, 0.0, 0.0, 0.0, 0.0);
    let load = weather_us(0.0, 0.5, 57.3, 8.0, 0.0);
    let initial = law.virgin(CurveKind::Initial);
    let (l0, _) = l0_of(6000.0 * LBF, &string, &initial);
    let stretch = |w: &Weather, start: History| {
        let (_, e) = l0_of(h_of(l0, w, &start), w, &start);
        let mut h = start;
        law.load(e, w.temperature_k, &mut h);
        h
    };
    let after_creep = law.creep_history_on_initial(&stretch(&string, law.virgin(CurveKind::Creep)));
    let after_load = stretch(&load, initial);
    weathers.iter().map(|w| [initial, after_load, after_creep].map(|h| h_of(l0, w, &h) / LBF)).collect()
}

/// (e) Reference D, the OTLS-Models fixture (code output, not published; aluminium compression 1500
/// psi/% as there). Three comparisons, docs/sagtension.md explains them:
/// 1. the average-tension model above with the load per stretched length (OTLS's method) reproduces the
///    fixture's nine tensions to 1.5 lb or 0.02 % (the fixture rounds to 1 lb; the rest, at most 3.3 lb
///    in the 17123 lb ice case, is not traced: OTLS's length transfer `L (1 + de)` instead of
///    `L (1 + e1) / (1 + e0)` is a candidate of that size);
/// 2. with the load per unstressed length it agrees with this solver using the same stretch point
///    (average tension) to 0.1 lb: the only difference left is the strain of the mean tension against
///    the mean strain, second order in the tension's variation along the span;
/// 3. this solver's default (stretch at the most strained point) is printed beside them.
#[test]
fn reference_d_otls_fixture_is_reproduced_and_every_difference_is_a_stated_convention() {
    let weathers = [
        weather_us(60.0, 0.0, 0.0, 0.0, 0.0),
        weather_us(212.0, 0.0, 0.0, 0.0, 0.0),
        weather_us(0.0, 1.0, 57.3, 8.0, 0.0),
    ];
    let expected = [[6000.0, 5561.0, 5582.0], [4701.0, 4527.0, 4516.0], [17123.0, 17123.0, 17123.0]];
    let c = drake(1500.0);
    let otls = average_tension_model(&c, true, &weathers);
    let unstressed = average_tension_model(&c, false, &weathers);
    let exact = |point| {
        let strung = reference_d(c, point).string().unwrap();
        weathers
            .iter()
            .map(|w| {
                [State::Initial, State::AfterLoad, State::AfterCreep]
                    .map(|s| strung.solve(w, s).unwrap().horizontal_tension_n / LBF)
            })
            .collect::<Vec<_>>()
    };
    let average = exact(StretchPoint::AverageTension);
    let most = exact(StretchPoint::MostStrained);
    println!(
        "| condition | state | fixture | avg-tension model (w per stretched) | (w per unstressed) | solver, stretch at avg tension | solver, default |"
    );
    for (i, w) in weathers.iter().enumerate() {
        for (j, state) in ["initial", "after load", "after creep"].iter().enumerate() {
            println!(
                "| {:.0} F, {} in ice, {} psf | {state} | {:.0} | {:.2} | {:.2} | {:.2} | {:.2} |",
                (w.temperature_k - 273.15) * 1.8 + 32.0,
                w.ice_thickness_m / INCH,
                (w.wind_pressure_pa / PSF).round(),
                expected[i][j],
                otls[i][j],
                unstressed[i][j],
                average[i][j],
                most[i][j]
            );
            let tol = (1.5f64).max(2e-4 * expected[i][j]);
            assert!((otls[i][j] - expected[i][j]).abs() <= tol, "{i} {j}: {} vs {}", otls[i][j], expected[i][j]);
            assert!(
                (unstressed[i][j] - average[i][j]).abs() <= 0.1,
                "{i} {j}: {} vs {}",
                unstressed[i][j],
                average[i][j]
            );
        }
    }
}

/// (f) Reference B, the CRC handbook's Table 14.5 (Drake, 700 ft, 6300 lb initial at 60 F, NESC heavy,
/// creep 10 years at 60 F). The handbook does not say which curves it used; here Drake's OTLS curves
/// (aluminium compression 0), FINAL the longer of after creep and after load (creep governs, as the
/// handbook says). Printed side by side for docs/sagtension.md. Bounds: tensions within 0.6 % and sags
/// within 0.05 ft, both columns. Justification: the table prints tensions to 1 lb and sags to 0.01 ft,
/// does not say whether its tension is horizontal (docs/sagtension_references.md: its sags fit every
/// reading to 0.01 ft), and used curves that are not given; found: 0.32 % (initial), 0.46 % (final),
/// 0.03 ft.
#[test]
fn reference_b_handbook_table_side_by_side() {
    let rows = published("handbook_drake_700ft_creep.toml");
    assert_eq!(rows.len(), 10, "Table 14.5 (700 ft) has ten rows");
    let p = Problem {
        creep: Some(weather_us(60.0, 0.0, 0.0, 0.0, 0.0)),
        heavy_load: Some(weather_us(0.0, 0.5, 57.0, 4.0, 0.30)),
        ..problem(drake(0.0), Span::level(700.0 * FT), 6300.0 * LBF, weather_us(60.0, 0.0, 0.0, 0.0, 0.0))
    };
    let strung = p.string().unwrap();
    println!("final state = {:?}", strung.histories.final_is);
    println!(
        "| T F | ice in | wind psf | K | final sag ft (pub / ohl) | final H lb (pub / ohl) | initial sag ft (pub / ohl) | initial H lb (pub / ohl) | knee (final) |"
    );
    let mut worst = [0.0f64; 3];
    for &(t, ice, wind, k, fs, ft, is, it) in &rows {
        let w = weather_us(t, ice, 57.0, wind, k);
        let f = strung.solve(&w, State::Final).unwrap();
        let i = strung.solve(&w, State::Initial).unwrap();
        println!(
            "| {t} | {ice} | {wind} | {k} | {fs} / {:.2} | {ft} / {:.0} | {is} / {:.2} | {it} / {:.0} | {} |",
            f.sag_midspan_m / FT,
            f.horizontal_tension_n / LBF,
            i.sag_midspan_m / FT,
            i.horizontal_tension_n / LBF,
            f.knee_passed
        );
        worst[0] = worst[0].max((i.horizontal_tension_n / LBF - it).abs() / it);
        worst[1] = worst[1].max((f.horizontal_tension_n / LBF - ft).abs() / ft);
        worst[2] = worst[2].max((f.sag_midspan_m / FT - fs).abs()).max((i.sag_midspan_m / FT - is).abs());
    }
    println!("largest tension differences: initial {:.4}, final {:.4}; sag {:.3} ft", worst[0], worst[1], worst[2]);
    assert!(worst[0] < 6e-3 && worst[1] < 6e-3 && worst[2] < 0.05, "{worst:?}");
}

/// Stringing by sag gives the length that stringing by the tension it produces gives (1e-12 relative),
/// and the temperature at a sag inverts the sag at a temperature (1e-8 K; the search stops at 1e-10 K).
#[test]
fn stringing_by_sag_and_the_temperature_at_a_sag_invert_their_forward_problems() {
    let p = reference_d(drake(0.0), StretchPoint::MostStrained);
    let strung = p.string().unwrap();
    let r = strung.solve(&p.stringing.weather, State::Initial).unwrap();
    let by_sag = Problem { stringing: Stringing { target: StringingTarget::Sag(r.sag_midspan_m), ..p.stringing }, ..p };
    let l0 = by_sag.string().unwrap().unstressed_length_m;
    assert!((l0 - strung.unstressed_length_m).abs() < 1e-12 * l0, "{l0} vs {}", strung.unstressed_length_m);
    for (state, theta) in [(State::Initial, 330.0), (State::Final, 380.0)] {
        let sag = strung.solve(&Weather::bare(theta), state).unwrap().sag_midspan_m;
        let back = strung.temperature_at_sag_k(state, sag).unwrap();
        assert!((back - theta).abs() < 1e-8, "{state:?}: {back} vs {theta}");
    }
    // a final stringing condition: the final H at the stringing weather is the target
    let final_target = Problem { stringing: Stringing { state: State::Final, ..p.stringing }, ..p };
    let s = final_target.string().unwrap();
    let h = s.solve(&p.stringing.weather, State::Final).unwrap().horizontal_tension_n;
    assert!((h - 6000.0 * LBF).abs() < 1e-9 * h, "{h}");
}

/// Bad input and impossible loads are typed errors, never a panic.
#[test]
fn bad_inputs_and_impossible_loads_are_errors() {
    let p = reference_d(drake(0.0), StretchPoint::MostStrained);
    let bad_span = Problem { span: Span::level(-1.0), ..p };
    assert!(matches!(bad_span.string(), Err(SagTensionError::Invalid { what: "span length [m]", .. })));
    let bad_ice = Problem { heavy_load: Some(Weather { ice_thickness_m: f64::NAN, ..Weather::bare(273.0) }), ..p };
    assert!(matches!(bad_ice.string(), Err(SagTensionError::Invalid { .. })));
    let mut bad_law = p;
    bad_law.conductor.law.outer.unloading_stiffness_n = f64::NAN;
    assert!(matches!(
        bad_law.string(),
        Err(SagTensionError::Invalid { what: "outer layers' unloading stiffness [N]", .. })
    ));
    let no_creep = Problem { creep: None, ..p };
    assert!(matches!(
        no_creep.string().unwrap().solve(&Weather::bare(300.0), State::AfterCreep),
        Err(SagTensionError::MissingStretch("after_creep"))
    ));
    // 3 m of ice on a 366 m span strung at 27 kN: the conductor would need a strain beyond its curves'
    // reach (100 %): an error, not a panic
    let strung = p.string().unwrap();
    let monster = Weather { ice_thickness_m: 3.0, ice_density_kg_per_m3: 913.0, ..Weather::bare(273.15) };
    match strung.solve(&monster, State::Initial) {
        Err(e) => println!("{e}"),
        Ok(r) => assert!(r.strain_max.is_finite() && r.horizontal_tension_n.is_finite()),
    }
    let table = solve_table(&p, &[Weather::bare(300.0)]).unwrap();
    assert_eq!(table.len(), 4);
}

/// (g) Reference A, Alcoa's SAG10 sample (Drake, 1000 ft, 10000 lb initial at 0 F with 0.5 in ice, 4
/// psf, K = 0.30 lb/ft; extra-heavy 1.5 in ice at 0 F governs the final state; "creep is not a
/// factor"). Its curves (Alcoa chart 1-537) are not given: Drake's OTLS curves here, creep at 60 F bare
/// offered to the final-state choice, the 10000 lb read as horizontal. The table prints `H` and the
/// length-averaged tension beside the published tension (the source does not say which it prints).
/// Bounds: 1 % on `H`, 0.3 ft on sags. They record what this comparison found (0.77 % and 0.21 ft), with
/// the curves unknown, so they are a regression guard rather than a verification (docs/sagtension.md).
/// The published final tensions match the length-averaged tension to 0-5 lb.
#[test]
fn reference_a_alcoa_sample_side_by_side() {
    let rows = published("alcoa_drake_1000ft_nesc_heavy.toml");
    assert_eq!(rows.len(), 11, "the Alcoa sample has eleven rows");
    let p = Problem {
        creep: Some(weather_us(60.0, 0.0, 0.0, 0.0, 0.0)),
        heavy_load: Some(weather_us(0.0, 1.5, 57.0, 0.0, 0.0)),
        ..problem(drake(0.0), Span::level(1000.0 * FT), 10000.0 * LBF, weather_us(0.0, 0.5, 57.0, 4.0, 0.30))
    };
    let strung = p.string().unwrap();
    println!("final state = {:?}", strung.histories.final_is);
    println!(
        "| T F | ice in | wind psf | K | final sag ft (pub / ohl) | final T lb (pub / ohl H / ohl mean) | initial sag ft (pub / ohl) | initial T lb (pub / ohl H / ohl mean) |"
    );
    let mut worst = [0.0f64; 2];
    for &(t, ice, wind, k, fs, ft, is, it) in &rows {
        let w = weather_us(t, ice, 57.0, wind, k);
        let f = strung.solve(&w, State::Final).unwrap();
        let i = strung.solve(&w, State::Initial).unwrap();
        println!(
            "| {t} | {ice} | {wind} | {k} | {fs} / {:.2} | {ft} / {:.0} / {:.0} | {is} / {:.2} | {it} / {:.0} / {:.0} |",
            f.sag_midspan_m / FT,
            f.horizontal_tension_n / LBF,
            f.tension_mean_n / LBF,
            i.sag_midspan_m / FT,
            i.horizontal_tension_n / LBF,
            i.tension_mean_n / LBF,
        );
        for (r, pub_t, pub_s) in [(&f, ft, fs), (&i, it, is)] {
            worst[0] = worst[0].max((r.horizontal_tension_n / LBF - pub_t).abs() / pub_t);
            worst[1] = worst[1].max((r.sag_midspan_m / FT - pub_s).abs());
        }
    }
    println!("largest differences: tension {:.4}, sag {:.3} ft", worst[0], worst[1]);
    assert!(worst[0] < 0.01 && worst[1] < 0.3, "{worst:?}");
}

/// The catalogue's Drake (data/conductors.toml, the same OTLS polynomials converted to Pa with 7
/// significant digits) gives reference B's tensions of this file's Drake to 2e-6: the conversion's
/// rounding (5e-7 relative per coefficient) moves `H` by about as much.
#[test]
fn the_catalogues_drake_is_this_files_drake() {
    let catalogue = ohl::thermal::catalog::find("drake").unwrap();
    let law = SagConductor::from_catalog(catalogue).expect("Drake has stress-strain data").law;
    let mine = drake(0.0);
    let b = |c: SagConductor| Problem {
        creep: Some(weather_us(60.0, 0.0, 0.0, 0.0, 0.0)),
        heavy_load: Some(weather_us(0.0, 0.5, 57.0, 4.0, 0.30)),
        ..problem(c, Span::level(700.0 * FT), 6300.0 * LBF, weather_us(60.0, 0.0, 0.0, 0.0, 0.0))
    };
    let rows_of =
        |c| solve_table(&b(c), &[weather_us(212.0, 0.0, 0.0, 0.0, 0.0), weather_us(0.0, 0.5, 57.0, 4.0, 0.3)]).unwrap();
    for (x, y) in rows_of(SagConductor { law, ..mine }).iter().zip(rows_of(mine)) {
        let d = (x.horizontal_tension_n - y.horizontal_tension_n).abs() / y.horizontal_tension_n;
        assert!(d < 2e-6, "{:?}: {} vs {} ({d:e})", x.state, x.horizontal_tension_n, y.horizontal_tension_n);
    }
}

/// The load of a condition against the weights the published tables print (references A and B: NESC,
/// 57 lb/ft^3 ice, wind on the iced diameter, K added to the resultant): 0.5 in ice 2.094 lb/ft; with 4
/// psf and K = 0.30, 2.509 lb/ft; 1.5 in ice 5.961 lb/ft. Tolerance 0.0006 lb/ft (the printed rounding)
/// for the first two; the 1.5 in row's 5.961 is 0.002 above the formula (5.959, as
/// docs/sagtension_references.md found by hand), so 0.003 there.
#[test]
fn the_load_per_length_is_the_published_weight() {
    let c = drake(0.0);
    for (ice, wind, k, published, tol) in [
        (0.5, 0.0, 0.0, 2.094, 6e-4),
        (0.5, 4.0, 0.30, 2.509, 6e-4),
        (1.5, 0.0, 0.0, 5.961, 3e-3),
        (0.0, 0.0, 0.0, 1.094, 1e-9),
    ] {
        let w = weather_us(0.0, ice, 57.0, wind, k).load_n_per_m(&c, STANDARD_GRAVITY_M_PER_S2) / (LBF / FT);
        assert!((w - published).abs() < tol, "{ice} in, {wind} psf, K {k}: {w} lb/ft vs {published}");
    }
}

/// The two sags of an inclined span against Irvine's closed-form positions (linear law): at the
/// horizontal mid-point (found by bisection on Irvine's `x(s)`) and the largest (a fine scan of Irvine's
/// curve refined by golden section): 1e-9 m. Both sides solve the same closure to 1e-12 of the span;
/// the sag differs from the chord offset by the rise times the slope's error, well below 1e-9 m.
#[test]
fn the_sags_of_an_inclined_span_are_irvines() {
    let c = linear_conductor(false);
    let k = c.law.outer.initial.coefficients_n[1];
    let (l, h, l0, w, theta) = (400.0, 80.0, 1.004 * 400f64.hypot(80.0), 25.0, 293.15);
    let span = span_law(&c.law, c.law.virgin(CurveKind::Initial), theta, w, l, h, l0);
    let hv = span.solve().unwrap().hv();
    let mid = span.sag_at_x(0.5 * l, hv).unwrap();
    let max = span.max_sag(hv).unwrap();
    let cat = ElasticCatenary::solve([0.0; 3], [0.0, l, h], l0, [0.0, 0.0, -w], k).unwrap();
    let pos = |s: f64| {
        let p = cat.position(s);
        (p[1], p[2])
    };
    let sag_at = |s: f64| {
        let (x, y) = pos(s);
        h * x / l - y
    };
    let (mut a, mut b) = (0.0, l0);
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if pos(m).0 < 0.5 * l { a = m } else { b = m }
    }
    let irvine_mid = sag_at(0.5 * (a + b));
    let n = 2000;
    let best = (0..=n).map(|i| l0 * i as f64 / n as f64).max_by(|p, q| sag_at(*p).total_cmp(&sag_at(*q))).unwrap();
    let (mut a, mut b) = ((best - l0 / n as f64).max(0.0), (best + l0 / n as f64).min(l0));
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..200 {
        let (c1, c2) = (b - g * (b - a), a + g * (b - a));
        if sag_at(c1) > sag_at(c2) { b = c2 } else { a = c1 }
    }
    let irvine_max = sag_at(0.5 * (a + b));
    println!("mid-span sag {mid} m (Irvine {irvine_mid}), largest {max} m (Irvine {irvine_max})");
    assert!((mid - irvine_mid).abs() < 1e-9 && (max - irvine_max).abs() < 1e-9);
    assert!(max > mid, "on an inclined span the largest sag is off mid-span");
}

/// The clearance rating with the knee (docs/sagtension.md, last table): the single-modulus Drake (`EA` =
/// the sum of the final moduli, the modulus-weighted `alpha`, the form of the default conductor) and the
/// two-material Drake strung alike (initial state); a clearance limit set by the single-modulus sag at
/// 100, 125 and 150 C is reached by the two-material conductor at the printed temperature, and IEEE 738
/// (Annex B's weather: 40 C air, 0.61 m/s across, sun) gives the ampacity at each. Checks: the
/// single-modulus conductor reaches its own sag at the given temperature (1e-8 K: the search's
/// tolerance is 1e-10 K), and past the knee the two-material conductor reaches it later (its sag grows
/// with the steel's alpha).
#[test]
fn clearance_rating_with_the_knee_against_a_single_modulus() {
    use ohl::thermal::examples::annex_b;
    use ohl::thermal::ieee738::Ieee738;
    use ohl::thermal::steady::ampacity;
    let area = 0.7264 * INCH * INCH;
    let ea = 101000.0 * PSI * 100.0 * area;
    let alpha = (64000.0 * 12.8e-6 + 37000.0 * 6.4e-6) / 101000.0 * 1.8;
    let two = drake(0.0);
    let one = SagConductor {
        law: TwoMaterial {
            outer: Component::linear(area, ea / area, alpha),
            core: None,
            reference_temperature_k: kelvin_of_f(70.0),
        },
        ..two
    };
    let rating = Ieee738 { conductor: annex_b::drake(), weather: annex_b::weather() };
    let amps = |t: f64| ampacity(&rating, t).unwrap().current_a;
    for (span_ft, h_lb) in [(700.0, 6300.0), (1200.0, 6000.0)] {
        let at = weather_us(60.0, 0.0, 0.0, 0.0, 0.0);
        let s2 = problem(two, Span::level(span_ft * FT), h_lb * LBF, at).string().unwrap();
        let s1 = problem(one, Span::level(span_ft * FT), h_lb * LBF, at).string().unwrap();
        let knee = s2.knee_temperature_k(State::Initial).unwrap();
        println!("{span_ft} ft, {h_lb} lb initial at 60 F: knee {:.1} C", knee - 273.15);
        for tc in [100.0, 125.0, 150.0] {
            let theta = tc + 273.15;
            let sag1 = s1.solve(&Weather::bare(theta), State::Initial).unwrap().sag_midspan_m;
            let sag2 = s2.solve(&Weather::bare(theta), State::Initial).unwrap().sag_midspan_m;
            let back = s1.temperature_at_sag_k(State::Initial, sag1).unwrap();
            assert!((back - theta).abs() < 1e-8, "{back} vs {theta}");
            let t2 = s2.temperature_at_sag_k(State::Initial, sag1).unwrap();
            if theta > knee {
                assert!(t2 > theta, "past the knee the two-material conductor sags less");
            }
            println!(
                "  limit = single-modulus sag at {tc} C = {sag1:.3} m (two-material {sag2:.3} m): two-material reaches it at {:.1} C; IEEE 738 Annex B weather: {:.0} A at {tc} C, {:.0} A at {:.1} C",
                t2 - 273.15,
                amps(theta),
                amps(t2),
                t2 - 273.15
            );
        }
    }
}

/// Drake's knee temperatures for references D and B in each state (docs/sagtension.md). Check: the
/// table row 0.01 K below the knee has the aluminium loaded at the support and 0.01 K above it not (the
/// search's root is the row's flag's switch, 1e-10 K apart).
#[test]
fn drakes_knee_temperatures_for_references_d_and_b() {
    let b = Problem {
        creep: Some(weather_us(60.0, 0.0, 0.0, 0.0, 0.0)),
        heavy_load: Some(weather_us(0.0, 0.5, 57.0, 4.0, 0.30)),
        ..problem(drake(0.0), Span::level(700.0 * FT), 6300.0 * LBF, weather_us(60.0, 0.0, 0.0, 0.0, 0.0))
    };
    for (name, p) in [("D", reference_d(drake(1500.0), StretchPoint::MostStrained)), ("B", b)] {
        let s = p.string().unwrap();
        for state in [State::Initial, State::AfterCreep, State::AfterLoad, State::Final] {
            let k = s.knee_temperature_k(state).unwrap();
            println!(
                "{name} {state:?} (final = {:?}): knee {:.2} C = {:.1} F",
                s.histories.final_is,
                k - 273.15,
                (k - 273.15) * 1.8 + 32.0
            );
            assert!(!s.solve(&Weather::bare(k - 0.01), state).unwrap().knee_passed);
            assert!(s.solve(&Weather::bare(k + 0.01), state).unwrap().knee_passed);
        }
    }
}

/// A section's spans at the ruling span's H (linear law): each span's unstressed length and sag against
/// Irvine's closed form at that H, `l = H L0' / EA' + (2 H / w') asinh(w' L0' / (2 H))` solved for `L0'`
/// (bisection to round-off; `'`: the thermal-strain scaling of (a)). Sag to 1e-9 m and `L0` to 1e-12
/// relative, as (a); and the span equal to the ruling span returns the ruling span's own row.
#[test]
fn the_spans_of_a_section_carry_the_ruling_spans_h() {
    let c = linear_conductor(false);
    let k = c.law.outer.initial.coefficients_n[1];
    let alpha = c.law.outer.expansion_per_k;
    let lengths = [200.0, 350.0, 500.0];
    let ruling = Span::ruling(&lengths).unwrap();
    let p = problem(c, ruling, 20e3, Weather::bare(288.15));
    let strung = p.string().unwrap();
    let weather = Weather::bare(333.15);
    let r = strung.solve(&weather, State::Initial).unwrap();
    let same = strung.section_span(&weather, State::Initial, ruling).unwrap();
    assert!((same.unstressed_length_m - strung.unstressed_length_m).abs() < 1e-12 * same.unstressed_length_m);
    let h = r.horizontal_tension_n;
    let cth = alpha * (333.15 - 293.15);
    let w = weather.load_n_per_m(&c, p.gravity_m_per_s2) / (1.0 + cth);
    let ea = k * (1.0 + cth);
    for l in lengths {
        let row = strung.section_span(&weather, State::Initial, Span::level(l)).unwrap();
        let x = |l0: f64| h * l0 / ea + 2.0 * h / w * (w * l0 / (2.0 * h)).asinh() - l;
        let (mut a, mut b) = (0.9 * l, 1.1 * l);
        for _ in 0..200 {
            let m = 0.5 * (a + b);
            if x(m) < 0.0 { a = m } else { b = m }
        }
        let l0 = 0.5 * (a + b);
        let cat = ElasticCatenary::level(l, l0, w, ea).unwrap();
        let sag = -cat.midspan_displacement_m()[2];
        println!(
            "span {l} m: H {} N (ruling {h}), sag {} m (Irvine {sag})",
            row.horizontal_tension_n, row.sag_midspan_m
        );
        assert!((row.horizontal_tension_n - h).abs() < 1e-10 * h);
        assert!(
            (row.unstressed_length_m - l0 / (1.0 + cth)).abs() < 1e-12 * l0,
            "{} vs {}",
            row.unstressed_length_m,
            l0 / (1.0 + cth)
        );
        assert!((row.sag_midspan_m - sag).abs() < 1e-9, "{} vs {sag}", row.sag_midspan_m);
    }
}
