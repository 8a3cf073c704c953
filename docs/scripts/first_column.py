# Where the target particles that started next to the impact axis are now
# (docs/verification.md, RZ against 3-D). Reads the t = 0 snapshot and a later one of
# the same run; keeps the target particles (material id TARGET) that started within
# R0_MAX of the axis and above Z0_MIN, matched by their stable id, and prints their start,
# their position now, their radial velocity and damage, and the mean distance from the
# axis. The radius is sqrt(x^2 + y^2): for RZ snapshots (x = r, y = 0) that is the ring
# radius, for 3-D ones the distance from the axis.
#
# Usage: python3 first_column.py TARGET INITIAL.vtu SNAPSHOT.vtu R0_MAX_M Z0_MIN_M
import sys, math, os
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtu_read import read


def radial(p, v):
    r = math.hypot(p[0], p[1])
    return r, (v[0] * p[0] + v[1] * p[1]) / r if r > 0.0 else 0.0


def main():
    target, first, now_path = int(sys.argv[1]), sys.argv[2], sys.argv[3]
    r0_max, z0_min = float(sys.argv[4]), float(sys.argv[5])
    d0, d = read(first), read(now_path)
    start = {i: (math.hypot(p[0], p[1]), p[2])
             for i, p, m in zip(d0["id"], d0["Points"], d0["material"])
             if m == target and math.hypot(p[0], p[1]) < r0_max and p[2] > z0_min}
    now = {i: (p, v, dm) for i, p, v, dm in zip(d["id"], d["Points"], d["velocity"], d["damage"])}
    radii = []
    for i, (r0, z0) in sorted(start.items(), key=lambda kv: -kv[1][1]):
        p, v, dm = now[i]
        r, v_r = radial(p, v)
        radii.append(r)
        print("id %d: r0 %.2f z0 %.2f mm -> r %.2f z %.2f mm, v_r %.1f m/s, D %.2f"
              % (i, r0 * 1e3, z0 * 1e3, r * 1e3, p[2] * 1e3, v_r, dm))
    if radii:
        print("mean r %.2f mm over %d particles" % (1e3 * sum(radii) / len(radii), len(radii)))


if __name__ == "__main__":
    main()
