//! Subcommands of the `ohl` binary, one file each; the work itself lives in the library.

pub mod bench;
pub mod cases;
pub mod paper;
pub mod plot;
pub mod rating;
pub mod run;
pub mod sweep;
pub mod thermal;
