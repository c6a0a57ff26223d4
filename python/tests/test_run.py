"""Runs from Python against the same runs of the `ohl` command line, bit for bit: `timeseries.csv`
against `RunResult.table`, `snapshots.csv` against `RunResult.snapshots`, `summary.json` against
`RunResult.summary` (less its wall-clock timings)."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

import ohl
from conftest import REPO, assert_bitwise, cli, read_csv, read_json, without_timing

# The README's example (weight release with a side wind), with a named probe, snapshots and an event.
README_EXAMPLE = """
name = "weight release with side wind"

[conductor]
axial_stiffness_n = 791999.5
linear_density_kg_per_m = 1.0
diameter_m = 0.01553

[geometry]
left_support_m = [0.0, 0.0, 0.0]
right_support_m = [0.0, 160.0, 5.0]
segments = 50

[loads]
gravity_m_per_s2 = 9.81

[loads.wind]
law = "aerodynamic"
direction = [1.0, 0.0, 0.0]
speed_m_per_s = 20.0

[numerics]
courant = 0.9
smoothing = 0.02
mu = 0.15

[duration]
end_time_s = 10.0

[output]
sample_interval_s = 0.05
snapshot_times_s = [1.0, 5.0]
probes = [{ name = "quarter", at_fraction = 0.25 }]

