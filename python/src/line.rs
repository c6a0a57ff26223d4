//! Line scenarios (`[line]`: several conductors on shared towers, `ohl::scenario::line`): parsed,
//! validated and planned as `ohl run` does, run by `ohl::run::line::run_line_observed` with the GIL
//! released, and their static equilibrium (`ohl::statics::solve_line`). Each conductor's numbers come from
//! the same observer as a single run's ([`Record`]), the line's clearances and tower loads from the run's
//! own samples (`LineSamples`, the numbers of `clearances.csv` and `towers.csv`).

use ohl::line::clearance::ClearanceTracker;
use ohl::output::probe::MIDSPAN;
use ohl::run::line::{LineRunError, LineRunOptions, LineWorkEstimate, run_line_observed};
use ohl::run::{Observer, timeseries_columns};
use ohl::scenario::line::{self as line_scenario, LinePlan};
use ohl::scenario::{self, InputError};
use ohl::statics;
use pyo3::exceptions::{PyKeyboardInterrupt, PyOSError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

use crate::args;
use crate::convert::{array1, array2, array3, to_py};
use crate::dict_input;
use crate::errors::{input_error, raise};
use crate::scenario::{
    Interrupt, Record, file_name, interrupted, report_into, run_options, state_dict, static_options,
};

/// A line scenario (a file with `[line]`: several conductors), parsed, validated and planned: ready to
/// run. Build it with `LineScenario.from_file`, `LineScenario.from_toml` or `LineScenario.from_dict` (or
/// `ohl.load_line`, `ohl.loads_line`, `ohl.line_from_dict`); an invalid scenario raises
/// `ohl.ScenarioError` with the message of `ohl run`.
#[pyclass(module = "ohl", frozen)]
pub struct LineScenario {
    plan: LinePlan,
    file: String,
    text: String,
}

/// Parse, validate and plan the line `text` (named `file` in messages) without the GIL, as `ohl run`
/// does; its warnings are issued as `ohl.ScenarioWarning`, as `ohl run` prints them.
fn build(py: Python<'_>, text: String, file: String) -> PyResult<LineScenario> {
    if text.parse::<toml::Table>().is_ok_and(|t| !t.contains_key("line")) {
        let message = "a single-conductor scenario (it has no [line] table) is not a line scenario: load it with \
                       `ohl.load`, `ohl.loads` or `ohl.from_dict`"
            .to_string();
        return Err(input_error(py, InputError::Parse { file, message }));
    }
    let planned = py.detach(|| line_scenario::parse(&text, &file).and_then(|s| line_scenario::plan(&s, &file)));
    let plan = planned.map_err(|e| input_error(py, e))?;
    let category = py.import("ohl._errors")?.getattr("ScenarioWarning")?;
    for (p, name) in plan.plans.iter().zip(plan.line.names()) {
        for w in &p.warnings {
            PyErr::warn(py, &category, &std::ffi::CString::new(format!("{file}: {name}: {w}"))?, 2)?;
        }
    }
    Ok(LineScenario { plan, file, text })
}

#[pymethods]
impl LineScenario {
    /// Read a line scenario file (TOML, SI units). A missing file raises `FileNotFoundError`; an invalid
    /// one `ohl.ScenarioError`.
    #[staticmethod]
    fn from_file(py: Python<'_>, path: &Bound<'_, PyAny>) -> PyResult<LineScenario> {
        let path = args::path("path", path)?;
        let file = path.display().to_string();
        let text = scenario::read_text(&path).map_err(|e| input_error(py, e))?;
        build(py, text, file)
    }

    /// A line scenario from TOML text; `name` stands for the file name in messages.
    #[staticmethod]
    #[pyo3(signature = (text, name = None))]
    fn from_toml(py: Python<'_>, text: &Bound<'_, PyAny>, name: Option<&Bound<'_, PyAny>>) -> PyResult<LineScenario> {
        let text = args::text("text", text)?;
        build(py, text, file_name(name, "<string>")?)
    }

    /// A line scenario from a dict with the tables and keys of a line file (`{"line": {"conductors":
    /// [{...}, ...]}, ...}`), written as TOML text and read like a file (`Scenario.from_dict`'s rules:
    /// every error names the dict's field path).
    #[staticmethod]
    #[pyo3(signature = (d, name = None))]
    fn from_dict(py: Python<'_>, d: &Bound<'_, PyAny>, name: Option<&Bound<'_, PyAny>>) -> PyResult<LineScenario> {
        let name = file_name(name, "<dict>")?;
        let t = dict_input::table_of("d", d, &name, "")?;
        let text = dict_input::to_text(py, &t, &name)?;
        dict_input::check_line(&t, &name).map_err(|e| input_error(py, e))?;
        build(py, text, name)
    }

    /// The scenario's name (`name` in the file, or "line").
    #[getter]
    fn name(&self) -> String {
        self.plan.name.clone()
    }

    /// The file name used in messages (the path, `<string>` or `<dict>`).
    #[getter]
    fn file(&self) -> String {
        self.file.clone()
    }

    /// The TOML text the scenario was read from.
    #[getter]
    fn toml(&self) -> String {
        self.text.clone()
    }

    /// The line's conductors by name, in order: a bundle's sub-conductors are `NAME.1`, `NAME.2`, ...
    #[getter]
    fn conductors(&self) -> Vec<String> {
        self.plan.line.names().to_vec()
    }

    /// Each conductor's role: "phase", "earth_wire" or "sub_conductor".
    #[getter]
    fn roles(&self) -> Vec<&'static str> {
        self.plan.line.roles().iter().map(|r| role_word(*r)).collect()
    }

    /// The conductors as the file declares them (phases, earth wires, bundles), each with the line's
    /// conductors it is made of: a dict name -> list of names (`["A.1", "A.2"]` for a twin bundle `A`).
    #[getter]
    fn groups<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        let names = self.plan.line.names();
        for (g, members) in self.plan.group_names.iter().zip(&self.plan.groups) {
            d.set_item(g, members.iter().map(|&c| names[c].clone()).collect::<Vec<_>>())?;
        }
        Ok(d)
    }

    /// The pairs of groups whose least distance is tracked, in the order of the clearance columns.
    #[getter]
    fn clearance_pairs(&self) -> Vec<(String, String)> {
        let g = &self.plan.group_names;
        ClearanceTracker::new(self.plan.groups.clone())
            .pairs()
            .iter()
            .map(|&(a, b)| (g[a].clone(), g[b].clone()))
            .collect()
    }

    /// The towers (supports shared by conductors, and those of strings with axial damping), by name.
    #[getter]
    fn towers(&self) -> Vec<String> {
        self.plan.line.supports().map(|s| s.name.clone()).collect()
    }

    /// Each conductor's number of segments: a dict name -> `N`.
    #[getter]
    fn segments<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for (name, c) in self.plan.line.names().iter().zip(self.plan.line.conductors()) {
            d.set_item(name, c.wire().segments())?;
        }
        Ok(d)
    }

    /// Each conductor's own supports (fixed nodes and its own strings; a support held by a tower is the
    /// tower's): a dict name -> list of (node index, position [m]).
    #[getter]
    fn supports<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for (name, c) in self.plan.line.names().iter().zip(self.plan.line.conductors()) {
            d.set_item(name, c.wire().supports())?;
        }
        Ok(d)
    }

    /// Each conductor's probes: a dict name -> ["mid", the named probes of `[output] probes`].
    #[getter]
    fn probes<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for (name, p) in self.plan.line.names().iter().zip(&self.plan.plans) {
            let probes: Vec<String> =
                std::iter::once(MIDSPAN.to_string()).chain(p.probes.iter().map(|(n, _)| n.clone())).collect();
            d.set_item(name, probes)?;
        }
        Ok(d)
    }

    /// Each conductor's time-series columns (its `timeseries.csv`): a dict name -> list of columns.
    #[getter]
    fn columns<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for (name, p) in self.plan.line.names().iter().zip(&self.plan.plans) {
            d.set_item(name, timeseries_columns(p).header().to_vec())?;
        }
        Ok(d)
    }

    /// The line's time step (the smallest of its conductors' steps) [s].
    #[getter]
    fn dt_s(&self) -> f64 {
        self.plan.line.params().dt_s
    }

    /// The end time, or the time cap of a run until settled [s].
    #[getter]
    fn end_time_s(&self) -> f64 {
        self.plan.stop.horizon_s()
    }

    /// Interval of the time series, the clearances and the tower loads [s].
    #[getter]
    fn sample_interval_s(&self) -> f64 {
        self.plan.sample_interval_s
    }

    /// Snapshot times, sorted [s] (the final state is always recorded too).
    #[getter]
    fn snapshot_times_s(&self) -> Vec<f64> {
        self.plan.plans.first().map(|p| p.snapshot_times_s.clone()).unwrap_or_default()
    }

    /// Valid but doubtful values, one message each, `NAME: message` (as `ohl run` prints them).
    #[getter]
    fn warnings(&self) -> Vec<String> {
        let names = self.plan.line.names();
        (self.plan.plans.iter().zip(names))
            .flat_map(|(p, name)| p.warnings.iter().map(move |w| format!("{name}: {w}")))
            .collect()
    }

    /// The static solve of `[initial] shape = "equilibrium"` of the whole line (iterations, residual_n,
    /// tolerance_n [N]), or None.
    #[getter]
    fn initial_equilibrium<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let Some(r) = &self.plan.initial_equilibrium else { return Ok(None) };
        let d = PyDict::new(py);
        d.set_item("iterations", r.iterations)?;
        d.set_item("residual_n", r.residual_n)?;
        d.set_item("tolerance_n", r.tolerance_n)?;
        Ok(Some(d))
    }

    /// The work of a run before it runs (`ohl run --dry-run` on the line): conductors, nodes, dt_s,
    /// horizon_s, steps, node_steps, output_bytes, wall_time_s [s] and within_budget.
    fn work_estimate<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        estimate_dict(py, &LineWorkEstimate::of(&self.plan))
    }

    fn __repr__(&self) -> String {
        format!(
            "LineScenario(name={:?}, file={:?}, conductors={:?}, dt_s={:e}, end_time_s={})",
            self.plan.name,
            self.file,
            self.plan.line.names(),
            self.dt_s(),
            self.end_time_s()
        )
    }

    /// Pickling: the scenario is rebuilt from its TOML text.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, (String, String))> {
        let ctor = slf.get_type().getattr("from_toml")?;
        let s = slf.get();
        Ok((ctor, (s.text.clone(), s.file.clone())))
    }
}

