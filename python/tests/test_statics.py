"""The static equilibrium (Newton) from Python: bit for bit the initial state `ohl run` starts from with
`[initial] shape = "equilibrium"`, and in balance with the loads."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import ohl
from conftest import REPO, assert_bitwise, cli, read_csv, read_json

SPAN = """
name = "statics"
[conductor]
axial_stiffness_n = 2.9e7
linear_density_kg_per_m = 1.628
diameter_m = 0.0281
[geometry]
left_support_m = [0.0, 0.0, 30.0]
right_support_m = [0.0, 400.0, 20.0]
segments = 80
[initial]
shape = "{shape}"
sag_m = 12.0
[loads.wind]
law = "aerodynamic"
speed_m_per_s = 15.0
[duration]
end_time_s = 0.01
[output]
snapshot_times_s = [0.0]
"""


def test_equilibrium_is_the_command_lines_initial_state(tmp_path: Path, ohl_cli: Path) -> None:
    path = tmp_path / "eq.toml"
    path.write_text(SPAN.replace("{shape}", "equilibrium"))
    p = cli(ohl_cli, "run", str(path), "--out", str(tmp_path / "out"), "--quiet")
    assert p.returncode == 0, p.stderr
    header, snaps = read_csv(tmp_path / "out" / "snapshots.csv")
    first = snaps[snaps[:, 0] == 0.0]
    assert first.shape[0] == 81

    # From the same parabola (same nodes, same unstretched length) the Newton solve gives the same state.
    e = ohl.equilibrium(ohl.loads(SPAN.replace("{shape}", "parabola")))
    assert_bitwise(e["x_m"], first[:, 4:7], "x_m")
    assert_bitwise(e["s_m"], first[:, 3], "s_m")
    assert_bitwise(e["node_tension_n"], first[:, 10], "node tension")
    assert e["iterations"] > 0 and e["residual_n"] <= e["tolerance_n"]
    assert len(e["residual_history_n"]) == e["iterations"] + 1
    # The scenario solved at load time reports the same solve.
    sc = ohl.load(path)
    assert sc.initial_equilibrium["iterations"] == e["iterations"]
    assert sc.initial_equilibrium["residual_n"] == e["residual_n"]


def test_equilibrium_balances_the_loads() -> None:
    d = {
        "conductor": {"axial_stiffness_n": 2.9e7, "linear_density_kg_per_m": 1.628},
        "geometry": {"left_support_m": [0.0, 0.0, 0.0], "right_support_m": [0.0, 400.0, 0.0], "segments": 100},
        "initial": {"shape": "parabola", "sag_m": 10.0},
        "duration": {"end_time_s": 1.0},
    }
    e = ohl.equilibrium(d)
    x = e["x_m"]
    length = np.sum(np.diff(e["s_m"]))
    weight = 1.628 * 9.81 * length
    f = e["support_forces_n"]
    assert e["support_nodes"] == [0, 100]
    # The supports carry the weight (the wire pulls them down), and the level span symmetrically.
    assert f[:, 2].sum() == pytest.approx(-weight, rel=1e-9)
    assert f[0, 2] == pytest.approx(f[1, 2], rel=1e-9)
    assert f[0, 1] == pytest.approx(-f[1, 1], rel=1e-9)
    # Tension everywhere, largest at the supports; the lowest point at mid-span.
    assert (e["segment_tension_n"] > 0).all()
    assert e["max_tension_n"] == e["segment_tension_n"].max()
    assert np.argmin(x[:, 2]) == 50
    assert e["midspan_displacement_m"][2] == x[50, 2]


def test_equilibrium_that_does_not_converge() -> None:
    with pytest.raises(ohl.StaticsError, match="did not converge"):
        ohl.equilibrium(ohl.loads(SPAN.replace("{shape}", "parabola")), max_iterations=1)


def test_static_after_a_run_is_the_command_lines_static_json(tmp_path: Path, ohl_cli: Path) -> None:
    """`ohl.run(..., static_after=True)` solves the residual static state of the broken conductor (case
    (a): the conductor broken at the first dead-end, the piece hanging from support 1 to the ground and
    lying on it) and gives the numbers of `ohl run --static-after`'s static.json bit for bit. Independent
    checks: the support loads and the ground's reaction balance the weight of the section (five spans of
    conductor at their unstretched lengths and four 100 kg strings) to 1e-6 (the Newton tolerance is 1e-10
    of the nodal loads), and nothing is left along the line (sum of f2, 1e-6 of the weight)."""
    case = REPO / "cases" / "a_broken_conductor.toml"
    p = cli(ohl_cli, "run", str(case), "--out", str(tmp_path / "cli"), "--static-after", "--quiet")
    assert p.returncode == 0, p.stderr
    r = ohl.run(case, out_dir=tmp_path / "py", static_after=True)
    st = r.static
    assert st is not None
    assert read_json(tmp_path / "py" / "static.json") == read_json(tmp_path / "cli" / "static.json")
    written = read_json(tmp_path / "cli" / "static.json")
    for k, sup in enumerate(written["supports"]):
        assert sup["force_n"] == st["supports"][k]["force_n"]
        assert_bitwise(np.array(sup["force_n"]), st["support_forces_n"][k], f"support {k}")
    assert written["spans"] == st["spans"]
    assert st["spans"][0]["sag_m"] is None and all(s["sag_m"] > 0 for s in st["spans"][1:])
    # The weight: what the supports carry in the intact section's equilibrium without the ground and the
    # break (the same masses: case (a) has no ice).
    text = case.read_text()
    intact = text[: text.index("[ground]")] + text[text.index("[duration]") : text.index("[[events]]")]
    weight = -ohl.equilibrium(ohl.loads(intact))["support_forces_n"][:, 2].sum()
    f = np.array([s["force_n"] for s in st["supports"]])
    assert f.shape == (len(r.scenario.supports), 3)
    assert abs(f[:, 2].sum() - st["ground_reaction_n"][2] + weight) < 1e-6 * weight
    assert abs(f[:, 1].sum()) < 1e-6 * weight
    # The ground carries most of the fallen 400 m piece.
    assert st["ground_reaction_n"][2] > 0.8 * 400 * 1.628 * 9.80665
    assert ohl.run(case).static is None


def test_static_after_is_refused_for_a_line_before_it_runs() -> None:
    """As `ohl run --static-after` on a `[line]` (exit 2): not available yet, refused before the run."""
    line = ohl.load_line(REPO / "cases" / "e_three_phases_wind.toml")
    with pytest.raises(ValueError, match="static_after is not available for a line scenario"):
        ohl.run(line, static_after=True)
