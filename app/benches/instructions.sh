#!/usr/bin/env bash
# Instructions per node-step of the explicit step, counted by valgrind (callgrind), which is exact and
# does not depend on the machine's load: the count of a run of S2 steps minus that of S1 steps, divided
# by (S2 - S1) (N + 1), so start-up and set-up cancel.
#
# usage: app/benches/instructions.sh OHL_BINARY LABEL [CSV]   (appends "label,config,n,instructions_per_node_step")
# e.g.   app/benches/instructions.sh target/release/ohl after figures/bench/instructions.csv
set -euo pipefail
bin=$1
label=$2
csv=${3:-/dev/stdout}
command -v valgrind > /dev/null || { echo "valgrind is not installed (apt-get install valgrind)" >&2; exit 2; }
[ -s "$csv" ] || [ "$csv" = /dev/stdout ] || echo "label,config,n,instructions_per_node_step" > "$csv"
ir() { valgrind --tool=callgrind --callgrind-out-file=/dev/null "$bin" bench --fixed "$1:$2:$3" 2>&1 | awk '/Collected/ {print $4}'; }
for c in plane_weight wind_3d kv_smoothing_3d two_material_plane; do
  for n in 50 200 1000 5000; do
    # at most 3100 steps: 10 s simulated at N = 50, inside the stable transient of the undamped release
    d=$(( 1000000 / (n + 1) )); [ "$d" -le 3000 ] || d=3000
    s1=100; s2=$(( s1 + d ))
    a=$(ir "$c" "$n" "$s1"); b=$(ir "$c" "$n" "$s2")
    echo "$label,$c,$n,$(awk -v a="$a" -v b="$b" -v d=$(( (s2 - s1) * (n + 1) )) 'BEGIN { printf "%.2f", (b - a) / d }')" >> "$csv"
  done
done
