#!/usr/bin/env python3
"""Compares two runs' history.csv at the snapshot times they share (issue 6: RZ against
3-D for the first 20 µs). Prints, per time, β and the crater depth on the axis
(`crater_axis_depth_m`, docs/diagnostics.md §4.4) of both runs and the second's
relative difference from the first, then the largest |difference| from --from on.

    python3 docs/scripts/compare_histories.py RZ_DIR/history.csv Q3D_DIR/history.csv [--from 1e-6]

Pure Python (no numpy). Rows are the snapshot rows (`crater_measured` = 1); times match
within 1e-12 s.
"""
import csv
import sys


def snapshot_rows(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["crater_measured"] == "1"]
    return {round(float(r["t_s"]) * 1e12): r for r in rows}


def main(argv):
    args = [a for a in argv[1:]]
    t_from = 0.0
    if "--from" in args:
        k = args.index("--from")
        t_from = float(args[k + 1])
        del args[k : k + 2]
    if len(args) != 2:
        sys.exit(__doc__)
    a, b = (snapshot_rows(p) for p in args)
    keys = sorted(set(a) & set(b))
    if not keys:
        sys.exit("no snapshot time in common")
    print("| t (µs) | β first | β second | β diff | axis depth first (mm) | second (mm) | depth diff |")
    print("|---|---|---|---|---|---|---|")
    worst = {"beta": (0.0, None), "depth": (0.0, None)}
    for k in keys:
        ra, rb = a[k], b[k]
        t = float(ra["t_s"])
        if t == 0.0:
            continue
        ba, bb = float(ra["beta"]), float(rb["beta"])
        # Histories of earlier versions have no axis depth: shown as nan.
        da, db = (float(r.get("crater_axis_depth_m", "nan")) for r in (ra, rb))
        dbeta = bb / ba - 1.0
        ddepth = db / da - 1.0 if da != 0.0 else float("nan")
        print(
            f"| {t * 1e6:.2f} | {ba:.4f} | {bb:.4f} | {100 * dbeta:+.1f} % | "
            f"{da * 1e3:.3f} | {db * 1e3:.3f} | {100 * ddepth:+.1f} % |"
        )
        if t >= t_from - 1e-12:
            for name, d in (("beta", dbeta), ("depth", ddepth)):
                if abs(d) > abs(worst[name][0]):
                    worst[name] = (d, t)
    for name, (d, t) in worst.items():
        if t is not None:
            print(f"largest |{name} diff| from {t_from * 1e6:.2f} µs: {100 * d:+.2f} % at {t * 1e6:.2f} µs")


if __name__ == "__main__":
    main(sys.argv)
