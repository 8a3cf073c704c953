# Exploratory (docs/validation.md, "Resolution"): where the ejecta of a snapshot
# started. Ejecta follow the rule of docs/diagnostics.md §2 (target material above the
# original surface z = 0, moving up); each is traced back by its id to the first snapshot
# and binned by its starting distance from the axis r0. Per bin: mass, axial momentum, the
# mass-weighted mean v_z and the range of starting depths.
#
#   python3 ejecta_by_origin.py TARGET_MATERIAL_ID SNAPSHOT_AT_T0.vtu SNAPSHOT.vtu
#
# Works for RZ and 3-D snapshots (r0 = sqrt(x0^2 + y0^2)).
import sys, math, os
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtu_read import read

EDGES_MM = [0, 3, 4, 5, 6, 8, 10, 12, 15, float('inf')]

def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__ or "usage: ejecta_by_origin.py TARGET_ID T0.vtu SNAPSHOT.vtu")
    target = int(sys.argv[1])
    first, snap = read(sys.argv[2]), read(sys.argv[3])
    start = dict(zip(first['id'], first['Points']))
    # per bin: mass, momentum, shallowest and deepest start
    bins = [[0.0, 0.0, math.inf, -math.inf] for _ in EDGES_MM[1:]]
    for i, p, v, m, mat in zip(snap['id'], snap['Points'], snap['velocity'], snap['mass'],
                               snap['material']):
        if mat != target or p[2] <= 0 or v[2] <= 0:
            continue
        x0, y0, z0 = start[i]
        r0_mm = 1e3 * math.hypot(x0, y0)
        k = max(j for j in range(len(EDGES_MM) - 1) if EDGES_MM[j] <= r0_mm)
        b = bins[k]
        b[0] += m
        b[1] += m * v[2]
        b[2] = min(b[2], -z0)
        b[3] = max(b[3], -z0)
    total_m = sum(b[0] for b in bins)
    total_p = sum(b[1] for b in bins)
    print("%s: ejecta %.4g g, %.4g kg m/s" % (sys.argv[3], 1e3 * total_m, total_p))
    for k, (m, pz, zmin, zmax) in enumerate(bins):
        if m == 0:
            continue
        hi = EDGES_MM[k + 1]
        print("  r0 %g-%s mm: %.3f g, %.3f kg m/s, <v_z> %.0f m/s, depth %.2f-%.2f mm"
              % (EDGES_MM[k], "inf" if math.isinf(hi) else "%g" % hi, 1e3 * m, pz, pz / m,
                 1e3 * zmin, 1e3 * zmax))

main()
