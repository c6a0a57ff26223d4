//! The checks of the public functions' scalar arguments, before any of them is used: a value of the wrong
//! type raises `TypeError` naming the argument (``argument `max_iterations` must be an int, not float``),
//! a value of the right type outside its range `ohl.ScenarioError` with file `<arguments>` and the argument
//! as its field (as the thermal functions' values, checked by the library, already do). The package's
//! error contract is in `python/README.md`; array arguments (NumPy) are checked in `ohl/__init__.py`.

use std::path::PathBuf;

use ohl::scenario::validate::number;
use ohl::scenario::{InputError, Problem};
use pyo3::exceptions::{PyOverflowError, PyTypeError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyBytes, PyFloat, PyInt, PyString};

use crate::errors::input_error;

/// What stands for the file in the messages of values of arguments.
pub const ARGUMENTS: &str = "<arguments>";

/// The name of `v`'s type, for messages.
pub fn type_name(v: &Bound<'_, PyAny>) -> String {
    v.get_type().name().map(|n| n.to_string()).unwrap_or_else(|_| "?".into())
}

/// `TypeError`: argument `param` must be `what`, not (the type of `v`).
pub fn wrong_type(param: &str, what: &str, v: &Bound<'_, PyAny>) -> PyErr {
    PyTypeError::new_err(format!("argument `{param}` must be {what}, not {}", type_name(v)))
}

/// `ohl.ScenarioError`: argument `param` = `value` is not allowed: `allowed`.
pub fn bad_value(py: Python<'_>, param: &str, value: String, allowed: &str) -> PyErr {
    let problem = Problem { field: param.into(), value, allowed: allowed.into() };
    input_error(py, InputError::Invalid { file: ARGUMENTS.into(), problems: vec![problem] })
}

/// `repr(v)`, cut to 60 characters, for messages.
pub fn short_repr(v: &Bound<'_, PyAny>) -> String {
    let r = v.repr().map(|r| r.to_string()).unwrap_or_else(|_| format!("<{}>", type_name(v)));
    if r.chars().count() > 60 { format!("{}...", r.chars().take(57).collect::<String>()) } else { r }
}

/// Whether `v` is a NumPy boolean (`numpy.bool_`, `numpy.True_`), taken as a bool.
fn numpy_bool(v: &Bound<'_, PyAny>) -> bool {
    let t = v.get_type();
    let module = t.module().map(|m| m.to_string()).unwrap_or_default();
    let name = type_name(v);
    module == "numpy" && (name == "bool_" || name == "bool")
}

/// A str argument. A str that cannot be encoded as UTF-8 (a lone surrogate) is a bad value.
pub fn text(param: &str, v: &Bound<'_, PyAny>) -> PyResult<String> {
    let s = v.cast::<PyString>().map_err(|_| wrong_type(param, "a str", v))?;
    s.to_cow().map(|c| c.into_owned()).map_err(|_| {
        bad_value(v.py(), param, short_repr(v), "must be text that can be written as UTF-8 (no lone surrogates)")
    })
}

/// A path argument: a str, bytes or `os.PathLike`, without NUL characters (which no file name can have).
pub fn path(param: &str, v: &Bound<'_, PyAny>) -> PyResult<PathBuf> {
    let py = v.py();
    let fs = if v.is_instance_of::<PyString>() || v.is_instance_of::<PyBytes>() || v.hasattr("__fspath__")? {
        py.import("os")?.call_method1("fsdecode", (v,)).map_err(|_| wrong_type(param, "a str or os.PathLike", v))?
    } else {
        return Err(wrong_type(param, "a str or os.PathLike (a path)", v));
    };
    let s = text(param, &fs)?;
    if s.contains('\0') {
        return Err(bad_value(py, param, short_repr(&fs), "must be a path without NUL characters"));
    }
    Ok(PathBuf::from(s))
}

/// A bool argument: `True` or `False` (or a NumPy boolean); 0, 1, None and strings are refused.
pub fn flag(param: &str, v: &Bound<'_, PyAny>) -> PyResult<bool> {
    if v.is_instance_of::<PyBool>() || numpy_bool(v) {
        return v.is_truthy();
    }
    Err(wrong_type(param, "a bool (True or False)", v))
}

/// A real-number argument: an int or float (or a NumPy number); a bool or a str is refused. An int beyond
/// the range of a float is a bad value; NaN and infinities are left to the range check of the value.
pub fn real(param: &str, v: &Bound<'_, PyAny>) -> PyResult<f64> {
    if v.is_instance_of::<PyBool>() || numpy_bool(v) || v.is_instance_of::<PyString>() || v.is_instance_of::<PyBytes>()
    {
        return Err(wrong_type(param, "a number (an int or a float)", v));
    }
    if !(v.is_instance_of::<PyFloat>() || v.is_instance_of::<PyInt>() || v.hasattr("__float__")?) {
        return Err(wrong_type(param, "a number (an int or a float)", v));
    }
    v.extract::<f64>().map_err(|e| {
        if e.is_instance_of::<PyOverflowError>(v.py()) {
            bad_value(v.py(), param, short_repr(v), "must be a number within the range of a float (|x| < 1.8e308)")
        } else {
            wrong_type(param, "a number (an int or a float)", v)
        }
    })
}

/// An optional real-number argument: None or [`real`].
pub fn optional_real(param: &str, v: Option<&Bound<'_, PyAny>>) -> PyResult<Option<f64>> {
    match v {
        Some(v) if !v.is_none() => real(param, v).map(Some),
        _ => Ok(None),
    }
}

/// A whole-number argument in `[0, max]`: an int (or a NumPy integer); a bool or a float is refused, a
/// negative or too large int is a bad value.
pub fn count(param: &str, v: &Bound<'_, PyAny>, max: u64) -> PyResult<usize> {
    let whole = v.is_instance_of::<PyInt>() || (v.hasattr("__index__")? && !v.is_instance_of::<PyFloat>());
    if v.is_instance_of::<PyBool>() || numpy_bool(v) || !whole {
        return Err(wrong_type(param, "an int", v));
    }
    let i = v.call_method0("__index__").map_err(|_| wrong_type(param, "an int", v))?;
    match i.extract::<u64>() {
        Ok(n) if n <= max => usize::try_from(n).map_err(|_| PyOverflowError::new_err("usize")),
        _ => Err(bad_value(v.py(), param, short_repr(&i), &format!("must be a whole number in [0, {max}]"))),
    }
}

/// A finite real number `> 0` [`unit`], or None (then the library's default is used).
pub fn optional_positive(param: &str, v: Option<&Bound<'_, PyAny>>, unit: &str) -> PyResult<Option<f64>> {
    let Some(v) = v.filter(|v| !v.is_none()) else { return Ok(None) };
    let x = real(param, v)?;
    if !(x.is_finite() && x > 0.0) {
        let allowed = format!("must be None (the default) or a finite number > 0 {unit}");
        return Err(bad_value(v.py(), param, number(x), &allowed));
    }
    Ok(Some(x))
}
