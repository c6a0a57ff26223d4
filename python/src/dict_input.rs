//! Scenarios and weather given as Python dicts: the dict as a TOML table, and every error of it named by
//! the dict's own field path (`geometry.segments`, `line.conductors[0].section.supports[2].kind`), never
//! by a line of the TOML text the dict is written to.
//!
//! A dict is turned into a TOML table ([`table_of`]) value by value: `bool` a boolean, `int` an integer
//! (64 bits, as TOML's), `float` a float, `str` a string, a mapping a table, a list or tuple an array;
//! NumPy scalars and arrays through `.tolist()`. What TOML cannot hold (None, an int beyond 64 bits, an
//! object of another type, a key that is not a str, a dict that contains itself, nesting deeper than
//! [`MAX_DEPTH`]) is refused there, at its path. The table is then read by the library's own schema
//! ([`located`]): serde's first error is found in the TOML text by its span (`toml::de::Error::span`) and
//! the span in the text's tree of spanned values (`toml::de::DeTable::parse`), which gives the path.

use std::ops::Range;

use ohl::scenario::{InputError, Problem, fill_from_catalog, plain_types};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyMapping, PyString, PyTuple};
use serde::de::DeserializeOwned;
use toml::Spanned;
use toml::de::{DeTable, DeValue};

use crate::args::{short_repr, type_name, wrong_type};
use crate::errors::input_error;

/// Deepest nesting of tables and arrays taken from a dict, the dict itself counted. A scenario nests six
/// deep (the dict, `line`, `conductors`, `[k]`, `section`, `supports`, `[j]`, `pivot_m`: eight); the bound
/// keeps a pathologically deep (or endlessly `.tolist()`-ing) value from exhausting the stack.
pub const MAX_DEPTH: usize = 32;

/// The argument `param` (a mapping: a dict or any `collections.abc.Mapping`) as a TOML table; `prefix` is
/// the path of its fields in messages (`""` for a scenario, `"weather"` for the weather argument) and
/// `file` what stands for the file (`<dict>`, `<arguments>`). Anything TOML cannot hold raises
/// `ohl.ScenarioError` naming its path; an argument that is not a mapping `TypeError`.
pub fn table_of(param: &str, v: &Bound<'_, PyAny>, file: &str, prefix: &str) -> PyResult<toml::Table> {
    let m = v.cast::<PyMapping>().map_err(|_| wrong_type(param, "a dict (a mapping)", v))?;
    let mut ancestors = vec![v.as_ptr() as usize];
    let mut to = Writer { file, ancestors: &mut ancestors };
    to.table(m, prefix)
}

/// Walks a Python value into TOML, keeping the containers it is inside (to refuse a cycle).
struct Writer<'a> {
    file: &'a str,
    ancestors: &'a mut Vec<usize>,
}

