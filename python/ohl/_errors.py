"""The exceptions and the warning category of the ``ohl`` package.

They are raised by the Rust extension (``ohl._ohl``) and defined here so that they carry their
attributes in ``__init__`` and pickle (Dask's process and distributed schedulers send them between
processes).
"""

from __future__ import annotations

from typing import Any, List, NamedTuple, Optional


class Problem(NamedTuple):
    """One field of a scenario that is not allowed: its dotted path, its value as written, what is allowed."""

    field: str
    value: str
    allowed: str


class ScenarioError(ValueError):
    """An invalid scenario or argument (``ohl run`` exits 2 on it).

    ``str(e)`` is the message ``ohl run`` prints after ``error: ``. For a TOML syntax or type error the
    message has the line and column and ``field``, ``value`` and ``allowed`` are None; for values out of
    their range ``problems`` lists every offending field and ``field``, ``value``, ``allowed`` are the
    first one's.

    Attributes:
        file: the file named in the message (the path, ``<string>``, ``<dict>`` or ``<arguments>``).
        field: dotted path of the first offending field, e.g. ``numerics.courant``.
        value: its value as written.
        allowed: what is allowed (the range, with its unit).
        problems: every offending field, as :class:`Problem` tuples.
    """

    def __init__(
        self,
        message: str,
        file: Optional[str] = None,
        field: Optional[str] = None,
        value: Optional[str] = None,
        allowed: Optional[str] = None,
        problems: Any = (),
    ) -> None:
        super().__init__(message)
        self.file = file
        self.field = field
        self.value = value
        self.allowed = allowed
        self.problems: List[Problem] = [Problem(*p) for p in problems]

    def __reduce__(self):  # keep the attributes through pickle
        return (
            type(self),
            (str(self), self.file, self.field, self.value, self.allowed, [tuple(p) for p in self.problems]),
        )


class WorkBudgetError(ValueError):
    """A run above the work budget (2e10 node-steps or 2 GB of output), refused as ``ohl run`` refuses it;
    pass ``allow_large=True`` to run it anyway. ``estimate`` is the work estimate (a dict)."""

    def __init__(self, message: str, estimate: Optional[dict] = None) -> None:
        super().__init__(message)
        self.estimate = estimate

    def __reduce__(self):
        return (type(self), (str(self), self.estimate))


class UnstableError(RuntimeError):
    """The explicit scheme went unstable (``ohl run`` exits 1 on it).

    Attributes:
        time_s: the time of the failure [s].
        node: the node where it was detected (of ``conductor`` in a line).
        reason: why (the speed or the value that was not finite).
        result: the :class:`ohl.RunResult` up to the failure (time series, snapshots, summary), or the
            :class:`ohl.LineResult` of a line run.
        conductor: the conductor of a line run that went unstable (None for a single run).
    """

    def __init__(
        self,
        message: str,
        time_s: float = float("nan"),
        node: int = -1,
        reason: str = "",
        result: Any = None,
        conductor: Optional[str] = None,
    ) -> None:
        super().__init__(message)
        self.time_s = time_s
        self.node = node
        self.reason = reason
        self.result = result
        self.conductor = conductor

    def __reduce__(self):
        return (type(self), (str(self), self.time_s, self.node, self.reason, self.result, self.conductor))


class StaticsError(RuntimeError):
    """The static (Newton) solve did not converge."""


class ThermalError(RuntimeError):
    """A heat-balance computation has no answer: no steady state (thermal runaway), no ampacity (the sun
    alone heats the conductor above the limit), or ice that does not shed."""


class ScenarioWarning(UserWarning):
    """A valid but doubtful value of a scenario (``ohl run`` prints it as ``warning: ``)."""
