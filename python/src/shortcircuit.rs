//! `ohl.shortcircuit`: a line scenario with `[short_circuit]` by the IEC 60865-1 simplified method and by
//! the dynamic run, side by side ([`ohl::run::shortcircuit_case`], the numbers of `ohl shortcircuit`), run
//! with the GIL released. Returned as the text of `shortcircuit.json` (parsed by `ohl/__init__.py`), so
//! that Python and the command's file hold the same numbers.

use ohl::run::shortcircuit_case::{CompareError, compare, to_json};
use ohl::scenario;
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;

use crate::errors::input_error;

/// Both halves for the line scenario at `path` (str or os.PathLike), nothing written. Invalid input
/// raises `ohl.ScenarioError`; a scenario without `[short_circuit]` `ValueError`; a run that went unstable
/// `RuntimeError`.
#[pyfunction]
#[pyo3(signature = (path))]
pub fn shortcircuit_raw(py: Python<'_>, path: &Bound<'_, PyAny>) -> PyResult<String> {
    let path = crate::args::path("path", path)?;
    let file = path.display().to_string();
    let s =
        scenario::read_text(&path).and_then(|t| scenario::line::parse(&t, &file)).map_err(|e| input_error(py, e))?;
    let plan = scenario::line::plan(&s, &file).map_err(|e| input_error(py, e))?;
    let c = py.detach(|| compare(&s, plan, None)).map_err(|e| match e {
        CompareError::NoShortCircuit => PyValueError::new_err(format!("{file}: {e}")),
        CompareError::Run(_) => PyRuntimeError::new_err(format!("{file}: {e}")),
    })?;
    Ok(serde_json::to_string(&to_json(&c)).expect("serialises"))
}
