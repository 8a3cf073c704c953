# Exploratory (docs/validation.md, "β in time"): ejecta mass and axial momentum of an RZ or
# 3-D snapshot split by decade of v_z, with the ejecta rule of docs/diagnostics.md §2
# (target material above the original surface z = 0, moving up).
# Usage: python3 ejecta_by_speed.py TARGET_MATERIAL_ID SNAPSHOT.vtu...
import sys, math, collections
sys.path.insert(0, __import__('os').path.dirname(__import__('os').path.abspath(__file__)))
from vtu_read import read
target = int(sys.argv[1])
for path in sys.argv[2:]:
    d = read(path)
    h = collections.defaultdict(lambda: [0, 0.0, 0.0])
    for p, v, m, mat in zip(d['Points'], d['velocity'], d['mass'], d['material']):
        if mat != target or p[2] <= 0 or v[2] <= 0:
            continue
        k = h[int(math.floor(math.log10(max(v[2], 1e-3))))]
        k[0] += 1; k[1] += m; k[2] += m * v[2]
    total = sum(k[2] for k in h.values())
    print(path, "ejecta momentum %.4g kg m/s" % total)
    for dec, (n, m, pz) in sorted(h.items()):
        print("  v_z in [%g, %g) m/s: %d particles, %.4g kg, %.4g kg m/s (%.1f %%)" % (10**dec, 10**(dec+1), n, m, pz, 100 * pz / total))
