"""The documented Dask example (`python/examples/dask_sweep.py`): `ohl.run` mapped over cases by Dask's
local schedulers gives the results of plain sequential runs."""

from __future__ import annotations

import importlib.util
import sys

import pytest

import ohl
from conftest import REPO

pytest.importorskip("dask", reason="dask is not installed (pip install dask); .ci/run installs it")


def load_example():
    path = REPO / "python" / "examples" / "dask_sweep.py"
    spec = importlib.util.spec_from_file_location("dask_sweep", path)
    module = importlib.util.module_from_spec(spec)
    sys.modules["dask_sweep"] = module
    spec.loader.exec_module(module)
    return module


@pytest.mark.parametrize("scheduler", ["threads", "synchronous"])
def test_dask_sweep(scheduler: str) -> None:
    ex = load_example()
    speeds = [0.0, 10.0, 20.0, 30.0]
    rows = ex.sweep(speeds, end_time_s=5.0, scheduler=scheduler, workers=2)
    assert [r["speed_m_per_s"] for r in rows] == speeds
    for u, row in zip(speeds, rows):
        assert row == ex.peaks(ex.case(u, 5.0))
    # More wind swings the wire further across the line.
    swings = [r["peak_swing_m"] for r in rows]
    assert swings == sorted(swings) and swings[0] == 0.0


def test_dask_processes_scheduler() -> None:
    """Scenarios and results cross process boundaries (pickle) with the "processes" scheduler."""
    import dask

    sc = ohl.from_dict(load_example().case(10.0, 2.0))
    (r,) = dask.compute(dask.delayed(ohl.run)(sc), scheduler="processes", num_workers=1)
    assert (r.table == ohl.run(sc).table).all()
