//! Every case of `paper_cases/` runs (N = 50, as the paper; each takes well under a second in release)
//! and its equilibrium values are checked: against the paper's value within the case's tolerance
//! (1 %) where the paper's value is reproducible, and against the independent exact reference
//! (`ohl::exact`) within 0.2 % wherever the case has one at an equilibrium. The 0.2 % bound: the N = 50
//! chain differs from the continuous catenary/arc by 1.3e-4 (tests/catenary_sag.rs, tests/wind_arc.rs),
//! the wind-and-weight reference treats the normal pressure as a fixed load (0.56 % on x1, so x1 of
//! fig3 is held to the paper's tolerance only), and the settling residual is below 1e-4.

use std::path::Path;

use ohl::paper::{self, Row};
use ohl::scenario::paper::CompareSpec;

fn rows() -> Vec<Row> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("paper_cases");
    let files = paper::case_files(&dir).expect("paper_cases/");
    assert!(files.len() >= 6, "expected the paper's cases, found {files:?}");
    paper::run_cases(&files, None, 2)
        .into_iter()
        .flat_map(|r| r.unwrap_or_else(|e| panic!("case failed: {e}")).rows)
        .collect()
}

fn find<'a>(rows: &'a [Row], case: &str, quantity: &str) -> &'a Row {
    rows.iter()
        .find(|r| r.case == case && r.quantity.starts_with(quantity))
        .unwrap_or_else(|| panic!("no row {case} / {quantity}"))
}

#[test]
fn equilibria_match_the_paper_and_the_exact_references() {
    let rows = rows();
    // Equilibria the paper prints and we reproduce within 1 %.
    for (case, q) in [
        ("fig2a_wind_arc", "equilibrium mid-span x1"),
        ("fig2b_catenary", "equilibrium mid-span x3"),
        ("fig3_wind_weight", "equilibrium mid-span x3"),
        ("fig3_wind_weight", "equilibrium mid-span x1"),
        ("fig4_break_fall", "mid-span x3 at the break"),
        ("fig6_deicing", "iced equilibrium mid-span x3"),
        ("fig6_deicing", "iced equilibrium tension"),
    ] {
        let r = find(&rows, case, q);
        let d = r.relative_to_paper().expect("paper value");
        println!("{case}: {q}: paper {:?}, computed {:.6}, {:+.3} %", r.paper, r.computed, 100.0 * d);
        assert!(d.abs() <= 0.01, "{case}: {q}: {:+.3} % from the paper", 100.0 * d);
    }
    // Every equilibrium with an exact reference (match rows, and the wind-free catenary/arc ones).
    for r in rows.iter().filter(|r| r.compare == CompareSpec::Match && r.exact.is_some()) {
        let d = r.relative_to_exact().unwrap();
        let bound = if r.quantity.contains("x1") && r.case.starts_with("fig3") { 0.01 } else { 2e-3 };
        println!("{}: {}: exact {:?}, computed {:.6}, {:+.3} %", r.case, r.quantity, r.exact, r.computed, 100.0 * d);
        assert!(d.abs() <= bound, "{}: {}: {:+.3} % from the exact reference", r.case, r.quantity, 100.0 * d);
    }
    // The paper's own-weight de-icing equilibrium (2.30 m, 6.2 kN) is not the exact catenary's (2.353 m,
    // 6.12 kN): the table must say so rather than pass it.
    let r = find(&rows, "fig6_deicing", "own-weight equilibrium mid-span x3");
    assert_eq!(r.verdict(), "NOT REPRODUCED");
    assert!((r.computed - -2.353).abs() < 0.005, "{}", r.computed);
}
