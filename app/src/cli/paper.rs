//! `ohl paper CASE|all`: reproduce a case of the paper (`paper_cases/<case>.toml`) or all of them, write
//! `figures/<case>.png`, `.svg` and the `.csv` each is drawn from, and print the table
//! quantity | paper | exact | computed | relative differences | verdict.
//!
//! Exit codes: 0 when every case ran (the table says which of the paper's values are not reproduced,
//! and why); 1 when a case failed to run or its output could not be written; 2 for an invalid case file
//! or an unknown case. When every case is refused or fails, only the errors are printed (on stderr).

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

use ohl_app::paper::spec::CompareSpec;
use ohl_app::paper::{self, PaperError, table};

/// Arguments of `ohl paper`.
#[derive(clap::Args)]
pub struct PaperArgs {
    /// case name (a file `<cases>/<case>.toml`) or `all`
    case: String,
    /// directory of the case files
    #[arg(long, default_value = "paper_cases")]
    cases: PathBuf,
    /// directory for the figures and their CSV files
    #[arg(long, default_value = "figures")]
    out: PathBuf,
    /// number of cases run at the same time (`all`)
    #[arg(long, default_value_t = 2, allow_negative_numbers = true)]
    threads: usize,
}

/// Run the command.
pub fn main(args: PaperArgs) -> ExitCode {
    let started = Instant::now();
    let args = PaperArgs {
        cases: ohl_app::rooted_default(args.cases, "paper_cases"),
        out: ohl_app::rooted_default(args.out, "figures"),
        ..args
    };
    let paths = if args.case == "all" {
        match paper::case_files(&args.cases) {
            Ok(v) if !v.is_empty() => v,
            Ok(_) => {
                err!("error: no case files (*.toml) in {}", args.cases.display());
                return ExitCode::from(2);
            }
            Err(e) => {
                err!("error: cannot read {}: {e}", args.cases.display());
                return ExitCode::from(2);
            }
        }
    } else {
        let p = args.cases.join(format!("{}.toml", args.case));
        if !p.exists() {
            let known = paper::case_files(&args.cases).unwrap_or_default();
            let names: Vec<String> =
                known.iter().filter_map(|p| p.file_stem().and_then(|s| s.to_str()).map(String::from)).collect();
            err!("error: no case `{}` ({} does not exist); cases: {}, all", args.case, p.display(), names.join(", "));
            return ExitCode::from(2);
        }
        vec![p]
    };
    // Taken before the cases rewrite their figures (which would read as a dirty tree).
    let stamp = ohl_app::stamp::stamp();
    let results = paper::run_cases(&paths, Some(&args.out), args.threads);
    let mut rows = Vec::new();
    let mut code = 0u8;
    for r in results {
        match r {
            Ok(c) => {
                out!("== {} (paper section {}): {}", c.name, c.section, c.title);
                out!("   run {} in {:.2} s", c.status, c.wall_s);
                if let Some(e) = &c.estimate {
                    out!("   estimated before the run: {e}");
                }
                for (t, e) in &c.events {
                    out!("   event at t = {t:.3} s: {e}");
                }
                for n in &c.notes {
                    out!("   note: {n}");
                }
                if let Some(f) = &c.figure {
                    out!("   figure: {}.png, .svg; data: {}.csv", f.display(), f.display());
                }
                rows.extend(c.rows);
            }
            Err(e) => {
                err!("error: {e}");
                code = code.max(if matches!(e, PaperError::Input(_) | PaperError::NotACase(_)) { 2 } else { 1 });
            }
        }
    }
    // Every case refused or failed: the errors above are the whole answer (no empty table, no summary).
    if rows.is_empty() && code != 0 {
        return ExitCode::from(code);
    }
    out!();
    let table = table::format(&rows);
    out_text!("{table}");
    let missed = rows.iter().filter(|r| r.compare == CompareSpec::Match && !r.within_tolerance()).count();
    let summary = format!(
        "{} values checked, {} equilibria/exact values not reproduced; wall time {:.2} s",
        rows.len(),
        missed,
        started.elapsed().as_secs_f64()
    );
    out!("\n{summary}");
    // `all` also keeps the table, stamped, beside the figures.
    if args.case == "all" {
        let path = args.out.join("paper_table.md");
        let text = format!(
            "# The paper's values against this code\n\nWritten by `ohl paper all`. {stamp}\n\n{table}\n{summary}\n"
        );
        match std::fs::write(&path, text) {
            Ok(()) => out!("table written to {}", path.display()),
            Err(e) => {
                err!("error: cannot write {}: {e}", path.display());
                code = code.max(1);
            }
        }
    }
    ExitCode::from(code)
}