fn role_word(r: ohl::line::Role) -> &'static str {
    match r {
        ohl::line::Role::Phase => "phase",
        ohl::line::Role::EarthWire => "earth_wire",
        ohl::line::Role::SubConductor { .. } => "sub_conductor",
    }
}

fn estimate_dict<'py>(py: Python<'py>, e: &LineWorkEstimate) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("conductors", e.conductors)?;
    d.set_item("nodes", e.nodes)?;
    d.set_item("dt_s", e.dt_s)?;
    d.set_item("horizon_s", e.horizon_s)?;
    d.set_item("steps", e.steps)?;
    d.set_item("node_steps", e.node_steps)?;
    d.set_item("output_bytes", e.output_bytes)?;
    d.set_item("wall_time_s", e.wall_time_s())?;
    d.set_item("within_budget", e.check().is_ok())?;
    Ok(d)
}

/// Run a line scenario; the raw arrays and the summary for `ohl.run_line` (which builds the
/// `LineResult`).
#[pyfunction]
pub fn run_line_raw<'py>(
    py: Python<'py>,
    scenario: &Bound<'py, LineScenario>,
    out_dir: Option<&Bound<'py, PyAny>>,
    allow_large: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyDict>> {
    let (out_dir, allow_large) = run_options(out_dir, allow_large)?;
    let sc = scenario.get();
    let estimate = LineWorkEstimate::of(&sc.plan);
    let checked = if allow_large { estimate.check_resolvable() } else { estimate.check() };
    if let Err(refusal) = checked {
        return Err(raise(py, "WorkBudgetError", (format!("{}: {refusal}", sc.file), estimate_dict(py, &estimate)?)));
    }
    let plan = sc.plan.clone();
    let mut records: Vec<Record> = plan.plans.iter().map(Record::new).collect();
    let mut interrupt = Interrupt::new();
    let opts = LineRunOptions { out_dir, record: true };
    let result = py.detach(|| {
        let mut extra: Vec<Vec<&mut dyn Observer>> = records.iter_mut().map(|r| vec![r as &mut dyn Observer]).collect();
        if let Some(first) = extra.first_mut() {
            first.push(&mut interrupt);
        }
        run_line_observed(plan, &opts, &mut extra)
    });
    if let Some(e) = interrupt.error {
        return Err(e);
    }
    let (outcome, instability) = match result {
        Ok(o) => (o, None),
        Err(LineRunError::Unstable { instability, outcome }) => (*outcome, Some(instability)),
        Err(LineRunError::Io(e)) if interrupted(&e) => {
            return Err(PyKeyboardInterrupt::new_err("the run was interrupted"));
        }
        Err(LineRunError::Io(e)) => return Err(PyOSError::new_err(e.to_string())),
    };
    let d = PyDict::new(py);
    let conductors = PyList::empty(py);
    let names = sc.plan.line.names();
    for (c, record) in records.into_iter().enumerate() {
        let cd = PyDict::new(py);
        cd.set_item("name", &names[c])?;
        record.into_dict(&cd, sc.plan.line.conductors()[c].wire().nodes())?;
        conductors.append(cd)?;
    }
    d.set_item("conductors", conductors)?;
    let s = outcome.samples;
    let rows = s.t_s.len();
    let (pairs, towers) = (s.pairs.len(), s.towers.len());
    d.set_item("sample_t_s", array1(py, s.t_s))?;
    d.set_item("clearance_pairs", s.pairs.iter().map(|[a, b]| (a.clone(), b.clone())).collect::<Vec<_>>())?;
    d.set_item("clearance_m", array2(py, s.clearance_m, rows, pairs)?)?;
    d.set_item("towers", s.towers)?;
    d.set_item("tower_force_n", array3(py, s.tower_force_n, (rows, towers, 3))?)?;
    d.set_item("tower_displacement_m", array3(py, s.tower_displacement_m, (rows, towers, 2))?)?;
    d.set_item("summary", to_py(py, &outcome.summary)?)?;
    d.set_item("status", outcome.summary.status.clone())?;
    match instability {
        Some(i) => {
            let u = PyDict::new(py);
            u.set_item("time_s", i.source.time_s)?;
            u.set_item("conductor", i.name.clone())?;
            u.set_item("node", i.source.node)?;
            u.set_item("reason", i.to_string())?;
            u.set_item("message", format!("{}: {i}", sc.file))?;
            d.set_item("instability", u)?;
        }
        None => d.set_item("instability", py.None())?,
    }
    Ok(d)
}