impl Writer<'_> {
    fn refuse(&self, py: Python<'_>, field: &str, value: String, allowed: &str) -> PyErr {
        let field = if field.is_empty() { "(the top level)" } else { field };
        let problem = Problem { field: field.into(), value, allowed: allowed.into() };
        input_error(py, InputError::Invalid { file: self.file.into(), problems: vec![problem] })
    }

    fn table(&mut self, m: &Bound<'_, PyMapping>, at: &str) -> PyResult<toml::Table> {
        let py = m.py();
        let items = match m.cast::<PyDict>() {
            Ok(d) => d.items(),
            Err(_) => m.items()?,
        };
        let mut t = toml::Table::new();
        for item in items.iter() {
            let (k, v): (Bound<'_, PyAny>, Bound<'_, PyAny>) = item.extract()?;
            let Ok(key) = k.cast::<PyString>().map(|s| s.to_cow().map(|c| c.into_owned())) else {
                let allowed = format!("a key must be a str, not {}", type_name(&k));
                return Err(self.refuse(py, at, short_repr(&k), &allowed));
            };
            let Ok(key) = key else {
                return Err(self.refuse(py, at, short_repr(&k), "a key must be text that can be written as UTF-8"));
            };
            let path = if at.is_empty() { key.clone() } else { format!("{at}.{key}") };
            let value = self.value(&v, &path)?;
            t.insert(key, value);
        }
        Ok(t)
    }

    /// A container inside the current one: refused if it is one of its own ancestors or too deep.
    fn enter(&mut self, v: &Bound<'_, PyAny>, at: &str) -> PyResult<()> {
        let py = v.py();
        let id = v.as_ptr() as usize;
        if self.ancestors.contains(&id) {
            let value = format!("<the {} that contains it>", type_name(v));
            let allowed = "must not contain itself: a dict or list cannot be one of its own items (a reference cycle)";
            return Err(self.refuse(py, at, value, allowed));
        }
        if self.ancestors.len() >= MAX_DEPTH {
            let allowed = format!("tables and arrays may be nested at most {MAX_DEPTH} deep (the dict itself counts)");
            return Err(self.refuse(py, at, format!("<{} nested deeper>", type_name(v)), &allowed));
        }
        self.ancestors.push(id);
        Ok(())
    }

    fn value(&mut self, v: &Bound<'_, PyAny>, at: &str) -> PyResult<toml::Value> {
        let py = v.py();
        if v.is_instance_of::<PyBool>() {
            return Ok(toml::Value::Boolean(v.is_truthy()?));
        }
        if v.is_instance_of::<PyInt>() {
            return v.extract::<i64>().map(toml::Value::Integer).map_err(|_| {
                let allowed = "an int must fit in 64 bits, [-2^63, 2^63 - 1] (as a TOML integer); write a float \
                               (1e30, not 10**30) for a number";
                self.refuse(py, at, short_repr(v), allowed)
            });
        }
        if v.is_instance_of::<PyFloat>() {
            return Ok(toml::Value::Float(v.extract()?));
        }
        if let Ok(s) = v.cast::<PyString>() {
            return s.to_cow().map(|s| toml::Value::String(s.into_owned())).map_err(|_| {
                self.refuse(py, at, short_repr(v), "must be text that can be written as UTF-8 (no lone surrogates)")
            });
        }
        if let Ok(m) = v.cast::<PyMapping>() {
            self.enter(v, at)?;
            let t = self.table(m, at)?;
            self.ancestors.pop();
            return Ok(toml::Value::Table(t));
        }
        if v.is_instance_of::<PyList>() || v.is_instance_of::<PyTuple>() {
            self.enter(v, at)?;
            let mut out = Vec::new();
            for (k, item) in v.try_iter()?.enumerate() {
                out.push(self.value(&item?, &format!("{at}[{k}]"))?);
            }
            self.ancestors.pop();
            return Ok(toml::Value::Array(out));
        }
        if v.is_none() {
            return Err(self.refuse(py, at, "None".into(), "must be a value: leave the key out instead of None"));
        }
        // NumPy scalars (numpy.int64, numpy.bool_, ...) and arrays: their Python equivalent.
        if v.hasattr("tolist").unwrap_or(false)
            && let Ok(plain) = v.call_method0("tolist")
            && !plain.is(v)
        {
            self.enter(v, at)?;
            let out = self.value(&plain, at);
            self.ancestors.pop();
            return out;
        }
        let allowed = format!(
            "must be a bool, int, float, str, dict, list or tuple (or a NumPy number or array), not {}",
            type_name(v)
        );
        Err(self.refuse(py, at, short_repr(v), &allowed))
    }
}

/// The table as TOML text (the text the library reads, kept as `Scenario.toml`).
pub fn to_text(py: Python<'_>, t: &toml::Table, file: &str) -> PyResult<String> {
    toml::to_string(t).map_err(|e| {
        let problem = Problem {
            field: "(the top level)".into(),
            value: "the dict".into(),
            allowed: format!("cannot be written as TOML: {e}"),
        };
        input_error(py, InputError::Invalid { file: file.into(), problems: vec![problem] })
    })
}

/// A step of a field path: a key of a table or an index of an array.
#[derive(Clone, Debug, PartialEq)]
enum Step {
    Key(String),
    Index(usize),
}

/// A field path as the user writes it: `line.conductors[0].section.supports[2].kind`.
fn path_text(steps: &[Step]) -> String {
    let mut s = String::new();
    for step in steps {
        match step {
            Step::Key(k) if s.is_empty() => s.push_str(k),
            Step::Key(k) => {
                s.push('.');
                s.push_str(k);
            }
            Step::Index(i) => s.push_str(&format!("[{i}]")),
        }
    }
    if s.is_empty() { "(the top level)".into() } else { s }
}

