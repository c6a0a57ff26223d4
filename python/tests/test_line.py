"""Line scenarios (`[line]`: several conductors on shared towers) from Python, against independent
expectations:

- a line of conductors on supports of their own is, conductor by conductor, bit for bit the single-
  conductor scenarios of its conductors run through `ohl.run` (the line adds nothing to uncoupled
  conductors; `tests/line_scenario.rs` builds the same equivalence in Rust);
- a line run is bit for bit `ohl run` on the same file: every conductor's `timeseries.csv` and
  `snapshots.csv`, `clearances.csv`, `towers.csv` and `summary.json` (less its timings);
- sampled at every time level, the least clearance of the summary (tracked every level) is the minimum of
  the returned clearance series, with its time and pair;
- at the start of an equilibrium run the supports carry the weight of the conductors and strings,
  to the bound the Newton solve's residual sets;
- `ohl.line_equilibrium` from the strung line is bit for bit the state an equilibrium start runs from;
- invalid files give `ohl run`'s message as `ScenarioError`, above-budget runs `WorkBudgetError`.
"""

from __future__ import annotations

import pickle
import re
import sys
from pathlib import Path
from typing import Dict

import numpy as np
import pytest

import ohl
from conftest import REPO, assert_bitwise, cli, read_csv, read_json, run_lasting, without_timing

CONDUCTOR = {"axial_stiffness_n": 2.9e7, "linear_density_kg_per_m": 1.628, "diameter_m": 0.0281}


def section(x1: float) -> Dict:
    return {
        "horizontal_tension_n": 28000.0,
        "segments_per_span": 24,
        "supports": [
            {"kind": "dead_end", "point_m": [x1, 0.0, 26.5]},
            {
                "kind": "suspension",
                "pivot_m": [x1, 380.0, 30.0],
                "insulator_length_m": 3.5,
                "insulator_mass_kg": 100.0,
                "insulator_stiffness_n": 5.0e7,
            },
            {"kind": "dead_end", "point_m": [x1, 800.0, 28.0]},
        ],
    }


# The tables every conductor shares (a line's global tables; a single scenario's own).
GLOBAL = {
    "loads": {
        "wind": {
            "law": "aerodynamic",
            "direction": [1.0, 0.0, 0.0],
            "speed_m_per_s": 25.0,
            "normal_coefficient": 1.0,
            "tangential_coefficient": 0.0,
            "initial_scale": 0.0,
        }
    },
    "numerics": {"courant": 0.5, "smoothing": 0.01, "eta_n_s": 5000.0, "mu": 1.0},
    "duration": {"end_time_s": 3.0},
    "output": {
        "sample_interval_s": 0.1,
        "snapshot_times_s": [0.0, 1.0, 2.5],
        "probes": [{"name": "quarter", "at_fraction": 0.25}],
    },
}

WIND = {"time_s": 0.5, "action": "wind", "scale": 1.0}


def ice(span: int, kg_per_m: float) -> Dict:
    return {"time_s": 0.7, "action": "ice", "span": span, "linear_density_kg_per_m": kg_per_m}


# Conductor name, x1 of its supports, its own ice event.
UNCOUPLED = [("A", -4.0, ice(1, 0.8)), ("B", 4.0, ice(0, 0.3))]


def uncoupled_line() -> Dict:
    conductors = [
        {"name": name, "conductor": CONDUCTOR, "section": section(x1), "events": [own]} for name, x1, own in UNCOUPLED
    ]
    return {"name": "two phases", "line": {"conductors": conductors}, **GLOBAL, "events": [WIND]}


