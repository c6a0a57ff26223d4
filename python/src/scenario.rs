//! Scenarios (parse, validate, plan), runs and static equilibria.

use std::path::PathBuf;
use std::time::{Duration, Instant};

use ohl::output::clock::{LANDING, ListClock, SampleClock};
use ohl::output::probe::{MIDSPAN, ProbePoint};
use ohl::output::snapshots::node_rows;
use ohl::output::timeseries::Columns;
use ohl::run::{Control, Ending, Level, Observer, OutputError, RunError, RunOptions, run_observed, timeseries_columns};
use ohl::scenario::{self, Plan, WorkEstimate};
use ohl::scheme::Explicit;
use ohl::statics::{self, StaticOptions, StaticReport};
use pyo3::exceptions::{PyKeyboardInterrupt, PyOSError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

use crate::args;
use crate::convert::{array1, array2, array3, to_py};
use crate::dict_input;
use crate::errors::{input_error, raise};

/// A scenario, parsed, validated and planned: ready to run. Build it with `Scenario.from_file`,
/// `Scenario.from_toml` or `Scenario.from_dict` (or `ohl.load`, `ohl.loads`, `ohl.from_dict`); an
/// invalid scenario raises `ohl.ScenarioError`.
#[pyclass(module = "ohl", frozen)]
pub struct Scenario {
    plan: Plan,
    file: String,
    text: String,
}

/// Parse, validate and plan `text` (named `file` in messages) without the GIL, as `ohl run` does.
fn build(py: Python<'_>, text: String, file: String) -> PyResult<Scenario> {
    let planned = py.detach(|| scenario::parse(&text, &file).and_then(|sc| scenario::plan(&sc, &file)));
    let plan = planned.map_err(|e| input_error(py, e))?;
    let category = py.import("ohl._errors")?.getattr("ScenarioWarning")?;
    for w in &plan.warnings {
        PyErr::warn(py, &category, &std::ffi::CString::new(format!("{file}: {w}"))?, 2)?;
    }
    Ok(Scenario { plan, file, text })
}

#[pymethods]
impl Scenario {
    /// Read a scenario file (TOML, SI units). A missing file raises `FileNotFoundError`; an invalid one
    /// `ohl.ScenarioError`. Warnings (valid but doubtful values) are issued as `ohl.ScenarioWarning`.
    #[staticmethod]
    fn from_file(py: Python<'_>, path: &Bound<'_, PyAny>) -> PyResult<Scenario> {
        let path = args::path("path", path)?;
        let file = path.display().to_string();
        let text = scenario::read_text(&path).map_err(|e| input_error(py, e))?;
        build(py, text, file)
    }

    /// A scenario from TOML text; `name` stands for the file name in messages.
    #[staticmethod]
    #[pyo3(signature = (text, name = None))]
    fn from_toml(py: Python<'_>, text: &Bound<'_, PyAny>, name: Option<&Bound<'_, PyAny>>) -> PyResult<Scenario> {
        let text = args::text("text", text)?;
        build(py, text, file_name(name, "<string>")?)
    }

    /// A scenario from a dict with the tables and keys of a scenario file (nested dicts for tables, a
    /// list of dicts for `events`). Python `int` is a TOML integer and `float` a TOML float, so a field
    /// that takes a whole number (`segments`) needs an `int`; a number field takes either. The dict is
    /// written as TOML text (`Scenario.toml`) and read like a file; `name` stands for the file name in
    /// messages, and every error names the dict's field path (`dict_input`). A relative
    /// `thermal.conductor_catalog` (a user catalogue) is taken relative to `base_dir` (a path; default the
    /// current working directory), as a file's is relative to the file's folder; the text holds it made
    /// absolute.
    #[staticmethod]
    #[pyo3(signature = (d, name = None, base_dir = None))]
    fn from_dict(
        py: Python<'_>,
        d: &Bound<'_, PyAny>,
        name: Option<&Bound<'_, PyAny>>,
        base_dir: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Scenario> {
        let name = file_name(name, "<dict>")?;
        let mut t = dict_input::table_of("d", d, &name, "")?;
        dict_input::rebase_catalog(&mut t, base_dir)?;
        let text = dict_input::to_text(py, &t, &name)?;
        dict_input::check_scenario(&t, &name).map_err(|e| input_error(py, e))?;
        build(py, text, name)
    }

    /// The scenario's name (`name` in the file, or "scenario").
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

    /// Number of segments `N` of the line (nodes: `N + 1`).
    #[getter]
    fn segments(&self) -> usize {
        self.plan.solver.wire().segments()
    }

    /// The nominal time step `dt` of (3.7) [s].
    #[getter]
    fn dt_s(&self) -> f64 {
        self.plan.solver.params().dt_s
    }

    /// Courant number `C = c dt / ds` [-].
    #[getter]
    fn courant(&self) -> f64 {
        self.plan.courant
    }

    /// Longitudinal wave speed `c = sqrt(EA / rho0)` [m/s].
    #[getter]
    fn wave_speed_m_per_s(&self) -> f64 {
        self.plan.wave_speed_m_per_s
    }

    /// Chord length between the first and last support [m].
    #[getter]
    fn chord_m(&self) -> f64 {
        self.plan.chord_m
    }

    /// The end time, or the time cap of a run until settled [s].
    #[getter]
    fn end_time_s(&self) -> f64 {
        self.plan.stop.horizon_s()
    }

    /// Interval of the time series [s].
    #[getter]
    fn sample_interval_s(&self) -> f64 {
        self.plan.sample_interval_s
    }

    /// Snapshot times, sorted [s] (the final state is always recorded too).
    #[getter]
    fn snapshot_times_s(&self) -> Vec<f64> {
        self.plan.snapshot_times_s.clone()
    }

    /// The supports: (node index, position [m]) for each fixed node or suspension string, in node order.
    #[getter]
    fn supports(&self) -> Vec<(usize, [f64; 3])> {
        self.plan.solver.wire().supports()
    }

    /// The probes' names: "mid" (mid-span) and the named probes of `[output] probes`.
    #[getter]
    fn probes(&self) -> Vec<String> {
        std::iter::once(MIDSPAN.to_string()).chain(self.plan.probes.iter().map(|(n, _)| n.clone())).collect()
    }

    /// The columns of the run's time series (`timeseries.csv`), in order.
    #[getter]
    fn columns(&self) -> Vec<String> {
        timeseries_columns(&self.plan).header().to_vec()
    }

    /// Valid but doubtful values, one message each (as `ohl run` prints them).
    #[getter]
    fn warnings(&self) -> Vec<String> {
        self.plan.warnings.iter().map(|w| w.to_string()).collect()
    }

    /// The static solve of `[initial] shape = "equilibrium"` (iterations, residual_n, tolerance_n [N]),
    /// or None.
    #[getter]
    fn initial_equilibrium<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let Some(r) = &self.plan.initial_equilibrium else { return Ok(None) };
        let d = PyDict::new(py);
        d.set_item("iterations", r.iterations)?;
        d.set_item("residual_n", r.residual_n)?;
        d.set_item("tolerance_n", r.tolerance_n)?;
        Ok(Some(d))
    }

    /// The work of a run before it runs (`ohl run --dry-run`): steps, node-steps, heat sub-steps, rows and
    /// bytes of output, and the estimated wall time [s] at the budget's throughput.
    fn work_estimate<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let e = self.plan.work_estimate();
        estimate_dict(py, &e)
    }

    fn __repr__(&self) -> String {
        format!(
            "Scenario(name={:?}, file={:?}, segments={}, dt_s={:e}, end_time_s={})",
            self.plan.name,
            self.file,
            self.segments(),
            self.dt_s(),
            self.end_time_s()
        )
    }

    /// Pickling (Dask's process and distributed schedulers): the scenario is rebuilt from its TOML text.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, (String, String))> {
        let ctor = slf.get_type().getattr("from_toml")?;
        let s = slf.get();
        Ok((ctor, (s.text.clone(), s.file.clone())))
    }
}

