//! Setting a field of the parsed scenario document to a case's value, keeping the field's type.
//!
//! The value is written as text (from `--vary` or a cases file) and becomes the TOML type of the value the
//! base file has at that place: an integer field stays an integer (`geometry.segments = 40`; `12.5` there
//! is refused), a number field becomes a float (`10` gives `10.0`), a `true`/`false` field a boolean, a
//! text field the text as written (no quotes needed: `tension_law=linear,tension_only`). An array or a
//! table is replaced by a TOML literal (`[0.0, 150.0, 0.0]`, in a cases file cell in double quotes); one
//! component is simpler to vary by its index (`geometry.right_support_m[1]`).
//!
//! A temperature field replaces its twin in the other unit (`conductor.reference_temperature_c = 15` removes
//! the base file's `conductor.reference_temperature_k`, [`ohl::scenario::temperature`]).
//!
//! Every table and array on the way to the field must be in the base file, an index must be within its
//! array and a name (`[name=A]`) must name one of its tables; only the last key may be missing, and its
//! value's type is then read from the text (a whole number, a number, `true`/`false`, a TOML array or
//! inline table, otherwise text). Such a field is checked once before the sweep: a key that the scenario
//! format does not know is refused then ([`super::Sweep`]).

use ohl::scenario::temperature::{celsius_twin, kelvin_twin};
use toml::{Table, Value};

use super::path::{FieldPath, Step};

/// A field that cannot be set in the base document (the sweep stops before any case runs, exit 2).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("field `{field}`: {reason}")]
pub struct PathError {
    /// the field
    pub field: String,
    /// why, in the terms of the base file
    pub reason: String,
}

/// A case's value that does not fit its field (the case's row is `invalid` with this message).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("field `{field}` = {value} is not allowed: expected {expected}")]
pub struct ValueError {
    /// the field
    pub field: String,
    /// the value as written
    pub value: String,
    /// what the field takes
    pub expected: String,
}

/// Why a value could not be set.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum OverrideError {
    /// the field's place is not in the base document
    #[error(transparent)]
    Path(#[from] PathError),
    /// the value does not fit the field
    #[error(transparent)]
    Value(#[from] ValueError),
}

impl OverrideError {
    /// The same error about the field as written `field` (a path with names, where the error was found at
    /// the place it resolves to).
    pub fn named(self, field: &FieldPath) -> OverrideError {
        match self {
            OverrideError::Path(e) => OverrideError::Path(PathError { field: field.to_string(), ..e }),
            OverrideError::Value(e) => OverrideError::Value(ValueError { field: field.to_string(), ..e }),
        }
    }
}

/// What a value is, in the words of the scenario reference.
fn kind(v: &Value) -> &'static str {
    match v {
        Value::String(_) => "text",
        Value::Integer(_) => "a whole number",
        Value::Float(_) => "a number",
        Value::Boolean(_) => "true or false",
        Value::Datetime(_) => "a date",
        Value::Array(_) => "an array",
        Value::Table(_) => "a table",
    }
}

/// The value that holds the last step of `path` (a table or an array), inside `root`.
fn parent<'a>(root: &'a mut Value, path: &FieldPath) -> Result<&'a mut Value, PathError> {
    let fail = |reason: String| PathError { field: path.to_string(), reason };
    let mut v = root;
    for (k, step) in path.steps[..path.steps.len() - 1].iter().enumerate() {
        let here = path.prefix(k);
        let next = path.prefix(k + 1);
        v = match (step, v) {
            (Step::Key(key), Value::Table(t)) => t.get_mut(key).ok_or_else(|| {
                fail(format!(
                    "the base file has no `{next}`: the tables and arrays on the way to a field must be in the \
                     base file (only the last key may be missing)"
                ))
            })?,
            (Step::Index(i), Value::Array(a)) => {
                let n = a.len();
                a.get_mut(*i).ok_or_else(|| fail(index_reason(&here, *i, n)))?
            }
            (Step::Name(name), Value::Array(a)) => {
                let i = named(a, name, &here).map_err(fail)?;
                &mut a[i]
            }
            (Step::Key(_), other) => return Err(fail(format!("`{here}` is {}, not a table", kind(other)))),
            (_, other) => return Err(fail(format!("`{here}` is {}, not an array", kind(other)))),
        };
    }
    Ok(v)
}