def test_a_line_of_own_supports_is_its_single_conductor_runs() -> None:
    line = ohl.run_line(uncoupled_line())
    assert list(line.conductors) == ["A", "B"] and line.status == "completed"
    for name, x1, own in UNCOUPLED:
        # The conductor as a single-conductor scenario: its own event first, then the file's (the order the
        # line gives each conductor's timeline).
        single = ohl.run({"conductor": CONDUCTOR, "section": section(x1), **GLOBAL, "events": [own, WIND]})
        c = line[name]
        assert c.columns == single.columns, name
        assert_bitwise(c.table, single.table, f"{name} time series")
        for field in ("t_s", "tau", "s_m", "x_m", "v_m_per_s", "tension_n"):
            assert_bitwise(getattr(c.snapshots, field), getattr(single.snapshots, field), f"{name} snapshots {field}")
        assert_bitwise(c.support_forces_n, single.support_forces_n, f"{name} supports")
        assert_bitwise(c.probes["quarter"], single.probes["quarter"], f"{name} quarter")
        s = single.summary
        for key in ("peak_max_tension_n", "peak_max_tension_time_s", "final_max_tension_n", "final_midspan_displacement_m"):
            assert c.summary[key] == s[key], (name, key)
        assert c.summary["peak_midspan_displacement_m"] == s["peak_midspan_displacement_m"], name
        assert [w for t, who, w in line.events if who == name] == [e[1] for e in single.events], name
    # The wind moved both across the line; the line has one pair and no tower.
    assert line["A"].mid_displacement_m[-1, 0] > 0.1 and line["B"].mid_displacement_m[-1, 0] > 0.1
    assert line.clearance_pairs == [("A", "B")] and line.towers == [] and line.tower_forces_n.shape == (len(line.t_s), 0, 3)


def shortened(case: str, end_time_s: float, snapshots: str, tmp_path: Path) -> Path:
    """A case of `cases/` with a shorter end time and other snapshot times (and every other line kept)."""
    text = (REPO / "cases" / case).read_text()
    text, n = re.subn(r"(?m)^end_time_s = .*$", f"end_time_s = {end_time_s}", text)
    assert n == 1
    text, n = re.subn(r"(?m)^snapshot_times_s = .*$", f"snapshot_times_s = {snapshots}", text)
    assert n == 1
    p = tmp_path / case
    p.write_text(text)
    return p


def check_line_against_cli(r: ohl.LineResult, out: Path) -> None:
    for name, c in r.conductors.items():
        d = out / "conductors" / re.sub(r"[^A-Za-z0-9.\-]", "_", name)
        header, table = read_csv(d / "timeseries.csv")
        assert header == c.columns, name
        assert_bitwise(c.table, table, f"{name} timeseries.csv")
        _, snaps = read_csv(d / "snapshots.csv")
        nodes = c.snapshots.x_m.shape[1]
        s = snaps.reshape(-1, nodes, 11)
        assert_bitwise(c.snapshots.t_s, s[:, 0, 0], f"{name} snapshot t_s")
        assert_bitwise(c.snapshots.s_m, s[:, :, 3], f"{name} s_m")
        assert_bitwise(c.snapshots.x_m, s[:, :, 4:7], f"{name} x_m")
        assert_bitwise(c.snapshots.v_m_per_s, s[:, :, 7:10], f"{name} v_m_per_s")
        assert_bitwise(c.snapshots.tension_n, s[:, :, 10], f"{name} tension_n")
    header, cl = read_csv(out / "clearances.csv")
    assert len(header) == 1 + len(r.clearance_pairs)
    assert_bitwise(r.t_s, cl[:, 0], "clearances.csv t_s")
    assert_bitwise(r.clearances_m, cl[:, 1:], "clearances.csv")
    header, tw = read_csv(out / "towers.csv")
    assert len(header) == 1 + 5 * len(r.towers)
    assert_bitwise(r.t_s, tw[:, 0], "towers.csv t_s")
    per_tower = tw[:, 1:].reshape(len(r.t_s), len(r.towers), 5)
    assert_bitwise(r.tower_forces_n, per_tower[:, :, :3], "tower forces")
    assert_bitwise(r.tower_displacements_m, per_tower[:, :, 3:], "tower displacements")
    assert without_timing(r.summary) == without_timing(read_json(out / "summary.json"))


@pytest.mark.parametrize(
    "case, end, snapshots",
    [
        ("e_three_phases_wind.toml", 2.0, "[1.0]"),  # 4 conductors on 2 rigid towers, wind from 1 s
        ("g_quad_bundle_break.toml", 1.0, "[0.5]"),  # a quad bundle with spacers, damped strings, a break
    ],
)
def test_line_run_equals_the_command_line(case: str, end: float, snapshots: str, tmp_path: Path, ohl_cli: Path) -> None:
    path = shortened(case, end, snapshots, tmp_path)
    out = tmp_path / "cli"
    p = cli(ohl_cli, "run", str(path), "--out", str(out), "--quiet")
    assert p.returncode == 0, p.stderr
    sc = ohl.load_line(path)
    r = ohl.run(sc)
    assert isinstance(r, ohl.LineResult) and r.status == "completed"
    assert list(r.conductors) == sc.conductors and [c.role for c in r.conductors.values()] == sc.roles
    assert r.clearance_pairs == sc.clearance_pairs and r.towers == sc.towers
    check_line_against_cli(r, out)
    # out_dir writes the command line's files, byte for byte (but summary.json's timings).
    again = ohl.run_line(path, out_dir=tmp_path / "py")
    for f in ["clearances.csv", "towers.csv"] + [f"conductors/{d.name}/{n}" for d in (out / "conductors").iterdir() for n in ("timeseries.csv", "snapshots.csv")]:
        assert (tmp_path / "py" / f).read_bytes() == (out / f).read_bytes(), f
    assert without_timing(read_json(tmp_path / "py" / "summary.json")) == without_timing(again.summary)


