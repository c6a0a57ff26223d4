//! Scenarios and weather given as Python dicts: the dict as a TOML table, and every error of it named by
//! the dict's own field path (`geometry.segments`, `line.conductors[0].section.supports[2].kind`), never
//! by a line of the TOML text the dict is written to.
//!
//! A dict is turned into a TOML table ([`table_of`]) value by value: `bool` a boolean, `int` an integer
//! (64 bits, as TOML's), `float` a float, `str` a string, a mapping a table, a list or tuple an array;
//! NumPy scalars and arrays through `.tolist()`. What TOML cannot hold (None, an int beyond 64 bits, an
//! object of another type, a key that is not a str, a dict that contains itself, nesting deeper than
//! [`MAX_DEPTH`]) is refused there, at its path. The table is then read by the library's own schema
//! ([`check`], through [`ohl::scenario::locate::from_table_alone`], which names the field path of serde's
//! error in the table itself).

use ohl::scenario::locate::from_table_alone;
use ohl::scenario::{InputError, Problem, fill_from_catalog};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyMapping, PyString, PyTuple};
use serde::de::DeserializeOwned;

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

/// Make a relative `thermal.conductor_catalog` of a scenario dict's table absolute: joined to `base_dir`
/// (the argument, a path) or, without it, to the current working directory. A dict has no file whose
/// folder a relative path could be taken from (a file's is resolved relative to its folder,
/// `ohl::scenario::thermal_conductor`). A value that is not text is left for the library to refuse.
pub fn rebase_catalog(t: &mut toml::Table, base_dir: Option<&Bound<'_, PyAny>>) -> PyResult<()> {
    let base = match base_dir {
        Some(b) if !b.is_none() => Some(crate::args::path("base_dir", b)?),
        _ => None,
    };
    let Some(toml::Value::Table(thermal)) = t.get_mut("thermal") else { return Ok(()) };
    let Some(toml::Value::String(rel)) = thermal.get_mut("conductor_catalog") else { return Ok(()) };
    let base = match base {
        Some(b) => b,
        None => std::env::current_dir()?,
    };
    *rel = base.join(&*rel).to_string_lossy().into_owned();
    Ok(())
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

/// The first error of reading the table as a `T`, at its field path (the library's
/// [`ohl::scenario::locate::from_table_alone`]).
pub fn check<T: DeserializeOwned>(t: &toml::Table, file: &str) -> Result<(), InputError> {
    from_table_alone::<T>(t.clone(), file).map(|_| ())
}
