# Crater depth on the impact axis from the target's volume fraction (docs/verification.md,
# RZ against 3-D). phi(z) = sum_j V_j W(|x_axis(z) - x_j|, H) over the target's wall
# particles (not ejecta: above the surface and moving up), V_j = m_j / rho_j, with the
# 3-D Wendland C2 kernel of one support radius H for every particle (given; the code's
# own h at rest is about 2.5 A_res). The particles' own h adapts differently in RZ and
# 3-D (next to the axis of the 3-D rings placement it moves by 10 % in rock the shock
# has not reached), so it is not used.
#
# The floor is the highest z on the axis where phi(z, t) >= phi(z, 0) / 2, scanning down
# from above the surface (phi(z, 0) taken at z = -H above that depth); depth = -floor
# (surface at z = 0). Dividing by the initial field at the same point cancels the kernel
# sum's quadrature error, which depends on the local spacing (variable resolution) and
# on the ring placement next to the axis, and is the same in both geometries at t = 0.
#
# RZ snapshots hold rings (x = r, the ring's whole mass): every point of ring j is at
# distance sqrt(r_j^2 + (z - z_j)^2) from the axis point. A 3-D quarter model's snapshot
# gives each particle the mass of its four mirror copies, all four equidistant from the
# axis. So one formula serves RZ, the quarter and a full 3-D body.
#
# LEVEL (default 0.5, the code's own) replaces the half level, for checking how much the
# depth depends on where the field is cut (docs/verification.md, "the axis jet").
#
# --profile TOP_M BOTTOM_M prints phi(z, t) / phi(z', 0) every 0.125 mm from TOP down to
# BOTTOM for each snapshot instead (the profiles in docs/verification.md).
#
# Usage: python3 crater_axis_depth.py [--level LEVEL] [--profile TOP_M BOTTOM_M]
#            TARGET_MATERIAL_ID H_M INITIAL.vtu SNAPSHOT.vtu...
import sys, math, os
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtu_read import read


def w3(q, h):
    if q >= 1.0:
        return 0.0
    u = 1.0 - q
    return 21.0 / (2.0 * math.pi) / h ** 3 * u ** 4 * (1.0 + 4.0 * q)


def wall_particles(path, target, reach):
    """(s^2, z, V) of the target's wall particles within `reach` of the axis."""
    d = read(path)
    parts = []
    for p, v, m, rho, mat in zip(d["Points"], d["velocity"], d["mass"], d["density"],
                                 d["material"]):
        if mat != target or (p[2] > 0.0 and v[2] > 0.0):
            continue
        s2 = p[0] ** 2 + p[1] ** 2
        if s2 < reach * reach:
            parts.append((s2, p[2], m / rho))
    return parts


def axis_fraction(parts, z, H):
    return sum(v * w3(math.sqrt(s2 + (z - zj) ** 2) / H, H) for s2, zj, v in parts
               if abs(z - zj) < H)


def highest_filled(filled, top, bottom, dz, iterations):
    """The highest z in [bottom, top] where filled(z) holds: scanned down in steps of dz,
    then bisected `iterations` times; nan when it never holds."""
    z = top
    while z > bottom:
        if filled(z):
            lo, hi = z, z + dz
            for _ in range(iterations):
                mid = 0.5 * (lo + hi)
                lo, hi = (mid, hi) if filled(mid) else (lo, mid)
            return 0.5 * (lo + hi)
        z -= dz
    return float("nan")


def axis_floor(parts, initial, H, top=0.005, bottom=-0.06, dz=1e-4, level=0.5):
    def filled(z):
        return axis_fraction(parts, z, H) >= level * axis_fraction(initial, min(z, -H), H)
    return highest_filled(filled, top, bottom, dz, 30)


def main():
    args, level, profile = sys.argv[1:], 0.5, None
    while args[:1] in (["--level"], ["--profile"]):
        if args[0] == "--level":
            level, args = float(args[1]), args[2:]
        else:
            profile, args = (float(args[1]), float(args[2])), args[3:]
    target, H, first, files = int(args[0]), float(args[1]), args[2], args[3:]
    initial = wall_particles(first, target, H)
    if profile:
        snaps = [wall_particles(f, target, H) for f in files]
        print("z_mm " + " ".join(os.path.basename(f) for f in files))
        z = profile[0]
        while z >= profile[1] - 1e-12:
            ref = axis_fraction(initial, min(z, -H), H)
            print("%7.3f " % (z * 1e3)
                  + " ".join("%5.2f" % (axis_fraction(p, z, H) / ref) for p in snaps))
            z -= 0.125e-3
        return
    for f in files:
        floor = axis_floor(wall_particles(f, target, H), initial, H, level=level)
        print("%s: axis depth %.3f mm" % (f, -floor * 1e3))


if __name__ == "__main__":
    main()
