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
