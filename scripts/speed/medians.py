#!/usr/bin/env python3
"""Prints criterion's median (and its 95 % interval) for each estimates.json
given, under the benchmark's full id, sorted by id. Used by criterion-medians.sh."""
import json
import os
import sys


def fmt(ns):
    for unit, scale in (("s", 1e9), ("ms", 1e6), ("µs", 1e3)):
        if ns >= scale:
            return f"{ns / scale:.4g} {unit}"
    return f"{ns:.4g} ns"


rows = []
for path in sys.argv[1:]:
    new = os.path.dirname(path)
    with open(path) as f:
        med = json.load(f)["median"]
    with open(os.path.join(new, "benchmark.json")) as f:
        full_id = json.load(f)["full_id"]
    ci = med["confidence_interval"]
    rows.append((full_id, med["point_estimate"], ci["lower_bound"], ci["upper_bound"]))
for full_id, m, lo, hi in sorted(rows):
    print(f"median  {fmt(m):>10}  [{fmt(lo)} … {fmt(hi)}]  {full_id}")
