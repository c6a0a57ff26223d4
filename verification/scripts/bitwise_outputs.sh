#!/usr/bin/env bash
# Bitwise identity of every output of the paper cases, the cases a-g (line sections a-d, multi-conductor
# lines e-g), the examples and the thermal examples between two builds of `ohl`:
#
#   bash verification/scripts/bitwise_outputs.sh OLD_OHL NEW_OHL [WORK_DIR]
#   ALL_CASES=1 bash verification/scripts/bitwise_outputs.sh OLD_OHL NEW_OHL [WORK_DIR]   (and cases h-l)
#
# Runs both binaries on the same inputs (the current checkout's files), then compares every CSV and JSON
# file byte for byte, except the fields that measure the machine (`wall_time_s`, `node_steps_per_second`,
# `cpu_time_s`, `cpu_node_steps_per_second` in summary.json, the stamp line of paper_table.md), which are
# removed before comparing. Figures are compared too. Prints one line per differing file and a count; exits 1 if any differs.
set -euo pipefail
old="$(realpath "$1")"; new="$(realpath "$2")"
work="${3:-$(mktemp -d "${TMPDIR:-/tmp}/ohl-bitwise.XXXXXX")}"
cd "$(dirname "$0")/../.."
cases_abc=(a_broken_conductor b_ice_shedding c_progressive_shedding d_deicing
  e_three_phases_wind f_vertical_ice_shedding g_quad_bundle_break)
# ALL_CASES=1 adds the cases h-l (twin bundle, slack spans, reclosing, droppers, their short circuit), run
# whole: about 20 s more per binary.
if [ "${ALL_CASES:-0}" = 1 ]; then
  cases_abc+=(h_strained_twin_bundle i_slack_span j_distribution_reclose k_slack_span_dropper
    l_slack_droppers_short_circuit)
fi
for side in old new; do
  bin="$old"; [ "$side" = new ] && bin="$new"
  out="$work/$side"; rm -rf "$out"; mkdir -p "$out"
  "$bin" paper all --out "$out/paper" > "$out/paper.txt" 2>&1
  for c in "${cases_abc[@]}"; do "$bin" cases "$c" --out "$out/cases" > "$out/cases_$c.txt" 2>&1; done
  for f in examples/mechanical/*.toml paper_cases/*.toml; do
    n="$(basename "$f" .toml)"
    [ "$n" = heat_two_halves ] && continue
    "$bin" run "$f" --out "$out/run/$n" --quiet > /dev/null 2>&1 || true
  done
  for f in examples/thermal/*.toml; do
    n="$(basename "$f" .toml)"
    "$bin" thermal "$f" --out "$out/thermal/$n" > /dev/null 2>&1 || "$bin" rating "$f" > "$out/thermal/$n.txt" 2>&1 || true
  done
done
# Remove what measures the machine or names the output folder: wall times and throughputs, the stamp
# (commit, date) of paper_table.md, and the run's own directory in printed paths.
strip() {
  local side="$2"
  case "$1" in
    *.json) grep -v -E '"(wall_time_s|node_steps_per_second|cpu_time_s|cpu_node_steps_per_second)"' "$1" ;;
    *.md | *.txt) grep -v -E 'completed in|equalised in|time loop|throughput|node-steps/s|wall time|^Written by' "$1" | sed "s|$work/$side|OUT|g" ;;
    *) cat "$1" ;;
  esac
}
differ=0; same=0
while IFS= read -r -d '' f; do
  rel="${f#"$work/old/"}"
  g="$work/new/$rel"
  if [ ! -f "$g" ]; then echo "only in old: $rel"; differ=$((differ + 1)); continue; fi
  if cmp -s <(strip "$f" old) <(strip "$g" new); then same=$((same + 1)); else echo "differs: $rel"; differ=$((differ + 1)); fi
done < <(find "$work/old" -type f -print0 | sort -z)
echo "$same files identical, $differ differ (outputs in $work)"
[ "$differ" -eq 0 ]