/// The static equilibrium of the whole line under its loads at `t = 0` (before any event), by the
/// library's Newton solver on the line (`statics::solve_line`) from the scenario's initial state.
#[pyfunction]
pub fn line_equilibrium<'py>(
    py: Python<'py>,
    scenario: &Bound<'py, LineScenario>,
    tolerance_n: Option<&Bound<'py, PyAny>>,
    max_iterations: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyDict>> {
    let opts = static_options(tolerance_n, max_iterations)?;
    let sc = scenario.get();
    let mut line = sc.plan.line.clone();
    let solved = py.detach(|| {
        let r = statics::solve_line(&mut line, &opts);
        line.evaluate_forces();
        r
    });
    let report = solved.map_err(|e| raise(py, "StaticsError", (format!("{}: {e}", sc.file),)))?;
    let d = PyDict::new(py);
    let conductors = PyDict::new(py);
    for (name, c) in line.names().iter().zip(line.conductors()) {
        conductors.set_item(name, state_dict(py, c)?)?;
    }
    d.set_item("conductors", conductors)?;
    let towers: Vec<String> = line.supports().map(|s| s.name.clone()).collect();
    let n = towers.len();
    let force: Vec<f64> = (0..n).flat_map(|s| line.support_resultant_n(s)).collect();
    let displacement: Vec<f64> = (0..n).flat_map(|s| line.support_displacement_m(s)).collect();
    d.set_item("towers", towers)?;
    d.set_item("tower_forces_n", array2(py, force, n, 3)?)?;
    d.set_item("tower_displacements_m", array2(py, displacement, n, 3)?)?;
    report_into(&d, report)?;
    Ok(d)
}
