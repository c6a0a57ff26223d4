//! `verify`: the verification harness of the `ohl` wire solver.
//!
//! Each study is one module registered in [`STUDIES`]; `verify list` names them and `verify <study>`
//! runs one. The studies themselves (convergence, implicit reference, sensitivity) are filled in by the
//! harness issue; this skeleton fixes the command-line shape.

use std::process::ExitCode;

/// A study: its command-line name and a one-line description.
struct Study {
    name: &'static str,
    about: &'static str,
}

/// The registry of studies. Adding a study is one module plus one line here.
const STUDIES: &[Study] = &[];

fn main() -> ExitCode {
    let arg = std::env::args().nth(1).unwrap_or_else(|| "list".to_string());
    match arg.as_str() {
        "list" => {
            if STUDIES.is_empty() {
                println!("no studies registered yet");
            }
            for s in STUDIES {
                println!("{:<24} {}", s.name, s.about);
            }
            ExitCode::SUCCESS
        }
        other => {
            eprintln!("verify: unknown study '{other}' (try `verify list`)");
            ExitCode::from(2)
        }
    }
}