/// The index of the table of `array` (at the path `at`) whose `name` is `name`, or why there is none.
fn named(array: &[Value], name: &str, at: &str) -> Result<usize, String> {
    let name_of = |v: &Value| v.as_table().and_then(|t| t.get("name")).and_then(Value::as_str).map(str::to_string);
    let found: Vec<usize> = (0..array.len()).filter(|&i| name_of(&array[i]).as_deref() == Some(name)).collect();
    match found[..] {
        [i] => Ok(i),
        [] => {
            let names: Vec<String> = array.iter().filter_map(name_of).map(|n| format!("{n:?}")).collect();
            let held = if names.is_empty() {
                "none of its entries has a `name`".to_string()
            } else {
                format!("its names in the base file are {}", names.join(", "))
            };
            Err(format!("no entry of `{at}` is named {name:?}: {held}"))
        }
        _ => Err(format!("{} entries of `{at}` are named {name:?}: select one by its index", found.len())),
    }
}

/// `path` with every name (`[name=A]`) replaced by the index of the table it names in `doc`: the place a
/// path names, whatever its form (two paths of the same place are the same field).
pub fn resolve(doc: &Table, path: &FieldPath) -> Result<FieldPath, PathError> {
    let fail = |reason: String| PathError { field: path.to_string(), reason };
    let mut steps = Vec::with_capacity(path.steps.len());
    let root = Value::Table(doc.clone());
    let mut at = Some(&root);
    for (k, step) in path.steps.iter().enumerate() {
        let here = path.prefix(k);
        let resolved = match (step, at) {
            (Step::Name(name), Some(Value::Array(a))) => Step::Index(named(a, name, &here).map_err(fail)?),
            (Step::Name(_), Some(other)) => {
                return Err(fail(format!("`{here}` is {}, not an array", kind(other))));
            }
            (Step::Name(_), None) => return Err(fail(format!("the base file has no `{here}`"))),
            (other, _) => other.clone(),
        };
        at = match (&resolved, at) {
            (Step::Key(key), Some(Value::Table(t))) => t.get(key),
            (Step::Index(i), Some(Value::Array(a))) => a.get(*i),
            _ => None,
        };
        steps.push(resolved);
    }
    Ok(FieldPath { steps })
}

fn index_reason(array: &str, i: usize, n: usize) -> String {
    let held = match n {
        0 => "no entries".to_string(),
        1 => "1 entry, index 0".to_string(),
        _ => format!("{n} entries, indices 0 to {}", n - 1),
    };
    format!("index {i} is beyond `{array}`, which has {held} in the base file (indices count from 0)")
}

/// The value at `path` in `doc`: `Ok(None)` when its last key is missing (allowed), an error when its
/// place is not in the document.
pub fn existing(doc: &Table, path: &FieldPath) -> Result<Option<Value>, PathError> {
    let mut root = Value::Table(doc.clone());
    let p = parent(&mut root, path)?;
    let n = path.steps.len();
    let fail = |reason: String| PathError { field: path.to_string(), reason };
    match (&path.steps[n - 1], p) {
        (Step::Key(key), Value::Table(t)) => Ok(t.get(key).cloned()),
        (Step::Index(i), Value::Array(a)) => {
            a.get(*i).cloned().map(Some).ok_or_else(|| fail(index_reason(&path.prefix(n - 1), *i, a.len())))
        }
        (Step::Name(name), Value::Array(a)) => Ok(Some(a[named(a, name, &path.prefix(n - 1)).map_err(fail)?].clone())),
        (Step::Key(_), other) => Err(fail(format!("`{}` is {}, not a table", path.prefix(n - 1), kind(other)))),
        (_, other) => Err(fail(format!("`{}` is {}, not an array", path.prefix(n - 1), kind(other)))),
    }
}

