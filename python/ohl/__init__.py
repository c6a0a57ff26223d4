"""ohl: dynamics of overhead power-line wires, from Python.

The package wraps the Rust library ``ohl`` (not the command line): a scenario (a TOML file, TOML text or
a dict with the same tables) is parsed, validated and planned by the library, run with the GIL released,
and its results come back as NumPy arrays holding exactly the numbers ``ohl run`` writes to
``timeseries.csv``, ``snapshots.csv`` and ``summary.json``. Everything is in SI units, temperatures in
kelvin. ``docs/python.md`` in the repository documents the API.

    >>> import ohl
    >>> r = ohl.run("paper_cases/fig3_wind_weight.toml")
    >>> r.t_s, r.mid_displacement_m[:, 2], r.max_tension_n      # [s], [m], [N]
    >>> ohl.ampacity(373.15, conductor="ACSR Drake", weather={...})["current_a"]   # [A]
    >>> line = ohl.run_line("cases/e_three_phases_wind.toml")   # several conductors ([line])
    >>> line["A"].max_tension_n, line.least_clearance["least_m"], line.tower_forces_n   # [N], [m], [N]
"""

from __future__ import annotations

import numbers
import os
from collections.abc import Mapping
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import _ohl
from ._errors import (
    Problem,
    ScenarioError,
    ScenarioWarning,
    StaticsError,
    ThermalError,
    UnstableError,
    WorkBudgetError,
)
from ._ohl import LineScenario, Scenario

__version__: str = _ohl.__version__

__all__ = [
    "ConductorResult",
    "LineResult",
    "LineScenario",
    "Problem",
    "RunResult",
    "Scenario",
    "ScenarioError",
    "ScenarioWarning",
    "Snapshots",
    "StaticsError",
    "ThermalError",
    "UnstableError",
    "WorkBudgetError",
    "ampacity",
    "conductor",
    "conductors",
    "converge",
    "deicing",
    "deicing_current",
    "equilibrium",
    "from_dict",
    "heat_terms",
    "line_equilibrium",
    "line_from_dict",
    "load",
    "load_line",
    "loads",
    "loads_line",
    "run",
    "run_line",
    "sagtension",
    "shortcircuit",
    "steady_temperature",
    "transient",
]

ScenarioLike = Union[Scenario, Mapping, str, "os.PathLike[str]"]
LineScenarioLike = Union[LineScenario, Mapping, str, "os.PathLike[str]"]


# --- scenarios ---------------------------------------------------------------------------------------


def load(path: Union[str, "os.PathLike[str]"]) -> Scenario:
    """Read, validate and plan a scenario file (TOML, SI units).

    Raises ``FileNotFoundError`` if the file does not exist and :class:`ScenarioError` if it is invalid
    (with ``file``, ``field``, ``value``, ``allowed``). Valid but doubtful values are issued as
    :class:`ScenarioWarning`.
    """
    return Scenario.from_file(path)


def loads(text: str, name: str = "<string>") -> Scenario:
    """A scenario from TOML text; ``name`` stands for the file name in messages."""
    return Scenario.from_toml(text, name)


def from_dict(
    d: Mapping, name: str = "<dict>", base_dir: Optional[Union[str, "os.PathLike[str]"]] = None
) -> Scenario:
    """A scenario from a dict with the tables and keys of a scenario file.

    Tables are nested dicts, ``events`` a list of dicts. A Python ``int`` is a TOML integer and a
    ``float`` a TOML float: a whole-number field (``segments``) needs an ``int``, a number field takes
    either (exactly as in a file). The dict is written as TOML (``Scenario.toml``) and read like a file,
    so a dict and the equivalent TOML text give bitwise the same run. Every error names the dict's field
    path (``geometry.segments``), as written in the dict.

    A relative ``thermal.conductor_catalog`` (a user catalogue of conductors) is taken relative to
    ``base_dir`` (default: the current working directory), as a file's is relative to the file's folder;
    ``Scenario.toml`` holds the path made absolute.
    """
    return Scenario.from_dict(d, name, base_dir)


def load_line(path: Union[str, "os.PathLike[str]"]) -> LineScenario:
    """Read, validate and plan a line scenario file (``[line]``: several conductors on shared towers).

    Raises ``FileNotFoundError`` if the file does not exist and :class:`ScenarioError` with the message
    ``ohl run`` prints if it is invalid (each field named under ``line.conductors[k]``); warnings are
    issued as :class:`ScenarioWarning`, ``NAME: message`` for conductor ``NAME``.
    """
    return LineScenario.from_file(path)


def loads_line(text: str, name: str = "<string>") -> LineScenario:
    """A line scenario from TOML text; ``name`` stands for the file name in messages."""
    return LineScenario.from_toml(text, name)


