//! Rating by clearance (`ohl::scenario::rating`) against an independent exact answer: the 400 m level
//! Drake span of `examples/thermal/drake_span_rating.toml` reaches its 11 m clearance limit (a mid-span
//! sag of 14 m below the 25 m supports) at the temperature `T*` where the exact elastic catenary
//! (`ohl::exact::catenary`, closed form) with the thermally stretched unstretched length `L (1 + alpha (T -
//! T0))` and the same total weight sags 14 m. The library's limiting temperature converges to `T*` at
//! order 2 (the chain's `O(ds^2)` sag error divided by `d sag / dT`), and its rating is the IEEE 738
//! ampacity at that temperature.

use ohl::exact::catenary::ElasticCatenary as Catenary;
use ohl::scenario::{self, rating};
use ohl::thermal::{Model, Standard, catalog, steady};

const FILE: &str = "examples/thermal/drake_span_rating.toml";

fn rated(segments: usize) -> (rating::Rating, f64) {
    let text = std::fs::read_to_string(FILE)
        .unwrap()
        .replace("segments_per_span = 40", &format!("segments_per_span = {segments}"));
    let s = scenario::parse(&text, FILE).unwrap();
    let plan = scenario::plan(&s, FILE).unwrap();
    let length: f64 = plan.solver.wire().reference_length.iter().sum();
    (rating::rate(&s, FILE).unwrap(), length)
}

/// The exact temperature at which the span sags `sag_m`, by bisection on the closed-form catenary.
fn exact_limit_k(length_m: f64, sag_m: f64) -> f64 {
    let (ea, w, alpha, t0) = (2.9e7, 1.628 * 9.81, 1.89e-5, 288.15);
    let sag = |t: f64| {
        let f = 1.0 + alpha * (t - t0);
        let c = Catenary::level(400.0, length_m * f, w / f, ea).unwrap();
        -c.position(0.5 * length_m * f)[2]
    };
    let (mut lo, mut hi) = (t0, 600.0);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if sag(mid) < sag_m { lo = mid } else { hi = mid }
    }
    0.5 * (lo + hi)
}

#[test]
fn limiting_temperature_converges_to_the_exact_catenary_at_order_two() {
    let ns = [20, 40, 80];
    let mut errors = Vec::new();
    for &n in &ns {
        let (r, length) = rated(n);
        let t_lim = r.limit_temperature_k.expect("the clearance governs in this example");
        let exact = exact_limit_k(length, 14.0);
        println!(
            "N = {n}: T_lim {:.4} C, exact {:.4} C, rating {:.2} A, {} solves",
            t_lim - 273.15,
            exact - 273.15,
            r.rating_a,
            r.solves
        );
        errors.push((t_lim - exact).abs());
        // The rating is the ampacity at the limiting temperature (IEEE 738, the example's weather).
        let k = catalog::find("ACSR Drake").unwrap();
        let s = scenario::load(std::path::Path::new(FILE)).unwrap();
        let model = Model::new(Standard::Ieee738, k.thermal(), scenario::thermal::weather(&s.thermal.unwrap().weather));
        assert!((steady::ampacity(&model, t_lim).unwrap().current_a - r.rating_a).abs() < 1e-9);
    }
    let orders: Vec<f64> = errors.windows(2).map(|e| (e[0] / e[1]).log2()).collect();
    println!("errors {errors:?} K, orders {orders:?}");
    // Order 2 +- 0.15: the bisection on T stops at 1e-3 K, 3 % of the finest error (0.03 K).
    for p in &orders {
        assert!((p - 2.0).abs() < 0.15, "orders {orders:?}");
    }
}

#[test]
fn a_rating_without_ampacity_says_why() {
    // Still air and the example's sun at 40 C: the sun alone heats Drake above 42 C (IEEE 738 Annex B:
    // about 22 W/m of solar heating against a few W/m of cooling 2 K above the air), so there is no
    // ampacity for a maximum temperature of 42 C; the clearance stays above 1 m up to it. The message
    // names both limits and what the ampacity said.
    let text = std::fs::read_to_string(FILE)
        .unwrap()
        .replace("wind_speed_m_per_s = 0.61", "wind_speed_m_per_s = 0.0")
        .replace("min_clearance_m = 11.0", "min_clearance_m = 1.0")
        .replace("max_temperature_k = 373.15", "max_temperature_k = 315.15");
    let s = scenario::parse(&text, FILE).unwrap();
    let e = rating::rate(&s, FILE).unwrap_err().to_string();
    println!("{e}");
    assert!(
        e.starts_with(
            "no ampacity at the limiting temperature: the clearance stays within its limit 1 m up to 315.150 K; "
        ),
        "{e}"
    );
    assert!(
        e.contains("rating.max_temperature_k, at 315.150 K (42.00 C): no ampacity for 315.15 K (42 C): solar heating"),
        "{e}"
    );
    // The solar heating and cooling it quotes are the heat balance's own at 42 C.
    let model = Model::new(
        Standard::Ieee738,
        catalog::find("ACSR Drake").unwrap().thermal(),
        scenario::thermal::weather(&s.thermal.unwrap().weather),
    );
    let terms = ohl::thermal::HeatBalance::terms(&model, 315.15, 1.0);
    assert!(terms.solar_w_per_m > terms.convection_w_per_m + terms.radiation_w_per_m, "{terms:?}");
    assert!(e.contains(&format!("solar heating {:.3} W/m", terms.solar_w_per_m)), "{e}");
}

