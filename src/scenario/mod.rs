//! Scenarios: the TOML file format ([`schema`]), its validation ([`validate`]) and the one conversion
//! into a run plan ([`build`], [`plan`]). Either a plan that is safe to run comes out, or an
//! [`InputError`] that names the file and, for every problem found, the field, the value and what is
//! allowed. [`warnings`] lists the valid but doubtful values of a plan (printed, and kept in
//! `summary.json`). [`work`] estimates the work of a run before it runs and holds the budget above which a
//! run is refused.

pub mod build;
pub mod dropper;
pub mod events;
pub mod line;
pub mod locate;
pub mod range;
pub mod rating;
pub mod sagtension;
pub mod sagtension_table;
pub mod schema;
pub mod section;
pub mod short_circuit;
pub mod short_circuit_iec;
pub mod temperature;
pub mod thermal;
pub mod thermal_conductor;
pub mod two_material;
pub mod validate;
pub mod warnings;
pub mod work;

use std::fmt;
use std::path::Path;

pub use build::{Plan, build};
pub use schema::Scenario;
pub use validate::Problem;
pub use warnings::Warning;
pub use work::{Refusal, WorkEstimate};

/// Why a scenario could not be used. Every variant names the file.
#[derive(Debug, thiserror::Error)]
pub enum InputError {
    /// The file could not be read.
    #[error("{file}: cannot read the scenario: {source}")]
    Io {
        /// the scenario file
        file: String,
        /// the I/O error
        source: std::io::Error,
    },
    /// TOML syntax error, unknown field or wrong type (the message has line and column).
    #[error("{file}: {message}")]
    Parse {
        /// the scenario file
        file: String,
        /// the parser's message with line and column
        message: String,
    },
    /// One or more fields have values outside their allowed range.
    #[error("{}", Invalid(.file, .problems))]
    Invalid {
        /// the scenario file
        file: String,
        /// each offending field
        problems: Vec<Problem>,
    },
}

struct Invalid<'a>(&'a String, &'a Vec<Problem>);

impl fmt::Display for Invalid<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (file, problems) = (self.0, self.1);
        for (k, p) in problems.iter().enumerate() {
            if k > 0 {
                writeln!(f)?;
            }
            write!(f, "{file}: {p}")?;
        }
        Ok(())
    }
}

/// Parse a scenario from TOML text; `file` names it in messages. A `[conductor]` table that names a
/// conductor of the catalogue (`catalog = "ACSR Drake"`, [`crate::thermal::catalog`]) takes the fields it
/// does not give from there: `linear_density_kg_per_m`, `diameter_m`, `rated_tensile_strength_n`,
/// `thermal_expansion_per_k` and `axial_stiffness_n` (unless `youngs_modulus_pa` is given).
pub fn parse(text: &str, file: &str) -> Result<Scenario, InputError> {
    let mut doc = locate::parse_table(text, file)?;
    if line::is_line_table(&doc) {
        return Err(InputError::Parse {
            file: file.to_string(),
            message: "a line scenario ([line]: several conductors) is not a single-conductor scenario: run it with \
                      `ohl run`, `ohl cases` or `ohl sweep`, or in Python with `ohl.load_line` and `ohl.run_line` \
                      (docs/line.md)"
                .into(),
        });
    }
    if sagtension::is_sagtension_table(&doc) {
        return Err(InputError::Parse { file: file.to_string(), message: sagtension::NOT_HERE.into() });
    }
    if thermal::is_thermal_table(&doc) {
        return Err(InputError::Parse {
            file: file.to_string(),
            message: "a thermal case (a top-level [weather] and `conductor = \"NAME\"`), not a wire \
                      scenario: compute it with `ohl thermal` (docs/thermal.md)"
                .into(),
        });
    }
    catalog_defaults(&mut doc, file)?;
    let celsius = temperature::to_kelvin(&mut doc)
        .map_err(|problems| InputError::Invalid { file: file.to_string(), problems })?;
    let mut scenario: Scenario = locate::from_table(doc, text, file)?;
    scenario.celsius = celsius;
    let problems = scenario.celsius.as_written(validate::validate(&scenario));
    if problems.is_empty() { Ok(scenario) } else { Err(InputError::Invalid { file: file.to_string(), problems }) }
}

/// Fill in the document's `[conductor]` fields from its catalogue conductor and replace the `[thermal]`
/// conductor of a user catalogue (`thermal.conductor_catalog`, [`thermal_conductor::resolve_user_catalog`])
/// by its properties; a document with neither is left as it is.
fn catalog_defaults(doc: &mut toml::Table, file: &str) -> Result<(), InputError> {
    let user = match doc.get_mut("thermal") {
        Some(toml::Value::Table(t)) => thermal_conductor::resolve_user_catalog(t, "thermal.", file)?,
        _ => None,
    };
    if let Some(toml::Value::Table(c)) = doc.get_mut("conductor") {
        fill_from_catalog(c, file, "conductor", user.as_deref())?;
    }
    Ok(())
}

