//! `verify`: the verification harness of the `ohl` wire solver.
//!
//! ```text
//! verify list                      list the studies
//! verify <study> [--coarse]        run one study
//! verify all [--coarse]            run every study (in parallel) and write REPORT.md
//!        [--out DIR]               output directory (default <workspace>/figures/verification)
//! ```
//!
//! Each study writes its CSV tables and PNG + SVG plots under the output directory; the exit status is
//! non-zero if any check fails.

use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use std::path::PathBuf;
use std::process::ExitCode;
use verification::report::{Budget, full_report};
use verification::studies::{STUDIES, Study, find, run_study};

/// The kernel's arrays spread over the page (`ohl::staggered_alloc`; results are bitwise the same).
#[global_allocator]
static ALLOC: ohl::staggered_alloc::StaggeredAlloc = ohl::staggered_alloc::StaggeredAlloc;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut budget = Budget::Full;
    let mut out = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../figures/verification"));
    let mut what = None;
    let mut it = args.iter();
    while let Some(a) = it.next() {
        match a.as_str() {
            "-h" | "--help" | "help" => {
                println!(
                    "verify: the verification harness of the ohl wire solver\n\n\
                     usage:\n  verify list                 list the studies\n  \
                     verify STUDY [--coarse]     run one study (--coarse: the CI budget)\n  \
                     verify all [--coarse]       run every study and write REPORT.md\n  \
                     options: --out DIR          output directory (default <workspace>/figures/verification)\n\n\
                     exit status: 0 every check passed, 1 a check failed, 2 bad arguments"
                );
                return ExitCode::SUCCESS;
            }
            "--coarse" => budget = Budget::Coarse,
            "--out" => match it.next() {
                Some(d) => out = PathBuf::from(d),
                None => {
                    eprintln!("verify: --out needs a directory");
                    return ExitCode::from(2);
                }
            },
            other if what.is_none() => what = Some(other.to_string()),
            other => {
                eprintln!("verify: unexpected argument '{other}'");
                return ExitCode::from(2);
            }
        }
    }
    let what = what.unwrap_or_else(|| "list".into());
    let selected: Vec<&Study> = match what.as_str() {
        "list" => {
            for s in STUDIES {
                println!("{:<12} {}", s.name, s.about);
            }
            println!("{:<12} every study above, and figures/verification/REPORT.md", "all");
            return ExitCode::SUCCESS;
        }
        "all" => STUDIES.iter().collect(),
        name => match find(name) {
            Some(s) => vec![s],
            None => {
                eprintln!("verify: unknown study '{name}' (try `verify list`)");
                return ExitCode::from(2);
            }
        },
    };
    let stamp = verification::report::stamp();
    let t0 = std::time::Instant::now();
    let bar = ProgressBar::new(selected.len() as u64);
    bar.set_style(
        ProgressStyle::with_template("{spinner} [{elapsed_precise}] {bar:30} {pos}/{len} studies {msg}")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    bar.enable_steady_tick(std::time::Duration::from_millis(200));
    let reports: Vec<_> = selected
        .par_iter()
        .map(|s| {
            let r = run_study(s, budget, &out);
            bar.inc(1);
            bar.println(format!(
                "{:<12} {} ({} checks, {:.1} s)",
                s.name,
                if r.passed() { "PASS" } else { "FAIL" },
                r.checks.len(),
                r.wall_s
            ));
            r
        })
        .collect();
    bar.finish_and_clear();
    let wall = t0.elapsed().as_secs_f64();
    for r in &reports {
        println!("\n== {} ({}) : {}", r.name, r.title, if r.passed() { "PASS" } else { "FAIL" });
        print!("{}", r.check_lines());
    }
    if what == "all" {
        let path = out.join("REPORT.md");
        if let Err(e) = std::fs::create_dir_all(&out)
            .and_then(|_| std::fs::write(&path, full_report(&reports, budget, wall, &stamp)))
        {
            eprintln!("verify: cannot write {}: {e}", path.display());
            return ExitCode::FAILURE;
        }
        println!("\nwrote {} ({wall:.1} s)", path.display());
    }
    if reports.iter().all(|r| r.passed()) { ExitCode::SUCCESS } else { ExitCode::FAILURE }
}
