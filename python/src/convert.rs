//! Conversions between Python objects and the library's data: Python values to TOML (scenario and
//! thermal inputs given as dicts), JSON values to Python (the summary), vectors to NumPy arrays.

use numpy::IntoPyArray;
use numpy::ndarray::{Array1, Array2, Array3};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};

/// A Python value as a TOML value, for a scenario or thermal case given as a dict. `at` is the dotted
/// path of the value (for the error message).
///
/// `bool` becomes a TOML boolean, `int` an integer, `float` a float (so `segments = 50` must be an int and
/// `end_time_s = 10` may be either, exactly as in a TOML file), `str` a string, a dict a table, a list or
/// tuple an array. NumPy scalars and arrays are taken through `.tolist()`. `None` is refused: leave the key
/// out instead.
pub fn to_toml(v: &Bound<'_, PyAny>, at: &str) -> PyResult<toml::Value> {
    if v.is_instance_of::<PyBool>() {
        return Ok(toml::Value::Boolean(v.extract()?));
    }
    if v.is_instance_of::<PyInt>() {
        let i: i64 = v.extract().map_err(|_| type_error(at, v, "an integer that fits in 64 bits"))?;
        return Ok(toml::Value::Integer(i));
    }
    if v.is_instance_of::<PyFloat>() {
        return Ok(toml::Value::Float(v.extract()?));
    }
    if v.is_instance_of::<PyString>() {
        return Ok(toml::Value::String(v.extract()?));
    }
    if let Ok(d) = v.cast::<PyDict>() {
        return Ok(toml::Value::Table(table(d, at)?));
    }
    if v.is_instance_of::<PyList>() || v.is_instance_of::<PyTuple>() {
        let mut out = Vec::new();
        for (k, item) in v.try_iter()?.enumerate() {
            out.push(to_toml(&item?, &format!("{at}[{k}]"))?);
        }
        return Ok(toml::Value::Array(out));
    }
    if v.is_none() {
        return Err(type_error(at, v, "a value (leave the key out instead of None)"));
    }
    // NumPy scalars (numpy.int64, numpy.bool_, ...) and arrays: their Python equivalent.
    if v.hasattr("tolist")? {
        let plain = v.call_method0("tolist")?;
        if !plain.is(v) {
            return to_toml(&plain, at);
        }
    }
    Err(type_error(at, v, "a bool, int, float, str, dict, list or tuple"))
}

/// A dict as a TOML table; keys must be strings.
pub fn table(d: &Bound<'_, PyDict>, at: &str) -> PyResult<toml::Table> {
    let mut t = toml::Table::new();
    for (k, v) in d.iter() {
        let key: String = k.extract().map_err(|_| type_error(at, &k, "a key that is a str"))?;
        let path = if at.is_empty() { key.clone() } else { format!("{at}.{key}") };
        t.insert(key, to_toml(&v, &path)?);
    }
    Ok(t)
}

fn type_error(at: &str, v: &Bound<'_, PyAny>, expected: &str) -> PyErr {
    let ty = v.get_type().name().map(|n| n.to_string()).unwrap_or_else(|_| "?".into());
    let at = if at.is_empty() { "the top level" } else { at };
    PyTypeError::new_err(format!("{at}: a value of type {ty} cannot be written to TOML: expected {expected}"))
}

/// A JSON value as a Python object (`null` -> None, numbers -> int or float, objects -> dict).
pub fn json_to_py<'py>(py: Python<'py>, v: &serde_json::Value) -> PyResult<Bound<'py, PyAny>> {
    use serde_json::Value;
    Ok(match v {
        Value::Null => py.None().into_bound(py),
        Value::Bool(b) => PyBool::new(py, *b).to_owned().into_any(),
        Value::Number(n) => {
            if let Some(u) = n.as_u64() {
                u.into_pyobject(py)?.into_any()
            } else if let Some(i) = n.as_i64() {
                i.into_pyobject(py)?.into_any()
            } else {
                n.as_f64().unwrap_or(f64::NAN).into_pyobject(py)?.into_any()
            }
        }
        Value::String(s) => PyString::new(py, s).into_any(),
        Value::Array(a) => {
            let l = PyList::empty(py);
            for x in a {
                l.append(json_to_py(py, x)?)?;
            }
            l.into_any()
        }
        Value::Object(o) => {
            let d = PyDict::new(py);
            for (k, x) in o {
                d.set_item(k, json_to_py(py, x)?)?;
            }
            d.into_any()
        }
    })
}

/// A serialisable value (the summary) as Python objects, through its JSON form: the same keys and numbers
/// as the JSON file written from it.
pub fn to_py<'py, T: serde::Serialize>(py: Python<'py>, v: &T) -> PyResult<Bound<'py, PyAny>> {
    let j = serde_json::to_value(v).map_err(|e| PyTypeError::new_err(e.to_string()))?;
    json_to_py(py, &j)
}

/// A 1-D float64 array.
pub fn array1<'py>(py: Python<'py>, v: Vec<f64>) -> Bound<'py, PyAny> {
    Array1::from_vec(v).into_pyarray(py).into_any()
}

/// A 2-D float64 array of `rows` rows from row-major data.
pub fn array2<'py>(py: Python<'py>, v: Vec<f64>, rows: usize, cols: usize) -> PyResult<Bound<'py, PyAny>> {
    let a = Array2::from_shape_vec((rows, cols), v).map_err(|e| PyTypeError::new_err(e.to_string()))?;
    Ok(a.into_pyarray(py).into_any())
}

/// A 3-D float64 array from row-major data.
pub fn array3<'py>(py: Python<'py>, v: Vec<f64>, shape: (usize, usize, usize)) -> PyResult<Bound<'py, PyAny>> {
    let a = Array3::from_shape_vec(shape, v).map_err(|e| PyTypeError::new_err(e.to_string()))?;
    Ok(a.into_pyarray(py).into_any())
}