def test_the_least_clearance_is_the_minimum_of_the_clearance_series(tmp_path: Path) -> None:
    # Sampled at every time level (an interval below the step), the series holds every level the tracker
    # saw, so its minimum is the summary's least distance, exactly, at the same time.
    # Case (e) to 6 s: the phases' least distance (A - B, at the end towers) passes its minimum near 4.2 s.
    path = shortened("e_three_phases_wind.toml", 6.0, "[1.0]", tmp_path)
    text = re.sub(r"(?m)^sample_interval_s = .*$", "sample_interval_s = 1e-4", path.read_text())
    sc = ohl.loads_line(text, "e every level")
    assert sc.sample_interval_s < sc.dt_s
    r = ohl.run_line(sc)
    levels = r.summary["steps"] + 1
    assert len(r.t_s) == levels
    least = r.least_clearance
    k, j = np.unravel_index(np.nanargmin(r.clearances_m), r.clearances_m.shape)
    print(f"least clearance {least['least_m']!r} m at {least['time_s']} s between {least['between']}; "
          f"series minimum {r.clearances_m[k, j]!r} m at {r.t_s[k]} s between {r.clearance_pairs[j]}")
    assert 1.0 < least["time_s"] < 6.0, "a minimum inside the run, not at its end"
    assert r.clearances_m[k, j] == least["least_m"]
    assert r.t_s[k] == least["time_s"]
    assert r.clearance_pairs[j] == tuple(least["between"])
    # Each pair's own least distance is its column's minimum, and the accessor finds the column.
    for p in r.summary["clearances"]:
        col = r.clearance_m(*p["between"])
        assert np.nanmin(col) == p["least_m"] and col[0] == p["initial_m"] and col[-1] == p["final_m"], p["between"]
    assert all(0.0 <= f <= 1.0 for f in least["at_fraction"])


def test_an_equilibrium_start_carries_the_weight_on_its_supports(tmp_path: Path) -> None:
    path = shortened("e_three_phases_wind.toml", 1.0, "[0.0]", tmp_path)
    sc = ohl.load_line(path)
    r = ohl.run_line(sc)
    g = 9.81  # [loads] gravity_m_per_s2, its default (docs/scenario.md); case (e) does not set it
    # Linear density [kg/m] and the mass of each string [kg] (2 suspension strings per conductor), from
    # the case file: ACSR Drake 1.628 kg/m (data/conductors.toml) on 100 kg strings, the earth wire
    # 0.407 kg/m on 20 kg clamps.
    density = {"A": 1.628, "B": 1.628, "C": 1.628, "earth wire": 0.407}
    strings = {"A": 200.0, "B": 200.0, "C": 200.0, "earth wire": 40.0}
    weight = 0.0
    vertical = 0.0
    for name, c in r.conductors.items():
        length = c.snapshots.s_m[0, -1]  # the unstretched length: the Lagrangian coordinate of the last node
        weight += (density[name] * length + strings[name]) * g
        vertical += c.support_forces_n[0, :, 2].sum()  # its own supports (the dead-ends) at t = 0
    vertical += r.tower_forces_n[0, :, 2].sum()  # the towers (the strings on them) at t = 0
    # Bound: the Newton solve stops with every free node's residual below residual_n; summed over the
    # free nodes the internal forces cancel, so the supports' loads miss the weight by at most
    # (nodes) * residual_n, plus the rounding of sums of about 500 terms of 1e4 N (500 * 1e4 * 2.2e-16).
    e = sc.initial_equilibrium
    nodes = sum(n + 1 for n in sc.segments.values())
    bound = nodes * e["residual_n"] + 500 * 1e4 * 2.2e-16
    print(f"weight {weight!r} N, support loads {-vertical!r} N, difference {vertical + weight:.3e} N, bound {bound:.3e} N "
          f"({nodes} nodes x residual {e['residual_n']:.3e} N)")
    assert abs(vertical + weight) <= bound


