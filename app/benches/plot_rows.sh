#!/usr/bin/env bash
# Time of `ohl plot` against the number of rows of a run's time series: 1e4, 1e5 and 1e6 rows (a 180 s
# run sampled at 0.02 s has 9000). The run folder is a real one (examples/mechanical/drake_level_400m_wind)
# whose timeseries.csv is replaced by N rows of smooth, noisy and constant columns under the same header.
#
# usage: app/benches/plot_rows.sh OHL_BINARY [WORK_DIR]     (prints "rows,seconds,max_rss_kb")
set -euo pipefail
bin=$(realpath "$1")
work=${2:-$(mktemp -d "${TMPDIR:-/tmp}/ohl-plot-rows.XXXXXX")}
cd "$(dirname "$0")/../.."
"$bin" run examples/mechanical/drake_level_400m_wind.toml --out "$work/base" --quiet > /dev/null
header=$(head -1 "$work/base/timeseries.csv")
echo "rows,seconds,max_rss_kb"
for n in 10000 100000 1000000; do
  d="$work/rows$n"; mkdir -p "$d"
  cp "$work/base/snapshots.csv" "$work/base/summary.json" "$d/"
  awk -v n="$n" -v h="$header" 'BEGIN {
    print h; cols = split(h, names, ","); srand(1)
    for (k = 0; k < n; k++) {
      t = 200.0 * k / n; line = sprintf("%.17g", t)
      for (c = 2; c <= cols; c++) {
        if (c % 3 == 0) v = 1000.0 * c                                  # constant
        else if (c % 3 == 1) v = c * sin(t / (1 + c)) + 0.01 * rand()   # smooth plus noise
        else v = c * cos(3 * t) * exp(-t / 100)                         # decaying oscillation
        line = line "," sprintf("%.17g", v)
      }
      print line
    }
  }' > "$d/timeseries.csv"
  /usr/bin/time -f "$n,%e,%M" "$bin" plot "$d" --quiet 2>&1 >/dev/null | tail -1
done