/// Fill the fields a conductor table `c` (at the dotted path `field`) does not give from the catalogue
/// conductor it names (`catalog = "..."`): `linear_density_kg_per_m`, `diameter_m`,
/// `rated_tensile_strength_n`, `thermal_expansion_per_k` and `axial_stiffness_n` (unless
/// `youngs_modulus_pa` is given). The name is looked up in `user` (a user catalogue's entries) first, then in
/// the built-in catalogue. Returns whether it names one.
pub fn fill_from_catalog(
    c: &mut toml::Table,
    file: &str,
    field: &str,
    user: Option<&[crate::thermal::catalog::CatalogConductor]>,
) -> Result<bool, InputError> {
    let Some(name) = c.get("catalog") else { return Ok(false) };
    let Some(name) = name.as_str() else {
        return Err(InputError::Invalid {
            file: file.into(),
            problems: vec![Problem {
                field: format!("{field}.catalog"),
                value: name.to_string(),
                allowed: "must be a conductor's name (a string)".into(),
            }],
        });
    };
    let from_user = user.and_then(|u| thermal_conductor::find_in(u, name));
    let k = from_user.map_or_else(|| crate::thermal::catalog::find(name), Ok).map_err(|e| InputError::Invalid {
        file: file.into(),
        problems: vec![Problem {
            field: format!("{field}.catalog"),
            value: format!("{name:?}"),
            allowed: e.to_string(),
        }],
    })?;
    let with_ea = !c.contains_key("youngs_modulus_pa");
    let mut fill = |key: &str, v: f64| {
        c.entry(key.to_string()).or_insert(toml::Value::Float(v));
    };
    fill("linear_density_kg_per_m", k.linear_density_kg_per_m);
    fill("diameter_m", k.diameter_m);
    fill("rated_tensile_strength_n", k.rated_tensile_strength_n);
    fill("thermal_expansion_per_k", k.thermal_expansion_per_k);
    if with_ea {
        fill("axial_stiffness_n", k.axial_stiffness_n);
    }
    Ok(true)
}

/// A parser message in the user's terms: serde names Rust types ("expected f64", "expected usize"); a
/// scenario's reader knows numbers, whole numbers, text and tables.
pub fn plain_types(message: &str) -> String {
    const PLAIN: [(&str, &str); 10] = [
        ("expected f64", "expected a number"),
        ("expected f32", "expected a number"),
        ("expected usize", "expected a whole number >= 0"),
        ("expected u64", "expected a whole number >= 0"),
        ("expected u32", "expected a whole number >= 0"),
        ("expected i64", "expected a whole number"),
        ("expected i32", "expected a whole number"),
        ("expected a boolean", "expected true or false"),
        ("expected a string", "expected text in quotes"),
        ("expected struct ", "expected a table "),
    ];
    let mut m = message.to_string();
    for (rust, plain) in PLAIN {
        m = m.replace(rust, plain);
    }
    m
}

/// Read a TOML document `text` into `T`: a syntax error keeps the parser's line and column; an error of a
/// value (wrong type, unknown field, missing fields) names the field's path as written in the file
/// (`section.supports[1].insulator_length_m`) and points at the value's own line ([`locate`]).
pub fn from_toml<T: serde::de::DeserializeOwned>(text: &str, file: &str) -> Result<T, InputError> {
    locate::from_text(text, file)
}

/// Read a text file: an I/O error names the file; a file that is not UTF-8 is refused with the line and
/// column of its first invalid byte.
pub fn read_text(path: &Path) -> Result<String, InputError> {
    let file = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|source| InputError::Io { file: file.clone(), source })?;
    String::from_utf8(bytes).map_err(|e| {
        let at = e.utf8_error().valid_up_to();
        let bytes = e.as_bytes();
        let line_start = bytes[..at].iter().rposition(|&b| b == b'\n').map_or(0, |p| p + 1);
        let line = bytes[..at].iter().filter(|&&b| b == b'\n').count() + 1;
        InputError::Parse {
            file,
            message: format!(
                "line {line}, column {}: the file is not valid UTF-8 (byte 0x{:02x} at byte offset {at}): save the \
                 scenario as UTF-8 text",
                at - line_start + 1,
                bytes[at]
            ),
        }
    })
}

/// Build a parsed scenario into its plan ([`build::build`]), naming `file` in the error.
pub fn plan(s: &Scenario, file: &str) -> Result<Plan, InputError> {
    build(s)
        .map_err(|problems| InputError::Invalid { file: file.to_string(), problems: s.celsius.as_written(problems) })
}

/// Read, parse and validate a scenario file.
pub fn load(path: &Path) -> Result<Scenario, InputError> {
    let text = read_text(path)?;
    parse(&text, &path.display().to_string())
}
