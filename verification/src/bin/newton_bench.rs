//! Wall time of the library's static solve (`ohl::statics::solve`: Newton, exact Jacobian, faer sparse
//! LU) on the paper's catenary (weight only, 160 m, 1 kg/m, EA = 7.92e5 N) from a parabolic start through
//! the exact mid-span sag, at N = 100, 1000, 5000, to the solver's default tolerance; the fastest of
//! several repetitions, single thread. Writes `figures/bench/newton.csv`.
//!
//! `cargo run --release -p verification --bin newton_bench [-- OUT_DIR]`

use std::io::Write;
use std::time::Instant;

use ohl::element::tension::LawKind;
use ohl::statics::{StaticOptions, solve};
use verification::setup::{Case, G_M_PER_S2, SPAN_M, loads, parabolic_wire, params};

fn main() {
    // One thread, as every figure of figures/bench (faer would otherwise use its thread pool).
    faer::set_global_parallelism(faer::Par::Seq);
    let out = std::env::args().nth(1).unwrap_or_else(|| "figures/bench".into());
    let sag = Case::Catenary.exact().position(0.5 * SPAN_M)[2];
    let mut rows = Vec::new();
    println!("static Newton, catenary from a parabola of sag {:.3} m, fastest of the repetitions", -sag);
    println!("{:>6} {:>10} {:>12} {:>14} {:>14}", "N", "iterations", "residual [N]", "wall [s]", "per iteration [s]");
    for (n, reps) in [(100, 20), (1000, 10), (5000, 4)] {
        let mut best = f64::INFINITY;
        let mut report = None;
        for _ in 0..reps {
            let mut s = ohl::scheme::Explicit::new(
                parabolic_wire(n, LawKind::Linear, 0.0, [0.0, 0.0, sag]),
                loads(G_M_PER_S2, [0.0; 3], None),
                params(n, 0.9, 0.0, 0.0),
            );
            let t0 = Instant::now();
            let r = match solve(&mut s, &StaticOptions::default()) {
                Ok(r) => r,
                Err(e) => {
                    eprintln!("error: N = {n}: {e}");
                    std::process::exit(1);
                }
            };
            best = best.min(t0.elapsed().as_secs_f64());
            report = Some(r);
        }
        let r = report.expect("at least one repetition");
        let (iters, res) = (r.iterations, r.residual_n);
        println!("{n:>6} {iters:>10} {res:>12.3e} {best:>14.4e} {:>14.4e}", best / iters.max(1) as f64);
        let hist: Vec<String> = r.residual_history.iter().map(|v| format!("{v:.1e}")).collect();
        println!(
            "       residual history [N]: {}; step factors {:?}; tolerance {:.1e} N; residual evaluations {}",
            hist.join(" "),
            r.step_factors,
            r.tolerance_n,
            r.residual_evaluations
        );
        rows.push((n, iters, res, best));
    }
    let path = std::path::Path::new(&out).join("newton.csv");
    let write = || -> std::io::Result<()> {
        std::fs::create_dir_all(&out)?;
        let mut f = std::fs::File::create(&path)?;
        writeln!(f, "n,iterations,final_residual_n,wall_s,cpu")?;
        let cpu = ohl_app::bench::machine().cpu;
        for (n, it, res, wall) in &rows {
            writeln!(f, "{n},{it},{res:.3e},{wall:.4e},\"{cpu}\"")?;
        }
        Ok(())
    };
    match write() {
        Ok(()) => println!("wrote {}", path.display()),
        Err(e) => {
            eprintln!("error: cannot write {}: {e}", path.display());
            std::process::exit(1);
        }
    }
}
