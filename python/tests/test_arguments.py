"""The error contract of the public API (python/README.md, "Errors"; issue 22): every invalid argument of
every public function and constructor raises, at the call, `ohl.ScenarioError` (a `ValueError`) naming
the field or argument, its value and what is allowed, or a `TypeError` naming the argument; an error in a
dict input names the dict's field path as the user wrote it, never a line of the TOML text the dict is
written to. One test per family: scenario dicts, line dicts, scenario constructors, runs, statics, the
thermal functions. The random inputs of every kind are in test_fuzz.py."""

from __future__ import annotations

import copy
import re
import sys
from pathlib import Path
from typing import Any, Dict

import numpy as np
import pytest

import ohl
from conftest import REPO

VALID = {
    "conductor": {"axial_stiffness_n": 792000.0, "linear_density_kg_per_m": 1.0},
    "geometry": {"left_support_m": [0.0, 0.0, 0.0], "right_support_m": [0.0, 160.0, 0.0], "segments": 20},
    "numerics": {"courant": 0.9},
    "duration": {"end_time_s": 0.5},
}
NIGHT = {"air_temperature_k": 263.15, "wind_speed_m_per_s": 2.0, "wind_angle_deg": 90.0}
DRAKE = "ACSR Drake"


def valid() -> Dict[str, Any]:
    return copy.deepcopy(VALID)


def dict_error(d: Any, line: bool = False) -> ohl.ScenarioError:
    with pytest.raises(ohl.ScenarioError) as e:
        (ohl.line_from_dict if line else ohl.from_dict)(d)
    return e.value


def problem(e: ohl.ScenarioError) -> tuple:
    """(file, field, value, allowed), checked against the message and the problems list."""
    assert str(e) == f"{e.file}: field `{e.field}` = {e.value} is not allowed: {e.allowed}"
    assert e.problems[0] == (e.field, e.value, e.allowed)
    return (e.file, e.field, e.value, e.allowed)


# --- scenario dicts ----------------------------------------------------------------------------------

INT64 = "an int must fit in 64 bits, [-2^63, 2^63 - 1] (as a TOML integer); write a float (1e30, not 10**30) for a number"
CYCLE = "must not contain itself: a dict or list cannot be one of its own items (a reference cycle)"


def test_an_int_beyond_64_bits_names_its_field() -> None:
    # Was a TypeError; a float field takes 1e30 (and then says its range), an int field refuses both.
    d = valid()
    d["numerics"]["courant"] = 10**30
    assert problem(dict_error(d)) == ("<dict>", "numerics.courant", str(10**30), INT64)
    d["numerics"]["courant"] = 1e30
    assert problem(dict_error(d)) == ("<dict>", "numerics.courant", "1e30", "must be in (0, 1]")
    d = valid()
    d["geometry"]["segments"] = -(2**63) - 1
    assert problem(dict_error(d))[1:3] == ("geometry.segments", str(-(2**63) - 1))


def test_a_self_containing_dict_or_list_names_the_cycle() -> None:
    # Was a RecursionError (and a stack overflow, a crash, through the thermal functions' weather).
    d = valid()
    d["geometry"]["again"] = d
    assert problem(dict_error(d)) == ("<dict>", "geometry.again", "<the dict that contains it>", CYCLE)
    d = valid()
    loop: list = [0.0, 0.0]
    loop.append(loop)
    d["geometry"]["left_support_m"] = loop
    assert problem(dict_error(d))[1:3] == ("geometry.left_support_m[2]", "<the list that contains it>")
    # The same dict twice, side by side, is no cycle.
    shared = {"axial_stiffness_n": 792000.0, "linear_density_kg_per_m": 1.0}
    assert ohl.from_dict({**valid(), "conductor": shared}).segments == 20
    w = dict(NIGHT)
    w["sun"] = w
    with pytest.raises(ohl.ScenarioError) as e:
        ohl.steady_temperature(800.0, conductor=DRAKE, weather=w)
    assert problem(e.value) == ("<arguments>", "weather.sun", "<the dict that contains it>", CYCLE)


