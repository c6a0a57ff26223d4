#!/usr/bin/env bash
# Instructions of whole runs (`ohl run`) of every case and mechanical example, counted by valgrind
# (callgrind): exact and independent of the machine's load, unlike CPU or wall time. Runs are whole (as
# written) except the three whose contact or short-circuit runs take seconds per simulated second
# (cases h, i, l): those are shortened to 0.25 s simulated (T_END overrides, for every scenario), in a
# copy under a temporary directory: `[duration] end_time_s` becomes min(end_time_s, T), `until_settled`'s
# max_time_s becomes T (its window 1 s), snapshot times after the end and `peaks_from_s` are dropped.
# Both binaries run the same copies, so a before/after pair counts the same simulated work. CPU time (user + system, from
# /usr/bin/time) of the same shortened run outside valgrind is printed beside it as a secondary, noisy
# figure (it depends on the machine's load).
#
# usage: app/benches/run_instructions.sh OHL_BINARY LABEL [CSV]   (appends "label,scenario,instructions,cpu_s")
# e.g.   app/benches/run_instructions.sh target/release/ohl after figures/bench/run_instructions.csv
set -euo pipefail
bin="$(realpath "$1")"
label=$2
csv=${3:-/dev/stdout}
command -v valgrind > /dev/null || { echo "valgrind is not installed (apt-get install valgrind)" >&2; exit 2; }
cd "$(dirname "$0")/../.."
[ -s "$csv" ] || [ "$csv" = /dev/stdout ] || echo "label,scenario,instructions,cpu_s" > "$csv"
work="$(mktemp -d "${TMPDIR:-/tmp}/ohl-run-instructions.XXXXXX")"
trap 'rm -rf "$work"' EXIT
shorten() {
  awk -v T="$t_end" '
    /^end_time_s *=/ { v = $3 + 0; if (v > T) v = T; print "end_time_s = " v; next }
    /^until_settled *=/ { sub(/window_s *= *[0-9.eE+-]+/, "window_s = 1.0"); sub(/max_time_s *= *[0-9.eE+-]+/, "max_time_s = " T); print; next }
    /^peaks_from_s *=/ { next }
    /^snapshot_times_s *=/ {
      s = $0; sub(/^[^[]*\[/, "", s); sub(/\].*$/, "", s); n = split(s, a, ","); out = ""
      for (i = 1; i <= n; i++) if (a[i] + 0 <= T) out = out (out == "" ? "" : ", ") (a[i] + 0)
      print "snapshot_times_s = [" out "]"; next
    }
    { print }' "$1"
}
for f in cases/*.toml examples/mechanical/*.toml; do
  n="$(basename "$f" .toml)"
  t_end=${T_END:-}
  case "$n" in h_strained_twin_bundle | i_slack_span | l_slack_droppers_short_circuit) t_end=${T_END:-0.25} ;; esac
  if [ -n "$t_end" ]; then shorten "$f" > "$work/$n.toml"; else cp "$f" "$work/$n.toml"; fi
  ir=$(valgrind --tool=callgrind --callgrind-out-file=/dev/null "$bin" run "$work/$n.toml" --out "$work/out" --quiet 2>&1 |
    awk '/Collected/ {print $4}')
  cpu=$( { /usr/bin/time -f '%U %S' "$bin" run "$work/$n.toml" --out "$work/out" --quiet > /dev/null; } 2>&1 | tail -1 |
    awk '{printf "%.2f", $1 + $2}')
  rm -rf "$work/out"
  echo "$label,$n,$ir,$cpu" >> "$csv"
done
