#!/usr/bin/env python3
"""Markdown table of `ohl bench` kernel CSVs: the median over rounds of node-steps per CPU second per
configuration and N, for up to three binaries, their ratios and the fraction of the compute limit.

Usage: app/benches/kernel_table.py 'BEFORE_GLOB' 'MIDDLE_GLOB' 'AFTER_GLOB'

Each glob names the CSVs (`ohl bench --out DIR --label LABEL` writes DIR/LABEL.csv) of one binary's rounds,
e.g. 'figures/bench/issue27_r7_kernel_now_[0-9].csv'. Each binary's fraction is of its own
`limit_node_steps_per_s` (the median over its rounds; the after binary's where the middle one's CSVs have
none); configurations without one show "-". Regenerates the kernel tables of issue 27's seventh and eighth
rounds in figures/bench/README.md (the seventh's took the after binary's limit for both, the same there).
"""
import csv
import glob
import statistics
import sys


def load(pattern):
    speed, limit = {}, {}
    for path in sorted(glob.glob(pattern)):
        for row in csv.DictReader(open(path)):
            key = (row["config"], int(row["n"]))
            speed.setdefault(key, []).append(float(row["node_steps_per_s"]))
            if row.get("limit_node_steps_per_s"):
                limit.setdefault(key, []).append(float(row["limit_node_steps_per_s"]))
    return speed, limit


(before, _), (middle, mid_limit), (after, limit) = (load(p) for p in sys.argv[1:4])
print("| config | N | before [node-steps/CPU s] | middle | after | after / before | after / middle "
      "| middle, of limit | after, of limit |")
print("|---|---|---|---|---|---|---|---|---|")
for key in after:
    a, b, c = (statistics.median(d[key]) if key in d else None for d in (before, middle, after))
    lim = statistics.median(limit[key]) if key in limit else None
    mid_lim = statistics.median(mid_limit[key]) if key in mid_limit else lim
    num = lambda x: f"{x:.3e}" if x else "-"
    ratio = lambda x, y: f"{x / y:.2f}" if x and y else "-"
    frac = lambda x, l: f"{100 * x / l:.0f} %" if l and x else "-"
    print(f"| {key[0]} | {key[1]} | {num(a)} | {num(b)} | {num(c)} | {ratio(c, a)} | {ratio(c, b)} | {frac(b, mid_lim)} "
          f"| {frac(c, lim)} |")
