//! What a sweep varies: its axes and its cases.
//!
//! An axis is either one `--vary FIELD=VALUES` (one field, one value per row) or a cases file
//! (`--cases CASES.csv`: a header of field paths, one row per case; several fields change together). The
//! cases are the Cartesian product of the axes: the cases file first (when given), then the `--vary`
//! axes in command-line order, the last varying fastest. Case ids count from 0 in that order, so the same
//! command always numbers its cases the same way. An empty cell of a cases file leaves that field at the
//! base file's value for that row.

use std::path::Path;

use serde::Serialize;

use super::path::{FieldPath, PathSyntaxError};
use super::values::{ValuesError, parse_values};

/// Most cases in one sweep.
pub const MAX_CASES: usize = 10_000_000;

/// Where an axis comes from.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Source {
    /// `--vary FIELD=VALUES`, as written
    Vary(String),
    /// `--cases FILE`, the path as given
    Cases(String),
}

/// One axis of the product: its fields and its rows (one value per field, `None` for an empty cell).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Axis {
    /// where it comes from
    pub source: Source,
    /// the fields it sets
    #[serde(serialize_with = "as_text")]
    pub fields: Vec<FieldPath>,
    /// its rows, each with one value (or none) per field
    pub rows: Vec<Vec<Option<String>>>,
}

fn as_text<S: serde::Serializer>(fields: &[FieldPath], s: S) -> Result<S::Ok, S::Error> {
    s.collect_seq(fields.iter().map(|f| f.to_string()))
}

/// Why the specification of a sweep cannot be used (exit code 2).
#[derive(Debug, thiserror::Error)]
pub enum SpecError {
    /// `--vary` without `=`.
    #[error("--vary {0:?}: expected FIELD=VALUES, e.g. loads.wind.speed_m_per_s=10,15,20 or =10:30:5")]
    NoEquals(String),
    /// A malformed field path in a `--vary` (the argument is named: its path may be empty).
    #[error("--vary {arg:?}: {source}")]
    Path {
        /// the argument, as given
        arg: String,
        /// what is wrong with its path
        source: PathSyntaxError,
    },
    /// A malformed list or range.
    #[error(transparent)]
    Values(#[from] ValuesError),
    /// The cases file cannot be read or is malformed.
    #[error("{file}: {message}")]
    CasesFile {
        /// the cases file
        file: String,
        /// what is wrong (with the line where known)
        message: String,
    },
    /// The same field (or a field and a part of it) is varied twice.
    #[error(
        "field `{0}` and field `{1}` are both varied: a field can be varied by one --vary or one cases column only"
    )]
    Overlap(String, String),
    /// Nothing is varied.
    #[error("nothing to vary: give --vary FIELD=VALUES (one or more) and/or --cases CASES.csv")]
    NoAxes,
    /// Too many cases.
    #[error("the sweep has {0} cases, more than {MAX_CASES}: split it into several sweeps")]
    TooMany(String),
}

/// The axes of a sweep and its cases ([module docs](self)).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Spec {
    /// the axes, the cases file first, then the `--vary` axes in command-line order
    pub axes: Vec<Axis>,
    /// number of cases (the product of the axes' lengths)
    pub cases: usize,
}

impl Spec {
    /// The sweep of `cases_file` (if any) and the `vary` arguments (`FIELD=VALUES` each).
    pub fn new(cases_file: Option<&Path>, vary: &[String]) -> Result<Spec, SpecError> {
        let mut axes = Vec::new();
        if let Some(f) = cases_file {
            axes.push(read_cases(f)?);
        }
        for arg in vary {
            axes.push(vary_axis(arg)?);
            // Refuse as soon as the axes read so far are too many (each holds up to
            // `values::MAX_RANGE_VALUES` values), rather than reading every `--vary` first.
            let n: f64 = axes.iter().map(|a| a.rows.len() as f64).product();
            if n > MAX_CASES as f64 {
                return Err(SpecError::TooMany(format!("at least {n:.0}")));
            }
        }
        Spec::of_axes(axes)
    }

