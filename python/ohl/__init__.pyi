"""Type stubs of the ``ohl`` package (SI units, temperatures in kelvin)."""

import os
from collections.abc import Mapping
from typing import Any, Dict, List, NamedTuple, Optional, Sequence, Tuple, TypedDict, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str

FloatArray = npt.NDArray[np.float64]
PathLike = Union[str, "os.PathLike[str]"]
ArrayLike = Union[float, Sequence[float], npt.NDArray[Any]]

# --- errors ------------------------------------------------------------------------------------------

class Problem(NamedTuple):
    field: str
    value: str
    allowed: str

class ScenarioError(ValueError):
    """Invalid scenario or argument; ``str(e)`` is the message ``ohl run`` prints after ``error: ``."""

    file: Optional[str]
    field: Optional[str]
    value: Optional[str]
    allowed: Optional[str]
    problems: List[Problem]
    def __init__(
        self,
        message: str,
        file: Optional[str] = ...,
        field: Optional[str] = ...,
        value: Optional[str] = ...,
        allowed: Optional[str] = ...,
        problems: Any = ...,
    ) -> None: ...

class WorkBudgetError(ValueError):
    """Above the work budget (2e10 node-steps or 2 GB of output); ``run(..., allow_large=True)`` runs it."""

    estimate: Optional[Dict[str, Any]]
    def __init__(self, message: str, estimate: Optional[Dict[str, Any]] = ...) -> None: ...

class UnstableError(RuntimeError):
    """The scheme went unstable at ``time_s`` [s], ``node`` (of ``conductor`` in a line); ``result`` holds
    the run up to then."""

    time_s: float
    node: int
    reason: str
    result: Union[RunResult, LineResult]
    conductor: Optional[str]
    def __init__(
        self,
        message: str,
        time_s: float = ...,
        node: int = ...,
        reason: str = ...,
        result: Any = ...,
        conductor: Optional[str] = ...,
    ) -> None: ...

class StaticsError(RuntimeError): ...
class ThermalError(RuntimeError): ...
class ScenarioWarning(UserWarning): ...

# --- scenarios ---------------------------------------------------------------------------------------

class Scenario:
    """A scenario, parsed, validated and planned: ready to run."""

    @staticmethod
    def from_file(path: PathLike) -> Scenario: ...
    @staticmethod
    def from_toml(text: str, name: str = "<string>") -> Scenario: ...
    @staticmethod
    def from_dict(d: Mapping[str, Any], name: str = "<dict>", base_dir: Optional[PathLike] = None) -> Scenario: ...
    @property
    def name(self) -> str: ...
    @property
    def file(self) -> str: ...
    @property
    def toml(self) -> str: ...
    @property
    def segments(self) -> int: ...
    @property
    def dt_s(self) -> float:
        """Nominal time step [s]."""
    @property
    def courant(self) -> float: ...
    @property
    def wave_speed_m_per_s(self) -> float: ...
    @property
    def chord_m(self) -> float: ...
    @property
    def end_time_s(self) -> float:
        """End time, or the time cap of a run until settled [s]."""
    @property
    def sample_interval_s(self) -> float: ...
    @property
    def snapshot_times_s(self) -> List[float]: ...
    @property
    def supports(self) -> List[Tuple[int, List[float]]]:
        """(node, position [m]) of each support, in node order."""
    @property
    def probes(self) -> List[str]:
        """"mid" and the named probes."""
    @property
    def columns(self) -> List[str]:
        """The columns of the time series (``timeseries.csv``)."""
    @property
    def warnings(self) -> List[str]: ...
    @property
    def initial_equilibrium(self) -> Optional[Dict[str, Any]]: ...
    def work_estimate(self) -> Dict[str, Any]: ...