/// The argument `name` (the file name of messages), or `default`.
pub(crate) fn file_name(name: Option<&Bound<'_, PyAny>>, default: &str) -> PyResult<String> {
    match name {
        Some(n) if !n.is_none() => args::text("name", n),
        _ => Ok(default.to_string()),
    }
}

pub(crate) fn estimate_dict<'py>(py: Python<'py>, e: &WorkEstimate) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("segments", e.segments)?;
    d.set_item("dt_s", e.dt_s)?;
    d.set_item("horizon_s", e.horizon_s)?;
    d.set_item("steps", e.steps)?;
    d.set_item("node_steps", e.node_steps)?;
    d.set_item("heat_substeps", e.heat_substeps)?;
    d.set_item("heat_node_updates", e.heat_node_updates)?;
    d.set_item("timeseries_rows", e.timeseries_rows)?;
    d.set_item("timeseries_columns", e.timeseries_columns)?;
    d.set_item("snapshot_rows", e.snapshot_rows)?;
    d.set_item("output_bytes", e.output_bytes)?;
    d.set_item("wall_time_s", e.wall_time_s())?;
    d.set_item("within_budget", e.check().is_ok())?;
    Ok(d)
}

/// Records in memory what `ohl run` writes to `timeseries.csv` and `snapshots.csv`, on the same clocks
/// and from the same code ([`Columns`], [`node_rows`]), so the numbers are the files' numbers.
pub(crate) struct Record {
    columns: Columns,
    samples: SampleClock,
    rows: Vec<f64>,
    snapshots: ListClock,
    snap_t: Vec<f64>,
    snap_tau: Vec<f64>,
    snap_s: Vec<f64>,
    snap_x: Vec<f64>,
    snap_v: Vec<f64>,
    snap_tension: Vec<f64>,
    tension: Vec<f64>,
}

