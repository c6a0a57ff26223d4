"""Errors: an invalid scenario raises `ohl.ScenarioError` (a `ValueError`) with the file, the field, the
value and the allowed range, and the message `ohl run` prints; a missing file `FileNotFoundError`; a run
above the work budget `ohl.WorkBudgetError`; an unstable run `ohl.UnstableError` with the result so far."""

from __future__ import annotations

import errno
import pickle
from pathlib import Path

import numpy as np
import pytest

import ohl
from conftest import REPO, assert_bitwise, cli, read_csv

# app/tests/bad_inputs/: the command line's bad inputs, and one valid control case.
BAD = sorted(p for p in (REPO / "app" / "tests" / "bad_inputs").glob("*.toml") if p.stem != "valid")


def test_the_control_case_is_valid() -> None:
    assert ohl.load("app/tests/bad_inputs/valid.toml").segments > 0


def cli_error(binary: Path, path: str) -> str:
    p = cli(binary, "run", path, "--out", "/nonexistent/never-written", "--quiet")
    assert p.returncode == 2, (path, p.returncode, p.stderr)
    lines = [line for line in p.stderr.splitlines() if not line.startswith("warning: ")]
    text = "\n".join(lines)
    assert text.startswith("error: ")
    return text[len("error: ") :]


@pytest.mark.parametrize("path", BAD, ids=[p.stem for p in BAD])
def test_every_bad_input_gives_the_command_lines_message(path: Path, ohl_cli: Path) -> None:
    rel = str(path.relative_to(REPO))
    if path.stem == "scenario_given_to_thermal":
        # A valid scenario, refused by `ohl thermal` (test_thermal covers the thermal functions).
        assert ohl.load(rel).segments > 0
        return
    if path.stem == "heat_conduction_above_budget":
        # Valid, but above the work budget: refused by `ohl run` and by `ohl.run`, not by loading.
        with pytest.raises(ohl.WorkBudgetError, match="heat node updates"):
            ohl.run(ohl.load(rel))
        assert "heat node updates" in cli_error(ohl_cli, rel)
        return
    # A line scenario ([line]: droppers, short circuits) is read by `ohl.load_line`, as `ohl run` reads it.
    load = ohl.load_line if b"\n[line]" in b"\n" + path.read_bytes() else ohl.load
    with pytest.raises(ohl.ScenarioError) as e:
        load(rel)
    if b"[rod]" in path.read_bytes():
        # A heat-conduction case of the paper: `ohl run` refuses it before parsing, pointing to `ohl paper`
        # (an application of the command line, not of the library); the package reports what the library
        # finds, the unknown tables of a wire scenario.
        assert "a heat-conduction case" in cli_error(ohl_cli, rel)
        assert "unknown field" in str(e.value)
        return
    assert str(e.value) == cli_error(ohl_cli, rel)
    assert isinstance(e.value, ValueError)
    # An error inside a user conductor catalogue names the catalogue, and the case that reads it.
    assert e.value.file == rel or e.value.file.endswith(f"(conductor_catalog of {rel})")
    if e.value.problems:
        first = e.value.problems[0]
        assert (e.value.field, e.value.value, e.value.allowed) == (first.field, first.value, first.allowed)
        assert len(e.value.problems) == len(str(e.value).splitlines())
        for p, line in zip(e.value.problems, str(e.value).splitlines()):
            assert line == f"{e.value.file}: field `{p.field}` = {p.value} is not allowed: {p.allowed}"
    else:  # a syntax or type error: line and column in the message
        assert e.value.field is None and e.value.value is None and e.value.allowed is None


def test_field_value_and_range() -> None:
    with pytest.raises(ohl.ScenarioError) as e:
        ohl.load("app/tests/bad_inputs/courant_above_one.toml")
    assert e.value.file == "app/tests/bad_inputs/courant_above_one.toml"
    assert e.value.field == "numerics.courant"
    assert e.value.value == "1.5"
    assert e.value.allowed == "must be in (0, 1]"
    assert str(e.value) == (
        "app/tests/bad_inputs/courant_above_one.toml: field `numerics.courant` = 1.5 is not allowed: must be in (0, 1]"
    )


def test_a_temperature_in_celsius_is_checked_in_celsius() -> None:
    # Issue 23: a dict (as a file) may give a temperature as `NAME_c` [C] instead of `NAME_k` [K], not both;
    # a Celsius value out of range is reported in Celsius (the range of the kelvin field less 273.15).
    d = {
        "conductor": {"axial_stiffness_n": 792000.0, "linear_density_kg_per_m": 1.0, "reference_temperature_c": 15.0},
        "geometry": {"left_support_m": [0.0, 0.0, 0.0], "right_support_m": [0.0, 160.0, 0.0], "segments": 20},
        "duration": {"end_time_s": 0.5},
    }
    ohl.from_dict(d)
    d["conductor"]["reference_temperature_k"] = 288.15
    with pytest.raises(ohl.ScenarioError) as e:
        ohl.from_dict(d)
    assert e.value.field == "conductor.reference_temperature_c"
    assert "`conductor.reference_temperature_k` is given too" in e.value.allowed
    del d["conductor"]["reference_temperature_k"]
    d["conductor"]["reference_temperature_c"] = -300.0
    with pytest.raises(ohl.ScenarioError) as e:
        ohl.from_dict(d)
    assert (e.value.field, e.value.value, e.value.allowed) == (
        "conductor.reference_temperature_c",
        "-300",
        "must be in [-100, 4726.85] C",
    )


