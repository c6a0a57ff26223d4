//! Conversions of the library's data to Python: JSON values to Python (the summary), vectors to NumPy
//! arrays. (Python dicts to TOML: `dict_input`.)

use numpy::IntoPyArray;
use numpy::ndarray::{Array1, Array2, Array3};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyList, PyString};

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
