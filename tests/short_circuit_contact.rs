//! The contact of `[short_circuit]` (`short_circuit.contact`, default on: `ohl::line::contact`) on the twin
//! bundle of `cases/h_strained_twin_bundle.toml` (IEC TR 60865-2 example 8a: sub-conductors 0.1 m apart, 43
//! mm thick, 63 kA): the pinch pulls the sub-conductors of each phase together within about 15 ms of
//! inception; with contact they stop at the gap `d` (their axes `d` apart, less the penalty's
//! penetration), without it they cross. The run is cut at 0.2 s (the clash and the first bounces).

use ohl::element::pair::closest_points;
use ohl::scenario::line;

/// The least distance between the axes of the two sub-conductors of phase A over the first 0.2 s [m],
/// every 4th level (the sub-conductors move at most a few m/s: 4 steps of 1e-4 s are 2 mm), with
/// `short_circuit.contact` as given.
fn least_bundle_distance(contact: bool) -> (f64, f64) {
    let file = concat!(env!("CARGO_MANIFEST_DIR"), "/cases/h_strained_twin_bundle.toml");
    let text = std::fs::read_to_string(file).unwrap();
    let text = text.replace(
        "[short_circuit]\n",
        &format!(
            "[short_circuit]\ncontact = {contact}\n{}",
            std::env::var("SC_EXTRA").unwrap_or_default().replace(';', "\n")
        ),
    );
    let s = line::parse(&text, file).unwrap();
    let mut plan = line::plan(&s, file).unwrap();
    let names = plan.line.names().to_vec();
    let (a1, a2) = (names.iter().position(|n| n == "A.1").unwrap(), names.iter().position(|n| n == "A.2").unwrap());
    let dt = plan.line.params().dt_s;
    let mut least = f64::INFINITY;
    let mut step = 0;
    let mut at = (0, 0, 0.0);
    while plan.line.time_s() < 0.2 {
        plan.line.step(dt).unwrap();
        step += 1;
        if step % 4 != 0 {
            continue;
        }
        let (wa, wb) = (plan.line.conductors()[a1].wire(), plan.line.conductors()[a2].wire());
        for i in 0..wa.segments() {
            // Sub-conductors run side by side: the nearby segments of the other suffice.
            for j in i.saturating_sub(2)..(i + 3).min(wb.segments()) {
                let (d2, _, _) = closest_points(wa.position(i), wa.position(i + 1), wb.position(j), wb.position(j + 1));

                if d2.sqrt() < least {
                    least = d2.sqrt();
                    at = (i, j, plan.line.time_s());
                }
            }
        }
    }
    println!(
        "least at segments {} and {}, t = {} s; ends {:?} {:?}",
        at.0,
        at.1,
        at.2,
        plan.line.conductors()[a1].wire().position(0),
        plan.line.conductors()[a2].wire().position(0)
    );
    let gap = plan.line.contact().map_or(0.043, |c| c.spec().pairs[0].gap_m);
    (least, gap)
}

/// With contact, the sub-conductors' axes never come closer than the gap less 20 % of it (the penetration
/// of the penalty under the pinch: the EM attraction at contact, `mu0 I^2 / (2 pi d)` with the peak
/// current per sub-conductor `kappa sqrt(2) I''k3 / 2` = 80.6 kA, is 30 kN/m; `k' = mu (w_c)^2` with `mu` =
/// 1.62 kg/m and `w_c = 0.25 / dt`: about 5e6 N/m^2 at the case's step, 6 mm of the 43 mm); without it they
/// cross (least distance below 2 mm, a tenth of a conductor's radius).
#[test]
fn bundle_sub_conductors_stop_at_contact_instead_of_crossing() {
    let (with, gap) = least_bundle_distance(true);
    let (without, _) = least_bundle_distance(false);
    println!("least distance of A.1 and A.2 in 0.2 s: with contact {with:.4} m (gap {gap} m), without {without:.4} m");
    assert!((gap - 0.043).abs() < 1e-12, "gap {gap}: the two radii of 21.5 mm");
    assert!(with > 0.8 * gap, "with contact: {with} m");
    assert!(without < 0.002, "without contact: {without} m");
}
