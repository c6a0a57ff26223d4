//! IEC 60865-1 simplified method for flexible conductors (issue 25, `ohl::shortcircuit::iec60865`): the
//! published worked examples of IEC TR 60865-2 and the FAU program's project "Riet" as far as public sources
//! give them (tests/data/iec60865, docs/short_circuit_iec60865.md), step by step and end to end, and the
//! method's invariants.

use ohl::shortcircuit::iec60865::equations as eq;
use ohl::shortcircuit::iec60865::psi::psi;
use ohl::shortcircuit::iec60865::{Bundle, Fault, G_N, Iec60865Error, Input, Mounting, Pinch, evaluate};
use std::collections::BTreeMap;

/// A value of a data file: an exact input (TOML number) or a printed, rounded value (string) with half a
/// unit of its last digit as its rounding bound.
#[derive(Clone, Copy, Debug)]
struct Value {
    x: f64,
    half_unit: f64,
}

/// Half a unit of the last printed digit of `s` ("0.594" -> 0.0005, "153" -> 0.5, "1.82e10" -> 0.005e10).
fn parse_printed(s: &str) -> Value {
    let (mantissa, exponent) = match s.split_once(['e', 'E']) {
        Some((m, e)) => (m, e.parse::<i32>().expect("exponent")),
        None => (s, 0),
    };
    let decimals = mantissa.split_once('.').map_or(0, |(_, f)| f.len()) as i32;
    Value { x: s.parse().expect("printed value"), half_unit: 0.5 * 10f64.powi(exponent - decimals) }
}

fn value_of(v: &toml::Value) -> Value {
    match v {
        toml::Value::String(s) => parse_printed(s),
        toml::Value::Float(x) => Value { x: *x, half_unit: 0.0 },
        toml::Value::Integer(i) => Value { x: *i as f64, half_unit: 0.0 },
        other => panic!("not a value: {other:?}"),
    }
}

/// One step of an example: the library's equation named `quantity` on the inputs by name.
fn compute(quantity: &str, p: &BTreeMap<String, f64>) -> f64 {
    let g = |k: &str| *p.get(k).unwrap_or_else(|| panic!("{quantity}: input {k} missing"));
    // g_n: the standard's 9.81 unless the source is known to use another value (input `g`)
    let g_n = p.get("g").copied().unwrap_or(G_N);
    // E_eff as printed, or from E by eq. (26) where the source prints no E_eff
    let e_eff =
        || p.get("e_eff").copied().unwrap_or_else(|| eq::effective_modulus(g("e"), g("f_st"), g("n"), g("a_s")));
    match quantity {
        "f_prime_three_phase" => eq::characteristic_force(true, g("current_a"), g("a"), g("l_c"), g("l")),
        "m_s_with_masses" => g("m_s") + g("m_c") / (g("n") * g("l_c")),
        "r" => eq::force_ratio(g("f_prime"), g("n"), g("m_s"), g_n),
        "b_c" => eq::static_sag(g("n"), g("m_s"), g_n, g("l"), g("f_st")),
        "t_res" => {
            let r = g("r");
            eq::resultant_period(eq::period(g("b_c"), g_n), r, eq::resultant_direction_deg(r))
        }
        "e_eff" => eq::effective_modulus(g("e"), g("f_st"), g("n"), g("a_s")),
        "zeta" => {
            let stiffness = eq::stiffness_norm(g("s"), g("l"), g("n"), e_eff(), g("a_s"));
            eq::stress_factor(g("n"), g_n, g("m_s"), g("l"), g("f_st"), stiffness)
        }
        // eqs. (33)-(36): F_t from the printed phi, psi (times `f_t_factor`, 1 unless given: the reading of
        // eq. (34) with 1.1 F_t for a bundle is tested where a source needs it), eps_ela, eps_th, C_D
        "c_d" => {
            let stiffness = eq::stiffness_norm(g("s"), g("l"), g("n"), e_eff(), g("a_s"));
            let factor = p.get("f_t_factor").copied().unwrap_or(1.0);
            let f_t = factor * eq::tensile_force(g("f_st"), g("phi"), g("psi"));
            let eps_ela = eq::elastic_expansion(stiffness, f_t, g("f_st"));
            let eps_th = eq::thermal_expansion(g("c_th"), g("current_a"), g("n"), g("a_s"), g("t_k1"), g("t_res"));
            eq::dilatation_factor(g("l"), g("b_c"), eps_ela, eps_th)
        }
        "delta_k" => eq::swing_out_end_deg(eq::resultant_direction_deg(g("r")), g("t_k1"), g("t_res")),
        "phi" => eq::load_parameter(g("r"), g("t_k1"), g("t_res"), g("delta_k")),
        "psi" => psi(g("phi"), g("zeta")).expect("psi"),
        "c_f" => eq::form_factor(g("r")),
        other => panic!("unknown quantity {other}"),
    }
}