    /// The sweep of these axes: checks that something is varied, that no field is varied twice, and the
    /// number of cases.
    pub fn of_axes(axes: Vec<Axis>) -> Result<Spec, SpecError> {
        if axes.is_empty() {
            return Err(SpecError::NoAxes);
        }
        let fields: Vec<&FieldPath> = axes.iter().flat_map(|a| &a.fields).collect();
        for (i, a) in fields.iter().enumerate() {
            if let Some(b) = fields[i + 1..].iter().find(|b| a.overlaps(b)) {
                return Err(SpecError::Overlap(a.to_string(), b.to_string()));
            }
        }
        let mut cases: usize = 1;
        for a in &axes {
            cases = cases.checked_mul(a.rows.len()).filter(|&n| n <= MAX_CASES).ok_or_else(|| {
                let n: f64 = axes.iter().map(|a| a.rows.len() as f64).product();
                SpecError::TooMany(format!("{n:.0}"))
            })?;
        }
        Ok(Spec { axes, cases })
    }

    /// Every varied field, in column order (axis by axis).
    pub fn fields(&self) -> impl Iterator<Item = &FieldPath> {
        self.axes.iter().flat_map(|a| &a.fields)
    }

    /// The values of case `id` (< [`Spec::cases`]), one per field of [`Spec::fields`] (`None`: the base
    /// file's value). The last axis varies fastest.
    pub fn case(&self, id: usize) -> Vec<Option<&str>> {
        let mut rows = vec![0; self.axes.len()];
        let mut rest = id;
        for (a, row) in self.axes.iter().zip(rows.iter_mut()).rev() {
            *row = rest % a.rows.len();
            rest /= a.rows.len();
        }
        (self.axes.iter().zip(rows)).flat_map(|(a, r)| a.rows[r].iter().map(|v| v.as_deref())).collect()
    }
}

/// The axis of one `--vary FIELD=VALUES`.
pub fn vary_axis(arg: &str) -> Result<Axis, SpecError> {
    // The first `=` outside brackets: a name in a path (`line.conductors[name=A].x=1,2`) has one of its own.
    let mut depth = 0_i32;
    let equals = arg.char_indices().find_map(|(i, c)| {
        depth += match c {
            '[' => 1,
            ']' => -1,
            _ => 0,
        };
        (c == '=' && depth <= 0).then_some(i)
    });
    let (field, values) =
        equals.map(|i| (&arg[..i], &arg[i + 1..])).ok_or_else(|| SpecError::NoEquals(arg.to_string()))?;
    let path = FieldPath::parse(field.trim()).map_err(|source| SpecError::Path { arg: arg.to_string(), source })?;
    let values = parse_values(field.trim(), values.trim())?;
    Ok(Axis {
        source: Source::Vary(arg.to_string()),
        fields: vec![path],
        rows: values.into_iter().map(|v| vec![Some(v)]).collect(),
    })
}

/// The axis of a cases file: a CSV header of field paths, then one row per case. Lines starting with `#`
/// are comments; cells are trimmed; an empty cell keeps the base file's value.
pub fn read_cases(file: &Path) -> Result<Axis, SpecError> {
    let name = file.display().to_string();
    let fail = |message: String| SpecError::CasesFile { file: name.clone(), message };
    let text = std::fs::read_to_string(file).map_err(|e| fail(format!("cannot read the cases file: {e}")))?;
    let mut reader =
        csv::ReaderBuilder::new().comment(Some(b'#')).trim(csv::Trim::All).flexible(false).from_reader(text.as_bytes());
    let header = reader.headers().map_err(|e| fail(e.to_string()))?.clone();
    if header.iter().all(str::is_empty) {
        return Err(fail(
            "no header: the first line names the fields, e.g. loads.wind.speed_m_per_s,numerics.mu".into(),
        ));
    }
    let fields = header
        .iter()
        .enumerate()
        .map(|(k, h)| FieldPath::parse(h).map_err(|e| fail(format!("column {}: {e}", k + 1))))
        .collect::<Result<Vec<_>, _>>()?;
    let mut rows = Vec::new();
    for record in reader.records() {
        let record = record.map_err(|e| fail(csv_message(&e)))?;
        rows.push(record.iter().map(|c| (!c.is_empty()).then(|| c.to_string())).collect());
    }
    if rows.is_empty() {
        return Err(fail("no cases: the header is followed by no row".into()));
    }
    Ok(Axis { source: Source::Cases(name), fields, rows })
}

