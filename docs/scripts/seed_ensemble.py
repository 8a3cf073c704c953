#!/usr/bin/env python3
"""Seed-to-seed scatter of finished runs (docs/validation.md, "The flaws' draw").

Groups run directories by a label and prints, per group, each run's crater and β from its
summary.json and history.csv, then the mean, the sample standard deviation, the standard
error of the mean and the range; and, for each run, the removed-material diameter read
from its stored crater profile (`crater_profile` in summary.json) at fixed depth
thresholds, next to the run's own one-bin threshold.

    python3 docs/scripts/seed_ensemble.py LABEL=RUN_DIR [LABEL=RUN_DIR ...]

e.g. `1mm=runs/s1_1mm 1mm=runs/s2_1mm 0.5mm=runs/s1_0.5mm`. Pure Python (no numpy).
Columns: Ø (spall) and Ø removed, bowl, binned and axis depth (mm), β, β_detached, and
the change of β over the last 100 µs (%).
"""
import csv
import json
import os
import statistics as st
import sys

KEYS = ["D", "Drem", "bowl", "depth", "axis", "beta", "bdet", "chg"]
THRESHOLDS_MM = [0.5, 1.0, 2.0, 3.0]


def removed_diameter(radius, depth, threshold):
    """2 × the outer edge of the run from the axis of bins deeper than `threshold`;
    empty bins (null) neither end nor extend it (docs/diagnostics.md §4.2)."""
    last = None
    for i, d in enumerate(depth):
        if d is None:
            continue
        if d > threshold:
            last = i
        else:
            break
    if last is None:
        return 0.0
    return 2.0 * (radius[last] + (radius[1] - radius[0]) / 2.0)


def read(run):
    s = json.load(open(os.path.join(run, "summary.json")))
    if not s.get("complete"):
        raise SystemExit(f"{run}: the run did not complete")
    rows = list(csv.DictReader(open(os.path.join(run, "history.csv"))))
    t_end, b_end = float(rows[-1]["t_s"]), float(rows[-1]["beta"])
    earlier = min(rows, key=lambda r: abs(float(r["t_s"]) - (t_end - 1e-4)))
    radius, depth = s["crater_profile"]
    bin_m = radius[1] - radius[0]
    return {
        "seed": s["scene"].get("seed", 1),
        "D": s["crater_diameter_m"] * 1e3,
        "Drem": s["crater_diameter_removed_m"] * 1e3,
        "bowl": s["bowl_diameter_m"] * 1e3,
        "depth": s["crater_depth_m"] * 1e3,
        "axis": s["crater_axis_depth_m"] * 1e3,
        "beta": s["beta"],
        "bdet": s["beta_detached"],
        "chg": 100.0 * (b_end / float(earlier["beta"]) - 1.0),
        "bin": bin_m * 1e3,
        "own": removed_diameter(radius, depth, bin_m) * 1e3,
        "fixed": [removed_diameter(radius, depth, t * 1e-3) * 1e3 for t in THRESHOLDS_MM],
    }


def main(args):
    if not args or any("=" not in a for a in args):
        raise SystemExit(__doc__)
    groups = {}
    for a in args:
        label, run = a.split("=", 1)
        groups.setdefault(label, []).append(read(run))
    for label, runs in groups.items():
        runs.sort(key=lambda r: r["seed"])
        print(f"\n## {label}: {len(runs)} runs")
        print("seed " + " ".join(f"{k:>7}" for k in KEYS))
        for r in runs:
            print(f"{r['seed']:4d} " + " ".join(f"{r[k]:7.3f}" for k in KEYS))
        if len(runs) > 1:
            n = len(runs)
            for name, f in [
                ("mean", lambda v: st.mean(v)),
                ("sd", lambda v: st.stdev(v)),
                ("se", lambda v: st.stdev(v) / n**0.5),
                ("min", min),
                ("max", max),
            ]:
                print(f"{name:4} " + " ".join(f"{f([r[k] for r in runs]):7.3f}" for k in KEYS))
        head = " ".join(f"{t:g} mm" for t in THRESHOLDS_MM)
        print(f"Ø removed (mm) at the run's own threshold (one bin) | at {head}")
        for r in runs:
            fixed = " ".join(f"{x:5.1f}" for x in r["fixed"])
            print(f"{r['seed']:4d} bin {r['bin']:.2f} mm: {r['own']:5.1f} | {fixed}")


if __name__ == "__main__":
    main(sys.argv[1:])