/// The range of `compute` over the corners of the rounding box of the inputs (every equation used here is
/// monotone in each input over a box this small, so the corners bound it), widened by half a unit of the
/// printed result's last digit: the interval the printed value must fall in.
fn interval(quantity: &str, inputs: &BTreeMap<String, Value>, printed: Value) -> (f64, f64) {
    let names: Vec<&String> = inputs.keys().collect();
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for corner in 0..(1u32 << names.len()) {
        let p: BTreeMap<String, f64> = names
            .iter()
            .enumerate()
            .map(|(i, k)| {
                let v = inputs[*k];
                let sign = if corner & (1 << i) == 0 { -1.0 } else { 1.0 };
                ((*k).clone(), v.x + sign * v.half_unit)
            })
            .collect();
        let y = compute(quantity, &p);
        lo = lo.min(y);
        hi = hi.max(y);
    }
    (lo - printed.half_unit, hi + printed.half_unit)
}

fn check_file(name: &str) -> usize {
    let path = format!("{}/tests/data/iec60865/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap();
    let doc: toml::Table = toml::from_str(&text).unwrap();
    assert!(doc["source"].as_str().is_some_and(|s| !s.is_empty()) && doc["url"].as_str().is_some());
    let steps = doc["step"].as_array().unwrap();
    for step in steps {
        let quantity = step["quantity"].as_str().unwrap();
        let label = step.get("label").and_then(|l| l.as_str()).unwrap_or("");
        let inputs: BTreeMap<String, Value> =
            step["inputs"].as_table().unwrap().iter().map(|(k, v)| (k.clone(), value_of(v))).collect();
        let printed = value_of(&step["printed"]);
        let (lo, hi) = interval(quantity, &inputs, printed);
        let inside = lo <= printed.x && printed.x <= hi;
        let reproduced = step["reproduced"].as_bool().unwrap();
        assert_eq!(
            inside, reproduced,
            "{name}: {quantity} {label}: printed {} against [{lo}, {hi}] (file says reproduced = {reproduced})",
            printed.x
        );
    }
    steps.len()
}

/// IEC TR 60865-2 example 7 (slack single conductor), every transcribed step: 16 reproduce (C_D at both
/// temperatures included), E_eff at the maximum temperature does not (docs/short_circuit_iec60865.md).
#[test]
fn tr60865_2_example_7_steps() {
    assert_eq!(check_file("tr60865_2_example7.toml"), 17);
}

/// IEC TR 60865-2 example 8 (strained twin bundle), every transcribed step: 16 reproduce (C_D at both
/// temperatures included), T_res at -20 C does not.
#[test]
fn tr60865_2_example_8_steps() {
    assert_eq!(check_file("tr60865_2_example8.toml"), 17);
}

/// Example 8 of IEC TR 60865-2 as an [`Input`] (tests/data/iec60865/tr60865_2_example8.toml): the spacer
/// distance 9.5 m is the most frequent of the xlsx's 4.2 / 9.5 / 9.5 / 14.2 m, d = 43 mm from its table.
fn example_8(f_st: f64, a_s: f64) -> Input {
    Input {
        span_m: 48.0,
        phase_distance_m: 5.0,
        mounting: Mounting::Strained { insulator_chain_length_m: 5.3 },
        subconductors: 2,
        mass_per_length_kg_per_m: 3.2482,
        concentrated_mass_kg: 74.0,
        area_m2: 1090e-6,
        young_modulus_pa: 60e9,
        diameter_m: 0.043,
        static_tension_n: f_st,
        spring_constant_n_per_m: 5e5,
        fault: Fault::ThreePhase { current_a: 63e3 },
        first_duration_s: 0.5,
        thermal_constant_m4_per_a2s: 0.27e-18,
        gravity_m_per_s2: G_N,
        bundle: Some(Bundle {
            subconductor_distance_m: a_s,
            spacer_distance_m: 9.5,
            frequency_hz: 50.0,
            peak_factor: 1.81,
        }),
    }
}

/// Example 8 (strained twin bundle, -20 C) through [`evaluate`] end to end: the chain without intermediate
/// rounding lands within the rounding of the printed intermediate values (F' 92.8, b_c 1.346 with
/// m'_s = 4.24, zeta 2.04, phi 1.495, psi 0.69) plus the effect of the TR's rounded m'_s (4.24 against
/// 4.2375: 0.06 %), and the derived quantities follow the clause's cases.
#[test]
fn example_8_end_to_end() {
    let out = evaluate(&example_8(17800.0, 0.1)).unwrap();
    let near = |x: f64, printed: f64, half: f64| (x - printed).abs() <= half;
    assert!(near(out.l_c_m, 37.4, 1e-12));
    assert!(near(out.f_prime_n_per_m, 92.8, 0.05), "{}", out.f_prime_n_per_m);
    // b_c from the unrounded m'_s = 4.2375 (printed 4.24 gives 1.346): 1.3452
    assert!(near(out.b_c_m, 1.346, 0.0005 + 1.346 * 0.0025 / 4.24), "{}", out.b_c_m);
    assert!(near(out.zeta, 2.04, 0.005 + 0.01), "{}", out.zeta);
    assert!(near(out.phi, 1.495, 0.0005 + 0.002), "{}", out.phi);
    assert!(near(out.psi, 0.69, 0.005), "{}", out.psi);
    // T_k1 = 0.5 s >= T_res / 4: phi by the first case of (32), delta_k by the first case of (29).
    assert!(out.t_res_s / 4.0 <= 0.5 && 0.5 / out.t_res_s <= 0.5);
    // r = 1.12 > 0.6; delta_m > 70 deg: F_f is asked for.
    assert!(out.delta_m_deg >= 70.0 && out.f_f_n.is_some());
    // strained: b_h = b_D sin delta_1 since delta_m >= delta_1 (45); a_min = a - 2 b_h (48).
    assert!(out.delta_m_deg >= out.delta_1_deg);
    assert!((out.b_h_m - out.b_d_m * out.delta_1_deg.to_radians().sin()).abs() < 1e-12);
    assert!((out.a_min_m - (5.0 - 2.0 * out.b_h_m)).abs() < 1e-12);
    // a_s / d = 2.33 <= 2.5 and l_s = 9.5 >= 70 a_s = 7: effective clash, F_pi = 1.1 F_t (51), (53).
    assert_eq!(out.pinch, Some(Pinch::EffectiveClash { force_n: 1.1 * out.f_t_n }));
    // example 8b: a_s = 0.4 m, a_s / d = 9.3: no effective clash (clause 6.4.2, not computed here).
    let b = evaluate(&example_8(17800.0, 0.4)).unwrap();
    let Some(Pinch::NotClashing(c)) = b.pinch else { panic!("8b clashes: {:?}", b.pinch) };
    assert!(c.f_pi_n.is_finite() && c.f_pi_n > 17800.0, "{c:?}");
}

/// F' is proportional to I^2 / a (eq. (19a)) and the two-phase force is 4/3 of the three-phase one at the
/// same current; psi stays in (0, 1); F_t > F_st.
#[test]
fn force_scaling_and_bounds() {
    let base = example_8(17800.0, 0.1);
    let f0 = evaluate(&base).unwrap();
    let mut doubled = base;
    doubled.fault = Fault::ThreePhase { current_a: 2.0 * 63e3 };
    doubled.phase_distance_m = 10.0;
    let f1 = evaluate(&doubled).unwrap();
    assert!((f1.f_prime_n_per_m / f0.f_prime_n_per_m - 2.0).abs() < 1e-14);
    let mut two = base;
    two.fault = Fault::LineToLine { current_a: 63e3 };
    let f2 = evaluate(&two).unwrap();
    assert!((f2.f_prime_n_per_m / f0.f_prime_n_per_m - 4.0 / 3.0).abs() < 1e-14);
    for out in [f0, f1, f2] {
        assert!(out.psi > 0.0 && out.psi < 1.0);
        assert!(out.f_t_n > base.static_tension_n);
    }
}

/// F_f is not asked for when r <= 0.6 (clause 6.2.6): a small current.
#[test]
fn no_fall_force_for_small_r() {
    let mut input = example_8(17800.0, 0.1);
    input.fault = Fault::ThreePhase { current_a: 20e3 };
    let out = evaluate(&input).unwrap();
    assert!(out.r <= 0.6, "r = {}", out.r);
    assert_eq!(out.f_f_n, None);
}

/// Bad input is a typed error naming the field and the allowed range, never a panic or NaN.
#[test]
fn bad_input_errors() {
    let mut input = example_8(17800.0, 0.1);
    input.static_tension_n = f64::NAN;
    let err = evaluate(&input).unwrap_err();
    assert!(matches!(err, Iec60865Error::OutOfRange { field: "static_tension_n", .. }));
    assert!(err.to_string().contains("static_tension_n = NaN is out of range: allowed a finite number > 0"));
    let mut input = example_8(17800.0, 0.1);
    input.mounting = Mounting::Strained { insulator_chain_length_m: 24.0 };
    assert!(matches!(evaluate(&input), Err(Iec60865Error::OutOfRange { field: "insulator_chain_length_m", .. })));
    let mut input = example_8(17800.0, 0.1);
    input.bundle = None;
    assert_eq!(evaluate(&input), Err(Iec60865Error::MissingBundle { subconductors: 2 }));
    let mut input = example_8(17800.0, 0.1);
    input.span_m = 130.0;
    assert!(matches!(evaluate(&input), Err(Iec60865Error::OutsideMethod { quantity: "span_m", .. })));
    // F_st = 1.8 kN: b_c = 13.3 m, 28 % of the span: outside the method
    let input = example_8(1800.0, 0.1);
    assert!(matches!(evaluate(&input), Err(Iec60865Error::OutsideMethod { .. })));
}

/// Clause 6.4.2 around j = 1, moved by the spacer distance l_s (eps_pi grows with l_s^3, eps_st with
/// l_s^2): on the j >= 1 side xi -> 1 and nu_4 = (a_s - d)/d; the roots lie in their stated intervals
/// (j^(2/3) <= xi <= j; 0 < eta <= 1, eta the smallest root); nu_2 solves nu_1 = f T_pi sqrt(nu_2(f T_pi)).
/// At j = 1 the eta equation also has the root 1 (f_eta(1) = 1), but its smallest root is below 1, so
/// F_pi jumps there: asserted, so that a corrected eta equation shows up here (docs, "not confirmed").
#[test]
fn pinch_case_boundary() {
    use ohl::shortcircuit::iec60865::bundle::{PinchData, contraction, nu_2_of};
    let base = PinchData {
        n: 2.0,
        a_s: 0.4,
        d: 0.043,
        l_s: 10.0,
        m_s: 4.24,
        current_a: 63e3,
        frequency_hz: 50.0,
        kappa: 1.81,
        f_st: 17800.0,
        stiffness: 5.77e-8,
    };
    let at = |l_s: f64| contraction(&PinchData { l_s, ..base }).unwrap();
    let (mut lo, mut hi) = (0.5, 60.0);
    assert!(at(lo).j < 1.0 && at(hi).j > 1.0, "{} {}", at(lo).j, at(hi).j);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if at(mid).j < 1.0 { lo = mid } else { hi = mid }
    }
    let (below, above) = (at(lo), at(hi));
    assert!(below.j < 1.0 && above.j >= 1.0);
    assert!((above.xi_or_eta - 1.0).abs() < 1e-9, "{above:?}");
    assert!((above.nu_4 - (0.4 - 0.043) / 0.043).abs() < 1e-12);
    assert!(below.xi_or_eta < 0.9 && below.f_pi_n < 0.9 * above.f_pi_n, "{below:?} {above:?}");
    for l_s in [1.0, 3.0, 10.0, 30.0, 60.0] {
        let c = at(l_s);
        if c.j >= 1.0 {
            assert!(c.xi_or_eta >= c.j.powf(2.0 / 3.0) - 1e-12 && c.xi_or_eta <= c.j + 1e-12);
        } else {
            assert!(c.xi_or_eta > 0.0 && c.xi_or_eta <= 1.0);
        }
        assert!(c.f_pi_n > base.f_st);
        let x = c.t_pi_s * base.frequency_hz;
        let tau = 3.0 / (2.0 * std::f64::consts::PI * 50.0 * ((1.81f64 - 1.02) / 0.98).ln().abs());
        let gamma = (2.0 * std::f64::consts::PI * 50.0 * tau).atan();
        assert!((x * nu_2_of(x, 50.0 * tau, gamma).sqrt() - c.nu_1).abs() < 1e-9 * c.nu_1);
    }
}