def line_from_dict(d: Mapping, name: str = "<dict>") -> LineScenario:
    """A line scenario from a dict with the tables and keys of a line file (``{"line": {"conductors":
    [...], "towers": [...]}, "duration": {...}, ...}``), read as :func:`from_dict` reads a scenario."""
    return LineScenario.from_dict(d, name)


def _as_scenario(source: ScenarioLike) -> Scenario:
    if isinstance(source, Scenario):
        return source
    if isinstance(source, Mapping):
        return from_dict(source)
    if isinstance(source, (str, os.PathLike)):
        return load(source)
    raise TypeError(
        f"argument `scenario` must be an ohl.Scenario, a dict or a path to a scenario file, not {type(source).__name__} "
        "(for TOML text use ohl.loads(text))"
    )


def _as_line_scenario(source: LineScenarioLike) -> LineScenario:
    if isinstance(source, LineScenario):
        return source
    if isinstance(source, Mapping):
        return line_from_dict(source)
    if isinstance(source, (str, os.PathLike)):
        return load_line(source)
    raise TypeError(
        f"argument `scenario` must be an ohl.LineScenario, a dict or a path to a line scenario file, not "
        f"{type(source).__name__} (for TOML text use ohl.loads_line(text))"
    )


# --- runs --------------------------------------------------------------------------------------------


class Snapshots:
    """The whole wire at the snapshot times and at the end (the rows of ``snapshots.csv``).

    ``k`` snapshots of ``N + 1`` nodes:

    Attributes:
        t_s: (k,) times [s] (the first time level at or after each requested time).
        tau: (k,) dimensionless times ``t U / l`` [-].
        s_m: (k, N+1) Lagrangian coordinate of each node (unstretched length from the first node) [m].
        x_m: (k, N+1, 3) node positions ``x1`` (across), ``x2`` (along), ``x3`` (up) [m].
        v_m_per_s: (k, N+1, 3) node velocities at the last half step [m/s].
        tension_n: (k, N+1) mean tension of the intact segments next to each node [N].
    """

    def __init__(self, raw: dict) -> None:
        self.t_s: np.ndarray = raw["snapshot_t_s"]
        self.tau: np.ndarray = raw["snapshot_tau"]
        self.s_m: np.ndarray = raw["snapshot_s_m"]
        self.x_m: np.ndarray = raw["snapshot_x_m"]
        self.v_m_per_s: np.ndarray = raw["snapshot_v_m_per_s"]
        self.tension_n: np.ndarray = raw["snapshot_tension_n"]

    def __len__(self) -> int:
        return len(self.t_s)

    def __repr__(self) -> str:
        nodes = self.x_m.shape[1] if self.x_m.ndim == 3 else 0
        return f"Snapshots({len(self)} times, {nodes} nodes)"


class _Series:
    """The time series and snapshots of one wire: a run's, or one conductor's of a line run."""

    def __init__(self, raw: dict, probes: Sequence[str], supports: int) -> None:
        self.columns: List[str] = list(raw["columns"])
        self.table: np.ndarray = raw["rows"]
        by_column = np.ascontiguousarray(self.table.T)
        self.timeseries: Dict[str, np.ndarray] = {c: by_column[k] for k, c in enumerate(self.columns)}
        self.snapshots = Snapshots(raw)
        self._probe_names: List[str] = list(probes)
        self._supports: int = supports

    def __getitem__(self, column: str) -> np.ndarray:
        """The column ``column`` of the time series (a name of ``timeseries.csv``)."""
        return self.timeseries[column]

    def _xyz(self, prefix: str, suffix: str) -> np.ndarray:
        return np.stack([self.timeseries[f"{prefix}{k}{suffix}"] for k in (1, 2, 3)], axis=1)

    @property
    def t_s(self) -> np.ndarray:
        """(rows,) time [s]."""
        return self.timeseries["t_s"]

    @property
    def tau(self) -> np.ndarray:
        """(rows,) dimensionless time ``tau = t U / l`` [-]."""
        return self.timeseries["tau"]

    @property
    def mid_displacement_m(self) -> np.ndarray:
        """(rows, 3) mid-span displacement from the chord midpoint, ``x1, x2, x3`` [m]; the sag is
        ``-mid_displacement_m[:, 2]``."""
        return self._xyz("mid_dx", "_m")

    @property
    def max_tension_n(self) -> np.ndarray:
        """(rows,) largest segment tension [N]."""
        return self.timeseries["max_tension_n"]

    @property
    def energies(self) -> Dict[str, np.ndarray]:
        """Kinetic, elastic, potential (gravity and uniform load) and total energy [J], (rows,) each."""
        return {k: self.timeseries[k] for k in ("kinetic_j", "elastic_j", "potential_j", "total_j")}

    @property
    def probes(self) -> Dict[str, np.ndarray]:
        """Probe name -> (rows, 3) displacement [m]: ``"mid"`` and the named probes of the scenario."""
        return {"mid": self.mid_displacement_m, **{p: self._xyz(f"{p}_dx", "_m") for p in self._probe_names[1:]}}

    @property
    def support_forces_n(self) -> np.ndarray:
        """(rows, supports, 3) force the wire applies to each support, ``F1`` across the line, ``F2`` along
        it, ``F3`` up [N] (supports in node order, as ``Scenario.supports``)."""
        n = self._supports
        if n == 0:
            return np.zeros((len(self.t_s), 0, 3))
        return np.stack([self._xyz(f"support{s}_f", "_n") for s in range(n)], axis=1)

    @property
    def temperature_k(self) -> Optional[np.ndarray]:
        """(rows,) conductor temperature [K] of a scenario with a ``[thermal]`` table, else None."""
        return self.timeseries.get("temperature_k")

    def to_pandas(self) -> Any:
        """The time series as a ``pandas.DataFrame`` (pandas is not a dependency of ohl)."""
        import pandas as pd

        return pd.DataFrame(self.timeseries, columns=self.columns)


