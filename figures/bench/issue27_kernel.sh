#!/usr/bin/env bash
# Issue 27, the kernel: `ohl bench` with the binary before and the binary after, alternately ROUNDS times
# (the machine is shared: alternating spreads the load over both), then one table of the median over the
# rounds of each configuration and N (node-steps per CPU second, itself the median of 5 repetitions), the
# compute limit of figures/bench/README.md ("Compute limit on this processor") at the clock measured in
# the same runs, and the fraction of the limit reached.
#
# usage: bash figures/bench/issue27_kernel.sh BEFORE_OHL AFTER_OHL [ROUNDS] [OUT_DIR]
# e.g.   bash figures/bench/issue27_kernel.sh /tmp/ohl-before target/release/ohl 3 figures/bench
# writes OUT_DIR/issue27_{before,after}_R.csv (and _primitives.csv) and OUT_DIR/issue27_kernel.csv
set -euo pipefail
before=$1; after=$2; rounds=${3:-3}; out=${4:-figures/bench}
for r in $(seq 1 "$rounds"); do
  for side in before after; do
    bin=$before; [ "$side" = after ] && bin=$after
    "$bin" bench --no-run --reps 5 --node-steps 4e6 --label "issue27_${side}_$r" --out "$out" > /dev/null
  done
done
# Cycles per node-step of the limit (README, "Compute limit on this processor": the busiest of the
# multiply pipes, the add pipes, the divide/square-root unit and the load and store pipes, from the
# operations counted per node-step in the source); the other workloads have none (scalar parts).
limits="plane_weight 4.375
wind_3d 8.5
kv_smoothing_3d 9.0"
python3 - "$out" "$rounds" "$limits" <<'EOF'
import csv, statistics, sys
out, rounds, limits = sys.argv[1], int(sys.argv[2]), dict(l.split() for l in sys.argv[3].splitlines())
def table(side):
    rows, clocks = {}, []
    for r in range(1, rounds + 1):
        for row in csv.DictReader(open(f"{out}/issue27_{side}_{r}.csv")):
            rows.setdefault((row["config"], int(row["n"]), int(row["nodes"])), []).append(float(row["node_steps_per_s"]))
        clocks.append(float(next(csv.DictReader(open(f"{out}/issue27_{side}_{r}_primitives.csv")))["clock_hz"]))
    return {k: statistics.median(v) for k, v in rows.items()}, statistics.median(clocks)
(b, cb), (a, ca) = table("before"), table("after")
with open(f"{out}/issue27_kernel.csv", "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["config", "n", "nodes", "before_node_steps_per_cpu_s", "after_node_steps_per_cpu_s", "after_over_before",
                "limit_cycles_per_node_step", "clock_hz", "limit_node_steps_per_s", "before_fraction_of_limit", "after_fraction_of_limit"])
    for k in a:
        c = float(limits.get(k[0], "0"))
        lim = ca / c if c > 0 else float("nan")
        bb = b.get(k, float("nan"))
        w.writerow([k[0], k[1], k[2], f"{bb:.4e}", f"{a[k]:.4e}", f"{a[k] / bb:.3f}", c or "", f"{ca:.4e}",
                    f"{lim:.4e}" if c else "", f"{bb / lim:.3f}" if c else "", f"{a[k] / lim:.3f}" if c else ""])
print(f"{out}/issue27_kernel.csv: clock before {cb:.4e} Hz, after {ca:.4e} Hz")
EOF