/// A CSV reader's error in the user's terms.
fn csv_message(e: &csv::Error) -> String {
    match e.kind() {
        csv::ErrorKind::UnequalLengths { pos, expected_len, len } => format!(
            "line {}: {len} cell(s), but the header names {expected_len} field(s) (leave a cell empty to keep \
             the base file's value)",
            pos.as_ref().map_or(0, |p| p.line())
        ),
        _ => e.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn vary(args: &[&str]) -> Result<Spec, SpecError> {
        Spec::new(None, &args.iter().map(|s| s.to_string()).collect::<Vec<_>>())
    }

    #[test]
    fn cases_are_the_product_with_the_last_axis_fastest() {
        let s = vary(&["a=1,2", "b.c=10:30:10"]).unwrap();
        assert_eq!(s.cases, 6);
        let all: Vec<Vec<Option<&str>>> = (0..6).map(|i| s.case(i)).collect();
        assert_eq!(all[0], [Some("1"), Some("10")]);
        assert_eq!(all[2], [Some("1"), Some("30")]);
        assert_eq!(all[3], [Some("2"), Some("10")]);
        assert_eq!(all[5], [Some("2"), Some("30")]);
        assert_eq!(s.fields().map(|f| f.to_string()).collect::<Vec<_>>(), ["a", "b.c"]);
        // the `=` of a name in brackets is part of the path
        let s = vary(&["line.conductors[name=A].section.segments_per_span=10,12"]).unwrap();
        assert_eq!(s.fields().next().unwrap().to_string(), "line.conductors[name=A].section.segments_per_span");
        assert_eq!(s.case(1), [Some("12")]);
    }

    #[test]
    fn a_cases_file_is_one_axis_before_the_vary_axes() {
        let dir = std::env::temp_dir().join(format!("ohl_spec_{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let f = dir.join("cases.csv");
        std::fs::write(&f, "# comment\nx, events[0].time_s\n1,2\n3,\n").unwrap();
        let s = Spec::new(Some(&f), &["y=5,6".into()]).unwrap();
        assert_eq!(s.cases, 4);
        assert_eq!(s.case(1), [Some("1"), Some("2"), Some("6")]);
        assert_eq!(s.case(2), [Some("3"), None, Some("5")]);
        std::fs::write(&f, "x,y\n1,2\n3\n").unwrap();
        let e = Spec::new(Some(&f), &[]).unwrap_err().to_string();
        assert!(e.contains("cases.csv") && e.contains("line 3"), "{e}");
        std::fs::write(&f, "x,y\n").unwrap();
        assert!(Spec::new(Some(&f), &[]).unwrap_err().to_string().contains("no cases"));
        std::fs::write(&f, "x,y z\n1,2\n").unwrap();
        assert!(Spec::new(Some(&f), &[]).unwrap_err().to_string().contains("column 2"));
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn bad_specifications_are_refused() {
        assert!(matches!(vary(&[]), Err(SpecError::NoAxes)));
        assert!(matches!(vary(&["a"]), Err(SpecError::NoEquals(_))));
        assert!(matches!(vary(&["a=1", "a=2"]), Err(SpecError::Overlap(..))));
        assert!(matches!(vary(&["g.r=1", "g.r[1]=2"]), Err(SpecError::Overlap(..))));
        assert!(matches!(vary(&["a=0:999:1", "b=0:999:1", "c=0:999:1"]), Err(SpecError::TooMany(_))));
        // Refused at the third axis, before the fourth is read: its count is a lower bound.
        let e = vary(&["a=0:999:1", "b=0:999:1", "c=0:999:1", "d=0:999999:1"]).unwrap_err();
        assert_eq!(
            e.to_string(),
            format!("the sweep has at least 1000000000 cases, more than {MAX_CASES}: split it into several sweeps")
        );
        assert!(matches!(vary(&["a..b=1"]), Err(SpecError::Path { .. })));
        // A finding of app/tests/fuzz_sweep.rs: an empty path is refused naming the argument it is in.
        let e = vary(&["a=1", "=0.01"]).unwrap_err().to_string();
        assert!(e.starts_with("--vary \"=0.01\": field path \"\": empty"), "{e}");
    }
}