class RunResult(_Series):
    """What a run produced: the time series, the snapshots, the summary and the events.

    The time series holds the columns of ``timeseries.csv`` (``columns``; one row per sample interval,
    at the first time level at or after each multiple of it), the same numbers bit for bit.

    Attributes:
        scenario: the :class:`Scenario` that ran.
        status: ``"completed"``, ``"settled"``, ``"not_settled"`` or ``"unstable"``.
        columns: the column names, in the order of ``timeseries.csv``.
        table: (rows, columns) array of the time series.
        timeseries: dict column name -> (rows,) array.
        snapshots: the :class:`Snapshots`.
        summary: the summary, a dict with the keys of ``summary.json``.
        events: the events applied, as (time [s], what) tuples.
        static: the residual static state after the run (``run(..., static_after=True)``), else None.
    """

    def __init__(self, raw: dict, scenario: Scenario) -> None:
        super().__init__(raw, scenario.probes, len(scenario.supports))
        self.scenario = scenario
        self.status: str = raw["status"]
        self.summary: Dict[str, Any] = raw["summary"]
        self.events: List[Tuple[float, str]] = list(raw["events"])
        self.static: Optional[Dict[str, Any]] = raw.get("static")

    def __repr__(self) -> str:
        return (
            f"RunResult(name={self.summary.get('name')!r}, status={self.status!r}, "
            f"rows={len(self.t_s)}, columns={len(self.columns)}, snapshots={len(self.snapshots)})"
        )


class ConductorResult(_Series):
    """One conductor of a line run: its time series and snapshots, as a single run's (the numbers of its
    ``conductors/NAME/timeseries.csv`` and ``snapshots.csv``), and its entry of the line's summary.

    Attributes:
        name: the conductor's name (a bundle's sub-conductors are ``NAME.1``, ``NAME.2``, ...).
        role: ``"phase"``, ``"earth_wire"`` or ``"sub_conductor"``.
        columns, table, timeseries, snapshots: as :class:`RunResult`'s; ``support_forces_n`` holds the
            supports its own wire holds (a support on a tower is the tower's: ``LineResult.tower_forces_n``).
        summary: its entry of ``summary.json``'s ``conductors`` (peak tension, mid-span peaks).
    """

    def __init__(self, raw: dict, summary: Dict[str, Any], probes: Sequence[str], supports: int) -> None:
        super().__init__(raw, probes, supports)
        self.name: str = raw["name"]
        self.role: str = summary["role"]
        self.summary: Dict[str, Any] = summary

    def __repr__(self) -> str:
        return f"ConductorResult(name={self.name!r}, role={self.role!r}, rows={len(self.t_s)}, snapshots={len(self.snapshots)})"