def test_line_equilibrium_is_the_state_an_equilibrium_start_runs_from(tmp_path: Path) -> None:
    path = shortened("e_three_phases_wind.toml", 1.0, "[0.0]", tmp_path)
    equilibrium_start = ohl.run_line(path)
    strung = ohl.loads_line(path.read_text().replace('shape = "equilibrium"', 'shape = "strung"'), "strung")
    assert strung.initial_equilibrium is None
    e = ohl.line_equilibrium(strung)
    assert e["iterations"] > 0 and e["residual_n"] <= e["tolerance_n"]
    assert ohl.equilibrium(strung)["residual_n"] == e["residual_n"]  # ohl.equilibrium takes a line too
    for name, c in equilibrium_start.conductors.items():
        assert_bitwise(e["conductors"][name]["x_m"], c.snapshots.x_m[0], f"{name} x_m")
        assert_bitwise(e["conductors"][name]["node_tension_n"], c.snapshots.tension_n[0], f"{name} tension")
        assert_bitwise(e["conductors"][name]["support_forces_n"], c.support_forces_n[0], f"{name} support forces")
    assert e["towers"] == equilibrium_start.towers
    assert_bitwise(e["tower_forces_n"], equilibrium_start.tower_forces_n[0], "tower forces")
    # The solve of the equilibrium start is the same solve.
    assert ohl.load_line(path).initial_equilibrium["iterations"] == e["iterations"]


def test_invalid_lines_give_the_command_lines_message(tmp_path: Path, ohl_cli: Path) -> None:
    text = (REPO / "cases" / "e_three_phases_wind.toml").read_text()
    text = text.replace('towers = ["", "T2", "T3", ""]', 'towers = ["", "T9", "T3", ""]', 1)
    text = text.replace("axial_stiffness_n = 9.5e6", "axial_stiffness_n = -9.5e6")
    path = tmp_path / "bad.toml"
    path.write_text(text)
    p = cli(ohl_cli, "run", str(path), "--out", str(tmp_path / "out"), "--quiet")
    assert p.returncode == 2
    with pytest.raises(ohl.ScenarioError) as e:
        ohl.load_line(path)
    assert "error: " + str(e.value) == p.stderr.strip()
    assert e.value.file == str(path)
    fields = [q.field for q in e.value.problems]
    assert fields == ["line.conductors[0].towers[1]", "line.conductors[3].conductor.axial_stiffness_n"], fields
    # The same checks from a dict, named <dict>.
    d = uncoupled_line()
    d["line"]["conductors"][1]["conductor"] = {**CONDUCTOR, "axial_stiffness_n": -2.9e7}
    with pytest.raises(ohl.ScenarioError, match=r"^<dict>: field `line.conductors\[1\].conductor.axial_stiffness_n`"):
        ohl.run_line(d)
    # A single-conductor scenario is not a line, and a line is not a single-conductor scenario.
    with pytest.raises(ohl.ScenarioError, match="no \\[line\\] table.*ohl.load"):
        ohl.load_line(REPO / "cases" / "a_broken_conductor.toml")
    with pytest.raises(ohl.ScenarioError, match="ohl.load_line"):
        ohl.run(REPO / "cases" / "e_three_phases_wind.toml")


def test_above_the_budget_is_refused_as_the_command_line_refuses_it(tmp_path: Path, ohl_cli: Path) -> None:
    path = tmp_path / "long.toml"
    path.write_text((REPO / "cases" / "e_three_phases_wind.toml").read_text().replace("end_time_s = 40.0", "end_time_s = 1.0e6"))
    p = cli(ohl_cli, "run", str(path), "--out", str(tmp_path / "out"), "--quiet")
    assert p.returncode == 2
    sc = ohl.load_line(path)
    assert not sc.work_estimate()["within_budget"]
    with pytest.raises(ohl.WorkBudgetError) as e:
        ohl.run_line(sc)
    assert "error: " + str(e.value) == p.stderr.strip()
    assert e.value.estimate["node_steps"] > 2e10


