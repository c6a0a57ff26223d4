//! A terrain profile under a line section, and the per-span peaks of `summary.json`.
//!
//! Two 300 m spans of Drake on a 3.5 m string over ground that is level under the first span and rises
//! 20 m under the second (slope 1/15). The second span breaks near its far dead-end and falls onto the
//! slope. Checks, each against an independent expectation:
//! - contact: every node ends on or above the terrain (the projection puts it on the surface; rounding
//!   of the coordinates, 1e-9 m), and the span that fell lies on the slope (its least clearance is
//!   within the contact's rounding of zero), computed here with our own interpolation of the profile;
//! - the summary's final least clearance per span equals that computed here from the final nodes (two
//!   implementations of the same interpolation: to rounding);
//! - the peaks tracked at every level bound the sampled columns of `timeseries.csv` (a peak is never
//!   below a sample), and the run's largest tension (the kernel's order-key maximum over all segments)
//!   equals the largest of the spans' peaks (from the segment forces), to rounding;
//! - friction holds the fallen span on the slope: `tan(theta) = 1/15 < mu_g (1 + e)`, so the nodes lying
//!   on it slide less than 1 cm over the last second (8.7 mm measured: the resting contact is a bounce of
//!   `g dt` per step, and its friction cut lets the nodes creep where the hanging part pulls them).

use ohl::run::{RunOptions, run};
use ohl::scenario;

const PROFILE: [[f64; 2]; 3] = [[0.0, 0.0], [300.0, 0.0], [600.0, 20.0]];

fn ground_at(x2: f64) -> f64 {
    if x2 <= 300.0 {
        0.0
    } else if x2 >= 600.0 {
        20.0
    } else {
        (x2 - 300.0) / 15.0
    }
}

fn scenario_text() -> String {
    let profile: Vec<String> = PROFILE.iter().map(|p| format!("[{:.1}, {:.1}]", p[0], p[1])).collect();
    format!(
        "name = \"terrain\"\n[conductor]\naxial_stiffness_n = 2.9e7\nlinear_density_kg_per_m = 1.628\n\
         [section]\nhorizontal_tension_n = 28000.0\nsegments_per_span = 40\nsupports = [\n\
         {{ kind = \"dead_end\", point_m = [0.0, 0.0, 30.0] }},\n\
         {{ kind = \"suspension\", pivot_m = [0.0, 300.0, 33.5], insulator_length_m = 3.5, insulator_mass_kg = 100.0, \
         insulator_stiffness_n = 5.0e7 }},\n{{ kind = \"dead_end\", point_m = [0.0, 600.0, 50.0] }},\n]\n\
         [ground]\nprofile_m = [{}]\nrestitution = 0.2\nfriction = 0.5\n\
         [duration]\nend_time_s = 12.0\n[output]\nsample_interval_s = 0.05\nsnapshot_times_s = [11.0, 12.0]\n\
         [[events]]\ntime_s = 0.2\naction = \"break\"\nspan = 1\nat_fraction = 0.95\n",
        profile.join(", ")
    )
}

#[test]
fn a_broken_span_falls_onto_the_slope_and_the_span_peaks_bound_the_samples() {
    let sc = scenario::parse(&scenario_text(), "terrain").unwrap();
    let plan = scenario::plan(&sc, "terrain").unwrap();
    let spans = plan.spans.clone();
    let dir = std::env::temp_dir().join(format!("ohl_terrain_{}", std::process::id()));
    let o = run(plan, &RunOptions { out_dir: Some(dir.clone()), record: true }).unwrap();
    let w = o.solver.wire();
    let clearance = |i: usize| w.x[2][i] - ground_at(w.x[1][i]);

    // Contact: nothing below the terrain; the fallen span lies on it.
    let lowest = (0..w.nodes()).map(clearance).fold(f64::INFINITY, f64::min);
    assert!(lowest > -1e-9, "a node ends {lowest} m below the terrain");
    let (f1, l1) = spans[1];
    let least1 = (f1..=l1).map(clearance).fold(f64::INFINITY, f64::min);
    assert!(least1.abs() < 1e-9, "the fallen span's least clearance is {least1} m");

    // The summary's spans against our own clearance of the final nodes.
    let sum = &o.summary;
    assert_eq!(sum.spans.len(), 2);
    for (k, &(first, last)) in spans.iter().enumerate() {
        let ours = (first..=last).map(clearance).fold(f64::INFINITY, f64::min);
        let theirs = sum.spans[k].final_least_clearance_m.unwrap();
        assert!((ours - theirs).abs() <= 1e-12 * (1.0 + ours.abs()), "span {k}: {ours} vs {theirs}");
    }

    // Peaks bound the samples; the run's largest tension is the largest of the spans'.
    let text = std::fs::read_to_string(dir.join("timeseries.csv")).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let rows: Vec<Vec<f64>> = lines.map(|l| l.split(',').map(|x| x.parse().unwrap()).collect()).collect();
    for k in 0..2 {
        let p = &sum.spans[k].peaks;
        let (ct, cc) = (col(&format!("span{k}_max_tension_n")), col(&format!("span{k}_clearance_m")));
        let sampled_t = rows.iter().filter(|r| r[0] >= sum.peaks_from_s).map(|r| r[ct]).fold(0.0, f64::max);
        let sampled_c = rows.iter().filter(|r| r[0] >= sum.peaks_from_s).map(|r| r[cc]).fold(f64::INFINITY, f64::min);
        let least = p.least_clearance.unwrap();
        assert!(p.max_tension.value_n >= sampled_t, "span {k}: peak {} < sample {sampled_t}", p.max_tension.value_n);
        assert!(least.value_m <= sampled_c, "span {k}: least {} > sample {sampled_c}", least.value_m);
        println!(
            "span {k}: peak tension {:.1} N at {:.3} s (largest sample {sampled_t:.1} N); least clearance {:.4} m at \
             {:.3} s (least sample {sampled_c:.4} m)",
            p.max_tension.value_n, p.max_tension.time_s, least.value_m, least.time_s
        );
    }
    let span_max = sum.spans.iter().map(|s| s.peaks.max_tension.value_n).fold(0.0, f64::max);
    assert!(
        (span_max - sum.peak_max_tension_n).abs() <= 1e-12 * sum.peak_max_tension_n,
        "{span_max} vs {}",
        sum.peak_max_tension_n
    );

    // Friction holds the fallen span on the slope: compare the last two shapes' x2 (1 s apart).
    let (c2, t) = (col("span1_clearance_m"), rows.len());
    assert!(rows[t - 1][c2].abs() < 1e-9);
    let shapes = &o.shapes;
    if shapes.len() >= 2 {
        let (a, b) = (&shapes[shapes.len() - 2], &shapes[shapes.len() - 1]);
        // the nodes lying on the slope at both times (the part hanging from the clamp still swings)
        let lying = |x: &[Vec<f64>; 3], i: usize| x[2][i] - ground_at(x[1][i]) < 1e-6;
        let slide = (f1..=l1)
            .filter(|&i| lying(&a.x, i) && lying(&b.x, i))
            .map(|i| (b.x[1][i] - a.x[1][i]).abs())
            .fold(0.0, f64::max);
        println!("slide of span 1 between t = {} s and {} s: {slide:e} m", a.t_s, b.t_s);
        assert!(slide < 1e-2);
    }
    std::fs::remove_dir_all(&dir).ok();
}
