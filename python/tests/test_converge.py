"""`ohl.converge`: the study of `ohl run --converge` from Python (docs/convergence.md). The same numbers as
the command's `convergence.json` (both are the same Rust code; compared bit for bit here), the exact
elastic catenary inside the GCI band of the settled sag (the derivation of the order tolerance is in
`app/tests/converge.rs`), and the budget refusal."""

from __future__ import annotations

from pathlib import Path

import pytest

import ohl

from conftest import REPO, cli, read_json


def settled_catenary(tmp_path: Path) -> Path:
    """Paper case fig2b run to rest on 20 segments (levels 20, 40, 80): mass damping 2 /s, 150 s."""
    text = (REPO / "paper_cases" / "fig2b_catenary.toml").read_text()
    text = (
        text.replace("segments = 50", "segments = 20")
        .replace("end_time_s = 260.8", "end_time_s = 150.0")
        .replace("[numerics]\n", "[numerics]\nmass_damping_per_s = 2.0\n")
        .replace("sample_interval_s = 0.02", "sample_interval_s = 1.0")
    )
    f = tmp_path / "catenary.toml"
    f.write_text(text)
    return f


def test_converge_gives_the_commands_table_and_the_exact_sag_in_its_band(tmp_path: Path, ohl_cli: Path) -> None:
    f = settled_catenary(tmp_path)
    study = ohl.converge(f, tmp_path / "py", rtol=1e-3)
    assert [lv["segments"] for lv in study["levels"]] == [20, 40, 80]
    q = {x["path"]: x for x in study["quantities"]}["final_midspan_displacement_m[2]"]
    e = q["estimate"]
    assert e["behaviour"] == "converging" and abs(e["order"] - 2.0) <= 0.02
    # The exact elastic catenary of the paper's data (docs/verification.md, study `exact`): 7.262345142 m
    # sag, to the 10 printed digits; the GCI band is 4.7e-4 m.
    exact = -7.262345142
    assert abs(e["extrapolate"] - exact) <= e["gci_fine_abs"]
    assert q["verdict"] == "converged within rtol"
    # The command on the same file: the same numbers, bit for bit (wall times aside).
    r = cli(ohl_cli, "run", str(f), "--out", str(tmp_path / "cli"), "--converge", "--rtol", "1e-3", "--quiet")
    assert r.returncode == 0, r.stderr
    written = read_json(tmp_path / "cli" / "convergence.json")
    assert [x["values"] for x in written["quantities"]] == [x["values"] for x in study["quantities"]]
    assert [x["verdict"] for x in written["quantities"]] == [x["verdict"] for x in study["quantities"]]
    assert read_json(tmp_path / "py" / "convergence.json")["quantities"] == study["quantities"]


def test_converge_above_the_budget_raises_with_the_estimate(tmp_path: Path) -> None:
    with pytest.raises(ohl.WorkBudgetError, match=r"needs 1\.166e8 node-steps"):
        ohl.converge(REPO / "paper_cases" / "fig2b_catenary.toml", tmp_path / "out", budget=1e6)
    assert not (tmp_path / "out").exists()
    with pytest.raises(ValueError, match="rtol"):
        ohl.converge(REPO / "paper_cases" / "fig2b_catenary.toml", tmp_path / "out", rtol=0.0)
    with pytest.raises(ValueError, match="refine"):
        ohl.converge(REPO / "paper_cases" / "fig2b_catenary.toml", tmp_path / "out", refine="space")


def test_converge_on_a_line_pairs_its_clearances(tmp_path: Path) -> None:
    """Case e (three phases and an earth wire in wind) on 10, 20, 40 segments per span for 5 s: its
    clearances are paired, and each quantity's finest value is the number of the finest run's summary."""
    text = (REPO / "cases" / "e_three_phases_wind.toml").read_text()
    text = text.replace("segments_per_span = 40", "segments_per_span = 10").replace("end_time_s = 40.0", "end_time_s = 5.0")
    text = "\n".join(l for l in text.splitlines() if not l.startswith("snapshot_times_s")) + "\n"
    f = tmp_path / "e.toml"
    f.write_text(text)
    study = ohl.converge(f, tmp_path / "out")
    summary = read_json(tmp_path / "out" / "summary.json")
    paths = [q["path"] for q in study["quantities"]]
    assert any(p.startswith("clearances[") for p in paths)
    least = {q["path"]: q for q in study["quantities"]}["clearances[0].least_m"]
    assert least["values"][2] == summary["clearances"][0]["least_m"]