impl Record {
    pub(crate) fn new(plan: &Plan) -> Self {
        Record {
            columns: timeseries_columns(plan),
            samples: SampleClock::new(plan.sample_interval_s),
            rows: Vec::new(),
            snapshots: ListClock::new(plan.snapshot_times_s.clone()),
            snap_t: Vec::new(),
            snap_tau: Vec::new(),
            snap_s: Vec::new(),
            snap_x: Vec::new(),
            snap_v: Vec::new(),
            snap_tension: Vec::new(),
            tension: Vec::new(),
        }
    }

    /// The time series (`columns`, `rows`) and the snapshots (`snapshot_*`) as NumPy arrays in `d`, for
    /// a wire of `nodes` nodes.
    pub(crate) fn into_dict(self, d: &Bound<'_, PyDict>, nodes: usize) -> PyResult<()> {
        let py = d.py();
        let header = self.columns.header().to_vec();
        let cols = header.len();
        let n_rows = self.rows.len() / cols.max(1);
        d.set_item("columns", header)?;
        d.set_item("rows", array2(py, self.rows, n_rows, cols)?)?;
        let k = self.snap_t.len();
        d.set_item("snapshot_t_s", array1(py, self.snap_t))?;
        d.set_item("snapshot_tau", array1(py, self.snap_tau))?;
        d.set_item("snapshot_s_m", array2(py, self.snap_s, k, nodes)?)?;
        d.set_item("snapshot_x_m", array3(py, self.snap_x, (k, nodes, 3))?)?;
        d.set_item("snapshot_v_m_per_s", array3(py, self.snap_v, (k, nodes, 3))?)?;
        d.set_item("snapshot_tension_n", array2(py, self.snap_tension, k, nodes)?)?;
        Ok(())
    }

    fn snapshot(&mut self, level: &Level) {
        self.snap_t.push(level.t_s);
        self.snap_tau.push(level.tau());
        let (s, x, v, tn) = (&mut self.snap_s, &mut self.snap_x, &mut self.snap_v, &mut self.snap_tension);
        node_rows(level.solver, &mut self.tension, |r| {
            s.push(r.s_m);
            x.extend_from_slice(&r.x_m);
            v.extend_from_slice(&r.v_m_per_s);
            tn.push(r.tension_n);
        });
    }
}

impl Observer for Record {
    fn observe(&mut self, level: &Level) -> Result<Control, OutputError> {
        let tol = LANDING * level.solver.params().dt_s;
        if self.samples.due(level.t_s, tol) {
            let rows = &mut self.rows;
            self.columns.values(level, |x| rows.push(x));
        }
        if self.snapshots.due(level.t_s, tol) {
            self.snapshot(level);
        }
        Ok(Control::Continue)
    }

    /// As `snapshots.csv`: the final state once more, unless the run went unstable or it was just taken.
    fn finish(&mut self, level: &Level, ending: &Ending) -> Result<(), OutputError> {
        if !matches!(ending, Ending::Unstable(_)) && self.snap_t.last() != Some(&level.t_s) {
            self.snapshot(level);
        }
        Ok(())
    }
}

/// Stops a run when Python has a pending signal (Ctrl-C): every 4096 time levels it looks at the clock,
/// and every 0.2 s it takes the GIL for `PyErr_CheckSignals`. Observers cannot change the state, so this
/// changes no number.
pub(crate) struct Interrupt {
    levels: u64,
    last: Instant,
    pub(crate) error: Option<PyErr>,
}

impl Interrupt {
    pub(crate) fn new() -> Self {
        Interrupt { levels: 0, last: Instant::now(), error: None }
    }
}

