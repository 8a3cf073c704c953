# Which particles make the target's volume fraction phi on the impact axis at one height
# (docs/verification.md, "Axisymmetric (RZ) geometry": what fills the 3-D axis field). Sums
# V_j W(|x_axis(z) - x_j|, H) over the wall particles with ZLO < z_j < ZHI within H of
# the axis (3-D Wendland C2, as crater_axis_depth.py, at z = (ZLO + ZHI)/2) and lists the
# largest shares with each particle's distance from the axis now and where it started.
#
# Usage: python3 axis_field_sources.py RUN_DIR SNAPSHOT.vtu ZLO_M ZHI_M [H_M]
import sys, math, os
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtu_read import read, snapshots
from crater_axis_depth import w3


def main():
    run, snap, z1, z2 = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
    H = float(sys.argv[5]) if len(sys.argv) > 5 else 1.25e-3
    d0, d = read(snapshots(run)[0]), read(run + "/snapshots/" + snap)
    start = {i: (math.hypot(p[0], p[1]), p[2]) for i, p in zip(d0["id"], d0["Points"])}
    zc = 0.5 * (z1 + z2)
    rows = []
    for i, p, v, m, rho, mat in zip(d["id"], d["Points"], d["velocity"], d["mass"],
                                    d["density"], d["material"]):
        s = math.hypot(p[0], p[1])
        if mat != 1 or s >= H or not z1 < p[2] < z2 or (p[2] > 0.0 and v[2] > 0.0):
            continue
        w = m / rho * w3(math.sqrt(s * s + (zc - p[2]) ** 2) / H, H)
        rows.append((w, s * 1e3, p[2] * 1e3, start[i][0] * 1e3, start[i][1] * 1e3, i))
    total = sum(r[0] for r in rows)
    rows.sort(reverse=True)
    print("phi at z = %.2f mm: %.3f" % (zc * 1e3, total))
    for r in rows[:12]:
        print("  share %.2f  s %.2f z %.2f mm  <- s0 %.2f z0 %.2f mm  id %d"
              % ((r[0] / total,) + r[1:]))


if __name__ == "__main__":
    main()
