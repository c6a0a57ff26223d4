"""`ohl.run` releases the GIL: runs in threads give the sequential results bit for bit, and Python code
in another thread keeps running while a run is in progress."""

from __future__ import annotations

import threading
import time
from concurrent.futures import ThreadPoolExecutor

import pytest

import ohl
from conftest import assert_bitwise, run_lasting


def case(speed: float, end_time_s: float = 20.0, segments: int = 50) -> dict:
    return {
        "name": f"wind {speed}",
        "conductor": {"axial_stiffness_n": 791999.5, "linear_density_kg_per_m": 1.0, "diameter_m": 0.01553},
        "geometry": {"left_support_m": [0.0, 0.0, 0.0], "right_support_m": [0.0, 160.0, 0.0], "segments": segments},
        "loads": {"wind": {"law": "aerodynamic", "speed_m_per_s": speed}},
        "numerics": {"mu": 0.15},
        "duration": {"end_time_s": end_time_s},
    }


def test_threads_give_the_sequential_results() -> None:
    cases = [case(u) for u in (5.0, 10.0, 15.0, 20.0)]
    sequential = [ohl.run(c) for c in cases]
    with ThreadPoolExecutor(max_workers=4) as pool:
        threaded = list(pool.map(ohl.run, cases))
    for s, t in zip(sequential, threaded):
        assert_bitwise(s.table, t.table, s.summary["name"])
        assert_bitwise(s.snapshots.x_m, t.snapshots.x_m)


def test_python_runs_while_a_run_is_in_progress() -> None:
    """While a run of at least 0.2 s goes on in a thread, this thread keeps executing bytecode: the
    longest pause between two of its loop iterations stays far below the run's duration. With the GIL
    held through the run, this thread would stop for the whole run (one pause as long as the run). The
    run's end time doubles from 800 s until it takes 0.2 s on this machine (800 s took 0.18 s on a Zen 5),
    at most 16 times as long."""
    ends = [800.0 * 2.0**k for k in range(5)]
    sc, duration = run_lasting(ends, lambda end: ohl.from_dict(case(20.0, end_time_s=end, segments=100)), ohl.run)
    assert duration > 0.2, f"the run is too short ({duration:.3f} s) to tell"

    done = threading.Event()
    worker = threading.Thread(target=lambda: (ohl.run(sc), done.set()))
    iterations, longest, last = 0, 0.0, time.perf_counter()
    worker.start()
    while not done.is_set():
        now = time.perf_counter()
        longest = max(longest, now - last)
        last = now
        iterations += 1
    worker.join()
    assert longest < 0.5 * duration, f"this thread paused {longest:.3f} s during a {duration:.3f} s run"
    assert iterations > 1000


def test_ctrl_c_stops_a_run() -> None:
    """SIGINT (Ctrl-C) during a run raises KeyboardInterrupt within a fraction of a second, not at the
    end of the run (about 40 s here). Python's own handler is installed for the test: a process started
    in the background by a non-interactive shell inherits SIGINT ignored."""
    import signal

    sc = ohl.from_dict(case(20.0, end_time_s=20000.0, segments=200))
    before = signal.signal(signal.SIGINT, signal.default_int_handler)
    timer = threading.Timer(0.5, lambda: signal.raise_signal(signal.SIGINT))
    start = time.perf_counter()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            ohl.run(sc)
    finally:
        timer.cancel()
        signal.signal(signal.SIGINT, before)
    assert time.perf_counter() - start < 10.0