/// The example's rating with `max_temperature_k` replaced (`None`: removed).
fn rated_with_max(max_k: Option<&str>, extra: &[(&str, &str)]) -> rating::Rating {
    let mut text = std::fs::read_to_string(FILE)
        .unwrap()
        .replace("max_temperature_k = 373.15", &max_k.map_or_else(String::new, |t| format!("max_temperature_k = {t}")));
    for (from, to) in extra {
        assert!(text.contains(from), "{from}");
        text = text.replace(from, to);
    }
    let s = scenario::parse(&text, FILE).unwrap();
    rating::rate(&s, FILE).unwrap()
}

#[test]
fn the_margin_to_the_clearance_is_where_the_clearance_alone_governs() {
    // T_max = 67 C governs (the clearance limit is reached near 82 C). The reported temperature of the
    // clearance limit must be the limiting temperature of the same rating without T_max, where the
    // clearance governs: both are bisections to 1e-3 K of the same root (each returns the lower end of a
    // bracket of width <= 1e-3 K around it), so they differ by less than 1e-3 K; the currents by less than
    // dI/dT * 1e-3 K, with dI/dT < 20 A/K here (592 A at 67 C, 824 A at 82 C: 15 A/K), so 0.02 A.
    let governed = rated_with_max(Some("340.15"), &[]);
    assert_eq!(governed.governing_temperature_k, 340.15, "T_max governs");
    assert_eq!(governed.limit_temperature_k, None);
    let other = governed.other.clone().expect("a margin with T_max");
    assert_eq!(other.quantity, "clearance");
    let t_c = other.temperature_k.expect("reached below 600 K");
    let alone = rated_with_max(None, &[]);
    let t_alone = alone.limit_temperature_k.expect("the clearance governs alone");
    println!("clearance limit at {:.4} C (T_max governing), {:.4} C alone", t_c - 273.15, t_alone - 273.15);
    assert!((t_c - t_alone).abs() < 1e-3, "{t_c} against {t_alone}");
    let (i_c, i_alone) = (other.current_a.unwrap(), alone.rating_a);
    assert!((i_c - i_alone).abs() < 0.02, "{i_c} A against {i_alone} A");
    assert!(i_c > governed.rating_a, "the margin is positive: {i_c} > {}", governed.rating_a);
    assert_eq!(alone.other, None, "no T_max, no other limit");
}

#[test]
fn a_clearance_limit_at_the_reported_clearance_governs_at_its_temperature() {
    // With T_max = 67 C governing, the least clearance there is reported (`at_rating_m`). A rating whose
    // clearance limit is that clearance, without T_max, must be governed by the clearance at 67 C: the
    // bisection's lower end lies within 1e-3 K below the root (plus the static solve's tolerance, whose
    // effect on the clearance, 1e-9 m against a clearance slope of about 0.1 m/K, is 1e-8 K).
    let governed = rated_with_max(Some("340.15"), &[]);
    let clearance = governed.at_rating_m;
    let limit = format!("min_clearance_m = {clearance:?}");
    let alone = rated_with_max(None, &[("min_clearance_m = 11.0", &limit)]);
    let t = alone.limit_temperature_k.unwrap();
    println!("clearance {clearance} m reached at {:.5} C", t - 273.15);
    assert!(t <= 340.15 + 1e-6 && t > 340.15 - 1.1e-3, "{t}");
    // Where the clearance governs, the other limit is T_max and its ampacity.
    let r = rated_with_max(Some("373.15"), &[]);
    let other = r.other.unwrap();
    assert_eq!((other.quantity, other.temperature_k), ("temperature", Some(373.15)));
    assert_eq!(other.current_a, r.temperature_ampacity_a);
}

#[test]
fn temperatures_in_celsius_give_the_kelvin_rating_bit_for_bit() {
    // The example in degrees Celsius (15 C, 40 C air, 100 C maximum): the same numbers as the file in
    // kelvin, because the conversion gives the decimal kelvin values exactly (288.15, 313.15, 373.15).
    let kelvin = rated_with_max(Some("373.15"), &[]);
    let celsius = rated_with_max(
        None,
        &[
            ("reference_temperature_k = 288.15", "reference_temperature_c = 15.0"),
            ("air_temperature_k = 313.15", "air_temperature_c = 40"),
            ("[rating]\n", "[rating]\nmax_temperature_c = 100.0\n"),
        ],
    );
    assert_eq!(celsius, kelvin);
}