def test_an_unstable_line_raises_with_the_conductor_and_the_run_so_far(tmp_path: Path) -> None:
    d = uncoupled_line()
    d["numerics"] = {**d["numerics"], "max_speed_m_per_s": 0.01}
    with pytest.raises(ohl.UnstableError) as e:
        ohl.run_line(d)
    u = e.value
    assert u.conductor in ("A", "B") and u.time_s > 0.0 and u.conductor in str(u)
    assert isinstance(u.result, ohl.LineResult) and u.result.status == "unstable"
    assert u.result.summary["instability"] is not None
    assert len(u.result["A"].t_s) > 0 and pickle.loads(pickle.dumps(u)).conductor == u.conductor


def test_scenario_properties_and_pickle(tmp_path: Path) -> None:
    sc = ohl.load_line(REPO / "cases" / "g_quad_bundle_break.toml")
    assert sc.groups == {"A": ["A.1", "A.2", "A.3", "A.4"]}  # one quad bundle
    assert sc.conductors == sc.groups["A"] and sc.roles == ["sub_conductor"] * 4
    assert sc.clearance_pairs == []  # a bundle's clearance is to other groups
    assert sc.columns["A.1"][:2] == ["t_s", "tau"] and sc.probes["A.1"][0] == "mid"
    assert all(f"{p}_dx1_m" in sc.columns["A.1"] for p in sc.probes["A.1"])
    e = sc.work_estimate()
    assert e["within_budget"] and e["conductors"] == 4 and e["nodes"] == sum(n + 1 for n in sc.segments.values())
    again = pickle.loads(pickle.dumps(sc))
    assert again.toml == sc.toml and again.file == sc.file and again.conductors == sc.conductors
    with pytest.raises(TypeError, match="ohl.loads_line"):
        ohl.run_line(42)  # type: ignore[arg-type]


@pytest.mark.skipif(sys.version_info < (3, 11), reason="tomllib (reading TOML into a dict) needs Python 3.11")
def test_a_line_dict_equals_its_toml(tmp_path: Path) -> None:
    import tomllib

    path = shortened("e_three_phases_wind.toml", 1.5, "[1.0]", tmp_path)
    text = path.read_text()
    a = ohl.run_line(ohl.loads_line(text))
    b = ohl.run_line(tomllib.loads(text))
    for name in a.conductors:
        assert_bitwise(a[name].table, b[name].table, name)
    assert_bitwise(a.clearances_m, b.clearances_m, "clearances")
    assert without_timing(a.summary) == without_timing(b.summary)


def test_a_line_run_releases_the_gil_and_stops_on_ctrl_c(tmp_path: Path) -> None:
    """As `test_threads.py` for one conductor: while a line runs in a thread this thread keeps executing
    (its longest pause far below the run's duration), and SIGINT stops a line run with
    KeyboardInterrupt long before its end (case (e), 40 s simulated, takes several seconds)."""
    import signal
    import threading
    import time

    # 8 s simulated, doubled until the run takes 0.2 s on this machine (case e runs 20 s in about 0.5 s of
    # CPU on a Zen 5, so 8 s is near the bound there)
    sc, duration = run_lasting(
        (8.0, 16.0, 32.0),
        lambda end: ohl.load_line(shortened("e_three_phases_wind.toml", end, "[1.0]", tmp_path)),
        ohl.run_line,
    )
    assert duration > 0.2, f"the run is too short ({duration:.3f} s) to tell"
    done = threading.Event()
    worker = threading.Thread(target=lambda: (ohl.run_line(sc), done.set()))
    longest, last = 0.0, time.perf_counter()
    worker.start()
    while not done.is_set():
        now = time.perf_counter()
        longest, last = max(longest, now - last), now
    worker.join()
    assert longest < 0.5 * duration, f"this thread paused {longest:.3f} s during a {duration:.3f} s run"

    full = ohl.load_line(REPO / "cases" / "e_three_phases_wind.toml")
    before = signal.signal(signal.SIGINT, signal.default_int_handler)
    timer = threading.Timer(0.3, lambda: signal.raise_signal(signal.SIGINT))
    start = time.perf_counter()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            ohl.run_line(full)
    finally:
        timer.cancel()
        signal.signal(signal.SIGINT, before)
    stopped = time.perf_counter() - start
    print(f"a {duration:.2f} s line run; SIGINT at 0.3 s stopped the full case after {stopped:.2f} s")
    assert stopped < 0.5 * 5 * duration  # the full case is 5 times the one timed above