class LineScenario:
    """A line scenario (``[line]``: several conductors), parsed, validated and planned: ready to run."""

    @staticmethod
    def from_file(path: PathLike) -> LineScenario: ...
    @staticmethod
    def from_toml(text: str, name: str = "<string>") -> LineScenario: ...
    @staticmethod
    def from_dict(d: Mapping[str, Any], name: str = "<dict>") -> LineScenario: ...
    @property
    def name(self) -> str: ...
    @property
    def file(self) -> str: ...
    @property
    def toml(self) -> str: ...
    @property
    def conductors(self) -> List[str]:
        """The line's conductors; a bundle's sub-conductors are ``NAME.1``, ``NAME.2``, ..."""
    @property
    def roles(self) -> List[str]:
        """"phase", "earth_wire" or "sub_conductor", per conductor."""
    @property
    def groups(self) -> Dict[str, List[str]]:
        """Declared conductor (phase, earth wire, bundle) -> the line's conductors it is made of."""
    @property
    def clearance_pairs(self) -> List[Tuple[str, str]]: ...
    @property
    def towers(self) -> List[str]: ...
    @property
    def segments(self) -> Dict[str, int]: ...
    @property
    def supports(self) -> Dict[str, List[Tuple[int, List[float]]]]:
        """Conductor -> (node, position [m]) of each of its own supports."""
    @property
    def probes(self) -> Dict[str, List[str]]: ...
    @property
    def columns(self) -> Dict[str, List[str]]:
        """Conductor -> the columns of its time series (``conductors/NAME/timeseries.csv``)."""
    @property
    def dt_s(self) -> float:
        """The line's time step [s]."""
    @property
    def end_time_s(self) -> float: ...
    @property
    def sample_interval_s(self) -> float: ...
    @property
    def snapshot_times_s(self) -> List[float]: ...
    @property
    def warnings(self) -> List[str]: ...
    @property
    def initial_equilibrium(self) -> Optional[Dict[str, Any]]: ...
    def work_estimate(self) -> Dict[str, Any]: ...

ScenarioLike = Union[Scenario, Mapping[str, Any], PathLike]
LineScenarioLike = Union[LineScenario, Mapping[str, Any], PathLike]

def load(path: PathLike) -> Scenario: ...
def loads(text: str, name: str = "<string>") -> Scenario: ...
def from_dict(d: Mapping[str, Any], name: str = "<dict>", base_dir: Optional[PathLike] = None) -> Scenario: ...
def load_line(path: PathLike) -> LineScenario: ...
def loads_line(text: str, name: str = "<string>") -> LineScenario: ...
def line_from_dict(d: Mapping[str, Any], name: str = "<dict>") -> LineScenario: ...

# --- runs --------------------------------------------------------------------------------------------

class Snapshots:
    """k snapshots of N + 1 nodes."""

    t_s: FloatArray  # (k,) [s]
    tau: FloatArray  # (k,) [-]
    s_m: FloatArray  # (k, N+1) Lagrangian coordinate [m]
    x_m: FloatArray  # (k, N+1, 3) positions [m]
    v_m_per_s: FloatArray  # (k, N+1, 3) velocities [m/s]
    tension_n: FloatArray  # (k, N+1) node tension [N]
    def __len__(self) -> int: ...

class _Series:
    """The time series and snapshots of one wire."""

    columns: List[str]
    table: FloatArray  # (rows, columns)
    timeseries: Dict[str, FloatArray]
    snapshots: Snapshots
    def __getitem__(self, column: str) -> FloatArray: ...
    @property
    def t_s(self) -> FloatArray:
        """(rows,) time [s]."""
    @property
    def tau(self) -> FloatArray: ...
    @property
    def mid_displacement_m(self) -> FloatArray:
        """(rows, 3) mid-span displacement from the chord midpoint [m]."""
    @property
    def max_tension_n(self) -> FloatArray:
        """(rows,) largest segment tension [N]."""
    @property
    def energies(self) -> Dict[str, FloatArray]:
        """kinetic_j, elastic_j, potential_j, total_j [J]."""
    @property
    def probes(self) -> Dict[str, FloatArray]:
        """Probe name -> (rows, 3) displacement [m]."""
    @property
    def support_forces_n(self) -> FloatArray:
        """(rows, supports, 3) force of the wire on each support [N]."""
    @property
    def temperature_k(self) -> Optional[FloatArray]:
        """(rows,) conductor temperature [K], with a [thermal] table."""
    def to_pandas(self) -> Any: ...

class RunResult(_Series):
    scenario: Scenario
    status: str
    summary: Dict[str, Any]
    events: List[Tuple[float, str]]
    static: Optional[Dict[str, Any]]  # run(..., static_after=True): the residual static state (static.json's keys)

class ConductorResult(_Series):
    """One conductor of a line run."""

    name: str
    role: str
    summary: Dict[str, Any]  # its entry of summary.json's "conductors"

class LineResult:
    scenario: LineScenario
    status: str
    summary: Dict[str, Any]
    conductors: Dict[str, ConductorResult]
    t_s: FloatArray  # (rows,) sample times [s]
    clearance_pairs: List[Tuple[str, str]]
    clearances_m: FloatArray  # (rows, pairs) [m]
    towers: List[str]
    tower_forces_n: FloatArray  # (rows, towers, 3) [N]
    tower_displacements_m: FloatArray  # (rows, towers, 2) [m]
    events: List[Tuple[float, str, str]]  # (time [s], conductor, what)
    def __getitem__(self, conductor: str) -> ConductorResult: ...
    def clearance_m(self, a: str, b: str) -> FloatArray:
        """(rows,) least distance between two groups [m]."""
    @property
    def least_clearance(self) -> Optional[Dict[str, Any]]:
        """The least distance over the run (least_m, time_s, between, conductors, at_fraction, points_m)."""

