#!/usr/bin/env bash
# Issue 27, the kernel: `ohl bench` with the binary before and the binary after, alternately ROUNDS times
# (the machine is shared: alternating spreads the load over both), then one table of the median over the
# rounds of each configuration and N (node-steps per CPU second, itself the median of 5 repetitions), the
# compute limit and the fraction of it reached.
#
# The limit: where the after binary's CSV has the column `limit_node_steps_per_s` (`ohl bench` derives it
# on the machine it runs on from the measured cost of each operation, `app/src/bench/limit.rs`), the
# median of that column over the rounds, and beside it the bound of the two passes
# (`passes_bound_node_steps_per_s`); otherwise the Zen 4 derivation of figures/bench/README.md
# ("Compute limit on this processor": cycles per node-step below) at the clock measured in the same runs.
#
# usage: bash figures/bench/issue27_kernel.sh BEFORE_OHL AFTER_OHL [ROUNDS] [OUT_DIR] [PREFIX]
# e.g.   bash figures/bench/issue27_kernel.sh /tmp/ohl-before target/release/ohl 3 figures/bench issue27
# writes OUT_DIR/PREFIX_{before,after}_R.csv (and _primitives.csv) and OUT_DIR/PREFIX_kernel.csv
set -euo pipefail
before=$1; after=$2; rounds=${3:-3}; out=${4:-figures/bench}; prefix=${5:-issue27}
for r in $(seq 1 "$rounds"); do
  for side in before after; do
    bin=$before; [ "$side" = after ] && bin=$after
    "$bin" bench --no-run --reps 5 --node-steps 4e6 --label "${prefix}_${side}_$r" --out "$out" > /dev/null
  done
done
limits="plane_weight 4.375
wind_3d 8.5
kv_smoothing_3d 9.0"
python3 - "$out" "$rounds" "$limits" "$prefix" <<'PY'
import csv, math, statistics, sys
out, rounds, prefix = sys.argv[1], int(sys.argv[2]), sys.argv[4]
zen4 = dict(l.split() for l in sys.argv[3].splitlines())
def table(side):
    rows, lims, passes, clocks = {}, {}, {}, []
    for r in range(1, rounds + 1):
        for row in csv.DictReader(open(f"{out}/{prefix}_{side}_{r}.csv")):
            k = (row["config"], int(row["n"]), int(row["nodes"]))
            rows.setdefault(k, []).append(float(row["node_steps_per_s"]))
            if row.get("limit_node_steps_per_s"):
                lims.setdefault(k, []).append(float(row["limit_node_steps_per_s"]))
                passes.setdefault(k, []).append(float(row["passes_bound_node_steps_per_s"]))
        clocks.append(float(next(csv.DictReader(open(f"{out}/{prefix}_{side}_{r}_primitives.csv")))["clock_hz"]))
    med = lambda d: {k: statistics.median(v) for k, v in d.items()}
    return med(rows), med(lims), med(passes), statistics.median(clocks)
(b, _, _, cb), (a, lim, passes, ca) = table("before"), table("after")
nan = float("nan")
fmt = lambda x, f: "" if math.isnan(x) else format(x, f)
with open(f"{out}/{prefix}_kernel.csv", "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["config", "n", "nodes", "before_node_steps_per_cpu_s", "after_node_steps_per_cpu_s", "after_over_before",
                "clock_hz", "limit_node_steps_per_s", "before_fraction_of_limit", "after_fraction_of_limit",
                "passes_bound_node_steps_per_s", "after_fraction_of_passes_bound"])
    for k in a:
        if k in lim:
            l, p = lim[k], passes[k]
        elif k[0] in zen4:
            l, p = ca / float(zen4[k[0]]), nan
        else:
            l, p = nan, nan
        bb = b.get(k, nan)
        w.writerow([k[0], k[1], k[2], f"{bb:.4e}", f"{a[k]:.4e}", f"{a[k] / bb:.3f}", f"{ca:.4e}", fmt(l, ".4e"),
                    fmt(bb / l, ".3f"), fmt(a[k] / l, ".3f"), fmt(p, ".4e"), fmt(a[k] / p, ".3f")])
print(f"{out}/{prefix}_kernel.csv: clock before {cb:.4e} Hz, after {ca:.4e} Hz")
PY
