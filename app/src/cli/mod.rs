//! Subcommands of the `ohl` binary, one file each; the work itself lives in the library.
//!
//! Every line a command prints goes through [`out!`] (stdout) or [`err!`] (stderr), which drop the line
//! when the stream is closed (`ohl run CASE.toml | head -1`) instead of the panic (exit 101) of
//! `println!`: a command's results are its files and its exit code, which a reader that stopped reading
//! must not change.

/// A line on stdout, dropped if stdout is closed (module doc).
macro_rules! out {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stdout(), $($arg)*);
    }};
}

/// Text on stdout without a line end, dropped if stdout is closed (module doc).
macro_rules! out_text {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = write!(std::io::stdout(), $($arg)*);
    }};
}

/// A line on stderr, dropped if stderr is closed (module doc).
macro_rules! err {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stderr(), $($arg)*);
    }};
}

pub mod bench;
pub mod cases;
pub mod converge;
pub mod load_case;
pub mod paper;
pub mod plot;
pub mod rating;
pub mod run;
pub mod sagtension;
pub mod shortcircuit;
pub mod sweep;
pub mod thermal;
