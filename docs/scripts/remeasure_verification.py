#!/usr/bin/env python3
"""Re-measure a verification data file (docs/verification/data/NAME.toml) in place.

Runs `BIN verify PROBLEM --resolution N --threads 1 --json [--geometry G]` for each
[[run]] of the file (or only those given with --resolution) and writes the output's
values for every key that has a tolerance back into the file; the header, the
tolerances, the columns and each run's `tested` flag are kept. Then
`cargo test -p sph-impact --test verification_pages` prints the page's new table.

    cargo build --release -p sph-impact
    python3 docs/scripts/remeasure_verification.py target/release/sph-impact \
        docs/verification/data/sedov_2d.toml [--resolution 50 --resolution 100]
"""

import argparse
import json
import math
import re
import subprocess
import sys
import time
import tomllib


def measure(binary, problem, geometry, resolution):
    cmd = [binary, "verify", problem.replace("_", "-"), "--resolution", str(resolution),
           "--threads", "1", "--json"]
    if geometry:
        cmd += ["--geometry", geometry]
    start = time.time()
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    line = [l for l in out.splitlines() if l.startswith("{")][-1]
    print(f"{' '.join(cmd[1:])}: {time.time() - start:.1f} s", file=sys.stderr)
    return json.loads(line)


def number(key, x):
    """Five significant digits; counts as integers."""
    if key in ("steps", "particles") or (float(x).is_integer() and abs(x) < 1e15):
        return str(int(x))
    return f"{x:.5g}".replace("e-0", "e-").replace("e+0", "e")


def rounding(x):
    """Half a unit of the fifth significant digit: how far `number` may move a value."""
    return 0.0 if x == 0 else 0.5 * 10 ** (math.floor(math.log10(abs(x))) - 4)


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("binary")
    ap.add_argument("data")
    ap.add_argument("--resolution", type=int, action="append",
                    help="only these runs (default: every run of the file)")
    args = ap.parse_args()

    text = open(args.data, encoding="utf-8").read()
    data = tomllib.loads(text)
    keys = list(data["tolerance"])
    head, *runs = re.split(r"(?m)^\[\[run\]\]\n", text)
    out = [head]
    for block, run in zip(runs, data["run"]):
        n = run["resolution"]
        if args.resolution and n not in args.resolution:
            out.append("[[run]]\n" + block)
            continue
        got = measure(args.binary, data["problem"], data.get("geometry"), n)
        missing = [k for k in keys if k not in got]
        if missing:
            sys.exit(f"{args.data}: the output at {n} has no key {', '.join(missing)}")
        lines = [f"resolution = {n}", f"tested = {'true' if run['tested'] else 'false'}"]
        lines += [f"{k} = {number(k, got[k])}" for k in keys]
        for k in keys:
            tol = data["tolerance"][k]
            if 0 < tol < rounding(got[k]) and not float(got[k]).is_integer():
                print(f"{args.data}: {k} = {got[k]} at {n} is stored to ±{rounding(got[k]):.1e},"
                      f" more than its tolerance {tol:.1e}: raise the tolerance", file=sys.stderr)
        out.append("[[run]]\n" + "\n".join(lines) + "\n\n")
    open(args.data, "w", encoding="utf-8").write("".join(out).rstrip("\n") + "\n")


if __name__ == "__main__":
    main()