class LineResult:
    """What a line run produced: each conductor's results, the clearances and the tower loads.

    The clearances and the tower loads are sampled as ``clearances.csv`` and ``towers.csv`` (one row per
    sample interval, the same numbers bit for bit); the least distances and peak loads of ``summary`` are
    tracked at every time level.

    Attributes:
        scenario: the :class:`LineScenario` that ran.
        status: ``"completed"``, ``"settled"``, ``"not_settled"`` or ``"unstable"``.
        conductors: dict conductor name -> :class:`ConductorResult`, in the line's order.
        t_s: (rows,) sample times of the clearances and tower loads [s].
        clearance_pairs: the pairs of conductor groups (phases, earth wires, bundles), in column order.
        clearances_m: (rows, pairs) least distance of each pair [m] (NaN where none can be measured).
        towers: the towers' names.
        tower_forces_n: (rows, towers, 3) resultant of every attachment on each tower, ``F1, F2, F3`` [N].
        tower_displacements_m: (rows, towers, 2) horizontal displacement ``u1, u2`` of an elastic top [m].
        summary: the line's summary, a dict with the keys of ``summary.json``.
        events: the events applied, as (time [s], conductor, what) tuples.
    """

    def __init__(self, raw: dict, scenario: "LineScenario") -> None:
        self.scenario = scenario
        self.status: str = raw["status"]
        self.summary: Dict[str, Any] = raw["summary"]
        probes = scenario.probes
        supports = scenario.supports
        by_name = {c["name"]: c for c in self.summary["conductors"]}
        self.conductors: Dict[str, ConductorResult] = {
            c["name"]: ConductorResult(c, by_name[c["name"]], probes[c["name"]], len(supports[c["name"]])) for c in raw["conductors"]
        }
        self.t_s: np.ndarray = raw["sample_t_s"]
        self.clearance_pairs: List[Tuple[str, str]] = [tuple(p) for p in raw["clearance_pairs"]]
        self.clearances_m: np.ndarray = raw["clearance_m"]
        self.towers: List[str] = list(raw["towers"])
        self.tower_forces_n: np.ndarray = raw["tower_force_n"]
        self.tower_displacements_m: np.ndarray = raw["tower_displacement_m"]
        self.events: List[Tuple[float, str, str]] = [(e["time_s"], e["conductor"], e["what"]) for e in self.summary["events"]]

    def __getitem__(self, conductor: str) -> ConductorResult:
        """The results of the conductor ``conductor`` (a name of ``LineScenario.conductors``)."""
        return self.conductors[conductor]

    def clearance_m(self, a: str, b: str) -> np.ndarray:
        """(rows,) least distance between the groups ``a`` and ``b`` (in either order) [m]."""
        for k, p in enumerate(self.clearance_pairs):
            if p == (a, b) or p == (b, a):
                return self.clearances_m[:, k]
        raise KeyError(f"no clearance between {a!r} and {b!r}: the pairs are {self.clearance_pairs}")

    @property
    def least_clearance(self) -> Optional[Dict[str, Any]]:
        """The least distance between any two groups over the run (tracked at every time level), as its
        entry of ``summary["clearances"]``: ``least_m`` [m], ``time_s`` [s], ``between`` (the two groups),
        ``conductors`` and ``at_fraction`` (where on each, as a fraction of its unstretched length),
        ``points_m``, ``initial_m``, ``final_m``; None for a line of one group."""
        pairs = self.summary["clearances"]
        return min(pairs, key=lambda p: p["least_m"]) if pairs else None

    def __repr__(self) -> str:
        return (
            f"LineResult(name={self.summary.get('name')!r}, status={self.status!r}, "
            f"conductors={list(self.conductors)}, rows={len(self.t_s)})"
        )


def run(
    scenario: ScenarioLike,
    *,
    out_dir: Optional[Union[str, "os.PathLike[str]"]] = None,
    allow_large: bool = False,
    static_after: bool = False,
) -> RunResult:
    """Run a scenario to its end and return its :class:`RunResult`.

    ``scenario`` is an :class:`ohl.Scenario`, a dict (:func:`from_dict`) or the path of a scenario file
    (:func:`load`); an :class:`ohl.LineScenario` is run by :func:`run_line`. The run releases the GIL, so runs in threads (``concurrent.futures``, Dask's threaded
    scheduler) run in parallel. With ``out_dir`` it also writes ``timeseries.csv``, ``snapshots.csv``
    and ``summary.json`` there, as ``ohl run --out`` does.

    With ``static_after`` (as ``ohl run --static-after``) the residual static state of the run's final
    configuration is solved after the run (Newton; broken pieces hang to the ground and lie on it) and
    returned as ``RunResult.static``, a dict with the keys of ``static.json`` (``supports``, ``spans``,
    ``ground_reaction_n``, ``iterations``, ...) and the solved wire as :func:`equilibrium` gives it
    (``x_m``, ``support_forces_n``, ...); with ``out_dir`` it also writes ``static.json``.

    Raises :class:`WorkBudgetError` above the work budget unless ``allow_large`` (as ``ohl run
    --allow-large``), :class:`UnstableError` (with the result so far in ``.result``) if the scheme goes
    unstable, :class:`StaticsError` if the static solve of ``static_after`` fails, ``KeyboardInterrupt``
    on Ctrl-C.
    """
    if isinstance(scenario, LineScenario):
        if static_after:
            raise ValueError("static_after is not available for a line scenario yet (a single conductor or a section only)")
        return run_line(scenario, out_dir=out_dir, allow_large=allow_large)
    sc = _as_scenario(scenario)
    raw = _ohl.run_raw(sc, out_dir, allow_large, static_after)
    result = RunResult(raw, sc)
    u = raw["instability"]
    if u is not None:
        raise UnstableError(u["message"], u["time_s"], u["node"], u["reason"], result)
    return result


