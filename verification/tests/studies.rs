//! CI: every study at the coarse budget (small grids, short runs), asserting its verdict: observed orders
//! within 0.1 of design where design is 2, explicit-versus-Newton agreement to 1e-8, the energy residual
//! below 1e-6 of the peak kinetic energy, the stability limits within 5 %. Output goes to a temporary
//! directory.

use verification::report::Budget;
use verification::studies::{STUDIES, run_study};

#[test]
fn every_study_passes_at_the_coarse_budget() {
    let dir = std::env::temp_dir().join(format!("ohl-verify-{}", std::process::id()));
    let mut failed = vec![];
    for s in STUDIES {
        let r = run_study(s, Budget::Coarse, &dir);
        println!("{} ({:.1} s): {}", s.name, r.wall_s, if r.passed() { "PASS" } else { "FAIL" });
        print!("{}", r.check_lines());
        if !r.passed() {
            failed.push(s.name);
        }
        assert!(dir.join(&r.figures[0]).exists(), "{}: figure not written", s.name);
    }
    let _ = std::fs::remove_dir_all(&dir);
    assert!(failed.is_empty(), "failed studies: {failed:?}");
}