def test_nesting_is_bounded() -> None:
    deep: Any = 1.0
    for _ in range(100):
        deep = [deep]
    d = valid()
    d["numerics"]["courant"] = deep
    e = dict_error(d)
    # the dict, numerics and 30 lists: 32 levels; the 31st list is refused
    assert e.field == "numerics.courant" + "[0]" * 30
    assert e.allowed == "tables and arrays may be nested at most 32 deep (the dict itself counts)"


@pytest.mark.parametrize(
    "where, value, field, shown, allowed",
    [
        (("geometry", "segments"), None, "geometry.segments", "None", "must be a value: leave the key out instead of None"),
        (("geometry", "segments"), 2.5, "geometry.segments", "2.5", "invalid type: floating point `2.5`, expected a whole number >= 0"),
        (("numerics", "courant"), "fast", "numerics.courant", '"fast"', 'invalid type: string "fast", expected a number'),
        (("numerics", "courrant"), 0.5, "numerics.courrant", "0.5", None),
        (("geometry", "right_support_m"), [0.0, 160.0], "geometry.right_support_m", "[0.0, 160.0]", "invalid length 2, expected exactly 3 components"),
        (("geometry", "left_support_m"), [0.0, "a", 0.0], "geometry.left_support_m[1]", '"a"', 'invalid type: string "a", expected a number'),
        (("conductor", "tension_law"), "plastic", "conductor.tension_law", '"plastic"', "unknown variant `plastic`, expected one of `tension_only`, `linear`, `two_material`"),
        (("numerics", "courant"), float("nan"), "numerics.courant", "NaN", "must be in (0, 1]"),
        (("numerics", "courant"), object(), "numerics.courant", None, None),
        (("numerics", "courant"), "\ud800", "numerics.courant", "'\\ud800'", "must be text that can be written as UTF-8 (no lone surrogates)"),
    ],
)
def test_a_bad_value_in_a_dict_names_its_field(where: tuple, value: Any, field: str, shown: Any, allowed: Any) -> None:
    d = valid()
    d[where[0]][where[1]] = value
    e = dict_error(d)
    got = problem(e)
    assert got[:2] == ("<dict>", field)
    if shown is not None:
        assert got[2] == shown
    if allowed is not None:
        assert got[3] == allowed
    assert not re.search(r"\bline \d", str(e)), str(e)


def test_missing_fields_keys_and_tables() -> None:
    d = valid()
    del d["geometry"]["segments"]
    assert problem(dict_error(d)) == ("<dict>", "geometry.segments", "(missing)", "missing field `segments`")
    d = valid()
    del d["conductor"]
    assert problem(dict_error(d)) == ("<dict>", "conductor", "(missing)", "missing field `conductor`")
    d = valid()
    d["geometry"][3] = 1.0
    assert problem(dict_error(d)) == ("<dict>", "geometry", "3", "a key must be a str, not int")
    d = valid()
    d["geometry"] = 3
    assert problem(dict_error(d))[1:3] == ("geometry", "3")


def test_events_name_their_entry() -> None:
    # An [[events]] entry is an internally tagged table: serde sees it whole; the entry and the field are
    # found again (the file's error points at the same field's line, test_every_bad_file_as_a_dict).
    d = valid()
    d["duration"]["end_time_s"] = 2.0
    d["events"] = [
        {"time_s": 0.1, "action": "break", "at_fraction": 0.5},
        {"time_s": 0.2, "action": "break", "at_fraction": "half"},
    ]
    e = dict_error(d)
    assert problem(e) == ("<dict>", "events[1].at_fraction", '"half"', 'invalid type: string "half", expected a number')
    d["events"][1] = {"time_s": 0.2, "action": "melt"}
    assert dict_error(d).field == "events[1].action"