/// The first error of reading the table `t` (a dict's, written as TOML text) as a `T`, as a problem at
/// the dict's field path; `None` if it reads.
///
/// serde gives the span of the innermost value it knows: a value, a key, or a table's header for a
/// missing field. An internally tagged table (an `events` entry, a support of `section.supports`) is read
/// through a buffer, so an error inside it comes back at the span of its whole array: the element is then
/// found by reading the document with that array cut to each element alone (the first that fails alike is
/// serde's), and the field inside it by what the message names (a key, a literal, a length).
fn located<T: DeserializeOwned>(t: &toml::Table) -> Option<Problem> {
    let text = toml::to_string(t).ok()?;
    let e = toml::from_str::<T>(&text).err()?;
    let message = plain_types(e.message());
    // No span, or an empty one (serde's position for the document itself: a missing top-level table).
    let Some(at) = e.span().filter(|s| !s.is_empty()) else { return Some(top(message)) };
    let tree = DeTable::parse(&text).ok()?;
    let Some(found) = deepest(tree.get_ref(), &at) else { return Some(top(message)) };
    let mut steps = found.steps.clone();
    let mut value = found.value;
    if let Some(array) = tables_array(tree.get_ref(), &found) {
        if let Some(i) = culprit::<T>(t, &array, &message) {
            steps = array;
            steps.push(Step::Index(i));
            value = lookup(tree.get_ref(), &steps)?;
        } else {
            steps = array;
            value = lookup(tree.get_ref(), &steps)?;
        }
    }
    Some(refine(&text, steps, value, &message))
}

/// A problem at the top level: a missing top-level table, or an error without a position.
fn top(message: String) -> Problem {
    match quoted(&message, "missing field `", '`').map(str::to_string) {
        Some(name) => Problem { field: name, value: "(missing)".into(), allowed: message },
        None => Problem { field: "(the top level)".into(), value: "the dict".into(), allowed: message },
    }
}

/// A value whose key or value span holds the error's position.
struct Found<'t, 'i> {
    steps: Vec<Step>,
    value: &'t Spanned<DeValue<'i>>,
    /// the span that holds the position (the narrowest wins; then the deepest)
    span: Range<usize>,
}

/// The narrowest (then deepest) value or key whose span holds the error's span `at` (none for an error of
/// the whole document, a missing top-level table).
fn deepest<'t, 'i>(tree: &'t DeTable<'i>, at: &Range<usize>) -> Option<Found<'t, 'i>> {
    let mut best = None;
    let mut steps = Vec::new();
    for (k, v) in tree.iter() {
        steps.push(Step::Key(k.get_ref().to_string()));
        find(Some(k.span()), v, &mut steps, at, &mut best);
        steps.pop();
    }
    best
}

fn find<'t, 'i>(
    key: Option<Range<usize>>,
    v: &'t Spanned<DeValue<'i>>,
    steps: &mut Vec<Step>,
    at: &Range<usize>,
    best: &mut Option<Found<'t, 'i>>,
) {
    for span in key.into_iter().chain([v.span()]) {
        if span.start <= at.start && at.end <= span.end {
            let better = best.as_ref().is_none_or(|b| {
                span.len() < b.span.len() || (span.len() == b.span.len() && steps.len() > b.steps.len())
            });
            if better {
                *best = Some(Found { steps: steps.clone(), value: v, span: span.clone() });
            }
        }
    }
    match v.get_ref() {
        DeValue::Table(t) => {
            for (k, x) in t.iter() {
                steps.push(Step::Key(k.get_ref().to_string()));
                find(Some(k.span()), x, steps, at, best);
                steps.pop();
            }
        }
        DeValue::Array(a) => {
            for (i, x) in a.iter().enumerate() {
                steps.push(Step::Index(i));
                find(None, x, steps, at, best);
                steps.pop();
            }
        }
        _ => {}
    }
}