def run_line(
    scenario: LineScenarioLike,
    *,
    out_dir: Optional[Union[str, "os.PathLike[str]"]] = None,
    allow_large: bool = False,
) -> LineResult:
    """Run a line scenario to its end and return its :class:`LineResult`.

    ``scenario`` is an :class:`ohl.LineScenario`, a dict (:func:`line_from_dict`) or the path of a line
    scenario file (:func:`load_line`). The run releases the GIL. With ``out_dir`` it also writes the files
    of ``ohl run --out`` (``summary.json``, ``clearances.csv``, ``towers.csv`` and
    ``conductors/NAME/``).

    Raises :class:`WorkBudgetError` above the work budget unless ``allow_large``, :class:`UnstableError`
    (with the result so far in ``.result`` and the conductor in ``.conductor``) if the scheme goes
    unstable, ``KeyboardInterrupt`` on Ctrl-C.
    """
    sc = _as_line_scenario(scenario)
    raw = _ohl.run_line_raw(sc, out_dir, allow_large)
    result = LineResult(raw, sc)
    u = raw["instability"]
    if u is not None:
        raise UnstableError(u["message"], u["time_s"], u["node"], u["reason"], result, u["conductor"])
    return result


def equilibrium(scenario: ScenarioLike, *, tolerance_n: Optional[float] = None, max_iterations: int = 100) -> Dict[str, Any]:
    """The static equilibrium of the scenario's line under its loads at ``t = 0`` (before any event).

    Newton's method on the scheme's own discrete equations at rest, with the exact Jacobian, from the
    scenario's initial shape (the library's ``statics::solve``; ``tolerance_n`` [N] on the largest nodal
    residual, default ``1e-10`` of the largest nodal load; None or a finite number > 0) in at most
    ``max_iterations`` (an int in [0, 10000]). Raises :class:`StaticsError` if it does not converge.
    Returns a dict:

    - ``x_m`` (N+1, 3) node positions [m]; ``s_m`` (N+1,) Lagrangian coordinate [m];
    - ``segment_tension_n`` (N,) and ``node_tension_n`` (N+1,) tensions [N] (a node's is the mean of its
      intact segments', as in ``snapshots.csv``); ``max_tension_n`` [N];
    - ``midspan_displacement_m`` [x1, x2, x3] from the chord midpoint [m];
    - ``support_nodes`` and ``support_forces_n`` (supports, 3): the force the wire applies to each
      support [N];
    - ``iterations``, ``residual_n``, ``tolerance_n`` [N], ``residual_history_n``.
    """
    if isinstance(scenario, LineScenario):
        return line_equilibrium(scenario, tolerance_n=tolerance_n, max_iterations=max_iterations)
    return _ohl.equilibrium(_as_scenario(scenario), tolerance_n, max_iterations)


def line_equilibrium(
    scenario: LineScenarioLike, *, tolerance_n: Optional[float] = None, max_iterations: int = 100
) -> Dict[str, Any]:
    """The static equilibrium of the whole line under its loads at ``t = 0`` (before any event): spacers,
    strings, towers and elastic tower tops included.

    Newton's method on the line's own discrete equations at rest (the library's ``statics::solve_line``,
    the solve of ``[initial] shape = "equilibrium"``) from the scenario's initial state. Raises
    :class:`StaticsError` if it does not converge. Returns a dict:

    - ``conductors``: conductor name -> the dict :func:`equilibrium` gives for one wire (``x_m``, ``s_m``,
      ``segment_tension_n``, ``node_tension_n``, ``max_tension_n``, ``midspan_displacement_m``,
      ``support_nodes`` and ``support_forces_n`` of its own supports);
    - ``towers``, ``tower_forces_n`` (towers, 3): the resultant of every attachment on each tower [N], and
      ``tower_displacements_m`` (towers, 3) of the elastic tops [m];
    - ``iterations``, ``residual_n``, ``tolerance_n`` [N], ``residual_history_n``.
    """
    return _ohl.line_equilibrium(_as_line_scenario(scenario), tolerance_n, max_iterations)