[[events]]
time_s = 6.0
action = "gust"
period_s = 1.0
amplitude = 0.5
"""

CASES = [
    "readme_example",
    "paper_cases/fig4_break_fall.toml",  # a break, the ground, snapshots
    "paper_cases/fig6_deicing.toml",  # heat conduction and thermal expansion
    "cases/a_broken_conductor.toml",  # a section: strings, crossarms, spans, per-span columns
    "cases/d_deicing.toml",  # [thermal]: the temperature column, de-icing and shedding
]


def scenario_path(case: str, tmp_path: Path) -> Path:
    if case == "readme_example":
        p = tmp_path / "readme_example.toml"
        p.write_text(README_EXAMPLE)
        return p
    return REPO / case


def check_against_cli(result: ohl.RunResult, out: Path, segments: int) -> None:
    header, table = read_csv(out / "timeseries.csv")
    assert header == result.columns
    assert_bitwise(result.table, table, "timeseries.csv")
    for k, c in enumerate(header):
        assert_bitwise(result[c], table[:, k], c)

    sh, snaps = read_csv(out / "snapshots.csv")
    assert sh == ["t_s", "tau", "node", "s_m", "x1_m", "x2_m", "x3_m", "v1_m_per_s", "v2_m_per_s", "v3_m_per_s", "tension_n"]
    nodes = segments + 1
    s = snaps.reshape(-1, nodes, len(sh))
    r = result.snapshots
    assert len(r) == s.shape[0]
    assert_bitwise(r.t_s, s[:, 0, 0], "snapshot t_s")
    assert_bitwise(r.tau, s[:, 0, 1], "snapshot tau")
    assert (s[:, :, 2] == np.arange(nodes)).all()
    assert_bitwise(r.s_m, s[:, :, 3], "s_m")
    assert_bitwise(r.x_m, s[:, :, 4:7], "x_m")
    assert_bitwise(r.v_m_per_s, s[:, :, 7:10], "v_m_per_s")
    assert_bitwise(r.tension_n, s[:, :, 10], "tension_n")

    assert without_timing(result.summary) == without_timing(read_json(out / "summary.json"))


@pytest.mark.parametrize("case", CASES)
def test_run_equals_the_command_line(case: str, tmp_path: Path, ohl_cli: Path) -> None:
    path = scenario_path(case, tmp_path)
    out = tmp_path / "cli"
    p = cli(ohl_cli, "run", str(path), "--out", str(out), "--quiet")
    assert p.returncode == 0, p.stderr
    sc = ohl.load(path)
    result = ohl.run(sc)
    assert result.status == result.summary["status"] == read_json(out / "summary.json")["status"]
    check_against_cli(result, out, sc.segments)
    # The named views are columns of the same table.
    assert_bitwise(result.t_s, result["t_s"])
    assert_bitwise(result.mid_displacement_m[:, 2], result["mid_dx3_m"])
    assert result.support_forces_n.shape == (len(result.t_s), len(sc.supports), 3)
    assert_bitwise(result.support_forces_n[:, -1, 2], result[f"support{len(sc.supports) - 1}_f3_n"])
    assert set(result.probes) == set(sc.probes)
    assert [e[1] for e in result.events] == [e["what"] for e in result.summary["events"]]


def test_out_dir_writes_the_command_lines_files(tmp_path: Path, ohl_cli: Path) -> None:
    path = scenario_path("readme_example", tmp_path)
    p = cli(ohl_cli, "run", str(path), "--out", str(tmp_path / "cli"), "--quiet")
    assert p.returncode == 0, p.stderr
    r = ohl.run(path, out_dir=tmp_path / "py")
    for f in ("timeseries.csv", "snapshots.csv"):
        assert (tmp_path / "py" / f).read_bytes() == (tmp_path / "cli" / f).read_bytes(), f
    assert without_timing(read_json(tmp_path / "py" / "summary.json")) == without_timing(r.summary)


@pytest.mark.skipif(sys.version_info < (3, 11), reason="tomllib (reading TOML into a dict) needs Python 3.11")
@pytest.mark.parametrize("case", ["readme_example", "cases/a_broken_conductor.toml"])
def test_dict_input_equals_toml_input(case: str, tmp_path: Path) -> None:
    import tomllib

    text = scenario_path(case, tmp_path).read_text()
    from_text = ohl.run(ohl.loads(text))
    d = tomllib.loads(text)
    from_dict = ohl.run(d)
    assert from_dict.columns == from_text.columns
    assert_bitwise(from_dict.table, from_text.table, "time series")
    assert_bitwise(from_dict.snapshots.x_m, from_text.snapshots.x_m, "snapshots")
    assert without_timing(from_dict.summary) == without_timing(from_text.summary)
    # The dict's TOML reads back to the same dict.
    assert tomllib.loads(ohl.from_dict(d).toml) == d


def test_int_and_float_in_a_dict() -> None:
    d = {
        "conductor": {"axial_stiffness_n": 792000, "linear_density_kg_per_m": 1},
        "geometry": {"left_support_m": [0, 0, 0], "right_support_m": [0, 160, 0], "segments": 20},
        "duration": {"end_time_s": 1},
    }
    # Whole numbers are fine where a number is expected (as in TOML), and give the same run as floats.
    as_floats = {
        "conductor": {"axial_stiffness_n": 792000.0, "linear_density_kg_per_m": 1.0},
        "geometry": {"left_support_m": [0.0, 0.0, 0.0], "right_support_m": [0.0, 160.0, 0.0], "segments": 20},
        "duration": {"end_time_s": 1.0},
    }
    assert_bitwise(ohl.run(d).table, ohl.run(as_floats).table)
    # A whole-number field refuses a float, as a TOML file does.
    d["geometry"]["segments"] = 20.0
    with pytest.raises(ohl.ScenarioError, match="expected a whole number"):
        ohl.from_dict(d)
    # NumPy numbers are taken by value.
    d["geometry"]["segments"] = np.int64(20)
    d["geometry"]["right_support_m"] = np.array([0.0, 160.0, 0.0])
    assert ohl.from_dict(d).segments == 20
    # None cannot be written to TOML: an error of the dict, at its field (python/README.md, "Errors").
    with pytest.raises(ohl.ScenarioError, match="geometry.segments") as e:
        ohl.from_dict({**d, "geometry": {**d["geometry"], "segments": None}})
    assert (e.value.field, e.value.value) == ("geometry.segments", "None")


def test_scenario_properties(tmp_path: Path) -> None:
    sc = ohl.load(scenario_path("readme_example", tmp_path))
    assert sc.name == "weight release with side wind"
    assert sc.segments == 50
    assert sc.probes == ["mid", "quarter"]
    assert sc.snapshot_times_s == [1.0, 5.0]
    assert sc.end_time_s == 10.0
    assert [s[0] for s in sc.supports] == [0, 50]
    assert sc.supports[1][1] == [0.0, 160.0, 5.0]
    e = sc.work_estimate()
    assert e["within_budget"] and e["segments"] == 50.0
    r = ohl.run(sc)
    assert r.columns == sc.columns
    assert r.probes["quarter"].shape == (len(r.t_s), 3)
    assert r.temperature_k is None
    assert set(r.energies) == {"kinetic_j", "elastic_j", "potential_j", "total_j"}
    # The final state is the last snapshot.
    assert r.snapshots.t_s[-1] == r.summary["final_time_s"] == 10.0
    assert_bitwise(r.snapshots.x_m[-1, 0], [0.0, 0.0, 0.0])
    # A scenario pickles through its TOML text.
    import pickle

    again = pickle.loads(pickle.dumps(sc))
    assert again.toml == sc.toml and again.file == sc.file
    assert_bitwise(ohl.run(again).table, r.table)


def test_to_pandas(tmp_path: Path) -> None:
    pd = pytest.importorskip("pandas", reason="pandas is optional")
    r = ohl.run(scenario_path("readme_example", tmp_path))
    df = r.to_pandas()
    assert list(df.columns) == r.columns
    assert_bitwise(df["max_tension_n"].to_numpy(), r.max_tension_n)
