//! `ohl bench`: kernel throughput (placeholder until the benchmark issue lands).

use std::process::ExitCode;

/// Arguments of `ohl bench`.
#[derive(clap::Args)]
pub struct BenchArgs {}

/// Not implemented yet.
pub fn main(_args: BenchArgs) -> ExitCode {
    eprintln!("error: `ohl bench` is not implemented yet");
    ExitCode::from(1)
}