# --- sag-tension -------------------------------------------------------------------------------------


def shortcircuit(path: Union[str, "os.PathLike[str]"]) -> Dict[str, Any]:
    """A line scenario with ``[short_circuit]`` by the IEC 60865-1 simplified method and by the dynamic
    run of the same line, side by side (the numbers of ``ohl shortcircuit``, docs/short_circuit.md);
    nothing is written.

    Returns the dict of ``shortcircuit.json``: ``main`` (the conductor compared), ``iec_input`` (the
    standard's input read off the line, or ``{"refused": why}``), ``iec_refusal`` (why the method
    refused, or ``None``), ``rows`` (one dict per quantity: ``quantity``, ``symbol``, ``equation``,
    ``unit``, ``iec``, ``dynamic``, ``difference``; ``None`` where a value does not exist) and
    ``dynamic`` (the run's ``short_circuit`` block of ``summary.json``: F_t, F_f, F_pi per phase and
    end with their times, b_h, a_min).

    Raises :class:`ScenarioError` for invalid input, ``ValueError`` without ``[short_circuit]`` and
    ``RuntimeError`` if the run goes unstable.
    """
    import json

    return json.loads(_ohl.shortcircuit_raw(path))


def converge(
    path: Union[str, "os.PathLike[str]"],
    out: Union[str, "os.PathLike[str]"],
    *,
    refine: str = "grid",
    levels: int = 3,
    ratio: int = 2,
    coarsen: bool = False,
    scaled_smoothing: bool = False,
    rtol: float = 0.01,
    budget: float = 2e10,
) -> Dict[str, Any]:
    """Error bars on a scenario's own numbers: the study of ``ohl run PATH --out OUT --converge``
    (docs/convergence.md), for a single conductor, a section or a line. The scenario runs on ``levels`` levels refined by ``ratio`` (``refine="grid"``:
    segments of every span, the step following at the Courant number; ``"step"``: the step alone), the
    written scenario the coarsest (the finest with ``coarsen=True``); every scalar of its summary gets
    Celik's observed order, the Richardson extrapolate and the GCI (F_s = 1.25) from the three finest
    levels, and a verdict against ``rtol``. The finest level's files are written to ``out``, the others
    under ``out/levels/``, and ``out/convergence.json``.

    Returns the dict of ``convergence.json``: ``options``, ``levels`` (segments, step, steps, estimated
    work, wall time, output directory per level, coarse to fine), ``cost_relative_to_one_run`` and
    ``quantities``, one dict each: ``path`` (as in ``summary.json``), ``values`` (coarse to fine),
    ``estimate`` (``behaviour``, ``order``, ``extrapolate``, ``gci_fine``, ``gci_fine_abs``, ... or None)
    and ``verdict`` ("converged within rtol", "not within rtol", "oscillatory", "divergent", "peak moves
    between events", "indeterminate", "constant", "constant to rounding", "zero to rounding", "unpaired").

    Raises :class:`ScenarioError` for invalid input, :class:`WorkBudgetError` when the finest level is
    above ``budget`` node-steps, ``ValueError`` for bad options or a level that is no valid scenario, and
    ``RuntimeError`` when a level goes unstable.
    """
    import json

    return json.loads(
        _ohl.converge_raw(path, out, refine, levels, ratio, coarsen, scaled_smoothing, rtol, budget)
    )


def sagtension(
    case: Union[Mapping, str, "os.PathLike[str]"], *, name: str = "<dict>"
) -> Dict[str, Any]:
    """The sag-tension table of a case (the file of ``ohl sagtension``, docs/sagtension_cases.md): a path
    to the TOML file, or a dict with its tables (``name`` stands for the file in messages).

    Returns a dict: ``name``, ``conductor``, ``law`` (``"two_material"`` or ``"single_modulus"``),
    ``spans_m``, ``span_m`` (the ruling span of a section), ``states`` (the states of the table, in
    order), ``final_is`` (the state ``final`` stands for), ``knee_temperature_k`` and
    ``sag_limit_temperature_k`` (state -> K, ``None`` where there is none), ``sag_limit_m``, ``labels``
    (one per condition) and ``rows``: columns of one entry per condition and state (conditions in the
    case's order, each with every state), named as ``sagtension.csv``'s, NumPy arrays of floats
    (``knee_passed`` of bools, ``condition`` of ints) and lists of str (``state``, ``history_of``);
    ``temperature_k`` is in kelvin where the CSV has ``temperature_c``; ``span_sags_m`` (rows, spans) holds
    the mid-span sag of each span (a section's spans each at the ruling span's horizontal tension).

    Raises :class:`ScenarioError` for invalid input (file, field, value, allowed) and
    :class:`StaticsError` if the solver finds no solution.
    """
    raw = _ohl.sagtension_raw(case, name)
    rows = raw["rows"]
    for key, value in list(rows.items()):
        if key in ("state", "history_of", "span_sags_m"):
            continue
        if key == "knee_passed":
            rows[key] = np.asarray(value, dtype=bool)
        elif key == "condition":
            rows[key] = np.asarray(value, dtype=np.int64)
        else:
            rows[key] = np.asarray(value, dtype=np.float64)
    return raw


