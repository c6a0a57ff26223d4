//! `ohl.converge`: the convergence study of `ohl run --converge` ([`ohl_app::converge`]; docs/convergence.md)
//! on a scenario file, run with the GIL released. Returned as the text of `convergence.json` (parsed by
//! `ohl/__init__.py`), which is also written to `out` with every level's files, as the command writes them.

use std::path::PathBuf;

use ohl_app::converge::{self, Options, Refine, StudyError, report};
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;

use crate::errors::{input_error, raise};

/// The study of the scenario at `path` into the directory `out`. Invalid input raises `ohl.ScenarioError`;
/// bad options or an invalid level `ValueError`, a study above `budget` `ohl.WorkBudgetError` (a
/// `ValueError`; the message quotes the finest level's estimate); a level that
/// went unstable or a file that could not be written `RuntimeError`.
#[pyfunction]
#[pyo3(signature = (path, out, refine, levels, ratio, coarsen, scaled_smoothing, rtol, budget))]
#[allow(clippy::too_many_arguments)]
pub fn converge_raw(
    py: Python<'_>,
    path: &Bound<'_, PyAny>,
    out: &Bound<'_, PyAny>,
    refine: &str,
    levels: usize,
    ratio: usize,
    coarsen: bool,
    scaled_smoothing: bool,
    rtol: f64,
    budget: f64,
) -> PyResult<String> {
    let path = crate::args::path("path", path)?;
    let out: PathBuf = crate::args::path("out", out)?;
    let refine = match refine {
        "grid" => Refine::Grid,
        "step" => Refine::Step,
        other => return Err(PyValueError::new_err(format!("refine = {other:?}: expected \"grid\" or \"step\""))),
    };
    if !(rtol.is_finite() && rtol > 0.0) {
        return Err(PyValueError::new_err(format!("rtol = {rtol}: must be a positive number (0.01 is 1 %)")));
    }
    if !(budget.is_finite() && budget > 0.0) {
        return Err(PyValueError::new_err(format!("budget = {budget}: must be a positive number of node-steps")));
    }
    let o = Options { refine, levels, ratio, coarsen, scaled_smoothing, rtol, budget_node_steps: budget };
    let result = py.detach(|| -> Result<String, StudyError> {
        let line = std::fs::read_to_string(&path).is_ok_and(|t| ohl::scenario::line::is_line(&t));
        let (runs, name) = if line {
            let planned = converge::line::plan_line(&path, Some(&out), &o)?;
            let (runs, finest) = converge::line::run_line_levels(&path, planned, |_, _| {})?;
            (runs, finest.name)
        } else {
            let planned = converge::plan(&path, &out, &o)?;
            let (runs, finest) = converge::run(&path, planned, |_, _| {})?;
            (runs, finest.name)
        };
        let quantities = converge::analyse(&runs, rtol);
        let study = report::Study::new(&path.display().to_string(), &name, &o, &runs, &quantities);
        report::write_json(&out, &study).map_err(|e| StudyError::Run {
            file: path.display().to_string(),
            label: "all".into(),
            message: format!("{}: {e}", out.join("convergence.json").display()),
        })?;
        Ok(serde_json::to_string(&study).expect("serialises"))
    });
    result.map_err(|e| match e {
        StudyError::Input(i) => input_error(py, i),
        e @ StudyError::Budget { .. } => raise(py, "WorkBudgetError", (e.to_string(), py.None())),
        e @ StudyError::Level(_) => PyValueError::new_err(e.to_string()),
        e => PyRuntimeError::new_err(e.to_string()),
    })
}
