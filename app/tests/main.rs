//! The `ohl` command's integration tests, one test binary (each file below is one module: one command or
//! concern; they run the built `ohl` binary). `fuzz_sweep` stays a binary of its own: it installs a
//! counting global allocator. Run one file's tests with `cargo test --release --test cli bad_input::`.

mod bad_input;
mod cases;
mod closed_pipe;
mod converge;
mod dry_run;
mod examples;
mod killed_run;
mod line_cases;
mod paper_cases;
mod plot_command;
mod sagtension;
mod stable_defaults;
mod sweep;