/// Whether an output error is the one [`Interrupt`] stops a run with.
pub(crate) fn interrupted(e: &OutputError) -> bool {
    e.path == INTERRUPTED
}

const INTERRUPTED: &str = "<interrupted>";

impl Observer for Interrupt {
    fn observe(&mut self, _level: &Level) -> Result<Control, OutputError> {
        self.levels += 1;
        if self.levels.is_multiple_of(4096) && self.last.elapsed() > Duration::from_millis(200) {
            self.last = Instant::now();
            if let Err(e) = Python::attach(|py| py.check_signals()) {
                self.error = Some(e);
                return Err(OutputError {
                    path: INTERRUPTED.into(),
                    source: std::io::Error::other("interrupted by a signal"),
                });
            }
        }
        Ok(Control::Continue)
    }
}

/// Run a scenario; the raw arrays and the summary for `ohl.run` (which builds the `RunResult`).
#[pyfunction]
pub fn run_raw<'py>(
    py: Python<'py>,
    scenario: &Bound<'py, Scenario>,
    out_dir: Option<&Bound<'py, PyAny>>,
    allow_large: &Bound<'py, PyAny>,
    static_after: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyDict>> {
    let (out_dir, allow_large) = run_options(out_dir, allow_large)?;
    let static_after = args::flag("static_after", static_after)?;
    let sc = scenario.get();
    let estimate = sc.plan.work_estimate();
    let checked = if allow_large { estimate.check_resolvable() } else { estimate.check() };
    if let Err(refusal) = checked {
        return Err(raise(py, "WorkBudgetError", (format!("{}: {refusal}", sc.file), estimate_dict(py, &estimate)?)));
    }
    let plan = sc.plan.clone();
    let mut record = Record::new(&plan);
    let mut interrupt = Interrupt::new();
    let opts = RunOptions { out_dir, record: false };
    let result = py.detach(|| {
        let mut extra: [&mut dyn Observer; 2] = [&mut record, &mut interrupt];
        run_observed(plan, &opts, &mut extra)
    });
    if let Some(e) = interrupt.error {
        return Err(e);
    }
    let (outcome, instability) = match result {
        Ok(o) => (o, None),
        Err(RunError::Unstable { instability, outcome }) => (*outcome, Some(instability)),
        Err(RunError::Io(e)) if interrupted(&e) => {
            return Err(PyKeyboardInterrupt::new_err("the run was interrupted"));
        }
        Err(RunError::Io(e)) => return Err(PyOSError::new_err(e.to_string())),
    };
    let d = PyDict::new(py);
    record.into_dict(&d, sc.plan.solver.wire().segments() + 1)?;
    d.set_item("summary", to_py(py, &outcome.summary)?)?;
    d.set_item("status", outcome.summary.status.clone())?;
    let events = PyList::empty(py);
    for (t, what) in &outcome.events {
        events.append((*t, what.as_str()))?;
    }
    d.set_item("events", events)?;
    // The residual static state of `ohl run --static-after`, of a run that did not go unstable.
    if static_after && instability.is_none() {
        let solved = py.detach(|| statics::residual::residual(&outcome.solver, &sc.plan.spans));
        let r = solved.map_err(|e| {
            raise(py, "StaticsError", (format!("{}: residual static state after the run: {e}", sc.file),))
        })?;
        if let Some(dir) = &opts.out_dir {
            ohl::run::write_residual(dir, &r).map_err(|e| PyOSError::new_err(e.to_string()))?;
        }
        let st = state_dict(py, &r.solver)?;
        for (k, v) in to_py(py, &r)?.cast_into::<PyDict>()?.iter() {
            st.set_item(k, v)?;
        }
        d.set_item("static", st)?;
    } else {
        d.set_item("static", py.None())?;
    }
    match instability {
        Some(i) => {
            let u = PyDict::new(py);
            u.set_item("time_s", i.time_s)?;
            u.set_item("node", i.node)?;
            u.set_item("reason", i.to_string())?;
            u.set_item("message", format!("{}: {i}", sc.file))?;
            d.set_item("instability", u)?;
        }
        None => d.set_item("instability", py.None())?,
    }
    Ok(d)
}

/// The checked options of a run: `out_dir` (None or a path) and `allow_large` (a bool).
pub(crate) fn run_options(
    out_dir: Option<&Bound<'_, PyAny>>,
    allow_large: &Bound<'_, PyAny>,
) -> PyResult<(Option<PathBuf>, bool)> {
    let out_dir = match out_dir {
        Some(d) => Some(args::path("out_dir", d)?),
        None => None,
    };
    Ok((out_dir, args::flag("allow_large", allow_large)?))
}