/// The FAU IEC 60865 program's project "Riet" (strained twin bundle, T_k1 > T_res / 2), every value of the
/// program that the public source passes on: 13 of 16 steps reproduce; zeta at 80 C, and C_D at -20 C with
/// eq. (34) as implemented and at 80 C under either reading, do not (tests/data/iec60865/fau_program_riet.toml,
/// docs/short_circuit_iec60865.md).
#[test]
fn fau_program_riet_steps() {
    assert_eq!(check_file("fau_program_riet.toml"), 16);
}

/// Project Riet of the FAU program (tests/data/iec60865/fau_program_riet.toml) as an [`Input`]: 2 x 600-AL1,
/// no concentrated masses, g = 9.80665 (the value with which the program's g-dependent digits reproduce).
/// No spacer positions are given (the xlsx leaves them empty): l_s = l_c = 20.5 m, which only the pinch
/// quantities after nu_1 depend on, and none of those is checked.
fn riet(f_st: f64) -> Input {
    Input {
        span_m: 31.0,
        phase_distance_m: 4.0,
        mounting: Mounting::Strained { insulator_chain_length_m: 5.25 },
        subconductors: 2,
        mass_per_length_kg_per_m: 1.659,
        concentrated_mass_kg: 0.0,
        area_m2: 600.38e-6,
        young_modulus_pa: 55e9,
        diameter_m: 0.03168,
        static_tension_n: f_st,
        spring_constant_n_per_m: 4e5,
        fault: Fault::ThreePhase { current_a: 40e3 },
        first_duration_s: 1.0,
        thermal_constant_m4_per_a2s: 0.27e-18,
        gravity_m_per_s2: 9.80665,
        bundle: Some(Bundle {
            subconductor_distance_m: 0.4,
            spacer_distance_m: 20.5,
            frequency_hz: 50.0,
            peak_factor: 1.8,
        }),
    }
}

