# How evenly a 3-D (or 3-D quarter) run's projectile debris is spread about the impact
# axis in its last snapshot (docs/studies.md, "n_target"): the projectile's particles
# (body 0) are split by azimuth into SECTORS equal sectors of the quarter x, y > 0 (of the
# whole circle for a full 3-D run) and the mass-weighted mean distance from the axis of
# each is compared. An axisymmetric spread gives equal sectors; the study saw n_target 2.0
# scatter the projectile irregularly.
#
#   python3 docs/scripts/projectile_scatter.py RUN_DIR [RUN_DIR ...]
#
# Prints, per run, the snapshot read, the projectile's particle count, each sector's mean
# distance (mm), and the spread (max − min)/mean.
import math, os, sys
sys.path.insert(0, os.path.dirname(__file__))
import vtu_read

SECTORS = 3

for run in sys.argv[1:]:
    last = vtu_read.snapshots(run)[-1]
    d = vtu_read.read(last)
    quarter = all(p[0] >= 0.0 and p[1] >= 0.0 for p in d['Points'])
    span = 0.5 * math.pi if quarter else 2.0 * math.pi
    mass = [0.0] * SECTORS
    moment = [0.0] * SECTORS
    count = 0
    for p, m, b in zip(d['Points'], d['mass'], d['material']):
        if b != 0:
            continue
        count += 1
        phi = math.atan2(p[1], p[0]) % (2.0 * math.pi)
        k = min(int(phi / span * SECTORS), SECTORS - 1)
        mass[k] += m
        moment[k] += m * math.hypot(p[0], p[1])
    means = [moment[k] / mass[k] if mass[k] > 0 else float('nan') for k in range(SECTORS)]
    mean = sum(moment) / sum(mass)
    spread = (max(means) - min(means)) / mean
    print(f"{run}: {os.path.basename(last)}, {count} projectile particles, mean distance by sector "
          + ", ".join(f"{1e3 * s:.3f}" for s in means) + f" mm; spread {spread:.3f}")
