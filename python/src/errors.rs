//! The library's errors as Python exceptions. The exception classes are defined in Python
//! (`ohl/_errors.py`: picklable, with their attributes in `__init__`); this module raises them.

use ohl::scenario::InputError;
use pyo3::call::PyCallArgs;
use pyo3::exceptions::{PyFileNotFoundError, PyIsADirectoryError, PyOSError, PyPermissionError};
use pyo3::prelude::*;
use pyo3::types::PyList;

/// An instance of the exception class `name` of `ohl._errors`, built from `args`, as a `PyErr`.
pub fn raise<'py>(py: Python<'py>, name: &str, args: impl PyCallArgs<'py>) -> PyErr {
    let built = py.import("ohl._errors").and_then(|m| m.getattr(name)).and_then(|cls| cls.call1(args));
    match built {
        Ok(e) => PyErr::from_value(e),
        Err(e) => e,
    }
}

/// A scenario or input error as the Python exception it maps to: an unreadable file as
/// `FileNotFoundError` (or `PermissionError`, `IsADirectoryError`, `OSError`) in Python's own form
/// (`errno`, `strerror`, `filename`, as `open()` raises them); a syntax or validation error as
/// `ohl.ScenarioError` with the file, the first problem's field, value and allowed range, and every
/// problem, and the message `ohl run` prints after `error: `.
pub fn input_error(py: Python<'_>, e: InputError) -> PyErr {
    let message = e.to_string();
    match e {
        InputError::Io { file, source } => {
            // Python's form, as open() raises it: errno, strerror, filename.
            let Some(code) = source.raw_os_error() else { return PyOSError::new_err(message) };
            let strerror = py
                .import("os")
                .and_then(|os| os.call_method1("strerror", (code,)))
                .and_then(|s| s.extract::<String>())
                .unwrap_or_else(|_| source.to_string());
            let args = (code, strerror, file);
            match source.kind() {
                std::io::ErrorKind::NotFound => PyFileNotFoundError::new_err(args),
                std::io::ErrorKind::PermissionDenied => PyPermissionError::new_err(args),
                std::io::ErrorKind::IsADirectory => PyIsADirectoryError::new_err(args),
                _ => PyOSError::new_err(args),
            }
        }
        InputError::Parse { file, .. } => {
            let none: Option<String> = None;
            raise(py, "ScenarioError", (message, file, none.clone(), none.clone(), none, PyList::empty(py)))
        }
        InputError::Invalid { file, problems } => {
            let list = PyList::empty(py);
            for p in &problems {
                if let Err(e) = list.append((p.field.as_str(), p.value.as_str(), p.allowed.as_str())) {
                    return e;
                }
            }
            let first = problems.first().map(|p| (p.field.clone(), p.value.clone(), p.allowed.clone()));
            let (field, value, allowed) = first.unwrap_or_default();
            raise(py, "ScenarioError", (message, file, field, value, allowed, list))
        }
    }
}