/// Project Riet through [`evaluate`] end to end, without intermediate rounding: every FAU value that the
/// step file reproduces lies within half a unit of its printed last digit here too (T_res at -20 C: the
/// 0.681 of the two transcribed values), the clause's cases are
/// the ones the printed values imply (T_k1 = 1 s > T_res / 2: delta_k = 2 delta_1 exactly, first case of
/// (32); -0.985 <= chi = 1 - r < 0.766: second case of (30)), and nu_1 of clause 6.4.2 (eq. (55)) is the printed
/// 2.764: the first value of the no-clash pinch branch confirmed against an independent program. nu_1 grows
/// with sqrt(m'_s): the 1.68 kg/m of the source's own conductor table would give 2.781, outside.
#[test]
fn fau_program_riet_end_to_end() {
    let cold = evaluate(&riet(19000.0)).unwrap();
    let hot = evaluate(&riet(7000.0)).unwrap();
    let near = |x: f64, printed: f64, half: f64| (x - printed).abs() <= half;
    assert!(near(cold.l_c_m, 20.5, 1e-12));
    assert!(near(cold.f_prime_n_per_m, 39.677, 0.0005), "{}", cold.f_prime_n_per_m);
    assert!(near(cold.r, 1.219, 0.0005), "{}", cold.r);
    assert!(near(cold.b_c_m, 0.206, 0.0005) && near(hot.b_c_m, 0.558, 0.0005), "{} {}", cold.b_c_m, hot.b_c_m);
    // T_res at -20 C unrounded is 0.6814: the 0.681 of one check call, not the 0.682 of the other two (that
    // one is reproduced only from the rounded b_c and r, step file)
    assert!(near(cold.t_res_s, 0.681, 0.0005) && near(hot.t_res_s, 1.123, 0.0005), "{} {}", cold.t_res_s, hot.t_res_s);
    assert!(near(cold.zeta, 0.059, 0.0005), "{}", cold.zeta);
    assert!(near(cold.delta_k_deg, 101.29, 0.005), "{}", cold.delta_k_deg);
    assert_eq!(cold.delta_k_deg, 2.0 * cold.delta_1_deg);
    assert!(near(cold.phi, 1.731, 0.0005), "{}", cold.phi);
    assert!(near(cold.psi, 0.134, 0.0005) && near(hot.psi, 0.563, 0.0005), "{} {}", cold.psi, hot.psi);
    assert!(near(cold.c_f, 1.092, 0.0005), "{}", cold.c_f);
    assert!(cold.chi < 0.766 && cold.chi >= -0.985);
    assert!((cold.delta_m_deg - (10.0 + cold.chi.acos().to_degrees())).abs() < 1e-12);
    // r > 0.6 and delta_m >= 70 deg: F_f asked for; strained, delta_m >= delta_1: b_h = b_D sin delta_1
    assert!(cold.f_f_n.is_some() && hot.f_f_n.is_some());
    assert!((cold.b_h_m - cold.b_d_m * cold.delta_1_deg.to_radians().sin()).abs() < 1e-12);
    // a_s / d = 12.6 > 2.5: no effective clash, clause 6.4.2; nu_1 does not depend on F_st
    for out in [cold, hot] {
        let Some(Pinch::NotClashing(c)) = out.pinch else { panic!("Riet clashes: {:?}", out.pinch) };
        assert!(near(c.nu_1, 2.764, 0.0005), "nu_1 = {}", c.nu_1);
    }
}