@overload
def run(scenario: LineScenario, *, out_dir: Optional[PathLike] = None, allow_large: bool = False) -> LineResult: ...
@overload
def run(
    scenario: ScenarioLike, *, out_dir: Optional[PathLike] = None, allow_large: bool = False, static_after: bool = False
) -> RunResult: ...
def run_line(scenario: LineScenarioLike, *, out_dir: Optional[PathLike] = None, allow_large: bool = False) -> LineResult: ...

class WireState(TypedDict):
    x_m: FloatArray  # (N+1, 3) [m]
    s_m: FloatArray  # (N+1,) [m]
    segment_tension_n: FloatArray  # (N,) [N]
    node_tension_n: FloatArray  # (N+1,) [N]
    max_tension_n: float
    midspan_displacement_m: List[float]
    support_nodes: List[int]
    support_forces_n: FloatArray  # (supports, 3) [N]

class Equilibrium(WireState):
    iterations: int
    residual_n: float
    tolerance_n: float
    residual_history_n: FloatArray

class LineEquilibrium(TypedDict):
    conductors: Dict[str, WireState]
    towers: List[str]
    tower_forces_n: FloatArray  # (towers, 3) [N]
    tower_displacements_m: FloatArray  # (towers, 3) [m]
    iterations: int
    residual_n: float
    tolerance_n: float
    residual_history_n: FloatArray

@overload
def equilibrium(scenario: LineScenario, *, tolerance_n: Optional[float] = None, max_iterations: int = 100) -> LineEquilibrium: ...
@overload
def equilibrium(scenario: ScenarioLike, *, tolerance_n: Optional[float] = None, max_iterations: int = 100) -> Equilibrium: ...
def line_equilibrium(
    scenario: LineScenarioLike, *, tolerance_n: Optional[float] = None, max_iterations: int = 100
) -> LineEquilibrium: ...

# --- sag-tension -------------------------------------------------------------------------------------

def shortcircuit(path: Union[str, os.PathLike[str]]) -> Dict[str, Any]: ...
def converge(
    path: Union[str, os.PathLike[str]],
    out: Union[str, os.PathLike[str]],
    *,
    refine: str = ...,
    levels: int = ...,
    ratio: int = ...,
    coarsen: bool = ...,
    scaled_smoothing: bool = ...,
    rtol: float = ...,
    budget: float = ...,
) -> Dict[str, Any]: ...
def sagtension(case: Union[Mapping, str, os.PathLike[str]], *, name: str = "<dict>") -> Dict[str, Any]: ...

# --- thermal -----------------------------------------------------------------------------------------

def conductors() -> List[str]: ...
def conductor(name: str) -> Dict[str, Any]: ...
def heat_terms(
    temperature_k: ArrayLike, current_a: ArrayLike, *, conductor: str, weather: Mapping[str, Any], standard: str = "ieee738"
) -> Dict[str, Any]: ...
def steady_temperature(
    current_a: ArrayLike, *, conductor: str, weather: Mapping[str, Any], standard: str = "ieee738"
) -> Dict[str, Any]: ...
def ampacity(
    max_temperature_k: ArrayLike, *, conductor: str, weather: Mapping[str, Any], standard: str = "ieee738"
) -> Dict[str, Any]: ...
def transient(
    current_a: Union[float, Sequence[Tuple[float, float]], Sequence[Sequence[float]], npt.NDArray[Any]],
    end_time_s: float,
    *,
    conductor: str,
    weather: Mapping[str, Any],
    standard: str = "ieee738",
    initial_temperature_k: Optional[float] = None,
    step_s: float = 1.0,
    limit_k: Optional[float] = None,
) -> Dict[str, Any]: ...
def deicing(
    thickness_m: float,
    current_a: float,
    *,
    conductor: str,
    weather: Mapping[str, Any],
    standard: str = "ieee738",
    density_kg_per_m3: float = 900.0,
    criterion: str = "slot",
    step_s: float = 1.0,
    record_every_s: float = 10.0,
) -> Dict[str, Any]: ...
def deicing_current(
    thickness_m: float,
    shed_within_s: float,
    *,
    conductor: str,
    weather: Mapping[str, Any],
    standard: str = "ieee738",
    density_kg_per_m3: float = 900.0,
    criterion: str = "slot",
    step_s: float = 1.0,
) -> float: ...