def test_several_problems_are_all_reported() -> None:
    with pytest.raises(ohl.ScenarioError) as e:
        ohl.load("app/tests/bad_inputs/ground_above_support.toml")
    assert len(e.value.problems) == 2
    assert e.value.problems[0].field == "ground.restitution"


def test_from_toml_and_dict_name_the_source() -> None:
    text = (REPO / "app/tests/bad_inputs/courant_above_one.toml").read_text()
    with pytest.raises(ohl.ScenarioError) as e:
        ohl.loads(text)
    assert e.value.file == "<string>" and e.value.field == "numerics.courant"
    with pytest.raises(ohl.ScenarioError) as e:
        ohl.loads(text, name="mine.toml")
    assert str(e.value).startswith("mine.toml: field `numerics.courant`")
    d = {
        "conductor": {"axial_stiffness_n": 792000.0, "linear_density_kg_per_m": 1.0},
        "geometry": {"left_support_m": [0.0, 0.0, 0.0], "right_support_m": [0.0, 160.0, 0.0], "segments": 20},
        "numerics": {"courant": 1.5},
        "duration": {"end_time_s": 0.5},
    }
    with pytest.raises(ohl.ScenarioError) as e:
        ohl.run(d)
    assert (e.value.file, e.value.field, e.value.value) == ("<dict>", "numerics.courant", "1.5")
    d["numerics"] = {"courrant": 0.5}
    with pytest.raises(ohl.ScenarioError, match="unknown field `courrant`"):
        ohl.from_dict(d)


def test_missing_file(ohl_cli: Path) -> None:
    with pytest.raises(FileNotFoundError) as e:
        ohl.load("no/such/scenario.toml")
    # Python's form of the error (as open() raises it), with what the command line says.
    assert e.value.filename == "no/such/scenario.toml"
    assert e.value.errno == errno.ENOENT
    assert str(e.value) == "[Errno 2] No such file or directory: 'no/such/scenario.toml'"
    assert cli_error(ohl_cli, "no/such/scenario.toml") == (
        "no/such/scenario.toml: cannot read the scenario: No such file or directory (os error 2)"
    )
    with pytest.raises(FileNotFoundError):
        ohl.run("no/such/scenario.toml")


def test_a_string_is_a_path_not_toml() -> None:
    with pytest.raises(FileNotFoundError):
        ohl.run("name = 'x'\n[conductor]\n")
    with pytest.raises(TypeError, match="ohl.loads"):
        ohl.run(42)


def test_errors_pickle() -> None:
    with pytest.raises(ohl.ScenarioError) as e:
        ohl.load("app/tests/bad_inputs/ground_above_support.toml")
    again = pickle.loads(pickle.dumps(e.value))
    assert (str(again), again.file, again.field, again.value, again.allowed, again.problems) == (
        str(e.value),
        e.value.file,
        e.value.field,
        e.value.value,
        e.value.allowed,
        e.value.problems,
    )


LARGE = """
[conductor]
axial_stiffness_n = 792000.0
linear_density_kg_per_m = 1.0
[geometry]
left_support_m = [0.0, 0.0, 0.0]
right_support_m = [0.0, 160.0, 0.0]
segments = 1000
[duration]
end_time_s = 1e7
"""


def test_work_budget(tmp_path: Path, ohl_cli: Path) -> None:
    p = tmp_path / "large.toml"
    p.write_text(LARGE)
    sc = ohl.load(p)
    assert not sc.work_estimate()["within_budget"]
    with pytest.raises(ohl.WorkBudgetError) as e:
        ohl.run(sc)
    assert str(e.value) == cli_error(ohl_cli, str(p))
    assert e.value.estimate["node_steps"] > 2e10


# Undamped, no smoothing, tension-only, from the straight chord: goes unstable within seconds
# (docs/architecture.md, "Stable defaults").
UNSTABLE = """
[conductor]
axial_stiffness_n = 792000.0
linear_density_kg_per_m = 1.0
[geometry]
left_support_m = [0.0, 0.0, 0.0]
right_support_m = [0.0, 160.0, 0.0]
segments = 50
unstretched_length_m = 170.0
[numerics]
courant = 0.9
smoothing = 0.0
[duration]
end_time_s = 100.0
[output]
sample_interval_s = 0.01
"""


def test_unstable_run(tmp_path: Path, ohl_cli: Path) -> None:
    p = tmp_path / "unstable.toml"
    p.write_text(UNSTABLE)
    out = tmp_path / "cli"
    c = cli(ohl_cli, "run", str(p), "--out", str(out), "--quiet")
    assert c.returncode == 1, c.stderr
    with pytest.warns(ohl.ScenarioWarning, match="smoothing"):
        sc = ohl.load(p)
    with pytest.raises(ohl.UnstableError) as e:
        ohl.run(sc)
    u = e.value
    assert isinstance(u, RuntimeError)
    assert u.time_s < 100.0 and u.node >= 0
    # The command line's message is "PATH: REASON; output so far is in DIR".
    errors = [line for line in c.stderr.splitlines() if not line.startswith("warning: ")]
    assert errors == [f"error: {u}; output so far is in {out}"]
    r = u.result
    assert r.status == "unstable" and r.summary["instability"]["time_s"] == u.time_s
    header, table = read_csv(out / "timeseries.csv")
    assert header == r.columns
    assert_bitwise(r.table, table, "timeseries.csv up to the failure")
    assert np.isfinite(r.table).all()
