"""`ohl.shortcircuit`: a line scenario with [short_circuit] from Python holds the numbers of
`ohl shortcircuit`'s shortcircuit.json on the same file (both the IEC 60865-1 half and the dynamic run's),
and a line without [short_circuit] is refused."""

from __future__ import annotations

import json

import pytest

import ohl
from conftest import REPO, cli

CASE = REPO / "cases" / "i_slack_span.toml"


def _short(tmp_path):
    """The slack span of cases/i_slack_span.toml run to 0.4 s only (CI time)."""
    text = CASE.read_text().replace("end_time_s = 2.0", "end_time_s = 0.4")
    path = tmp_path / "i_short.toml"
    path.write_text(text)
    return path


def test_python_holds_the_numbers_of_the_command(tmp_path, ohl_cli):
    path = _short(tmp_path)
    got = ohl.shortcircuit(path)
    out = tmp_path / "out"
    r = cli(ohl_cli, "shortcircuit", str(path), "--out", str(out))
    assert r.returncode == 0, r.stderr
    want = json.loads((out / "shortcircuit.json").read_text())
    # serde_json writes shortest round-trip floats: equal dicts are equal numbers, bit for bit.
    assert got == want
    rows = {row["symbol"]: row for row in got["rows"]}
    # The IEC half on the span of TR 60865-2 example 7: F' 27.1 N/m printed (docs/short_circuit_iec60865.md).
    assert abs(rows["F'"]["iec"] - 27.1) <= 0.05
    assert got["iec_input"]["span_m"] == 10.4


def test_a_line_without_short_circuit_is_refused(tmp_path):
    text = CASE.read_text()
    head, _, tail = text.partition("[short_circuit]")
    rest = tail[tail.index("[initial]"):]
    path = tmp_path / "no_sc.toml"
    path.write_text(head + rest)
    with pytest.raises(ValueError, match=r"no \[short_circuit\] table"):
        ohl.shortcircuit(path)