def test_not_a_dict() -> None:
    for bad in ([1, 2], "name = 'x'", None, 3):
        with pytest.raises(TypeError, match=r"^argument `d` must be a dict \(a mapping\), not "):
            ohl.Scenario.from_dict(bad)
        with pytest.raises(TypeError, match=r"^argument `d` must be a dict"):
            ohl.from_dict(bad)
    with pytest.raises(TypeError, match=r"^argument `name` must be a str, not int$"):
        ohl.from_dict(valid(), 3)


@pytest.mark.skipif(sys.version_info < (3, 11), reason="tomllib (reading TOML into a dict) needs Python 3.11")
@pytest.mark.parametrize("path", sorted((REPO / "app/tests/bad_inputs").glob("*.toml")), ids=lambda p: p.stem)
def test_every_bad_file_as_a_dict(path: Path) -> None:
    """Each bad input of the command line, read into a dict: a value out of range gives the file's own
    message (the file name aside); a type error, which the file reports at a line, names the field whose
    key (or table) is on that line of the file: an independent check of the dict's field path."""
    import tomllib

    try:
        d = tomllib.loads(path.read_text(encoding="utf-8"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError):
        pytest.skip("not TOML that a dict can hold")
    rel = str(path.relative_to(REPO))
    if path.stem == "valid":
        ohl.from_dict(d)
        return
    if "weather" in d or path.stem == "scenario_given_to_thermal" or "conductor_catalog" in str(d):
        # A case of `ohl thermal` (test_thermal covers the thermal functions), a scenario given to it, or a
        # user catalogue (a path relative to the case file, which a dict does not have).
        pytest.skip("not a scenario file read by ohl.load")
    if path.stem.startswith("sagtension_"):
        # A case of `ohl sagtension` or one given to another command (test_sagtension covers them).
        pytest.skip("a sag-tension case, not a scenario file read by ohl.load")
    if path.stem == "heat_conduction_above_budget":
        pytest.skip("valid, refused by the work budget of a run (test_errors)")
    with pytest.raises(ohl.ScenarioError) as file_error:
        (ohl.load_line if "line" in d else ohl.load)(rel)
    e = dict_error(d, line="line" in d)
    assert e.file == "<dict>"
    assert not re.search(r"\bline \d", str(e)), str(e)
    if file_error.value.problems:
        assert str(e) == str(file_error.value).replace(rel, "<dict>")
        return
    assert e.field and e.problems, str(e)
    m = re.search(r"at line (\d+)", str(file_error.value))
    assert m, str(file_error.value)
    line = path.read_text(encoding="utf-8").splitlines()[int(m.group(1)) - 1]
    names = [re.sub(r"\[\d+\]", "", s) for s in e.field.split(".")]
    # the field's own key on that line, or (a missing field) its table's header
    # (missing fields of an inline table in an array: the file points at the element's own line)
    assert names[-1] in line or (e.value == "(missing)" and (names[-2] in line or "{" in line)), (e.field, line)


# --- line dicts --------------------------------------------------------------------------------------


@pytest.mark.skipif(sys.version_info < (3, 11), reason="tomllib (reading TOML into a dict) needs Python 3.11")
def test_line_dict_errors_name_the_conductor_and_the_support() -> None:
    import tomllib

    base = tomllib.loads((REPO / "cases/e_three_phases_wind.toml").read_text(encoding="utf-8"))
    at = "line.conductors[1].section.supports[2]"
    # The conductors name a catalogue conductor (filled in before reading, as the library does).
    assert base["line"]["conductors"][1]["conductor"]["catalog"] == DRAKE
    cases = [
        ("insulator_stiffness_n", "x", f"{at}.insulator_stiffness_n", '"x"', 'invalid type: string "x", expected a number'),
        ("insulator_stiffness_n", -5.0, f"{at}.insulator_stiffness_n", "-5", "must be in [1e4, 1e10] N (strings are about 1e7 to 1e8 N)"),
        ("kind", "sideways", f"{at}.kind", '"sideways"', "unknown variant `sideways`, expected `dead_end` or `suspension`"),
        ("insulator_mass_kg", None, f"{at}.insulator_mass_kg", "None", "must be a value: leave the key out instead of None"),
    ]
    for key, value, field, shown, allowed in cases:
        d = copy.deepcopy(base)
        d["line"]["conductors"][1]["section"]["supports"][2][key] = value
        assert problem(dict_error(d, line=True)) == ("<dict>", field, shown, allowed)
    d = copy.deepcopy(base)
    del d["line"]["conductors"][2]["section"]["supports"][1]["pivot_m"]
    assert problem(dict_error(d, line=True))[1:3] == ("line.conductors[2].section.supports[1].pivot_m", "(missing)")
    d = copy.deepcopy(base)
    d["line"]["conductors"][3]["conductor"]["diameter_m"] = [0.0095]
    assert problem(dict_error(d, line=True))[1:] == (
        "line.conductors[3].conductor.diameter_m",
        "[0.0095]",
        "invalid type: sequence, expected a number",
    )


# --- scenario constructors ---------------------------------------------------------------------------


def test_constructor_arguments() -> None:
    for f in (ohl.load, ohl.load_line, ohl.Scenario.from_file, ohl.LineScenario.from_file):
        with pytest.raises(TypeError, match=r"^argument `path` must be a str or os.PathLike \(a path\), not int$"):
            f(3)
        with pytest.raises(ohl.ScenarioError) as e:
            f("cases/a\0.toml")
        assert problem(e.value) == ("<arguments>", "path", "'cases/a\\x00.toml'", "must be a path without NUL characters")
    for f in (ohl.loads, ohl.loads_line, ohl.Scenario.from_toml, ohl.LineScenario.from_toml):
        with pytest.raises(TypeError, match=r"^argument `text` must be a str, not bytes$"):
            f(b"name = 'x'")
        with pytest.raises(TypeError, match=r"^argument `name` must be a str, not float$"):
            f("name = 'x'", 1.5)
    with pytest.raises(TypeError, match=r"^argument `scenario` must be an ohl.Scenario, a dict or a path"):
        ohl.run(None)


# --- runs --------------------------------------------------------------------------------------------


def test_run_arguments(tmp_path: Path) -> None:
    sc = ohl.from_dict(valid())
    for bad in ("yes", 1, None, 1.0):
        with pytest.raises(TypeError, match=r"^argument `allow_large` must be a bool \(True or False\), not "):
            ohl.run(sc, allow_large=bad)
    assert ohl.run(sc, allow_large=np.bool_(False)).status == "completed"
    with pytest.raises(TypeError, match=r"^argument `out_dir` must be a str or os.PathLike \(a path\), not int$"):
        ohl.run(sc, out_dir=3)
    with pytest.raises(ohl.ScenarioError, match="must be a path without NUL characters"):
        ohl.run(sc, out_dir=str(tmp_path / "a\0b"))
    assert not list(tmp_path.iterdir())


# --- statics -----------------------------------------------------------------------------------------

TOLERANCE = "must be None (the default) or a finite number > 0 [N]"


def test_equilibrium_arguments() -> None:
    sc = ohl.from_dict(valid())
    for bad, shown in ((float("nan"), "NaN"), (-1.0, "-1"), (0.0, "0"), (float("inf"), "inf")):
        # A NaN tolerance was accepted and failed 100 iterations later.
        with pytest.raises(ohl.ScenarioError) as e:
            ohl.equilibrium(sc, tolerance_n=bad)
        assert problem(e.value) == ("<arguments>", "tolerance_n", shown, TOLERANCE)
    with pytest.raises(ohl.ScenarioError) as e:
        ohl.equilibrium(sc, max_iterations=-1)  # was an OverflowError
    assert problem(e.value) == ("<arguments>", "max_iterations", "-1", "must be a whole number in [0, 10000]")
    # At most 100 times the default: a tolerance it cannot reach with 2**63 - 1 iterations ran for ever.
    for big in (10_001, 2**63 - 1, 2**64):
        with pytest.raises(ohl.ScenarioError) as e:
            ohl.equilibrium(sc, tolerance_n=1e-300, max_iterations=big)
        assert (e.value.field, e.value.value) == ("max_iterations", str(big))
    assert ohl.equilibrium(sc, max_iterations=10_000)["iterations"] < 100
    for bad in (1.5, "100", True, None):
        with pytest.raises(TypeError, match=r"^argument `max_iterations` must be an int, not "):
            ohl.equilibrium(sc, max_iterations=bad)
    with pytest.raises(TypeError, match=r"^argument `tolerance_n` must be a number \(an int or a float\), not str$"):
        ohl.equilibrium(sc, tolerance_n="1e-6")
    # Valid: NumPy numbers; 0 iterations only checks the start against the tolerance.
    e = ohl.equilibrium(sc, tolerance_n=np.float64(1e-6), max_iterations=np.int64(50))
    assert e["tolerance_n"] == 1e-6 and 0 < e["iterations"] <= 50 and e["residual_n"] <= 1e-6
    with pytest.raises(ohl.StaticsError, match="did not converge in 0 iterations"):
        ohl.equilibrium(sc, max_iterations=0)


# --- thermal -----------------------------------------------------------------------------------------


def test_thermal_arguments() -> None:
    with pytest.raises(TypeError, match=r"^argument `current_a` must be a number or an array of numbers, not str$"):
        ohl.steady_temperature("800", conductor=DRAKE, weather=NIGHT)
    with pytest.raises(TypeError, match=r"^argument `current_a` must be a number or an array of numbers, not list$"):
        ohl.steady_temperature([800.0, [900.0, 1.0]], conductor=DRAKE, weather=NIGHT)
    with pytest.raises(TypeError, match=r"^argument `max_temperature_k` must be a number or an array of numbers, not bool$"):
        ohl.ampacity(True, conductor=DRAKE, weather=NIGHT)
    with pytest.raises(ohl.ScenarioError) as e:
        ohl.steady_temperature(10**400, conductor=DRAKE, weather=NIGHT)
    assert e.value.field == "current_a" and e.value.allowed == "must be numbers within the range of a float (|x| < 1.8e308)"
    with pytest.raises(ohl.ScenarioError) as e:
        ohl.steady_temperature(float("nan"), conductor=DRAKE, weather=NIGHT)
    assert problem(e.value) == ("<arguments>", "current_a", "NaN", "must be in [0, 1e5] A")
    with pytest.raises(ohl.ScenarioError) as e:
        ohl.heat_terms([300.0, 310.0], [1.0, 2.0, 3.0], conductor=DRAKE, weather=NIGHT)
    assert problem(e.value)[1:] == ("current_a", "an array of shape (3,)", "must broadcast with temperature_k's shape (2,)")
    for bad in (3, "ACSR Drake", None):
        with pytest.raises(TypeError, match=r"^argument `weather` must be a dict \(a mapping\), not "):
            ohl.steady_temperature(800.0, conductor=DRAKE, weather=bad)
    with pytest.raises(TypeError, match=r"^argument `conductor` must be a str, not int$"):
        ohl.steady_temperature(800.0, conductor=795, weather=NIGHT)
    with pytest.raises(TypeError, match=r"^argument `standard` must be a str, not NoneType$"):
        ohl.steady_temperature(800.0, conductor=DRAKE, weather=NIGHT, standard=None)
    with pytest.raises(TypeError, match=r"^argument `name` must be a str, not int$"):
        ohl.conductor(3)
    # Errors inside the weather dict name its path, not a line of the case's TOML text.
    with pytest.raises(ohl.ScenarioError) as e:
        ohl.steady_temperature(800.0, conductor=DRAKE, weather={**NIGHT, "elevation_m": "high"})
    assert problem(e.value) == ("<arguments>", "weather.elevation_m", '"high"', 'invalid type: string "high", expected a number')
    with pytest.raises(ohl.ScenarioError) as e:
        ohl.steady_temperature(800.0, conductor=DRAKE, weather={**NIGHT, "sun": {"latitude_deg": 30.0, "day_of_yaer": 161}})
    assert e.value.field == "weather.sun.day_of_yaer" and e.value.allowed.startswith("unknown field `day_of_yaer`")
    with pytest.raises(ohl.ScenarioError) as e:
        ohl.steady_temperature(800.0, conductor=DRAKE, weather={**NIGHT, "elevation_m": 10**30})
    assert problem(e.value) == ("<arguments>", "weather.elevation_m", str(10**30), INT64)
    with pytest.raises(ohl.ScenarioError) as e:
        ohl.steady_temperature(800.0, conductor=DRAKE, weather=NIGHT, standard="ieee")
    assert problem(e.value) == ("<arguments>", "standard", '"ieee"', "unknown variant `ieee`, expected `ieee738` or `cigre601`")


def test_transient_and_deicing_arguments() -> None:
    with pytest.raises(ohl.ScenarioError) as e:
        ohl.transient([0.0, 800.0, 60.0], 600.0, conductor=DRAKE, weather=NIGHT)
    assert problem(e.value)[1:] == (
        "current_a",
        "an array of shape (3,)",
        "must be one current [A] or a list of (t [s], I [A]) points, shape (n, 2)",
    )
    with pytest.raises(TypeError, match=r"^argument `end_time_s` must be a number \(an int or a float\), not str$"):
        ohl.transient(800.0, "1h", conductor=DRAKE, weather=NIGHT)
    with pytest.raises(TypeError, match=r"^argument `limit_k` must be a number \(an int or a float\), not list$"):
        ohl.transient(800.0, 600.0, conductor=DRAKE, weather=NIGHT, limit_k=[373.15])
    with pytest.raises(ohl.ScenarioError) as e:
        ohl.transient(800.0, 10**400, conductor=DRAKE, weather=NIGHT)
    assert e.value.field == "end_time_s" and e.value.allowed == "must be a number within the range of a float (|x| < 1.8e308)"
    with pytest.raises(ohl.ScenarioError) as e:
        ohl.transient(800.0, 600.0, conductor=DRAKE, weather=NIGHT, step_s=float("nan"))
    assert problem(e.value) == ("<arguments>", "step_s", "NaN", "must be in [1e-3, 600] s")
    for bad, shown in ((float("nan"), "NaN"), (-10.0, "-10"), (float("inf"), "inf")):
        with pytest.raises(ohl.ScenarioError) as e:  # NaN was a ThermalError from inside the computation
            ohl.deicing(0.010, 1000.0, conductor=DRAKE, weather=NIGHT, record_every_s=bad)
        assert problem(e.value) == ("<arguments>", "record_every_s", shown, "must be a finite number >= 0 s (0 records every step)")
    with pytest.raises(TypeError, match=r"^argument `criterion` must be a str, not int$"):
        ohl.deicing(0.010, 1000.0, conductor=DRAKE, weather=NIGHT, criterion=1)
    with pytest.raises(ohl.ScenarioError) as e:
        ohl.deicing_current(0.010, 3600.0, conductor=DRAKE, weather=NIGHT, criterion="melt")
    assert e.value.field == "criterion" and e.value.allowed.startswith("unknown variant `melt`")
    with pytest.raises(TypeError, match=r"^argument `thickness_m` must be a number \(an int or a float\), not NoneType$"):
        ohl.deicing_current(None, 3600.0, conductor=DRAKE, weather=NIGHT)