# --- thermal -----------------------------------------------------------------------------------------


def conductors() -> List[str]:
    """The names of the conductors in the catalogue (``data/conductors.toml``)."""
    return _ohl.conductors()


def conductor(name: str) -> Dict[str, Any]:
    """A catalogue conductor by name or alias (case-insensitive), every field in SI units and kelvin."""
    return _ohl.conductor(name)


def _argument_error(param: str, value: str, allowed: str) -> ScenarioError:
    """The error of an argument's value, as the library words a field's (file ``<arguments>``)."""
    message = f"<arguments>: field `{param}` = {value} is not allowed: {allowed}"
    return ScenarioError(message, "<arguments>", param, value, allowed, [(param, value, allowed)])


def _floats(param: str, x: Any) -> np.ndarray:
    """The argument ``param``, a number or an array of numbers (ints, floats, NumPy numbers), as a float64
    array of its shape. Anything else (a str, a bool, None, a ragged nesting) raises ``TypeError`` naming
    the argument; an int beyond the range of a float :class:`ScenarioError`. NaN and infinities pass: the
    library's range checks name them."""
    wrong = TypeError(f"argument `{param}` must be a number or an array of numbers, not {type(x).__name__}")
    if isinstance(x, (str, bytes, bool, np.bool_)):
        raise wrong
    try:
        a = np.asarray(x)
    except (TypeError, ValueError):  # a ragged nesting
        raise wrong from None
    if a.dtype.kind in "iuf":
        return a.astype(np.float64)
    if a.dtype.kind != "O" or not all(isinstance(v, numbers.Real) and not isinstance(v, (bool, np.bool_)) for v in a.flat):
        raise wrong
    for v in a.flat:  # ints beyond 64 bits
        try:
            float(v)
        except OverflowError:
            text = str(v) if len(str(v)) <= 60 else f"{str(v)[:57]}..."
            raise _argument_error(param, text, "must be numbers within the range of a float (|x| < 1.8e308)") from None
    return a.astype(np.float64)


def _vector(param: str, x: Any) -> Tuple[List[float], bool, Tuple[int, ...]]:
    a = _floats(param, x)
    return a.ravel().tolist(), a.ndim == 0, a.shape


def _shaped(d: Dict[str, Any], scalar: bool, shape: Tuple[int, ...]) -> Dict[str, Any]:
    out = {}
    for k, v in d.items():
        if isinstance(v, np.ndarray):
            v = float(v[0]) if scalar else v.reshape(shape)
        out[k] = v
    return out


def heat_terms(
    temperature_k: Any, current_a: Any, *, conductor: str, weather: Mapping, standard: str = "ieee738"
) -> Dict[str, Any]:
    """The heat-balance terms [W/m] at conductor temperature(s) ``temperature_k`` [K] and current(s)
    ``current_a`` [A] (broadcast together): ``joule_w_per_m``, ``solar_w_per_m``,
    ``convection_w_per_m``, ``radiation_w_per_m``.

    ``conductor`` is a catalogue name (:func:`conductors`); ``weather`` a dict with the keys of a
    ``[weather]`` table: ``air_temperature_k`` [K], ``wind_speed_m_per_s`` [m/s], ``wind_angle_deg``
    [deg, 90 = across the line], ``elevation_m`` [m], and ``sun`` (a dict: ``latitude_deg``,
    ``day_of_year``, ``solar_hour``, ``line_azimuth_deg``, ``atmosphere``, ...; omit for a night);
    ``standard`` is ``"ieee738"`` (IEEE Std 738-2012) or ``"cigre601"`` (CIGRE TB 601).
    """
    t, i = _floats("temperature_k", temperature_k), _floats("current_a", current_a)
    try:
        t, i = np.broadcast_arrays(t, i)
    except ValueError:
        raise _argument_error(
            "current_a", f"an array of shape {i.shape}", f"must broadcast with temperature_k's shape {t.shape}"
        ) from None
    scalar = t.ndim == 0
    d = _ohl.heat_terms(t.ravel().tolist(), i.ravel().tolist(), conductor, weather, standard, scalar)
    return _shaped(d, scalar, t.shape)


