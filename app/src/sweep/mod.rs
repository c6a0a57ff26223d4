//! Parameter sweeps (`ohl sweep`): one base scenario, many cases, each the base with some fields set to
//! other values, run in parallel into one table. `docs/sweeps.md` is the user's reference.
//!
//! A base scenario is a single-conductor scenario or a line (`[line]`: several conductors, `docs/line.md`);
//! a line's fields are named by their paths too, a conductor by its index or its name
//! (`line.conductors[name=A].section.tension_fraction_of_rts`), and its table has per-conductor columns.
//!
//! - [`path`]: field paths into the scenario document (`events[2].time_s`, `line.conductors[name=A]`);
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

/// What the base scenario is.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Kind {
    /// a single-conductor scenario
    Single,
    /// a line ([`ohl::scenario::line`]) of these conductors (a bundle's sub-conductors each, `A.1`, `A.2`,
    /// ...), as the base file declares them: the table's per-conductor columns
    Line {
        /// the line's conductors, in order
        conductors: Vec<String>,
    },
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
    /// the varied fields as places of the base document (names resolved to indices,
    /// [`overrides::resolve`]), in the order of [`Spec::fields`]
    pub places: Vec<path::FieldPath>,
    /// a single conductor or a line
    pub kind: Kind,
    /// run cases above the work budget
    pub allow_large: bool,
    /// `--converge`: run every case as a convergence study ([`crate::converge`]) and add the error bars
    /// of its design values to its row ([`table::CONVERGE_COLUMNS`])
    pub converge: Option<crate::converge::Options>,
}

impl Sweep {
    /// Read the base file and check every varied field against it: the tables and arrays on the way
    /// must be there and a name must name one table ([`overrides::existing`]), a field the base file does
    /// not set must be one the scenario format knows (checked by parsing the base with that field set to
    /// its first value), and no place may be varied twice (by its index and by its name). In a line, the
    /// fields that name the table's columns (a conductor's `name`, a bundle's `sub_conductors`) are not
    /// varied.
    pub fn new(base_path: &Path, spec: Spec, allow_large: bool) -> Result<Sweep, SweepError> {
        let file = base_path.display().to_string();
        let base_text = scenario::read_text(base_path)?;
        let base: Table = scenario::from_toml(&base_text, &file)?;
        let field_error = |source: overrides::PathError| SweepError::Field { file: file.clone(), source };
        let kind = if base.contains_key("line") {
            Kind::Line { conductors: line_conductors(&base).map_err(field_error)? }
        } else {
            Kind::Single
        };
        let mut sweep = Sweep {
            base_path: base_path.to_path_buf(),
            base_text,
            base,
            spec,
            places: Vec::new(),
            kind,
            allow_large,
            converge: None,
        };
        for axis in &sweep.spec.axes {
            for (j, field) in axis.fields.iter().enumerate() {
                let first = axis.rows.iter().find_map(|r| r[j].as_deref());
                sweep.check_field(field, first)?;
            }
        }
        let fields: Vec<&path::FieldPath> = sweep.spec.fields().collect();
        let places = fields
            .iter()
            .map(|f| overrides::resolve(&sweep.base, f))
            .collect::<Result<Vec<_>, _>>()
            .map_err(field_error)?;
        for (i, a) in places.iter().enumerate() {
            if let Some(j) = (0..i).find(|&j| places[j].overlaps(a)) {
                return Err(field_error(overrides::PathError {
                    field: fields[i].to_string(),
                    reason: format!(
                        "is `{a}` in the base file, and field `{}` is `{}`: one is the other or a part of it, and a \
                         field can be varied once",
                        fields[j], places[j]
                    ),
                }));
            }
        }
        if let Kind::Line { .. } = &sweep.kind {
            let n =
                sweep.base.get("line").and_then(|l| l.get("conductors")).and_then(|c| c.as_array()).map_or(0, Vec::len);
            let key = |k: &str| path::Step::Key(k.to_string());
            let at = |k: usize, tail: &[&str]| path::FieldPath {
                steps: [key("line"), key("conductors"), path::Step::Index(k)]
                    .into_iter()
                    .chain(tail.iter().map(|t| key(t)))
                    .collect(),
            };
            let naming: Vec<path::FieldPath> =
                (0..n).flat_map(|k| [at(k, &["name"]), at(k, &["bundle", "sub_conductors"])]).collect();
            for (field, place) in fields.iter().zip(&places) {
                if let Some(c) = naming.iter().find(|c| place.overlaps(c)) {
                    return Err(field_error(overrides::PathError {
                        field: field.to_string(),
                        reason: format!(
                            "sets `{c}`, which names the table's columns (each conductor's, as the base file \
                             declares them): vary another field, or sweep a base file per name"
                        ),
                    }));
                }
            }
        }
        sweep.places = places;
        Ok(sweep)
    }

    /// The result columns of this sweep's table ([`table::RESULT_COLUMNS`] or [`table::line_columns`]).
    pub fn result_columns(&self) -> Vec<String> {
        match &self.kind {
            Kind::Single if self.converge.is_some() => {
                table::RESULT_COLUMNS.iter().chain(table::CONVERGE_COLUMNS.iter()).map(|c| c.to_string()).collect()
            }
            Kind::Single => table::RESULT_COLUMNS.map(String::from).to_vec(),
            Kind::Line { conductors } => {
                let mut c = table::line_columns(conductors);
                if self.converge.is_some() {
                    c.extend(table::LINE_CONVERGE_COLUMNS.map(String::from));
                }
                c
            }
        }
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
        let parsed = match self.kind {
            Kind::Single => scenario::parse(&text, &file).map(|_| ()),
            Kind::Line { .. } => scenario::line::parse(&text, &file).map(|_| ()),
        };
        if let Err(InputError::Parse { message, .. }) = parsed
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

/// The conductors of a line's base document, as the line names them: each `line.conductors[k].name`, a
/// bundle's sub-conductors `NAME.1` to `NAME.n` (`bundle.sub_conductors`, a whole number in [2, 8]).
fn line_conductors(base: &Table) -> Result<Vec<String>, overrides::PathError> {
    let fail = |field: String, reason: &str| overrides::PathError {
        field,
        reason: format!("{reason}: a line sweep names its table's columns after the base file's conductors"),
    };
    let Some(list) = base.get("line").and_then(|l| l.get("conductors")).and_then(|c| c.as_array()) else {
        return Err(fail("line.conductors".into(), "the base file has no array of conductors"));
    };
    let mut names = Vec::new();
    for (k, c) in list.iter().enumerate() {
        let Some(name) = c.get("name").and_then(|n| n.as_str()) else {
            return Err(fail(format!("line.conductors[{k}].name"), "must be the conductor's name (text)"));
        };
        match c.get("bundle") {
            None => names.push(name.to_string()),
            Some(b) => {
                let n = b.get("sub_conductors").and_then(|n| n.as_integer()).filter(|n| (2..=8).contains(n));
                let Some(n) = n else {
                    return Err(fail(
                        format!("line.conductors[{k}].bundle.sub_conductors"),
                        "must be a whole number in [2, 8]",
                    ));
                };
                names.extend((1..=n).map(|i| format!("{name}.{i}")));
            }
        }
    }
    Ok(names)
}
