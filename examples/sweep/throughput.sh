#!/usr/bin/env bash
# The sweep throughput benchmark of docs/sweeps.md: a sweep of 1000 single-span cases
# (examples/sweep/drake_400m_wind.toml: a 400 m ACSR Drake span, N = 50 segments, 60 s simulated each;
# 40 wind speeds x 25 aerodynamic damping values), once on 1 thread and once on 2 threads. Each run is
# preceded and followed by the load average (`uptime`) and followed by the CPU time it got: other work on the
# machine takes cores from the sweep, so note the load beside each number and repeat when it was high. The two tables must be the same
# but for their timing columns (the last three); the script checks it.
#
# Usage (from the repository root, after `cargo build --release --bin ohl`):
#   examples/sweep/throughput.sh [OHL_BINARY] [OUT_DIR] [THREADS...]
# defaults: target/release/ohl, out/sweep_throughput, threads 1 and 2.
set -euo pipefail
OHL=${1:-target/release/ohl}
OUT=${2:-out/sweep_throughput}
shift $(( $# > 2 ? 2 : $# ))
THREADS=${*:-1 2}
BASE=$(dirname "$0")/drake_400m_wind.toml
# The CPU time the sweep got: on an idle machine, user + system is about `threads` x wall.
TIMEFORMAT="  cpu: %U s user + %S s system in %R s wall"
for t in $THREADS; do
  echo "threads $t, load before: $(uptime)"
  time ("$OHL" sweep "$BASE" --vary loads.wind.speed_m_per_s=10:29.5:0.5 --vary numerics.mu=0:0.96:0.04 \
    --threads "$t" --out "$OUT/threads_$t" 2>/dev/null | grep '^sweep:')
  echo "threads $t, load after:  $(uptime)"
done
# Same results on any number of threads: every column but the three timings.
set -- $THREADS
first=$1
for t in "$@"; do
  if ! diff -q <(awk -F, -v OFS=, '{NF -= 3; print}' "$OUT/threads_$first/sweep.csv") \
               <(awk -F, -v OFS=, '{NF -= 3; print}' "$OUT/threads_$t/sweep.csv") >/dev/null; then
    echo "the tables of $first and $t threads differ" >&2
    exit 1
  fi
done
echo "tables identical on threads $THREADS (timings aside)"