/// The value at `steps` in the tree.
fn lookup<'t, 'i>(tree: &'t DeTable<'i>, steps: &[Step]) -> Option<&'t Spanned<DeValue<'i>>> {
    let (Step::Key(first), rest) = steps.split_first()? else { return None };
    let mut v = tree.iter().find(|(k, _)| k.get_ref() == first).map(|(_, v)| v)?;
    for step in rest {
        v = match (step, v.get_ref()) {
            (Step::Key(key), DeValue::Table(t)) => t.iter().find(|(k, _)| k.get_ref() == key).map(|(_, v)| v)?,
            (Step::Index(i), DeValue::Array(a)) => a.get(*i)?,
            _ => return None,
        };
    }
    Some(v)
}

/// The path of the array of tables the error lies in, when serde could only point at the whole array:
/// the value found is that array, or its first element with the same span (an array of tables written
/// as `[[...]]` headers spans its first header).
fn tables_array(tree: &DeTable<'_>, found: &Found<'_, '_>) -> Option<Vec<Step>> {
    let of_tables = |v: &Spanned<DeValue<'_>>| -> bool {
        matches!(v.get_ref(), DeValue::Array(a) if a.iter().next().is_some() && a.iter().all(|x| matches!(x.get_ref(), DeValue::Table(_))))
    };
    if of_tables(found.value) {
        return Some(found.steps.clone());
    }
    let (last, parent) = found.steps.split_last()?;
    if *last != Step::Index(0) {
        return None;
    }
    let array = lookup(tree, parent)?;
    (of_tables(array) && array.span() == found.span).then(|| parent.to_vec())
}

/// Which element of the array at `array` in `t` gives the error `message`: the first whose document,
/// with the array cut to that element alone, fails with the same message inside the array.
fn culprit<T: DeserializeOwned>(t: &toml::Table, array: &[Step], message: &str) -> Option<usize> {
    let n = match get(t, array)? {
        toml::Value::Array(a) => a.len(),
        _ => return None,
    };
    let prefix = path_text(array);
    (0..n).find(|&i| {
        let mut one = t.clone();
        let Some(toml::Value::Array(a)) = get_mut(&mut one, array) else { return false };
        let element = a[i].clone();
        *a = vec![element];
        let Ok(text) = toml::to_string(&one) else { return false };
        let Err(e) = toml::from_str::<T>(&text) else { return false };
        if plain_types(e.message()) != message {
            return false;
        }
        let (Some(at), Ok(tree)) = (e.span(), DeTable::parse(&text)) else { return false };
        deepest(tree.get_ref(), &at).is_some_and(|f| path_text(&f.steps).starts_with(&prefix))
    })
}

fn get<'t>(t: &'t toml::Table, steps: &[Step]) -> Option<&'t toml::Value> {
    let (Step::Key(first), rest) = steps.split_first()? else { return None };
    let mut v = t.get(first)?;
    for step in rest {
        v = match (step, v) {
            (Step::Key(k), toml::Value::Table(t)) => t.get(k)?,
            (Step::Index(i), toml::Value::Array(a)) => a.get(*i)?,
            _ => return None,
        };
    }
    Some(v)
}

fn get_mut<'t>(t: &'t mut toml::Table, steps: &[Step]) -> Option<&'t mut toml::Value> {
    let (Step::Key(first), rest) = steps.split_first()? else { return None };
    let mut v = t.get_mut(first)?;
    for step in rest {
        v = match (step, v) {
            (Step::Key(k), toml::Value::Table(t)) => t.get_mut(k)?,
            (Step::Index(i), toml::Value::Array(a)) => a.get_mut(*i)?,
            _ => return None,
        };
    }
    Some(v)
}

