"""Shared helpers: the repository's paths, the `ohl` command-line binary the Python results are compared
with, and readers of its output files that give back the exact `f64` values (its CSV numbers are the
shortest round-trip forms, `ryu`, and `summary.json` is written by serde_json, also shortest round-trip:
Python's `float()` parses both correctly rounded, so a value read back is the value written)."""

from __future__ import annotations

import csv
import json
import os
import shutil
import subprocess
import time
from pathlib import Path
from typing import Any, Callable, Dict, Iterable, List, Optional, Tuple

import numpy as np
import pytest

REPO = Path(__file__).resolve().parents[2]


def _find_cli() -> Optional[Path]:
    """`OHL_BIN`, else the release binary of `cargo build --release --bin ohl` (`CARGO_TARGET_DIR` or
    `target/`), else `ohl` on the PATH."""
    if os.environ.get("OHL_BIN"):
        return Path(os.environ["OHL_BIN"])
    targets = [Path(os.environ["CARGO_TARGET_DIR"])] if os.environ.get("CARGO_TARGET_DIR") else []
    for t in targets + [REPO / "target"]:
        p = t / "release" / "ohl"
        if p.is_file():
            return p
    found = shutil.which("ohl")
    return Path(found) if found else None


@pytest.fixture(autouse=True)
def in_repository_root(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every test runs in the repository root, as the command line does in `cli`, so relative paths name
    files the same way in both."""
    monkeypatch.chdir(REPO)


@pytest.fixture(scope="session")
def ohl_cli() -> Path:
    """The `ohl` binary. Missing: the test is skipped, or fails when `OHL_REQUIRE_CLI=1` (CI sets it)."""
    p = _find_cli()
    if p is None or not p.is_file():
        msg = "the ohl binary was not found: run `cargo build --release --bin ohl` or set OHL_BIN"
        if os.environ.get("OHL_REQUIRE_CLI") == "1":
            pytest.fail(msg)
        pytest.skip(msg)
    return p


def cli(binary: Path, *args: str, cwd: Path = REPO) -> subprocess.CompletedProcess:
    """Run the binary with `args` in the repository root; stdout and stderr as text."""
    return subprocess.run([str(binary), *args], cwd=cwd, capture_output=True, text=True, timeout=600)


def read_csv(path: Path) -> Tuple[List[str], np.ndarray]:
    """The header and the numbers of a CSV file of `ohl` (float64, each parsed by `float`)."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    data = np.array([[float(x) for x in r] for r in body], dtype=np.float64).reshape(len(body), len(header))
    return header, data


def read_json(path: Path) -> Dict:
    with open(path) as f:
        return json.load(f)


def assert_bitwise(a: np.ndarray, b: np.ndarray, what: str = "") -> None:
    """Equal as IEEE 754 doubles: the same bits (so 0.0 and -0.0 differ), any NaN matching any NaN."""
    a = np.asarray(a, dtype=np.float64)
    b = np.asarray(b, dtype=np.float64)
    assert a.shape == b.shape, f"{what}: shape {a.shape} != {b.shape}"
    nan = np.isnan(a) & np.isnan(b)
    same = (a.view(np.uint64) == b.view(np.uint64)) | nan
    if not same.all():
        k = np.argwhere(~same)[0]
        raise AssertionError(f"{what}: {int((~same).sum())} values differ, first at {tuple(k)}: {a[tuple(k)]!r} != {b[tuple(k)]!r}")


# Keys of summary.json that measure the machine, not the run.
TIMING_KEYS = ("wall_time_s", "node_steps_per_second", "cpu_time_s", "cpu_node_steps_per_second")


def without_timing(summary: Dict) -> Dict:
    return {k: v for k, v in summary.items() if k not in TIMING_KEYS}


def run_lasting(end_times_s: Iterable[float], build: Callable[[float], Any], run: Callable[[Any], Any],
                min_s: float = 0.2) -> Tuple[Any, float]:
    """The first scenario `build(end_time_s)` over `end_times_s` whose `run` takes more than `min_s`
    seconds of wall time on this machine (else the last one): `(scenario, duration [s])`. For the tests
    that need a run long enough to watch another thread during it, on machines of any speed."""
    for end_time_s in end_times_s:
        sc = build(end_time_s)
        start = time.perf_counter()
        run(sc)
        duration = time.perf_counter() - start
        if duration > min_s:
            break
    return sc, duration
