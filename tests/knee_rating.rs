//! The clearance rating with the knee point (issue 24): `ohl rating`'s limiting temperature, found by the
//! finite-difference static solver with the two-material law (`conductor.tension_law = "two_material"`,
//! the section strung by the law at its stringing temperature), against the sag-tension solver's exact
//! catenary by quadrature (`ohl::sagtension`, `Strung::temperature_at_sag_k`), under grid refinement.
//!
//! The span is examples/thermal/drake_span_rating.toml's: 400 m level, ACSR Drake strung at 28 kN
//! (20 % of 140 kN) at 15 C, supports 25 m above level ground. A clearance limit `c` is the mid-span sag
//! `25 - c`. The discrete static solution differs from the continuous one by `O(ds^2)`, so the limiting
//! temperature does too: the test fits the observed order over the last three of four grids and asserts
//! 2 +- 0.25 (the rating's bisection stops at 1e-3 K, below a tenth of the finest error here), and that the
//! Richardson extrapolate of the two finest grids meets the exact limit within 5e-3 K.

use ohl::sagtension::{Problem, SagConductor, Span, State, StretchPoint, Stringing, StringingTarget, Weather};
use ohl::scenario;

const G: f64 = 9.81;

fn scenario_text(segments: usize, clearance_m: f64) -> String {
    format!(
        r#"
name = "knee_rating"
[conductor]
catalog = "ACSR Drake"
tension_law = "two_material"
linear_density_kg_per_m = 1.628
diameter_m = 0.0281
reference_temperature_k = 288.15
rated_tensile_strength_n = 140000.0
[section]
tension_fraction_of_rts = 0.20
segments_per_span = {segments}
supports = [
  {{ kind = "dead_end", point_m = [0.0, 0.0, 25.0] }},
  {{ kind = "dead_end", point_m = [0.0, 400.0, 25.0] }},
]
[initial]
shape = "equilibrium"
[ground]
height_m = 0.0
restitution = 0.0
[duration]
end_time_s = 1.0
[thermal]
standard = "ieee738"
conductor = "ACSR Drake"
current_a = [[0.0, 800.0]]
[thermal.weather]
air_temperature_k = 313.15
wind_speed_m_per_s = 0.61
wind_angle_deg = 90.0
[rating]
min_clearance_m = {clearance_m}
max_temperature_k = 523.15
"#
    )
}

fn rated_limit_k(segments: usize, clearance_m: f64) -> f64 {
    let sc = scenario::parse(&scenario_text(segments, clearance_m), "knee_rating").unwrap();
    let r = scenario::rating::rate(&sc, "knee_rating").unwrap();
    r.limit_temperature_k.expect("the clearance limit is reached below 250 C")
}

fn strung() -> ohl::sagtension::Strung {
    let drake = ohl::thermal::catalog::find("ACSR Drake").unwrap();
    let conductor = SagConductor { mass_kg_per_m: 1.628, ..SagConductor::from_catalog(drake).unwrap() };
    let p = Problem {
        conductor,
        span: Span { length_m: 400.0, rise_m: 0.0 },
        stringing: Stringing {
            target: StringingTarget::HorizontalTension(28e3),
            weather: Weather::bare(288.15),
            state: State::Initial,
        },
        creep: None,
        heavy_load: None,
        gravity_m_per_s2: G,
        stretch_point: StretchPoint::MostStrained,
    };
    p.string().unwrap()
}

fn exact_limit_k(clearance_m: f64) -> f64 {
    strung().temperature_at_sag_k(State::Initial, 25.0 - clearance_m).unwrap()
}

#[test]
fn the_rating_s_limiting_temperature_with_the_knee_converges_at_second_order_to_the_exact_catenary() {
    let knee = strung().knee_temperature_k(State::Initial).unwrap();
    println!("knee point of the span, initial state: {:.2} C", knee - 273.15);
    for clearance in [10.0, 9.0] {
        let exact = exact_limit_k(clearance);
        let grids = [10, 20, 40, 80];
        let t: Vec<f64> = grids.iter().map(|&n| rated_limit_k(n, clearance)).collect();
        let err: Vec<f64> = t.iter().map(|x| (x - exact).abs()).collect();
        println!("clearance {clearance} m: exact limit {:.4} C", exact - 273.15);
        for (n, (x, e)) in grids.iter().zip(t.iter().zip(&err)) {
            println!("  N = {n:3}: {:.4} C, error {e:.3e} K", x - 273.15);
        }
        // least-squares slope of log(err) against log(ds) over the last three grids
        let pts: Vec<(f64, f64)> = (1..4).map(|k| ((1.0 / grids[k] as f64).ln(), err[k].ln())).collect();
        let (mx, my) = (pts.iter().map(|p| p.0).sum::<f64>() / 3.0, pts.iter().map(|p| p.1).sum::<f64>() / 3.0);
        let order = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum::<f64>()
            / pts.iter().map(|p| (p.0 - mx).powi(2)).sum::<f64>();
        println!("  observed order {order:.3}");
        assert!((order - 2.0).abs() < 0.25, "observed order {order}");
        // Richardson's extrapolate of the two finest grids removes the ds^2 term: what remains is the
        // rating's bisection (1e-3 K per value, so up to (4 + 1) / 3 * 1e-3 K) and the O(ds^4) term.
        let richardson = t[3] + (t[3] - t[2]) / 3.0;
        println!(
            "  Richardson {:.4} C, {:.1e} K from the exact limit",
            richardson - 273.15,
            (richardson - exact).abs()
        );
        assert!((richardson - exact).abs() < 5e-3, "extrapolate {richardson} K vs exact {exact} K");
    }
}
