"""The heat balance from Python: against the IEEE 738 Annex B and CIGRE TB 601 numbers (docs/thermal.md)
and bit for bit against `ohl thermal` on the same inputs."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

import ohl
from conftest import REPO, assert_bitwise, cli, read_csv, read_json

# IEEE Std 738-2012 Annex B (examples/thermal/drake_annex_b.toml): ACSR Drake, 40 C air, 0.61 m/s across
# the line, sea level, 30 N, 10 June 11:00 solar time, east-west line, clear atmosphere.
ANNEX_B = {
    "air_temperature_k": 313.15,
    "wind_speed_m_per_s": 0.61,
    "wind_angle_deg": 90.0,
    "elevation_m": 0.0,
    "sun": {"latitude_deg": 30.0, "day_of_year": 161, "solar_hour": 11.0, "line_azimuth_deg": 90.0, "atmosphere": "clear"},
}
DRAKE = "ACSR Drake"

# CIGRE TB 601 Annex E Example A's weather: 40 C air, 0.61 m/s at 60 deg to the axis, the Annex B sun.
EXAMPLE_A = {
    "air_temperature_k": 313.15,
    "wind_speed_m_per_s": 0.61,
    "wind_angle_deg": 60.0,
    "elevation_m": 0.0,
    "sun": {"latitude_deg": 30.0, "day_of_year": 161, "solar_hour": 11.0, "line_azimuth_deg": 90.0, "clearness_ratio": 1.0, "albedo": 0.1},
}


def test_a_weather_in_celsius_is_the_weather_in_kelvin() -> None:
    # Issue 23: `air_temperature_c = 40` is read as 313.15 K exactly (the conversion rounds to 1e-9 K, so
    # a decimal Celsius value gives the decimal kelvin value): the same ampacity bit for bit.
    celsius = {k: v for k, v in ANNEX_B.items() if k != "air_temperature_k"}
    celsius["air_temperature_c"] = 40.0
    assert ohl.ampacity(373.15, conductor=DRAKE, weather=celsius) == ohl.ampacity(
        373.15, conductor=DRAKE, weather=ANNEX_B
    )


def test_ieee738_annex_b_ampacity() -> None:
    a = ohl.ampacity(373.15, conductor=DRAKE, weather=ANNEX_B)
    # docs/thermal.md and docs/verification.md: 1025.7852 A computed; the standard prints 1025 A.
    assert a["current_a"] == pytest.approx(1025.7852, abs=5e-5)
    assert abs(a["current_a"] - 1025.0) < 1.0
    assert isinstance(a["current_a"], float)
    # At the ampacity the heat balance closes: q_J + q_S = q_c + q_r.
    net = a["joule_w_per_m"] + a["solar_w_per_m"] - a["convection_w_per_m"] - a["radiation_w_per_m"]
    assert abs(net) < 1e-9 * a["joule_w_per_m"]
    # ... and the steady temperature at that current is the maximum temperature.
    s = ohl.steady_temperature(a["current_a"], conductor=DRAKE, weather=ANNEX_B)
    assert s["temperature_k"] == pytest.approx(373.15, abs=1e-6)


def test_annex_b_against_the_command_line(tmp_path: Path, ohl_cli: Path) -> None:
    p = cli(ohl_cli, "thermal", "examples/thermal/drake_annex_b.toml", "--out", str(tmp_path))
    assert p.returncode == 0, p.stderr
    j = read_json(tmp_path / "thermal.json")
    terms = ("joule_w_per_m", "solar_w_per_m", "convection_w_per_m", "radiation_w_per_m")

    currents = [row["current_a"] for row in j["steady"]]
    s = ohl.steady_temperature(currents, conductor=DRAKE, weather=ANNEX_B)
    assert_bitwise(s["temperature_k"], [row["temperature_k"] for row in j["steady"]], "steady temperature")
    for t in terms:
        assert_bitwise(s[t], [row["terms"][t] for row in j["steady"]], t)

    limits = [row["max_temperature_k"] for row in j["ampacity"]]
    a = ohl.ampacity(limits, conductor=DRAKE, weather=ANNEX_B)
    assert_bitwise(a["current_a"], [row["current_a"] for row in j["ampacity"]], "ampacity")
    for t in terms:
        assert_bitwise(a[t], [row["terms"][t] for row in j["ampacity"]], t)
    # One scalar gives floats, the same numbers.
    assert ohl.ampacity(limits[1], conductor=DRAKE, weather=ANNEX_B)["current_a"] == j["ampacity"][1]["current_a"]

    # [transient] of the file: a step 800 A -> 1200 A at t = 0, 3600 s, limit 100 C.
    tr = ohl.transient([(0.0, 800.0), (0.0, 1200.0)], 3600.0, conductor=DRAKE, weather=ANNEX_B, limit_k=373.15)
    header, csv = read_csv(tmp_path / "transient.csv")
    assert header == ["t_s", "current_a", "temperature_k"]
    assert_bitwise(tr["t_s"], csv[:, 0], "t_s")
    assert_bitwise(tr["current_a"], csv[:, 1], "current_a")
    assert_bitwise(tr["temperature_k"], csv[:, 2], "temperature_k")
    for k in ("initial_temperature_k", "final_temperature_k", "limit_k", "time_to_limit_s"):
        assert tr[k] == j["transient"][k], k
    assert 0.0 < tr["time_to_limit_s"] < 3600.0


def test_deicing_against_the_command_line(tmp_path: Path, ohl_cli: Path) -> None:
    p = cli(ohl_cli, "thermal", "examples/thermal/drake_deicing.toml", "--out", str(tmp_path))
    assert p.returncode == 0, p.stderr
    j = read_json(tmp_path / "thermal.json")["deicing"]
    night = {"air_temperature_k": 263.15, "wind_speed_m_per_s": 2.0, "wind_angle_deg": 90.0}
    for k, run in enumerate(j["runs"]):
        d = ohl.deicing(0.010, run["current_a"], conductor=DRAKE, weather=night)
        assert d["shed_time_s"] == run["shed_time_s"]
        assert d["melting_from_s"] == run["melting_from_s"]
        assert d["energy_j_per_m"] == run["energy_j_per_m"]
        assert d["ice_kg_per_m"] == j["ice_kg_per_m"]
        assert d["minimum_current_a"] == j["minimum_current_a"]
        if k == 0:  # deicing.csv holds the first current's series
            header, csv = read_csv(tmp_path / "deicing.csv")
            names = ["t_s", "conductor_k", "surface_k", "melted_kg_per_m", "joule_w_per_m", "loss_w_per_m"]
            assert header == names
            for c, name in enumerate(names):
                assert_bitwise(d[name], csv[:, c], name)
    for row in j["shed_within"]:
        i = ohl.deicing_current(0.010, row["time_s"], conductor=DRAKE, weather=night)
        assert i == row["current_a"]


CIGRE_CASE = """
name = "tb601_example_a_weather"
standard = "cigre601"
conductor = "ACSR Drake"
current_a = [600.0, 900.0]
max_temperature_k = [373.15]
[weather]
air_temperature_k = 313.15
wind_speed_m_per_s = 0.61
wind_angle_deg = 60.0
elevation_m = 0.0
[weather.sun]
latitude_deg = 30.0
day_of_year = 161
solar_hour = 11.0
line_azimuth_deg = 90.0
clearness_ratio = 1.0
albedo = 0.1
"""


def test_cigre601_against_the_command_line(tmp_path: Path, ohl_cli: Path) -> None:
    case = tmp_path / "cigre.toml"
    case.write_text(CIGRE_CASE)
    p = cli(ohl_cli, "thermal", str(case), "--out", str(tmp_path / "out"))
    assert p.returncode == 0, p.stderr
    j = read_json(tmp_path / "out" / "thermal.json")
    s = ohl.steady_temperature([600.0, 900.0], conductor=DRAKE, weather=EXAMPLE_A, standard="cigre601")
    assert_bitwise(s["temperature_k"], [r["temperature_k"] for r in j["steady"]])
    a = ohl.ampacity(373.15, conductor=DRAKE, weather=EXAMPLE_A, standard="cigre601")
    assert a["current_a"] == j["ampacity"][0]["current_a"]
    # TB 601 prints 976 A for Example A's Drake (D = 28.1 mm, outer strands 4.4 mm; docs/thermal.md:
    # 976.75 A computed). The catalogue's Drake (28.14 mm, 4.44 mm) differs a little from it.
    assert a["current_a"] == pytest.approx(976.0, rel=0.01)
    # The two standards differ, but not by much, on the same day.
    assert a["current_a"] != ohl.ampacity(373.15, conductor=DRAKE, weather=EXAMPLE_A)["current_a"]


def test_vectorised_shapes() -> None:
    i = np.array([[400.0, 600.0], [800.0, 1000.0]])
    s = ohl.steady_temperature(i, conductor="drake", weather=ANNEX_B)
    assert s["temperature_k"].shape == (2, 2)
    assert (np.diff(s["temperature_k"].ravel()) > 0).all()
    one = ohl.steady_temperature(800.0, conductor="drake", weather=ANNEX_B)
    assert one["temperature_k"] == s["temperature_k"][1, 0]
    q = ohl.heat_terms([300.0, 350.0, 400.0], 1000.0, conductor="drake", weather=ANNEX_B)
    assert q["joule_w_per_m"].shape == (3,)
    assert (np.diff(q["joule_w_per_m"]) > 0).all()


def test_conductor_catalogue() -> None:
    names = ohl.conductors()
    assert "ACSR Drake" in names and len(names) >= 4
    c = ohl.conductor("drake")
    assert c["name"] == "ACSR Drake" and c["kind"] == "ACSR"
    assert c["diameter_m"] == 28.14e-3
    assert c["temperature_low_k"] == 298.15
    with pytest.raises(ohl.ScenarioError) as e:
        ohl.conductor("ACSR Nonesuch")
    assert e.value.field == "conductor" and "ACSR Drake" in e.value.allowed


def test_thermal_argument_errors() -> None:
    with pytest.raises(ohl.ScenarioError) as e:
        ohl.steady_temperature(-5.0, conductor=DRAKE, weather=ANNEX_B)
    assert (e.value.field, e.value.value, e.value.allowed) == ("current_a", "-5", "must be in [0, 1e5] A")
    with pytest.raises(ohl.ScenarioError) as e:
        ohl.steady_temperature([100.0, 2e5], conductor=DRAKE, weather=ANNEX_B)
    assert e.value.field == "current_a[1]"
    with pytest.raises(ohl.ScenarioError) as e:
        ohl.ampacity(373.15, conductor=DRAKE, weather={**ANNEX_B, "air_temperature_k": 40.0})
    assert e.value.field == "weather.air_temperature_k"
    assert e.value.allowed == "must be in [200, 350] K (-73 to 77 C)"
    with pytest.raises(ohl.ScenarioError, match="unknown field `wind_speed`"):
        ohl.ampacity(373.15, conductor=DRAKE, weather={"air_temperature_k": 300.0, "wind_speed": 1.0})
    with pytest.raises(ohl.ScenarioError) as e:
        ohl.transient([(0.0, 800.0), (-1.0, 900.0)], 100.0, conductor=DRAKE, weather=ANNEX_B)
    assert e.value.field == "current_a[1][0]"
    with pytest.raises(ohl.ScenarioError) as e:
        ohl.deicing(0.5, 1000.0, conductor=DRAKE, weather=ANNEX_B)
    assert e.value.field == "thickness_m"
    with pytest.raises(ohl.ScenarioError, match="unknown variant"):
        ohl.ampacity(373.15, conductor=DRAKE, weather=ANNEX_B, standard="ieee")
    # The sun alone heats a conductor in hot still air above 41 C: no ampacity.
    with pytest.raises(ohl.ThermalError, match="no ampacity"):
        ohl.ampacity(314.0, conductor=DRAKE, weather={**ANNEX_B, "wind_speed_m_per_s": 0.0})


@pytest.mark.skipif(sys.version_info < (3, 11), reason="tomllib (reading TOML into a dict) needs Python 3.11")
def test_a_dict_finds_its_user_catalogue_in_base_dir(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A dict's relative `thermal.conductor_catalog` is taken relative to `base_dir` (default: the current
    working directory). The user catalogue holds the built-in Drake entry under another name, so the
    scenario must plan exactly as with the built-in Drake (an independent expectation: the same numbers)."""
    import tomllib

    text = (REPO / "data/conductors.toml").read_text(encoding="utf-8")
    drake = text[text.index("[[conductor]]\nname = \"ACSR Drake\"") :]
    drake = drake[: drake.index("[[conductor]]", 1)]
    drake = drake.replace('name = "ACSR Drake"', 'name = "My Drake"').replace('"drake", ', "")
    (tmp_path / "cat").mkdir()
    (tmp_path / "cat" / "mine.toml").write_text(drake, encoding="utf-8")
    base = tomllib.loads((REPO / "examples/thermal/drake_span_rating.toml").read_text(encoding="utf-8"))
    reference = ohl.from_dict(base)
    d = dict(base, thermal=dict(base["thermal"], conductor="My Drake", conductor_catalog="cat/mine.toml"))
    mine = ohl.from_dict(d, base_dir=tmp_path)
    assert f'conductor_catalog = "{tmp_path / "cat" / "mine.toml"}"' in mine.toml
    assert mine.initial_equilibrium == reference.initial_equilibrium
    # The default is the current working directory.
    monkeypatch.chdir(tmp_path)
    assert ohl.Scenario.from_dict(d).initial_equilibrium == reference.initial_equilibrium
    monkeypatch.chdir(tmp_path / "cat")
    with pytest.raises(ohl.ScenarioError, match="readable conductor catalogue") as e:
        ohl.from_dict(d)
    assert e.value.field == "thermal.conductor_catalog"
    with pytest.raises(TypeError, match=r"^argument `base_dir` must be a str or os.PathLike \(a path\), not int$"):
        ohl.from_dict(d, base_dir=3)
