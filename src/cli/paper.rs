//! `ohl paper CASE|all`: reproduce a case of the paper (placeholder until the paper-case issue lands).

use std::process::ExitCode;

/// Arguments of `ohl paper`.
#[derive(clap::Args)]
pub struct PaperArgs {
    /// case name (a file `paper_cases/<case>.toml`) or `all`
    case: String,
}

/// Not implemented yet.
pub fn main(args: PaperArgs) -> ExitCode {
    eprintln!("error: `ohl paper {}` is not implemented yet", args.case);
    ExitCode::from(1)
}