/// The problem at `steps`. serde reports a missing field at its table, and every error inside an
/// internally tagged table at the table: the field the message names is looked up among its keys.
fn refine(text: &str, steps: Vec<Step>, value: &Spanned<DeValue<'_>>, message: &str) -> Problem {
    let path = path_text(&steps);
    let DeValue::Table(t) = value.get_ref() else {
        return Problem { field: path, value: source(text, value.span()), allowed: message.into() };
    };
    if let Some(name) = quoted(message, "missing field `", '`') {
        return Problem { field: format!("{path}.{name}"), value: "(missing)".into(), allowed: message.into() };
    }
    let number = |s: &str| s.trim().parse::<f64>().ok();
    let wanted = |k: &str, x: &Spanned<DeValue<'_>>| -> bool {
        let literal = |open: &str| quoted(message, open, '`');
        if let Some(name) = literal("unknown field `") {
            return k == name;
        }
        if let Some(v) = literal("unknown variant `") {
            return x.get_ref().as_str() == Some(v);
        }
        if let Some(v) = quoted(message, "invalid type: string \"", '"') {
            return x.get_ref().as_str() == Some(v);
        }
        if let Some(v) = literal("invalid type: floating point `").or(literal("invalid type: integer `")) {
            let is_number = matches!(x.get_ref(), DeValue::Float(_) | DeValue::Integer(_));
            return is_number && number(v).is_some() && number(&source(text, x.span())) == number(v);
        }
        if let Some(v) = literal("invalid type: boolean `") {
            return matches!(x.get_ref(), DeValue::Boolean(b) if b.to_string() == v);
        }
        if message.starts_with("invalid type: sequence") {
            return matches!(x.get_ref(), DeValue::Array(_));
        }
        if message.starts_with("invalid type: map") {
            return matches!(x.get_ref(), DeValue::Table(_));
        }
        if let Some(n) = message.strip_prefix("invalid length ").and_then(|r| r.split(',').next()) {
            return matches!(x.get_ref(), DeValue::Array(a) if a.len().to_string() == n.trim());
        }
        false
    };
    let mut hits = t.iter().filter(|(k, x)| wanted(k.get_ref(), x));
    if let (Some((k, x)), None) = (hits.next(), hits.next()) {
        return Problem {
            field: format!("{path}.{}", k.get_ref()),
            value: source(text, x.span()),
            allowed: message.into(),
        };
    }
    Problem { field: path, value: "a table".into(), allowed: message.into() }
}

/// The text of `message` after `open`, up to `close`.
fn quoted<'m>(message: &'m str, open: &str, close: char) -> Option<&'m str> {
    let rest = message.strip_prefix(open)?;
    rest.find(close).map(|end| &rest[..end])
}

/// A value as the TOML text writes it, cut to 60 characters.
fn source(text: &str, span: Range<usize>) -> String {
    let s = text.get(span).unwrap_or("?").trim();
    if s.chars().count() > 60 { format!("{}...", s.chars().take(57).collect::<String>()) } else { s.to_string() }
}

/// The first error of a scenario dict's table read as a single-conductor scenario, at its field path,
/// with the fields of a catalogue conductor filled in as `ohl::scenario::parse` fills them. A table with
/// `line` is left to the library (which says what a line scenario is).
pub fn check_scenario(t: &toml::Table, file: &str) -> Result<(), InputError> {
    if t.contains_key("line") {
        return Ok(());
    }
    let mut resolved = t.clone();
    if let Some(toml::Value::Table(c)) = resolved.get_mut("conductor") {
        fill_from_catalog(c, file, "conductor", None)?;
    }
    check::<ohl::scenario::Scenario>(&resolved, file)
}

/// As [`check_scenario`] for a line scenario (each `line.conductors[k].conductor` may name a catalogue
/// conductor, as `ohl::scenario::line::parse` reads it). A table without `line` is left to the library.
pub fn check_line(t: &toml::Table, file: &str) -> Result<(), InputError> {
    if !t.contains_key("line") {
        return Ok(());
    }
    let mut resolved = t.clone();
    if let Some(toml::Value::Table(line)) = resolved.get_mut("line")
        && let Some(toml::Value::Array(cs)) = line.get_mut("conductors")
    {
        for (k, c) in cs.iter_mut().enumerate() {
            if let toml::Value::Table(c) = c
                && let Some(toml::Value::Table(cd)) = c.get_mut("conductor")
            {
                fill_from_catalog(cd, file, &format!("line.conductors[{k}].conductor"), None)?;
            }
        }
    }
    check::<ohl::scenario::line::LineScenario>(&resolved, file)
}

/// The first error of reading the table as a `T`, at its field path.
pub fn check<T: DeserializeOwned>(t: &toml::Table, file: &str) -> Result<(), InputError> {
    match located::<T>(t) {
        Some(p) => Err(InputError::Invalid { file: file.into(), problems: vec![p] }),
        None => Ok(()),
    }
}
