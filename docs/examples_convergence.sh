#!/usr/bin/env bash
# The grid, smoothing, aerodynamic-damping and drag-coefficient comparisons of docs/examples.md: copies of
# the examples of examples/mechanical/ with one numerical field changed (by sed), run by `ohl run`, and the
# numbers read back from summary.json and timeseries.csv. From the repository root, after
# `cargo build --release --bin ohl`:
#
#   bash docs/examples_convergence.sh
#
# Needs bash, sed and awk: 40 runs, about 20 s.
set -u
OHL=${CARGO_TARGET_DIR:-target}/release/ohl
OUT=${TMPDIR:-/tmp}/ohl-convergence
mkdir -p "$OUT"

# A scalar field of summary.json (the first line with that key).
field() { awk -F': ' -v k="\"$1\"" '$1 ~ k {gsub(/[,"]/, "", $2); print $2; exit}' "$2"; }
# Peak mid-span displacement component k (1, 2, 3) of summary.json: value, or time with `time`.
peak() { awk -v k="$1" -v key="${3:-value_m}" '/"peak_midspan_displacement_m"/ {p = 1}
  p && $0 ~ "\"" key "\"" && ++n == k {gsub(/,/, "", $2); print $2; exit}' "$2"; }
# Copy example $1 to $2.toml with "key = value" lines replaced ($3...: key=value), run it into $2.
run() {
  local src=examples/mechanical/$1.toml dst=$2; shift 2
  local args=()
  for kv in "$@"; do args+=(-e "s/^${kv%%=*} = .*/${kv%%=*} = ${kv#*=}/"); done
  sed "${args[@]}" "$src" > "$dst.toml"
  "$OHL" run "$dst.toml" --out "$dst" > /dev/null || echo "$dst: ohl run failed"
}

echo "== drake_level_400m_wind: segments x smoothing (wind sets in at 1 s)"
for n in 40 80 160; do
  for b in 0.02 0.002 0.0; do
    d=$OUT/wind-$n-$b; run drake_level_400m_wind "$d" segments_per_span=$n smoothing=$b
    s=$d/summary.json
    awk -F, 'NR == 2 {printf "sag(t=0) %.5f m, ", -$5; exit}' "$d/timeseries.csv" | sed "s/^/N=$n b=$b: /"
    echo "peak dx1 $(peak 1 "$s") m, peak tension $(field peak_max_tension_n "$s") N," \
      "$(field status "$s") at $(field final_time_s "$s") s"
  done
done

echo "== drake_inclined_350m_ice_shedding: segments x smoothing (ice shed at 1 s)"
for n in 40 80 160; do
  for b in 0.02 0.002 0.0; do
    d=$OUT/ice-$n-$b; run drake_inclined_350m_ice_shedding "$d" segments_per_span=$n smoothing=$b
    # mid-span: iced sag at t = 0, jump = iced sag minus the least sag after 1 s, then the lowest point
    awk -F, -v run="N=$n b=$b" 'NR == 2 {s0 = -$5} NR > 1 && $1 >= 1.0 && (m == "" || -$5 < m) {m = -$5}
      END {printf "%s: iced sag(t=0) %.5f m, jump %.4f m, ", run, s0, s0 - m}' "$d/timeseries.csv"
    echo "lowest after the shedding (peak dx3) $(peak 3 "$d/summary.json") m"
  done
done

echo "== linnet_level_300m_break: segments x smoothing (break at 1 s)"
for n in 40 80 160; do
  for b in 0.02 0.002 0.0; do
    d=$OUT/break-$n-$b; run linnet_level_300m_break "$d" segments_per_span=$n smoothing=$b
    awk -F, -v run="N=$n b=$b" 'NR == 1 {for (i = 1; i <= NF; i++) c[$i] = i; next} NR == 2 {s0 = -$c["mid_dx3_m"]}
      $1 > 1.2 {f = sqrt($c["support1_f1_n"]^2 + $c["support1_f2_n"]^2 + $c["support1_f3_n"]^2); if (f > m) {m = f; tm = $1}}
      END {printf "%s: sag(t=0) %.7f m, right dead-end force peak after 1.2 s %.0f N at %.2f s, ", run, s0, m, tm}' \
      "$d/timeseries.csv"
    echo "mid-span on the ground at $(peak 3 "$d/summary.json" time_s) s," \
      "wire peak tension $(field peak_max_tension_n "$d/summary.json") N"
  done
done

echo "== linnet_inclined_300m_gust: segments (gust from 2 s to 5 s)"
for n in 40 80 160; do
  d=$OUT/gust-$n; run linnet_inclined_300m_gust "$d" segments_per_span=$n
  s=$d/summary.json
  echo "N=$n: peak dx1 $(peak 1 "$s") m, peak tension $(field peak_max_tension_n "$s") N at" \
    "$(field peak_max_tension_time_s "$s") s, $(field status "$s") at $(field final_time_s "$s") s"
done

echo "== drake_level_400m_wind: aerodynamic damping mu"
for mu in 0.0 0.15 1.0; do
  d=$OUT/mu-$mu; run drake_level_400m_wind "$d" mu=$mu
  s=$d/summary.json
  echo "mu=$mu: peak dx1 $(peak 1 "$s") m, peak tension $(field peak_max_tension_n "$s") N," \
    "$(field status "$s") at $(field final_time_s "$s") s"
done

echo "== drake_level_400m_wind: the paper's drag coefficients instead of C = 1"
d=$OUT/paper-drag; run drake_level_400m_wind "$d" normal_coefficient=1.8446 tangential_coefficient=0.0554
s=$d/summary.json
mid=$(awk '/"final_midspan_displacement_m"/ {p = 1; next} p && /]/ {exit} p {gsub(/[ ,]/, ""); printf "%s ", $0}' "$s")
echo "final mid-span [x1 x2 x3] ${mid}m, final max tension $(field final_max_tension_n "$s") N, $(field status "$s")"
