#!/usr/bin/env bash
# CPU time (user + system, from the child's rusage: wait4, in microseconds) of whole runs (`ohl run`, as written, nothing shortened) of every
# case and mechanical example with two binaries, the runs of the two alternating so that a change of the
# machine's load falls on both; the median of REPS runs each. The issue-27 goal is stated in CPU time:
# this is its measurement (`run_instructions.sh` counts instructions, the load-independent proxy). Outputs
# go to a temporary directory and are deleted. A scenario the old binary rejects (a file format it does
# not know) gets "NA".
#
# usage: app/benches/run_cpu.sh OLD_BINARY NEW_BINARY [REPS] [CSV]   (writes "scenario,old_cpu_s,new_cpu_s,old_over_new")
# e.g.   app/benches/run_cpu.sh /tmp/ohl-060d9f9 target/release/ohl 5 figures/bench/run_cpu.csv
# ONLY="name name ..." restricts the runs to those scenarios (file names without .toml), e.g. for a pass
# with more repetitions of the short runs.
set -euo pipefail
old="$(realpath "$1")"
new="$(realpath "$2")"
reps=${3:-3}
csv=${4:-/dev/stdout}
cd "$(dirname "$0")/../.."
work="$(mktemp -d "${TMPDIR:-/tmp}/ohl-run-cpu.XXXXXX")"
trap 'rm -rf "$work"' EXIT
# The child's user + system time from wait4 (microseconds; /usr/bin/time prints hundredths, too coarse
# for the runs of a fraction of a second), or NA if the run fails.
cpu() {
  python3 - "$1" "$2" "$work/out" << 'PY'
import os, subprocess, sys
p = subprocess.Popen([sys.argv[1], "run", sys.argv[2], "--out", sys.argv[3], "--quiet"],
                     stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
_, status, usage = os.wait4(p.pid, 0)
print("%.4f" % (usage.ru_utime + usage.ru_stime) if status == 0 else "NA")
PY
  rm -rf "$work/out"
}
median() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{ a[NR] = $1 } END { if (NR == 0 || a[1] == "NA") print "NA"; else print a[int((NR + 1) / 2)] }'; }
[ "$csv" = /dev/stdout ] || echo "scenario,old_cpu_s,new_cpu_s,old_over_new" > "$csv"
for f in cases/*.toml examples/mechanical/*.toml; do
  n="$(basename "$f" .toml)"
  if [ -n "${ONLY:-}" ] && [[ " $ONLY " != *" $n "* ]]; then continue; fi
  o="" w=""
  for _ in $(seq "$reps"); do
    o="$o $(cpu "$old" "$f")"
    w="$w $(cpu "$new" "$f")"
  done
  mo=$(echo "$o" | median)
  mw=$(echo "$w" | median)
  ratio=$(awk -v a="$mo" -v b="$mw" 'BEGIN { if (a == "NA" || b == "NA" || b == 0) print "NA"; else printf "%.3f", a / b }')
  echo "$n,$mo,$mw,$ratio" >> "$csv"
  [ "$csv" = /dev/stdout ] || echo "$n,$mo,$mw,$ratio"
done
