"""Random inputs of every public function (fuzz_inputs.py): every call returns, or raises
`ohl.ScenarioError` naming a field (never a line of a dict's generated TOML text), a `TypeError` naming
its argument, or a documented outcome of a valid input; never another exception, never a crash.

The generator runs in a child process, so a crash (a stack overflow, a Rust panic that aborts) fails this
test with the case that crashed instead of ending the test session. Fixed seed; a budget of a few seconds
in CI. A longer run: `OHL_FUZZ_SECONDS=600 OHL_FUZZ_SEED=7 pytest python/tests/test_fuzz.py`."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest


SEED = int(os.environ.get("OHL_FUZZ_SEED", "22"))
SECONDS = float(os.environ.get("OHL_FUZZ_SECONDS", "4"))


@pytest.mark.skipif(sys.version_info < (3, 11), reason="the generator reads the scenario files with tomllib (Python 3.11)")
def test_random_inputs_keep_the_error_contract(tmp_path: Path) -> None:
    log = tmp_path / "cases.log"
    script = Path(__file__).with_name("fuzz_inputs.py")
    cmd = [sys.executable, str(script), "--seed", str(SEED), "--seconds", str(SECONDS), "--log", str(log)]
    # In an empty directory: relative paths the generator draws name nothing there, and nothing is written.
    work = tmp_path / "cwd"
    work.mkdir()
    p = subprocess.run(cmd, cwd=work, capture_output=True, text=True, timeout=SECONDS + 300)
    last = log.read_text(encoding="utf-8").splitlines()[-1:] if log.exists() else []
    assert p.returncode == 0, f"exit {p.returncode} at {last}\n{p.stdout[-4000:]}\n{p.stderr[-4000:]}"
    assert p.stdout.startswith(f"fuzz: seed {SEED}, "), p.stdout
    calls = int(p.stdout.split(", ")[1].split()[0])
    assert calls >= 100, p.stdout  # the budget bought a real sample
    assert not list(work.iterdir()), "the calls wrote files"
    print(p.stdout.strip())