/// Most Newton iterations a static solve may be given: 100 times the library's default (100,
/// `StaticOptions::default`); the solves of the repository converge in about ten (docs/python.md: 8 for
/// fig. 3). Without a bound, a tolerance the solve cannot reach (1e-300 N) with `max_iterations = 2**63 -
/// 1` runs for ever (found by test_fuzz.py); at this bound it ends, `ohl.StaticsError`.
pub const MAX_ITERATIONS: u64 = 10_000;

/// The checked options of a static solve: `tolerance_n` (None or a finite number > 0 [N]) and
/// `max_iterations` (an int in [0, `MAX_ITERATIONS`]; 0 only checks the start against the tolerance).
pub(crate) fn static_options(
    tolerance_n: Option<&Bound<'_, PyAny>>,
    max_iterations: &Bound<'_, PyAny>,
) -> PyResult<StaticOptions> {
    let tolerance_n = args::optional_positive("tolerance_n", tolerance_n, "[N]")?;
    let max_iterations = args::count("max_iterations", max_iterations, MAX_ITERATIONS)?;
    Ok(StaticOptions { tolerance_n, max_iterations })
}

/// The static equilibrium of the scenario's line under its loads at `t = 0` (before any event), by the
/// library's Newton solver started from the scenario's initial shape.
#[pyfunction]
pub fn equilibrium<'py>(
    py: Python<'py>,
    scenario: &Bound<'py, Scenario>,
    tolerance_n: Option<&Bound<'py, PyAny>>,
    max_iterations: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyDict>> {
    let opts = static_options(tolerance_n, max_iterations)?;
    let sc = scenario.get();
    let mut solver = sc.plan.solver.clone();
    let solved = py.detach(|| {
        let r = statics::solve(&mut solver, &opts);
        solver.evaluate_forces();
        r
    });
    let report = solved.map_err(|e| raise(py, "StaticsError", (format!("{}: {e}", sc.file),)))?;
    let d = state_dict(py, &solver)?;
    report_into(&d, report)?;
    Ok(d)
}

/// A wire at rest as `ohl.equilibrium` gives it: `x_m`, `s_m`, `segment_tension_n`, `node_tension_n`,
/// `midspan_displacement_m`, `max_tension_n`, `support_nodes`, `support_forces_n` (forces evaluated).
pub(crate) fn state_dict<'py>(py: Python<'py>, solver: &Explicit) -> PyResult<Bound<'py, PyDict>> {
    let w = solver.wire();
    let (n, nodes) = (w.segments(), w.segments() + 1);
    let x: Vec<f64> = (0..nodes).flat_map(|i| [w.x[0][i], w.x[1][i], w.x[2][i]]).collect();
    let segment_tension: Vec<f64> = (0..n).map(|j| solver.segment_tension(j)).collect();
    let (mut s_m, mut node_tension, mut scratch) = (Vec::new(), Vec::new(), Vec::new());
    node_rows(solver, &mut scratch, |r| {
        s_m.push(r.s_m);
        node_tension.push(r.tension_n);
    });
    let mid = ProbePoint::new(MIDSPAN, 0.5, w).displacement(w);
    let mut forces = Vec::new();
    solver.support_forces(&mut forces);
    let d = PyDict::new(py);
    d.set_item("x_m", array2(py, x, nodes, 3)?)?;
    d.set_item("s_m", array1(py, s_m))?;
    d.set_item("segment_tension_n", array1(py, segment_tension))?;
    d.set_item("node_tension_n", array1(py, node_tension))?;
    d.set_item("midspan_displacement_m", mid.to_vec())?;
    d.set_item("max_tension_n", solver.max_tension_n())?;
    d.set_item("support_nodes", forces.iter().map(|f| f.0).collect::<Vec<_>>())?;
    let f: Vec<f64> = forces.iter().flat_map(|f| f.1).collect();
    d.set_item("support_forces_n", array2(py, f, forces.len(), 3)?)?;
    Ok(d)
}

/// A Newton solve's report in `d`: `iterations`, `residual_n`, `tolerance_n` [N], `residual_history_n`.
pub(crate) fn report_into(d: &Bound<'_, PyDict>, report: StaticReport) -> PyResult<()> {
    d.set_item("iterations", report.iterations)?;
    d.set_item("residual_n", report.residual_n)?;
    d.set_item("tolerance_n", report.tolerance_n)?;
    d.set_item("residual_history_n", array1(d.py(), report.residual_history))?;
    Ok(())
}
