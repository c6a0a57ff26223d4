"""A structured generator of random inputs for every public function of ``ohl`` (issue 22), and its
driver. test_fuzz.py runs it in a child process (a crash fails that test with the case that crashed);
run it by hand for longer:

    python python/tests/fuzz_inputs.py --seed 1 --seconds 600      # from the repository root

Inputs: the repository's scenario files (paper_cases/, cases/, examples/, app/tests/bad_inputs/) read
into dicts, and the weather tables of examples/thermal/, mutated one to three times each: a value
replaced by a type-plausible one (a number scaled, an int near its own, a string from the pool of all
strings of the files, a list of the same kind), by an extreme number (0, -1, 1e300, nan, inf, 10**30,
2**63, 5e-324, ...) or by a value of a wrong type (None, bytes, a set, a complex, a NumPy array, a lone
surrogate, a NUL, an object); a key removed or added; a table made a list or a scalar, a list a table; a
non-str key; a dict that contains itself, a list that contains itself; nesting 40 deep; mappings that are
not dicts. The arguments of the thermal functions, the statics, the runs and the constructors are drawn
the same way around valid values (bounded so that a valid call stays short).

Every call must return, or raise ``ohl.ScenarioError`` naming a field (and, for a dict, never a line of
the generated TOML text), a ``TypeError`` naming its argument (``argument `x` ...``), or one of the
documented outcomes of a valid input (``StaticsError``, ``ThermalError``, ``WorkBudgetError``,
``UnstableError``; an ``OSError`` such as ``FileNotFoundError`` for a path, as ``open()`` raises it): anything else is a failure, printed with the seed
and the case number (``--cases`` replays exactly that many cases).
"""

from __future__ import annotations

import argparse
import collections
import collections.abc
import copy
import decimal
import fractions
import math
import random
import re
import sys
import time
import traceback
import types
import warnings
from pathlib import Path
from typing import Any, Callable, Dict, Iterator, List, Optional, Tuple

import numpy as np

import ohl

REPO = Path(__file__).resolve().parents[2]

EXTREMES: List[Any] = [
    0, -1, 1, 0.0, -0.0, -1.0, 1e300, -1e300, math.nan, math.inf, -math.inf, 10**30, -(10**30),
    2**63, 2**63 - 1, -(2**63) - 1, 2**64, 10**400, 1e-300, 5e-324, 1.7976931348623157e308,
]


class Opaque:
    """An object of no type TOML knows."""


class Loops:
    """An object whose ``tolist`` gives another such object, forever."""

    def tolist(self) -> "Loops":
        return Loops()


class Frozen(collections.abc.Mapping):
    """A mapping that is not a dict."""

    def __init__(self, d: Dict[str, Any]) -> None:
        self._d = dict(d)

    def __getitem__(self, k: str) -> Any:
        return self._d[k]

    def __iter__(self) -> Iterator[str]:
        return iter(self._d)

    def __len__(self) -> int:
        return len(self._d)


def wrong_values() -> List[Any]:
    return [
        None, "", "text", "\ud800", "a\0b", "x" * 5000, b"bytes", True, False, [], {}, [1, "a"], [[1.0], 2.0],
        Opaque(), Loops(), 1 + 2j, {1, 2}, frozenset(), range(3), decimal.Decimal("1.5"), fractions.Fraction(1, 3),
        np.float64("nan"), np.float32(1.5), np.int64(-1), np.uint64(2**64 - 1), np.bool_(True), np.array([1.0, 2.0]),
        np.array(5.0), np.array([[1, 2], [3, 4]]), np.array(["a"]), np.datetime64("2020-01-01"),
    ]


# --- seeds -------------------------------------------------------------------------------------------