def steady_temperature(current_a: Any, *, conductor: str, weather: Mapping, standard: str = "ieee738") -> Dict[str, Any]:
    """The steady conductor temperature for a current (or an array of currents) [A].

    Returns ``temperature_k`` [K] and the terms there [W/m] (``joule_w_per_m``, ``solar_w_per_m``,
    ``convection_w_per_m``, ``radiation_w_per_m``): floats for a scalar current, arrays of its shape
    otherwise. Raises :class:`ThermalError` where there is no steady state (thermal runaway). Arguments
    as :func:`heat_terms`.
    """
    v, scalar, shape = _vector("current_a", current_a)
    return _shaped(_ohl.steady_temperature(v, conductor, weather, standard, scalar), scalar, shape)


def ampacity(max_temperature_k: Any, *, conductor: str, weather: Mapping, standard: str = "ieee738") -> Dict[str, Any]:
    """The steady ampacity ``current_a`` [A] for a maximum conductor temperature (or an array) [K], with
    the terms there [W/m]. Raises :class:`ThermalError` if the sun alone heats the conductor above it.
    Arguments as :func:`heat_terms`."""
    v, scalar, shape = _vector("max_temperature_k", max_temperature_k)
    return _shaped(_ohl.ampacity(v, conductor, weather, standard, scalar), scalar, shape)


def transient(
    current_a: Any,
    end_time_s: float,
    *,
    conductor: str,
    weather: Mapping,
    standard: str = "ieee738",
    initial_temperature_k: Optional[float] = None,
    step_s: float = 1.0,
    limit_k: Optional[float] = None,
) -> Dict[str, Any]:
    """The conductor temperature in time for a current schedule (RK4, as ``ohl thermal``'s transient).

    ``current_a`` is a list of ``(t [s], I [A])`` points, piecewise linear, a step where two points share
    a time (``[(0, 800), (0, 1200)]``: a step from 800 to 1200 A at ``t = 0``), or one current [A]. The
    start is ``initial_temperature_k`` [K], by default the steady state of the first point's current.
    ``step_s`` is the longest RK4 step [s]. Returns ``t_s``, ``current_a`` and ``temperature_k`` arrays,
    ``initial_temperature_k``, ``final_temperature_k``, and with ``limit_k`` [K] the time it is first
    reached, ``time_to_limit_s`` [s] (None if not within ``end_time_s``).
    """
    a = _floats("current_a", current_a)
    if a.ndim == 0:
        points = [[0.0, float(a)]]
    elif a.shape == (2,) or (a.ndim == 2 and a.shape[1] == 2):
        points = a.reshape(-1, 2).tolist()
    else:
        raise _argument_error(
            "current_a", f"an array of shape {a.shape}", "must be one current [A] or a list of (t [s], I [A]) points, shape (n, 2)"
        )
    return _ohl.transient(points, end_time_s, conductor, weather, standard, initial_temperature_k, step_s, limit_k)


def deicing(
    thickness_m: float,
    current_a: float,
    *,
    conductor: str,
    weather: Mapping,
    standard: str = "ieee738",
    density_kg_per_m3: float = 900.0,
    criterion: str = "slot",
    step_s: float = 1.0,
    record_every_s: float = 10.0,
) -> Dict[str, Any]:
    """De-icing of a radial ice shell ``thickness_m`` [m] by a current ``current_a`` [A]: warming to 0 C,
    melting, and the time to shed (``criterion`` ``"slot"`` or ``"full_melt"``).

    Returns ``melting_from_s``, ``shed_time_s`` [s], ``minimum_current_a`` (the least current that melts)
    [A], ``ice_kg_per_m``, ``shed_kg_per_m``, the energy budget ``energy_j_per_m`` [J/m], and series
    every ``record_every_s`` [s]: ``t_s``, ``conductor_k``, ``surface_k``, ``melted_kg_per_m``,
    ``joule_w_per_m``, ``loss_w_per_m``. Raises :class:`ThermalError` if the ice does not shed.
    """
    return _ohl.deicing(thickness_m, current_a, conductor, weather, standard, density_kg_per_m3, criterion, step_s, record_every_s)


def deicing_current(
    thickness_m: float,
    shed_within_s: float,
    *,
    conductor: str,
    weather: Mapping,
    standard: str = "ieee738",
    density_kg_per_m3: float = 900.0,
    criterion: str = "slot",
    step_s: float = 1.0,
) -> float:
    """The least current [A] that sheds an ice shell ``thickness_m`` [m] within ``shed_within_s`` [s]."""
    return _ohl.deicing_current(thickness_m, shed_within_s, conductor, weather, standard, density_kg_per_m3, criterion, step_s)