/// Set `path` in `doc` to the value written `text`, of the type of the value there ([module docs](self)).
pub fn apply(doc: &mut Table, path: &FieldPath, text: &str) -> Result<(), OverrideError> {
    let mut root = Value::Table(std::mem::take(doc));
    let result = set(&mut root, path, text);
    if let Value::Table(t) = root {
        *doc = t;
    }
    result
}

fn set(root: &mut Value, path: &FieldPath, text: &str) -> Result<(), OverrideError> {
    let n = path.steps.len();
    let fail = |reason: String| PathError { field: path.to_string(), reason };
    let p = parent(root, path)?;
    let slot = match (&path.steps[n - 1], p) {
        (Step::Key(key), Value::Table(t)) => {
            // A temperature given in the other unit (`reference_temperature_k` for a varied
            // `reference_temperature_c`, or the reverse) is replaced: a file gives one of the two.
            let twin = celsius_twin(key).or_else(|| kelvin_twin(key)).filter(|twin| t.contains_key(twin));
            let was = t.get(key).or_else(|| twin.as_ref().and_then(|twin| t.get(twin)));
            let value = convert(was, path, text)?;
            if let Some(twin) = twin {
                t.remove(&twin);
            }
            t.insert(key.clone(), value);
            return Ok(());
        }
        (Step::Index(i), Value::Array(a)) => {
            let len = a.len();
            a.get_mut(*i).ok_or_else(|| fail(index_reason(&path.prefix(n - 1), *i, len)))?
        }
        (Step::Name(name), Value::Array(a)) => {
            let i = named(a, name, &path.prefix(n - 1)).map_err(fail)?;
            &mut a[i]
        }
        (Step::Key(_), other) => {
            return Err(fail(format!("`{}` is {}, not a table", path.prefix(n - 1), kind(other))).into());
        }
        (_, other) => {
            return Err(fail(format!("`{}` is {}, not an array", path.prefix(n - 1), kind(other))).into());
        }
    };
    *slot = convert(Some(slot), path, text)?;
    Ok(())
}

