#!/usr/bin/env bash
# MoorDyn side by side with ohl on the paper's weight release (paper_cases/fig2b_catenary.toml): CPU time
# per simulated second of both step loops, node-steps per CPU second, their ratio, and the error of each
# against a fine-step reference of the same chain. NOT part of CI: it compiles MoorDyn (about 4 min).
#
# Usage: app/benches/moordyn/run.sh [OHL_BIN]            (from anywhere; OHL_BIN default target/release/ohl)
# Environment:
#   MOORDYN_GIT  a git repository of MoorDyn (clone or mirror of FloatingArrayDesign/MoorDyn) with tag
#                MOORDYN_TAG; needed only when the venv is (re)built
#   MOORDYN_TAG  pinned MoorDyn version (default v2.7.1)
#   VENV         virtual environment with MoorDyn built from source (default /tmp/ohl-moordyn-venv); built
#                by build_moordyn.sh when it has no moordyn module or REBUILD=1
#   SEGMENTS     numbers of segments (default "50 100 200 300")
#   REPS         timed repetitions, the fastest counts (default 3)
#   SCHEME       MoorDyn's time scheme (tScheme; default RK2, MoorDyn's default)
#   WORK         scratch directory for inputs and outputs (default /tmp/ohl-moordyn-work)
#   CSV          result table (default figures/bench/moordyn_ratio.csv)
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../../.." && pwd)
ohl=$(realpath "${1:-$root/target/release/ohl}")
venv=${VENV:-/tmp/ohl-moordyn-venv}
work=${WORK:-/tmp/ohl-moordyn-work}
csv=${CSV:-$root/figures/bench/moordyn_ratio.csv}
segments=${SEGMENTS:-50 100 200 300}

[ -x "$ohl" ] || { echo "run.sh: no ohl binary at $ohl (cargo build --release, or pass its path)" >&2; exit 2; }
if [ "${REBUILD:-0}" = 1 ] || ! (cd / && "$venv/bin/python" -c 'import moordyn' 2>/dev/null); then
    [ -n "${MOORDYN_GIT:-}" ] || { echo "run.sh: set MOORDYN_GIT to a MoorDyn git repository to build it" >&2; exit 2; }
    bash "$here/build_moordyn.sh" "$venv" "$MOORDYN_GIT" "${MOORDYN_TAG:-v2.7.1}"
elif [ -f "$venv/build_time.txt" ]; then
    cat "$venv/build_time.txt"
fi
echo "load average before the runs: $(cut -d' ' -f1-3 /proc/loadavg)"
# shellcheck disable=SC2086
"$venv/bin/python" "$here/moordyn_case.py" --ohl "$ohl" --segments $segments --reps "${REPS:-3}" \
    --scheme "${SCHEME:-RK2}" \
    --out "$work" --csv "$csv"
