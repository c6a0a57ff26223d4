//! `ohl cases CASE|all`: run the line-section cases of `cases/` into `figures/cases/<case>/` with their
//! load figures, shapes and peak-to-residual tables ([`ohl_app::cases`]).
//!
//! Exit codes: 0 when every case ran; 1 when a run failed or a file could not be written; 2 for an
//! invalid case file or an unknown case.

use std::path::PathBuf;
use std::process::ExitCode;

use ohl_app::cases::{self, CaseError};

/// Arguments of `ohl cases`.
#[derive(clap::Args)]
pub struct CasesArgs {
    /// case name (a file `<cases>/<case>.toml`), a case file (`PATH.toml`), or `all`
    case: String,
    /// directory of the case files
    #[arg(long, default_value = "cases")]
    cases: PathBuf,
    /// directory for the results (one folder per case)
    #[arg(long, default_value = "figures/cases")]
    out: PathBuf,
    /// also run each section case on 2 and 4 times its segments per span and give every peak load and
    /// jump its Richardson extrapolate and GCI in the table (about 20 times a run; line cases: use
    /// `ohl run CASE --converge`)
    #[arg(long)]
    converge: bool,
}

/// Run the command.
pub fn main(args: CasesArgs) -> ExitCode {
    let args = CasesArgs {
        cases: ohl_app::rooted_default(args.cases, "cases"),
        out: ohl_app::rooted_default(args.out, "figures/cases"),
        ..args
    };
    let paths = if args.case == "all" {
        match ohl_app::paper::case_files(&args.cases) {
            Ok(v) if !v.is_empty() => v,
            _ => {
                err!("error: no case files (*.toml) in {}", args.cases.display());
                return ExitCode::from(2);
            }
        }
    } else {
        // A case is named (`b_ice_shedding`, looked up in the cases folder) or given as a file.
        let given = PathBuf::from(&args.case);
        let name = args.case.strip_suffix(".toml").unwrap_or(&args.case);
        let p = if given.extension().is_some_and(|e| e == "toml") && given.is_file() {
            given
        } else {
            args.cases.join(format!("{name}.toml"))
        };
        if !p.exists() {
            err!("error: no case `{}` ({} does not exist)", args.case, p.display());
            return ExitCode::from(2);
        }
        vec![p]
    };
    let mut code = 0u8;
    for p in &paths {
        if ohl_app::line_cases::is_line_case(p) {
            if args.converge {
                err!(
                    "note: {}: --converge is for section cases; for a line case run `ohl run {} --converge`",
                    p.display(),
                    p.display()
                );
            }
            match ohl_app::line_cases::run_line_case(p, &args.out) {
                Ok(c) => out!("{}", ohl_app::line_cases::format_line_table(&c)),
                Err(e) => {
                    err!("error: {e}");
                    code = code.max(if matches!(e, CaseError::Input(_)) { 2 } else { 1 });
                }
            }
            continue;
        }
        match cases::run_case(p, &args.out, args.converge) {
            Ok(c) => out!("{}", cases::format_table(&c)),
            Err(e) => {
                err!("error: {e}");
                code = code.max(if matches!(e, CaseError::Input(_)) { 2 } else { 1 });
            }
        }
    }
    ExitCode::from(code)
}