/// `text` as a value of the type of `was` (the base file's value; `None`: read the type from the text).
pub fn convert(was: Option<&Value>, path: &FieldPath, text: &str) -> Result<Value, ValueError> {
    let fail = |expected: String| ValueError { field: path.to_string(), value: text.to_string(), expected };
    let literal = || format!("v = {text}").parse::<Table>().ok().and_then(|mut t| t.remove("v"));
    match was {
        Some(Value::Integer(_)) => text
            .parse::<i64>()
            .map(Value::Integer)
            .map_err(|_| fail("a whole number (the base file has one here)".into())),
        Some(Value::Float(_)) => text
            .parse::<f64>()
            .map(Value::Float)
            .map_err(|_| fail("a number, e.g. 10, 0.5 or 1e-3 (the base file has one here)".into())),
        Some(Value::Boolean(_)) => match text {
            "true" => Ok(Value::Boolean(true)),
            "false" => Ok(Value::Boolean(false)),
            _ => Err(fail("true or false (the base file has one here)".into())),
        },
        Some(Value::String(_)) => Ok(Value::String(text.to_string())),
        Some(Value::Datetime(_)) => Err(fail("nothing: a date cannot be varied".into())),
        Some(Value::Array(_)) => literal().filter(Value::is_array).ok_or_else(|| {
            fail(format!(
                "an array in TOML form such as [0.0, 150.0, 0.0] (the base file has one here); to vary one \
                 component give its index, `{path}[1]`"
            ))
        }),
        Some(Value::Table(_)) => literal().filter(Value::is_table).ok_or_else(|| {
            fail("an inline table in TOML form such as { a = 1.0 } (the base file has one here)".into())
        }),
        None => Ok(literal().unwrap_or_else(|| Value::String(text.to_string()))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const BASE: &str = r#"
name = "n"
[geometry]
segments = 40
right_support_m = [0.0, 160.0, 0.0]
[loads.wind]
speed_m_per_s = 20.0
[duration]
until_settled = { kinetic_energy_fraction = 1e-6, window_s = 2.0 }
[[events]]
time_s = 1.0
action = "wind"
[[events]]
time_s = 2.0
action = "break"
"#;

    fn doc() -> Table {
        BASE.parse().unwrap()
    }
    fn p(t: &str) -> FieldPath {
        FieldPath::parse(t).unwrap()
    }
    fn set_to(field: &str, text: &str) -> Result<Table, OverrideError> {
        let mut d = doc();
        apply(&mut d, &p(field), text).map(|_| d)
    }
    fn at(d: &Table, field: &str) -> Value {
        existing(d, &p(field)).unwrap().unwrap()
    }

    #[test]
    fn a_temperature_replaces_its_twin_in_the_other_unit() {
        let mut d: Table = "[conductor]\nreference_temperature_k = 288.15\n".parse().unwrap();
        apply(&mut d, &p("conductor.reference_temperature_c"), "20").unwrap();
        // The base file's number type (a float) is kept; the kelvin twin is gone.
        assert_eq!(at(&d, "conductor.reference_temperature_c"), Value::Float(20.0));
        assert!(existing(&d, &p("conductor.reference_temperature_k")).unwrap().is_none());
        apply(&mut d, &p("conductor.reference_temperature_k"), "300").unwrap();
        assert_eq!(at(&d, "conductor.reference_temperature_k"), Value::Float(300.0));
        assert!(existing(&d, &p("conductor.reference_temperature_c")).unwrap().is_none());
    }

    #[test]
    fn values_keep_the_type_of_the_base_file() {
        let d = set_to("geometry.segments", "80").unwrap();
        assert_eq!(at(&d, "geometry.segments"), Value::Integer(80));
        let d = set_to("loads.wind.speed_m_per_s", "10").unwrap();
        assert_eq!(at(&d, "loads.wind.speed_m_per_s"), Value::Float(10.0));
        let d = set_to("events[1].time_s", "0.30000000000000004").unwrap();
        assert_eq!(at(&d, "events[1].time_s"), Value::Float(0.30000000000000004));
        let d = set_to("events[0].action", "gust").unwrap();
        assert_eq!(at(&d, "events[0].action"), Value::String("gust".into()));
        let d = set_to("geometry.right_support_m[1]", "150").unwrap();
        assert_eq!(at(&d, "geometry.right_support_m"), "v = [0.0, 150.0, 0.0]".parse::<Table>().unwrap()["v"]);
        let d = set_to("geometry.right_support_m", "[0.0, 200.0, 5.0]").unwrap();
        assert_eq!(at(&d, "geometry.right_support_m[2]"), Value::Float(5.0));
        let d = set_to("duration.until_settled.max_time_s", "60").unwrap();
        assert_eq!(at(&d, "duration.until_settled.max_time_s"), Value::Integer(60));
        let d = set_to("loads.wind.law", "uniform_normal").unwrap();
        assert_eq!(at(&d, "loads.wind.law"), Value::String("uniform_normal".into()));
        // only the field changes
        let d = set_to("geometry.segments", "80").unwrap();
        assert_eq!(at(&d, "loads.wind.speed_m_per_s"), Value::Float(20.0));
        assert_eq!(d.len(), doc().len());
    }

    #[test]
    fn values_of_the_wrong_type_are_refused_with_the_field() {
        let e = set_to("geometry.segments", "12.5").unwrap_err();
        assert_eq!(
            e.to_string(),
            "field `geometry.segments` = 12.5 is not allowed: expected a whole number (the base file has one here)"
        );
        assert!(matches!(set_to("loads.wind.speed_m_per_s", "fast"), Err(OverrideError::Value(_))));
        assert!(matches!(set_to("geometry.right_support_m", "7"), Err(OverrideError::Value(_))));
    }

    #[test]
    fn places_outside_the_base_file_are_refused() {
        for (field, reason) in [
            ("ground.height_m", "the base file has no `ground`"),
            ("events[2].time_s", "index 2 is beyond `events`, which has 2 entries, indices 0 to 1 in the base file"),
            ("geometry.right_support_m[3]", "index 3 is beyond `geometry.right_support_m`"),
            ("geometry.segments[0]", "`geometry.segments` is a whole number, not an array"),
            ("name.first", "`name` is text, not a table"),
            ("events.time_s", "`events` is an array, not a table"),
        ] {
            let e = existing(&doc(), &p(field)).unwrap_err();
            assert!(e.to_string().contains(reason), "{field}: {e}");
            assert!(matches!(set_to(field, "1"), Err(OverrideError::Path(_))), "{field}");
        }
        // a name must name exactly one table of its array
        for (field, reason) in [
            ("events[name=x].time_s", "no entry of `events` is named \"x\": none of its entries has a `name`"),
            ("geometry[name=x]", "`geometry` is a table, not an array"),
        ] {
            let e = existing(&doc(), &p(field)).unwrap_err();
            assert!(e.to_string().contains(reason), "{field}: {e}");
            assert!(matches!(set_to(field, "1"), Err(OverrideError::Path(_))), "{field}");
        }
        // a missing last key is allowed; its type is read from the text
        assert_eq!(existing(&doc(), &p("loads.wind.air_density_kg_per_m3")).unwrap(), None);
        let d = set_to("loads.wind.air_density_kg_per_m3", "1.2").unwrap();
        assert_eq!(at(&d, "loads.wind.air_density_kg_per_m3"), Value::Float(1.2));
        let d = set_to("geometry.tension_law", "linear").unwrap();
        assert_eq!(at(&d, "geometry.tension_law"), Value::String("linear".into()));
    }

    const NAMED: &str = r#"
[line]
towers = [{ name = "T2", position_m = [0.0, 400.0, 30.0] }]
[[line.conductors]]
name = "A"
section = { segments_per_span = 10 }
[[line.conductors]]
name = "earth wire"
section = { segments_per_span = 12 }
[[line.conductors]]
name = "twin"
section = { segments_per_span = 12 }
[[line.conductors]]
name = "twin"
"#;

    #[test]
    fn names_select_a_table_of_an_array() {
        let mut d: Table = NAMED.parse().unwrap();
        let field = p("line.conductors[name=earth wire].section.segments_per_span");
        assert_eq!(existing(&d, &field).unwrap(), Some(Value::Integer(12)));
        assert_eq!(resolve(&d, &field).unwrap(), p("line.conductors[1].section.segments_per_span"));
        apply(&mut d, &field, "16").unwrap();
        assert_eq!(existing(&d, &p("line.conductors[1].section.segments_per_span")).unwrap(), Some(Value::Integer(16)));
        assert_eq!(resolve(&d, &p("line.towers[name=T2].position_m[1]")).unwrap(), p("line.towers[0].position_m[1]"));
        // an index path resolves to itself
        assert_eq!(resolve(&d, &p("line.conductors[0].name")).unwrap(), p("line.conductors[0].name"));
        let e = existing(&d, &p("line.conductors[name=B].section")).unwrap_err();
        assert_eq!(
            e.to_string(),
            "field `line.conductors[name=B].section`: no entry of `line.conductors` is named \"B\": its names in \
             the base file are \"A\", \"earth wire\", \"twin\", \"twin\""
        );
        let e = resolve(&d, &p("line.conductors[name=twin].section")).unwrap_err();
        assert!(e.reason.contains("2 entries of `line.conductors` are named \"twin\""), "{e}");
        let e = resolve(&d, &p("line.towers[0].name[name=x]")).unwrap_err();
        assert!(e.reason.contains("`line.towers[0].name` is text, not an array"), "{e}");
    }
}
