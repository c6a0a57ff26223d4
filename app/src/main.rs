//! `ohl`: the command line of the wire solver.
//!
//! - `ohl run SCENARIO.toml --out DIR` runs a scenario and writes `DIR/timeseries.csv`,
//!   `DIR/snapshots.csv` and `DIR/summary.json`;
//! - `ohl paper CASE|all` reproduces a case of the paper into `figures/`;
//! - `ohl cases CASE|all` runs a line-section case of `cases/` into `figures/cases/`;
//! - `ohl bench` measures the explicit kernel's throughput;
//! - `ohl thermal CASE.toml` evaluates a conductor's heat balance (steady temperature, ampacity, transient,
//!   de-icing);
//! - `ohl rating SCENARIO.toml` rates a span or section by clearance or sag (steady, and after a step);
//! - `ohl shortcircuit CASE.toml` prints the IEC 60865-1 simplified method's short-circuit forces beside
//!   those of the dynamic run of the same line (docs/short_circuit.md).
//! - `ohl sagtension CASE.toml` prints a span's or ruling span's sag-tension table (initial, after creep,
//!   after load, final) and writes it with a figure of sag against temperature;
//! - `ohl load-case NAME` prints a code's combined ice-and-wind load case (NESC 250B districts, IEC 60826,
//!   EN 50341-1) as scenario TOML for a catalogue conductor (`ohl load-case list` names them);
//! - `ohl plot RUN_DIR` draws a run's time series, support forces and shapes to PNG and SVG;
//! - `ohl sweep BASE.toml --vary FIELD=VALUES` runs a parameter sweep in parallel into one table
//!   (`ohl sweep merge` joins the tables of its shards).
//!
//! Exit codes: 0 success; 1 the run went unstable (or an output file could not be written), and what
//! was written so far stays readable; 2 the scenario is invalid (the message names the file, the field,
//! the value and what is allowed) or the command line is wrong.

mod cli;

/// The kernel's arrays spread over the page (`ohl::staggered_alloc`: otherwise, at some lengths, they
/// alias in the low address bits; results are bitwise the same).
#[global_allocator]
static ALLOC: ohl::staggered_alloc::StaggeredAlloc = ohl::staggered_alloc::StaggeredAlloc;

use std::process::ExitCode;

use clap::{Parser, Subcommand};

#[derive(Parser)]
#[command(name = "ohl", version, about = "Dynamics of overhead power-line wires (explicit staggered-grid scheme)")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Run a scenario file and write timeseries.csv, snapshots.csv and summary.json.
    Run(cli::run::RunArgs),
    /// Reproduce a case of the paper (or `all`) into figures/, with a paper-versus-computed table.
    Paper(cli::paper::PaperArgs),
    /// Run a line-section case of cases/ (or `all`) into figures/cases/, with load figures and tables.
    Cases(cli::cases::CasesArgs),
    /// Measure the throughput of the explicit kernel (node-steps per second).
    Bench(cli::bench::BenchArgs),
    /// Heat balance of a conductor (IEEE 738 / CIGRE TB 601): steady temperature, ampacity, transient,
    /// de-icing; writes thermal.json, transient.csv, deicing.csv.
    Thermal(cli::thermal::ThermalArgs),
    /// Thermal rating of a span or section by ground clearance or sag, steady and after a current step;
    /// writes rating.json.
    Rating(cli::rating::RatingArgs),
    /// Sag-tension table of a span or ruling span (initial, after creep, after load, final; knee point,
    /// temperature at a sag limit); writes sagtension.csv, sagtension.json, sag_vs_temperature.png/.svg.
    Sagtension(cli::sagtension::SagTensionArgs),
    /// Short-circuit forces on a line span with [short_circuit]: the IEC 60865-1 simplified method beside
    /// the dynamic run; writes the run's files, short_circuit.csv and shortcircuit.json.
    Shortcircuit(cli::shortcircuit::ShortCircuitArgs),
    /// Print a code's combined ice-and-wind load case as scenario TOML (`list`: the cases).
    LoadCase(cli::load_case::LoadCaseArgs),
    /// Draw a run's time series, support forces and shapes (RUN_DIR/plots/*.png and *.svg).
    Plot(cli::plot::PlotArgs),
    /// Run a parameter sweep of a base scenario in parallel into one table (sweep.csv); `sweep merge` joins shards.
    Sweep(cli::sweep::SweepArgs),
}

fn main() -> ExitCode {
    match Cli::parse().command {
        Command::Run(a) => cli::run::main(a),
        Command::Paper(a) => cli::paper::main(a),
        Command::Cases(a) => cli::cases::main(a),
        Command::Bench(a) => cli::bench::main(a),
        Command::Thermal(a) => cli::thermal::main(a),
        Command::Rating(a) => cli::rating::main(a),
        Command::Sagtension(a) => cli::sagtension::main(a),
        Command::Shortcircuit(a) => cli::shortcircuit::main(a),
        Command::LoadCase(a) => cli::load_case::main(a),
        Command::Plot(a) => cli::plot::main(a),
        Command::Sweep(a) => cli::sweep::main(a),
    }
}
