//! Parameter sweeps (`ohl sweep`): one base scenario, many cases, each the base with some fields set to
//! other values, run in parallel into one table. `docs/sweeps.md` is the user's reference.
//!
//! - [`path`]: field paths into the scenario document (`events[2].time_s`);
//! - [`values`]: value lists and inclusive ranges of `--vary FIELD=VALUES`;
//! - [`spec`]: the axes (the `--vary` arguments and a cases file) and their Cartesian product;
//! - [`overrides`]: setting a field to a case's value, keeping its TOML type;
//! - [`case`]: one case, from its values to its row (parse, validate, plan, budget, run);
//! - [`execute`]: the cases of a sweep or shard on a pool of threads, and the files they write;
//! - [`table`]: the columns of `sweep.csv`;
//! - [`shard`]: `--shard K/N`;
//! - [`manifest`]: `sweep.json`, the identity of a sweep;
//! - [`merge`](mod@merge): `ohl sweep merge`, the shards' tables into one.

pub mod case;
pub mod execute;
pub mod manifest;
pub mod merge;
pub mod overrides;
pub mod path;
pub mod shard;
pub mod spec;
pub mod table;
pub mod values;

use std::path::{Path, PathBuf};

use ohl::scenario::{self, InputError};
use toml::Table;

pub use execute::{Options, Report, run_sweep};
pub use merge::{MergeError, merge};
pub use shard::Shard;
pub use spec::Spec;

/// Why a sweep cannot start (exit code 2), or its files cannot be written (exit code 1).
#[derive(Debug, thiserror::Error)]
pub enum SweepError {
    /// The specification (`--vary`, `--cases`) is malformed.
    #[error(transparent)]
    Spec(#[from] spec::SpecError),
    /// The base file cannot be read or is not TOML.
    #[error(transparent)]
    Base(#[from] InputError),
    /// A varied field has no place in the base document, or the scenario format has no such field.
    #[error("{file}: {source}")]
    Field {
        /// the base file
        file: String,
        /// which field and why
        source: overrides::PathError,
    },
    /// The thread pool could not be started.
    #[error("cannot start {threads} worker threads: {message}")]
    Threads {
        /// threads asked for
        threads: usize,
        /// the error
        message: String,
    },
    /// An output file or directory could not be written.
    #[error("{}: {source}", path.display())]
    Write {
        /// the file or directory
        path: PathBuf,
        /// the error
        source: std::io::Error,
    },
}

impl SweepError {
    /// The exit code: 1 for a file that could not be written, 2 for bad arguments or inputs.
    pub fn exit_code(&self) -> u8 {
        match self {
            SweepError::Write { .. } | SweepError::Threads { .. } => 1,
            _ => 2,
        }
    }
}

/// A sweep: the base scenario (its text and its TOML document) and what varies.
#[derive(Clone, Debug)]
pub struct Sweep {
    /// the base scenario, as given
    pub base_path: PathBuf,
    /// its text
    pub base_text: String,
    /// its TOML document
    pub base: Table,
    /// the axes and cases
    pub spec: Spec,
    /// run cases above the work budget
    pub allow_large: bool,
}

impl Sweep {
    /// Read the base file and check every varied field against it: the tables and arrays on the way
    /// must be there ([`overrides::existing`]), and a field the base file does not set must be one the
    /// scenario format knows (checked by parsing the base with that field set to its first value).
    pub fn new(base_path: &Path, spec: Spec, allow_large: bool) -> Result<Sweep, SweepError> {
        let file = base_path.display().to_string();
        let base_text = scenario::read_text(base_path)?;
        let base: Table = base_text.parse().map_err(|e| scenario::parse_error_at(&base_text, &file, e))?;
        let sweep = Sweep { base_path: base_path.to_path_buf(), base_text, base, spec, allow_large };
        for axis in &sweep.spec.axes {
            for (j, field) in axis.fields.iter().enumerate() {
                let first = axis.rows.iter().find_map(|r| r[j].as_deref());
                sweep.check_field(field, first)?;
            }
        }
        Ok(sweep)
    }

    /// Check one varied field against the base document; `first` is its first value in the sweep.
    fn check_field(&self, field: &path::FieldPath, first: Option<&str>) -> Result<(), SweepError> {
        let file = self.base_path.display().to_string();
        let fail = |reason: String| SweepError::Field {
            file: file.clone(),
            source: overrides::PathError { field: field.to_string(), reason },
        };
        let present = overrides::existing(&self.base, field)
            .map_err(|source| SweepError::Field { file: file.clone(), source })?;
        let (None, Some(first), Some(path::Step::Key(key))) = (present, first, field.steps.last()) else {
            return Ok(());
        };
        let mut doc = self.base.clone();
        if overrides::apply(&mut doc, field, first).is_err() {
            return Ok(());
        }
        let Ok(text) = toml::to_string(&doc) else { return Ok(()) };
        if let Err(InputError::Parse { message, .. }) = scenario::parse(&text, &file)
            && message.contains(&format!("unknown field `{key}`"))
        {
            let line = message.lines().find(|l| l.contains("unknown field")).unwrap_or(&message);
            return Err(fail(format!(
                "the base file does not set it and the scenario format has no such field ({})",
                line.trim()
            )));
        }
        Ok(())
    }

    /// The identity of this sweep's tables ([`manifest`]): the base file's and the values' fingerprints.
    pub fn fingerprints(&self) -> (String, String) {
        (manifest::fnv1a64(self.base_text.as_bytes()), manifest::spec_fingerprint(&self.spec, self.allow_large))
    }
}
