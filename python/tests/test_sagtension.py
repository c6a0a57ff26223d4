"""`ohl.sagtension`: the table of a sag-tension case from Python, bit for bit the numbers of
`ohl sagtension`'s sagtension.csv on the same file, the same from a dict as from the file, and invalid
input refused with the field named."""

from __future__ import annotations

import csv
import json
import math

import numpy as np
import pytest

import ohl
from conftest import REPO, assert_bitwise, cli

HANDBOOK = REPO / "examples" / "sagtension" / "drake_700ft.toml"
RULING = REPO / "examples" / "sagtension" / "drake_ruling_span.toml"

CASE = {
    "conductor": {"catalog": "ACSR Drake"},
    "span": {"length_m": 213.36},
    "stringing": {"tension_n": 28023.796, "temperature_c": 15.555555556, "state": "initial"},
    "condition": [{"temperature_c": -20.0}, {"temperature_c": 100.0}],
}


def _csv_columns(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    return {h: [r[k] for r in body] for k, h in enumerate(header)}


@pytest.mark.parametrize("case", [HANDBOOK, RULING], ids=["handbook_700ft", "ruling_span"])
def test_the_table_is_the_commands_bit_for_bit(case, ohl_cli, tmp_path):
    t = ohl.sagtension(case)
    r = cli(ohl_cli, "sagtension", str(case), "--out", str(tmp_path))
    assert r.returncode == 0, r.stderr
    f = _csv_columns(tmp_path / "sagtension.csv")
    rows = t["rows"]
    n = len(rows["state"])
    assert n == len(t["labels"]) * len(t["states"]) == len(f["state"])
    for key in ("horizontal_tension_n", "sag_m", "sag_max_m", "support_tension_n", "tension_percent_rts",
                "aluminium_stress_pa", "core_stress_pa", "strain", "load_n_per_m", "conductor_length_m"):
        assert rows[key].dtype == np.float64 and rows[key].shape == (n,)
        assert_bitwise(rows[key], np.array([float(x) for x in f[key]]), key)
    assert rows["state"] == f["state"]
    assert list(rows["knee_passed"]) == [x == "true" for x in f["knee_passed"]]
    # Each span's sag, as sagtension.json has it.
    doc = json.loads((tmp_path / "sagtension.json").read_text())
    assert rows["span_sags_m"].shape == (n, len(t["spans_m"]))
    assert_bitwise(rows["span_sags_m"], np.array([r["span_sags_m"] for r in doc["rows"]]), "span_sags_m")
    # The CSV's Celsius is the kelvin less 273.15 (the command writes T - 273.15).
    assert_bitwise(rows["temperature_k"] - 273.15, np.array([float(x) for x in f["temperature_c"]]), "temperature")


def test_a_dict_gives_the_same_table_as_its_file(tmp_path):
    text = (
        '[conductor]\ncatalog = "ACSR Drake"\n[span]\nlength_m = 213.36\n[stringing]\ntension_n = 28023.796\n'
        'temperature_c = 15.555555556\nstate = "initial"\n[[condition]]\ntemperature_c = -20.0\n'
        "[[condition]]\ntemperature_c = 100.0\n"
    )
    path = tmp_path / "case.toml"
    path.write_text(text)
    a, b = ohl.sagtension(CASE), ohl.sagtension(path)
    for key in ("horizontal_tension_n", "sag_m", "core_stress_pa"):
        assert_bitwise(a["rows"][key], b["rows"][key], key)
    # The stringing condition holds in its state: at the stringing weather, initial H is the 6300 lb
    # asked, to the solver's closure (1e-9 relative is far below its stated tolerance's effect on a row).
    s = ohl.sagtension({**CASE, "condition": [{"temperature_c": 15.555555556}]})
    h = s["rows"]["horizontal_tension_n"][s["rows"]["state"].index("initial")]
    assert math.isclose(h, 28023.796, rel_tol=1e-9), h


def test_the_knee_and_the_sag_limit_temperatures_are_reported_per_state():
    t = ohl.sagtension(RULING)
    assert set(t["knee_temperature_k"]) == set(t["states"])
    assert set(t["sag_limit_temperature_k"]) == set(t["states"])
    # Creep and the heavy load lengthen the conductor: its knee comes at a lower temperature than as strung.
    assert t["knee_temperature_k"]["final"] < t["knee_temperature_k"]["initial"]
    # 25 m supports, 10 m clearance: a sag of 15 m in the longest span (400 m), reached sooner (at a lower
    # temperature) by the stretched conductor.
    assert t["sag_limit_m"] == 15.0
    assert t["sag_limit_temperature_k"]["final"] < t["sag_limit_temperature_k"]["initial"]


def test_invalid_input_names_the_field():
    bad = {**CASE, "condition": [{"temperature_c": 400.0}]}
    with pytest.raises(ohl.ScenarioError) as e:
        ohl.sagtension(bad, name="case.toml")
    assert e.value.field == "condition[0].temperature_c"
    assert e.value.allowed == "must be in [-100, 300] C"
    with pytest.raises(FileNotFoundError):
        ohl.sagtension(REPO / "no_such_case.toml")
