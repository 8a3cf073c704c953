# Exploratory (docs/validation.md; to be replaced by a Rust diagnostics option): crater diameter with damaged material counted as removed (diagnostics §4.1
# max_damage), from the final RZ snapshot. Same profile rules otherwise: walls = target
# particles that are not ejecta (above the surface and moving up), floor = highest wall
# particle per 1 mm bin of r, depth = -floor - top_offset, diameter = contiguous run from
# the axis of bins deeper than one bin.
import sys, math, os
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtu_read import read
# Usage: python3 crater_damage_cut.py SNAPSHOT.vtu TARGET_MATERIAL_ID BIN_M TOP_OFFSET_M
d = read(sys.argv[1]); target = int(sys.argv[2]); b = float(sys.argv[3]); top = float(sys.argv[4])
for max_d in [1.01, 0.99, 0.9, 0.5]:
    floor = {}
    for p, v, D, mat in zip(d['Points'], d['velocity'], d['damage'], d['material']):
        if mat != target: continue
        r, z = math.hypot(p[0], p[1]), p[2]
        if z > 0 and v[2] > 0: continue   # ejecta
        if D >= max_d: continue
        k = int(r / b); floor[k] = max(floor.get(k, -1e9), z)
    run = 0; k = 0; last = 0
    kmax = max(floor)
    while k <= kmax:
        if k in floor:
            depth = -floor[k] - top
            if depth > b: last = k
            else: break
        k += 1
    dmax = max(-floor[k]-top for k in floor if k <= last)
    print("max_damage %.2f: diameter %.1f mm, max depth in the run %.1f mm" % (max_d, 2*(last+1)*b*1e3, dmax*1e3))
