#!/usr/bin/env bash
# Where whole runs spend their time: every case and mechanical example run whole (`ohl run`, as written)
# by a build with the cargo feature `phase-timing` (src/run/phase_cycles.rs), which prints the
# time-stamp-counter cycles per step of each phase of the run loop; this script collects them into one
# markdown table (one row per scenario: cycles per step of the whole loop, then each phase's share of it).
# The build goes to its own target directory (target/phase-timing), so `target/release/ohl` stays the
# normal build. The counters add a few percent to each loop; the shares are what the table is for.
#
# usage: app/benches/phase_table.sh [OUT_MD]   (default: standard output; the raw reports go to OUT_MD.log)
# e.g.   app/benches/phase_table.sh figures/bench/issue27_r9_phases.md
set -euo pipefail
cd "$(dirname "$0")/../.."
out=${1:-/dev/stdout}
log=${1:+$1.log}
log=${log:-/dev/null}
cargo build --release -p ohl-app --features ohl/phase-timing --target-dir target/phase-timing >&2
bin=target/phase-timing/release/ohl
work="$(mktemp -d "${TMPDIR:-/tmp}/ohl-phase-table.XXXXXX")"
trap 'rm -rf "$work"' EXIT
: > "$log"
{
  echo "| scenario | steps | cycles per step | forces of a level (segment pass; a line: links, pair forces) | node pass (step) | peaks | time series | settle | other outputs (a line: all its conductors' outputs) | clearances | short-circuit observer | links, towers | rest |"
  echo "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
  for f in cases/*.toml examples/mechanical/*.toml; do
    n="$(basename "$f" .toml)"
    "$bin" run "$f" --out "$work/out" --quiet 2> "$work/err" > /dev/null || true
    { echo "== $n"; cat "$work/err"; } >> "$log"
    python3 - "$n" "$work/err" << 'PY'
import re, sys
name, path = sys.argv[1], sys.argv[2]
steps, rows = None, []
for line in open(path):
    m = re.match(r"phase cycles per step \((\d+) steps", line)
    if m:
        steps = int(m.group(1))
    m = re.match(r"\s+([\d.]+) \(\s*([\d.]+) %\)\s+(.*)$", line)
    if m:
        rows.append((float(m.group(1)), float(m.group(2)), m.group(3)))
if steps is None:
    print(f"| {name} | (no report: the run failed) |")
    sys.exit()
# Each phase's column: the first rule whose text the phase's name holds (`^`: begins with).
rules = [("^forces of a level", "forces"), ("^step (", "step"), ("Peaks", "peaks"), ("Timeseries", "series"),
         ("Settle", "settle"), ("^observer", "other"), ("^every conductor's outputs", "other"),
         ("^clearances", "clear"), ("^short-circuit observer", "short"), ("^links'", "links"), ("^rest", "rest")]
share = {k: 0.0 for _, k in rules}
total = 0.0
for c, s, what in rows:
    if what == "whole loop":
        total = c
        continue
    for text, key in rules:
        if (what.startswith(text[1:]) if text.startswith("^") else text in what):
            share[key] += s
            break
cells = " | ".join(f"{share[k]:.1f} %" for k in share)
print(f"| {name} | {steps} | {total:.0f} | {cells} |")
PY
  done
} > "$out"
