#!/usr/bin/env python3
"""Where two output trees differ, by how much: for every CSV that differs between OLD and NEW (the work
folders `old/` and `new/` that bitwise_outputs.sh leaves), the largest relative difference of each
column, with the two values and the time of the row. Numbers are compared as numbers: the row files
pad mantissas with zeros to fill pages, so one changed digit moves the padding of other rows.

    python3 verification/scripts/column_differences.py WORK_DIR

The relative difference is |a - b| / max(|a|, |b|); a difference in the last bits of a number near zero
(an energy of 1e-22 J) shows as a large relative one, so the values are printed beside it.
"""
import csv
import glob
import sys

work = sys.argv[1]
for old in sorted(glob.glob(f"{work}/old/**/*.csv", recursive=True)):
    new = f"{work}/new/" + old[len(f"{work}/old/"):]
    try:
        a, b = list(csv.reader(open(old))), list(csv.reader(open(new)))
    except FileNotFoundError:
        print(f"{old}: only in old")
        continue
    if a == b:
        continue
    worst = {}
    for ra, rb in zip(a[1:], b[1:]):
        for h, x, y in zip(a[0], ra, rb):
            if x == y:
                continue
            try:
                fx, fy = float(x), float(y)
                rel = abs(fx - fy) / max(abs(fx), abs(fy), 1e-300)
            except ValueError:
                rel = float("inf")
            if rel == 0.0:
                continue  # the same number written with other padding (output/rows.rs pads to pages)
            if rel > worst.get(h, (-1.0,))[0]:
                worst[h] = (rel, x, y, ra[0])
    if len(a) != len(b):
        print(f"{old[len(work) + 5:]}: {len(a)} rows against {len(b)}")
    for h, (rel, x, y, t) in sorted(worst.items()):
        print(f"{old[len(work) + 5:]}: {h}: {rel:.1e} ({x} against {y} at {a[0][0]} = {t[:12]})")