def read_seeds() -> Tuple[List[Tuple[str, Dict[str, Any]]], List[Dict[str, Any]]]:
    """The scenario files as dicts, and the weather tables (with their sun) of the thermal examples."""
    import tomllib

    files = sorted(
        list((REPO / "paper_cases").glob("*.toml"))
        + list((REPO / "cases").glob("*.toml"))
        + list((REPO / "examples").rglob("*.toml"))
        + list((REPO / "app/tests/bad_inputs").glob("*.toml"))
    )
    scenarios, weathers = [], []
    for f in files:
        try:
            d = tomllib.loads(f.read_text(encoding="utf-8"))
        except (UnicodeDecodeError, tomllib.TOMLDecodeError):
            continue
        scenarios.append((str(f.relative_to(REPO)), d))
        for w in (d.get("weather"), d.get("thermal", {}).get("weather") if isinstance(d.get("thermal"), dict) else None):
            if isinstance(w, dict):
                weathers.append(w)
    return scenarios, weathers


def strings_of(v: Any, out: set) -> None:
    if isinstance(v, str):
        out.add(v)
    elif isinstance(v, dict):
        for k, x in v.items():
            out.add(k)
            strings_of(x, out)
    elif isinstance(v, list):
        for x in v:
            strings_of(x, out)


# --- the generator -----------------------------------------------------------------------------------


