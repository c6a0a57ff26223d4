"""A parameter sweep with Dask: the peak tension and mid-span swing of a 160 m span against the wind speed.

Each case is a dict with the tables of a scenario file; `dask.delayed` maps `ohl.run` over the cases and
Dask's threaded scheduler runs them in parallel (`ohl.run` releases the GIL, so threads use every core).
Run it from the repository root:

    python python/examples/dask_sweep.py              # 0, 5, ..., 30 m/s, 20 s each
    python python/examples/dask_sweep.py --workers 4

Dask's other local schedulers work too: "processes" (scenarios pickle through their TOML text) and
"synchronous" (one at a time, for debugging). The same function serves `python/tests/test_dask.py`.
"""

from __future__ import annotations

import argparse
import copy
from typing import Any, Dict, List, Optional, Sequence

import dask

import ohl

# The README's scenario: the weight release of the paper's section 4.2 with a wind from the side.
BASE: Dict[str, Any] = {
    "name": "wind sweep",
    "conductor": {"axial_stiffness_n": 791999.5, "linear_density_kg_per_m": 1.0, "diameter_m": 0.01553},
    "geometry": {"left_support_m": [0.0, 0.0, 0.0], "right_support_m": [0.0, 160.0, 0.0], "segments": 50},
    "loads": {"gravity_m_per_s2": 9.81, "wind": {"law": "aerodynamic", "direction": [1.0, 0.0, 0.0], "speed_m_per_s": 20.0}},
    "numerics": {"courant": 0.9, "smoothing": 0.02, "mu": 0.15},
    "duration": {"end_time_s": 20.0},
    "output": {"sample_interval_s": 0.05},
}


def case(speed_m_per_s: float, end_time_s: float) -> Dict[str, Any]:
    """The base scenario with the wind speed [m/s] (0: no wind table, still air) and end time [s] set."""
    d = copy.deepcopy(BASE)
    d["name"] = f"wind {speed_m_per_s:g} m/s"
    if speed_m_per_s > 0:
        d["loads"]["wind"]["speed_m_per_s"] = float(speed_m_per_s)
    else:
        del d["loads"]["wind"]
    d["duration"]["end_time_s"] = float(end_time_s)
    return d


def peaks(d: Dict[str, Any]) -> Dict[str, float]:
    """Run one case and keep what the sweep tabulates: peak tension [N], largest swing across the line
    and largest sag at mid-span [m] over the run. The peaks are the run summary's, tracked at every time
    step (the sampled arrays can miss a peak between two samples)."""
    s = ohl.run(d).summary
    swing, _, sag = s["peak_midspan_displacement_m"]
    return {
        "speed_m_per_s": d["loads"].get("wind", {}).get("speed_m_per_s", 0.0),
        "peak_tension_n": float(s["peak_max_tension_n"]),
        "peak_swing_m": abs(float(swing["value_m"])),
        "peak_sag_m": -float(sag["value_m"]),
    }


def sweep(
    speeds_m_per_s: Sequence[float],
    end_time_s: float = 20.0,
    scheduler: str = "threads",
    workers: Optional[int] = None,
) -> List[Dict[str, float]]:
    """The peaks of every case, computed by Dask's local `scheduler` ("threads", "processes" or
    "synchronous"), in the order of `speeds_m_per_s`."""
    tasks = [dask.delayed(peaks)(case(u, end_time_s)) for u in speeds_m_per_s]
    return list(dask.compute(*tasks, scheduler=scheduler, num_workers=workers))


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--speeds", type=float, nargs="+", default=[0, 5, 10, 15, 20, 25, 30], help="wind speeds [m/s]")
    p.add_argument("--end-time", type=float, default=20.0, help="end time of each run [s]")
    p.add_argument("--scheduler", default="threads", choices=["threads", "processes", "synchronous"])
    p.add_argument("--workers", type=int, default=None)
    a = p.parse_args()
    rows = sweep(a.speeds, a.end_time, a.scheduler, a.workers)
    print(f"{'U [m/s]':>8} {'peak T [N]':>12} {'swing [m]':>10} {'sag [m]':>9}")
    for r in rows:
        print(f"{r['speed_m_per_s']:8.1f} {r['peak_tension_n']:12.1f} {r['peak_swing_m']:10.3f} {r['peak_sag_m']:9.3f}")


if __name__ == "__main__":
    main()
