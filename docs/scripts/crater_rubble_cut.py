# Exploratory (docs/validation.md; to be replaced by making the diagnostics'
# DensityCut the default): crater depth with loose rubble left out of the profile. Same
# rules as docs/diagnostics.md §4.1-4.2 otherwise: walls = target particles that are not
# ejecta (above the surface and moving up), floor = highest wall particle per bin of r,
# depth = -floor - top_offset, the run = contiguous bins from the axis deeper than one bin,
# depth = the largest in the run, bowl = the run from the axis of bins at least half as
# deep. A particle whose density is below FRACTION x rho0 is
# rubble and left out (fraction 0 keeps everything: the default diagnostics).
# Usage: python3 crater_rubble_cut.py SNAPSHOT.vtu TARGET_MATERIAL_ID BIN_M TOP_OFFSET_M RHO0
import sys, math, os
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtu_read import read
d = read(sys.argv[1]); target = int(sys.argv[2]); b = float(sys.argv[3])
top = float(sys.argv[4]); rho0 = float(sys.argv[5])
for fraction in [0.0, 0.5, 0.8]:
    floor = {}
    for p, v, rho, mat in zip(d['Points'], d['velocity'], d['density'], d['material']):
        if mat != target: continue
        r, z = math.hypot(p[0], p[1]), p[2]
        if z > 0 and v[2] > 0: continue   # ejecta
        if rho < fraction * rho0: continue  # rubble
        k = int(r / b); floor[k] = max(floor.get(k, -1e9), z)
    k, last = 0, -1
    while k <= max(floor):
        if k in floor:
            if -floor[k] - top > b: last = k
            else: break
        k += 1
    dmax = max((-floor[k] - top for k in floor if k <= last), default=float('nan'))
    k, bowl = 0, -1
    while k <= max(floor):
        if k in floor:
            if -floor[k] - top >= 0.5 * dmax: bowl = k
            else: break
        k += 1
    print("rubble below %.1f rho0 left out: removed-material diameter %.0f mm, depth %.2f mm, "
          "bowl diameter %.0f mm" % (fraction, 2 * (last + 1) * b * 1e3, dmax * 1e3,
                                     2 * (bowl + 1) * b * 1e3))