class Generator:
    """Random inputs from the seeds; every choice from one ``random.Random(seed)``."""

    def __init__(self, seed: int) -> None:
        self.rng = random.Random(seed)
        self.scenarios, self.weathers = read_seeds()
        pool: set = set()
        for _, d in self.scenarios:
            strings_of(d, pool)
        self.strings = sorted(pool)

    # values

    def plausible(self, v: Any) -> Any:
        """A value of the same kind as ``v``, near it."""
        r = self.rng
        if isinstance(v, bool):
            return not v if r.random() < 0.5 else v
        if isinstance(v, int):
            return r.choice([v - 1, v + 1, 2 * v, v // 2, r.randint(0, max(2, 2 * abs(v) + 2))])
        if isinstance(v, float):
            if r.random() < 0.3:
                return float(r.choice([0, 1, 2, 10, 100]))
            return v * r.choice([0.5, 0.9, 1.0, 1.1, 2.0, -1.0]) if v else r.uniform(-10, 10)
        if isinstance(v, str):
            return r.choice(self.strings) if r.random() < 0.8 else v + r.choice(["_", "x", " ", "1"])
        if isinstance(v, list):
            if v and r.random() < 0.5:
                return [self.plausible(x) for x in v]
            return r.choice([v[:-1], v + v[-1:], list(reversed(v))]) if v else [r.uniform(0, 1)]
        if isinstance(v, dict):
            return {k: (self.plausible(x) if r.random() < 0.3 else x) for k, x in v.items()}
        return v

    def extreme(self) -> Any:
        return self.rng.choice(EXTREMES)

    def wrong(self) -> Any:
        return self.rng.choice(wrong_values())

    def any_value(self, v: Any) -> Any:
        x = self.rng.random()
        if x < 0.5:
            return self.plausible(v)
        if x < 0.8:
            return self.extreme()
        return self.wrong()

    # places in a document

    def places(self, root: Any) -> List[Tuple[Any, Any]]:
        """(container, key or index) of every value, each container once (the documents may have cycles)."""
        out: List[Tuple[Any, Any]] = []
        seen = set()

        def walk(c: Any) -> None:
            if id(c) in seen:
                return
            seen.add(id(c))
            if isinstance(c, dict):
                for k in list(c):
                    out.append((c, k))
                    walk(c[k])
            elif isinstance(c, list):
                for i in range(len(c)):
                    out.append((c, i))
                    walk(c[i])

        walk(root)
        return out

    def mutate(self, root: Dict[str, Any]) -> Dict[str, Any]:
        r = self.rng
        places = self.places(root)
        tables = [root] + [c[k] for c, k in places if isinstance(c[k], dict)]
        op = r.choice(
            ["plausible"] * 6 + ["extreme"] * 4 + ["wrong"] * 3
            + ["delete", "delete", "unknown", "self", "self_list", "wrap", "key", "mapping", "shape", "deep", "numpy"]
        )
        if op in ("unknown", "key", "self") or not places:
            t = r.choice(tables)
            if op == "key":
                t[r.choice([1, None, (1, 2), 2.5, b"k"])] = 1.0
            elif op == "self":
                t[r.choice(list(t) or ["again"])] = r.choice([t, root])
            else:
                t[r.choice(self.strings) + r.choice(["", "_x"])] = self.plausible(r.choice([1.0, 1, "a", [1.0]]))
            return root
        c, k = r.choice(places)
        v = c[k]
        if op == "plausible":
            c[k] = self.plausible(v)
        elif op == "extreme":
            c[k] = self.extreme()
        elif op == "wrong":
            c[k] = self.wrong()
        elif op == "delete":
            del c[k]
        elif op == "self_list":
            loop: list = [1.0]
            loop.append(loop)
            c[k] = loop
        elif op == "wrap":
            c[k] = [v]
        elif op == "mapping" and isinstance(v, dict):
            c[k] = r.choice([types.MappingProxyType(v), Frozen(v), collections.OrderedDict(v)])
        elif op == "shape":
            if isinstance(v, list) and v and isinstance(v[0], dict):
                c[k] = v[0]
            elif isinstance(v, dict):
                c[k] = r.choice([[v], 1.0, "table"])
            else:
                c[k] = {"value": v}
        elif op == "deep":
            deep: Any = v
            for _ in range(40):
                deep = [deep]
            c[k] = deep
        elif op == "numpy" and isinstance(v, (int, float, list)) and not isinstance(v, bool):
            try:
                c[k] = np.asarray(v)[()] if not isinstance(v, list) else np.asarray(v)
            except (ValueError, TypeError):
                c[k] = v
        return root

    def scenario(self) -> Tuple[str, Any]:
        name, d = self.rng.choice(self.scenarios)
        d = copy.deepcopy(d)
        if self.rng.random() < 0.05:
            return name, self.rng.choice([[d], None, "name = 'x'", 3, Frozen(d)])
        for _ in range(self.rng.choice([0, 1, 1, 2, 3])):
            d = self.mutate(d)
        return name, d

    def weather(self) -> Any:
        w = copy.deepcopy(self.rng.choice(self.weathers))
        if self.rng.random() < 0.05:
            return self.wrong()
        for _ in range(self.rng.choice([0, 1, 2])):
            w = self.mutate(w)
        return w

    def arg(self, valid: Any, p_valid: float = 0.6) -> Any:
        """``valid`` (or one near it) with probability ``p_valid``, else an extreme or a wrong value."""
        r = self.rng
        if r.random() < p_valid:
            return valid if r.random() < 0.5 else self.plausible(valid)
        return self.extreme() if r.random() < 0.6 else self.wrong()


# --- the calls ---------------------------------------------------------------------------------------

TINY = {
    "conductor": {"axial_stiffness_n": 792000.0, "linear_density_kg_per_m": 1.0},
    "geometry": {"left_support_m": [0.0, 0.0, 0.0], "right_support_m": [0.0, 160.0, 0.0], "segments": 20},
    "duration": {"end_time_s": 0.2},
}


class Call:
    """One call: its label, the function, and what kind of input it took."""

    def __init__(self, label: str, f: Callable[[], Any], dict_input: bool = False, path: bool = False) -> None:
        self.label, self.f, self.dict_input, self.path = label, f, dict_input, path


def draw(g: Generator) -> Call:
    r = g.rng
    x = r.random()
    if x < 0.55:
        name, d = g.scenario()
        as_line = isinstance(d, dict) and "line" in d
        if r.random() < 0.1:
            as_line = not as_line
        f = ohl.line_from_dict if as_line else ohl.from_dict
        if r.random() < 0.05:
            label = r.choice(["mine", 3, None, "\ud800"])
            return Call(f"{f.__name__}({name}, name={label!r})", lambda: f(d, label), dict_input=True)
        return Call(f"{f.__name__}({name})", lambda: f(d), dict_input=True)
    if x < 0.8:
        return thermal_call(g)
    if x < 0.9:
        sc = ohl.from_dict(TINY)
        tol = g.arg(1e-6)
        its = g.arg(50)
        target: Any = r.choice([sc, TINY])
        return Call(f"equilibrium(tolerance_n={tol!r:.40}, max_iterations={its!r:.40})", lambda: ohl.equilibrium(target, tolerance_n=tol, max_iterations=its), dict_input=True)
    if x < 0.95:
        sc = ohl.from_dict(TINY)
        # never a usable path (str, bytes or os.PathLike without a NUL): the run would write there
        out = r.choice([None, None, None, 3, 1.5, True, [], {}, "a\0b", b"a\0b", Opaque(), np.int64(1)])
        big = g.arg(False, 0.7)
        return Call(f"run(out_dir={out!r:.40}, allow_large={big!r:.40})", lambda: ohl.run(sc, out_dir=out, allow_large=big))
    text = (REPO / "app/tests/bad_inputs/valid.toml").read_text(encoding="utf-8")
    choice = r.randrange(4)
    if choice == 0:
        i = r.randrange(len(text))
        mutated = text[:i] + r.choice(["", "[", "]", "=", '"', "\n", "\0", "x = nan\n", "1e999"]) + text[i + 1 :]
        return Call("loads(mutated text)", lambda: ohl.loads(mutated))
    if choice == 1:
        return Call("loads(wrong)", lambda: ohl.loads(g.wrong(), g.arg("<string>", 0.5)))
    if choice == 2:
        p = g.arg("no/such/file.toml", 0.3)
        return Call(f"load({p!r:.40})", lambda: ohl.load(p), path=True)
    p = g.arg("no/such/file.toml", 0.3)
    return Call(f"load_line({p!r:.40})", lambda: ohl.load_line(p), path=True)


def thermal_call(g: Generator) -> Call:
    r = g.rng
    w = g.weather()
    conductor = g.arg("ACSR Drake", 0.8)
    standard = g.arg(r.choice(["ieee738", "cigre601"]), 0.8)
    kw = {"conductor": conductor, "weather": w, "standard": standard}
    which = r.randrange(7)
    if which == 0:
        t, i = g.arg(r.choice([350.0, [300.0, 350.0]])), g.arg(r.choice([800.0, [0.0, 800.0]]))
        return Call("heat_terms", lambda: ohl.heat_terms(t, i, **kw), dict_input=True)
    if which == 1:
        i = g.arg(r.choice([800.0, [600.0, 1200.0], np.array([[100.0], [900.0]])]))
        return Call("steady_temperature", lambda: ohl.steady_temperature(i, **kw), dict_input=True)
    if which == 2:
        t = g.arg(r.choice([373.15, [350.0, 373.15]]))
        return Call("ampacity", lambda: ohl.ampacity(t, **kw), dict_input=True)
    if which == 3:
        points = g.arg(r.choice([800.0, [(0.0, 800.0), (0.0, 1200.0)], [[0.0, 800.0], [600.0, 1000.0]]]))
        end = r.uniform(1.0, 3600.0) if r.random() < 0.6 else g.extreme()
        # a valid step stays >= 0.5 s (a valid 1e7 s at 1e-3 s would run for hours: no check refuses it)
        step = r.choice([1.0, 10.0]) if r.random() < 0.6 else r.choice([0.0, -1.0, math.nan, math.inf, 1e300, 10**30, "1", None])
        t0, lim = g.arg(None, 0.5), g.arg(373.15, 0.5)
        return Call("transient", lambda: ohl.transient(points, end, initial_temperature_k=t0, step_s=step, limit_k=lim, **kw), dict_input=True)
    if which == 4:
        thick, cur = g.arg(0.010), g.arg(1000.0)
        dens, crit = g.arg(900.0, 0.7), g.arg(r.choice(["slot", "full_melt"]), 0.7)
        step = r.choice([1.0, 5.0]) if r.random() < 0.6 else r.choice([0.0, -1.0, math.nan, 1e300, "1", None])
        rec = g.arg(10.0, 0.7)
        return Call("deicing", lambda: ohl.deicing(thick, cur, density_kg_per_m3=dens, criterion=crit, step_s=step, record_every_s=rec, **kw), dict_input=True)
    if which == 5:
        thick, within = g.arg(0.010), g.arg(3600.0)
        step = r.choice([1.0, 5.0]) if r.random() < 0.6 else r.choice([0.0, -1.0, math.nan, 1e300, "1", None])
        return Call("deicing_current", lambda: ohl.deicing_current(thick, within, step_s=step, **kw), dict_input=True)
    name = g.arg("drake", 0.5)
    return Call(f"conductor({name!r:.40})", lambda: ohl.conductor(name))


# --- the judge ---------------------------------------------------------------------------------------

LINE_OF_TEXT = re.compile(r"TOML parse error|\bat line \d|\bline \d+, column|table that starts at line")
OUTCOMES_OF_VALID_INPUT = (ohl.StaticsError, ohl.ThermalError, ohl.WorkBudgetError, ohl.UnstableError)


def judge(call: Call) -> Tuple[str, Optional[str]]:
    """The outcome's class, and what is wrong with it (None if it keeps the contract)."""
    try:
        call.f()
    except ohl.ScenarioError as e:
        if not str(e) or not isinstance(e, ValueError):
            return "ScenarioError", "an empty message"
        if call.dict_input and LINE_OF_TEXT.search(str(e)):
            return "ScenarioError", f"names a line of the generated TOML text: {e}"
        if e.problems and not e.field:
            return "ScenarioError", f"no field: {e}"
        return "ScenarioError", None
    except TypeError as e:
        if not re.match(r"argument `\w+` must be ", str(e)):
            return "TypeError", f"does not name its argument: {e!r}"
        return "TypeError", None
    except OUTCOMES_OF_VALID_INPUT as e:
        return type(e).__name__, None
    except OSError as e:  # a file that cannot be read: FileNotFoundError, a name too long, ... (as open())
        return type(e).__name__, None if call.path else f"{e!r}"
    except KeyboardInterrupt:
        raise
    except BaseException as e:  # noqa: BLE001 - anything else breaks the contract (PanicException too)
        return type(e).__name__, "".join(traceback.format_exception(type(e), e, e.__traceback__))
    return "returned", None


def main(argv: Optional[List[str]] = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seed", type=int, default=22)
    ap.add_argument("--seconds", type=float, default=3.0)
    ap.add_argument("--cases", type=int, default=None, help="exactly this many cases (ignores --seconds)")
    ap.add_argument("--log", type=Path, default=None, help="write each case's number and label here first")
    a = ap.parse_args(argv)
    warnings.simplefilter("ignore")  # ScenarioWarning of doubtful but valid values
    g = Generator(a.seed)
    counts: Dict[str, int] = collections.Counter()
    start = time.perf_counter()
    slowest = (0.0, "")
    log = open(a.log, "w", encoding="utf-8") if a.log else None
    n = 0
    while (n < a.cases) if a.cases is not None else (time.perf_counter() - start < a.seconds):
        call = draw(g)
        if log:
            log.write(f"case {n}: {call.label!r}\n")
            log.flush()
        t = time.perf_counter()
        outcome, wrong = judge(call)
        dt = time.perf_counter() - t
        slowest = max(slowest, (dt, call.label))
        counts[outcome] += 1
        if wrong is not None:
            print(f"FAIL seed {a.seed} case {n} ({call.label!r}): {outcome}: {wrong}")
            return 1
        n += 1
    summary = ", ".join(f"{k} {v}" for k, v in sorted(counts.items()))
    print(f"fuzz: seed {a.seed}, {n} calls in {time.perf_counter() - start:.1f} s: {summary}; slowest {slowest[0]:.3f} s ({slowest[1]!r})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
