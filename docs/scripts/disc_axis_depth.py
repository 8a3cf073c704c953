# Crater depth from the target's volume fraction averaged over a disc of radius R about
# the impact axis: the code's axis depth (docs/diagnostics.md §4.4,
# sph_diagnostics::AxisDepth with DiscKernel), for snapshots of runs whose history.csv
# holds the earlier reading on the axis line (an earlier version), and to check the code.
#
# crater_axis_depth.py reads the field phi on the axis line alone, where the kernel falls
# steeply with a particle's distance from the axis, so a few particles that stay close to
# it (3-D) or a column that moves out evenly (RZ rings) decide it. Here phi at height z is
# the mean over the disc r < R of the 3-D Wendland C2 field of support H:
#   phi(z) = sum_j V_j K(s_j, z - z_j),
#   K(s, dz) = 1/(pi R^2) int_0^Q W(sqrt(q^2 + dz^2), H) alpha(q) q dq,  Q = sqrt(H^2 - dz^2),
# alpha(q) the angle of the circle of radius q about the particle's foot that lies inside
# the disc (2 pi, 0, or 2 acos((q^2 + s^2 - R^2) / (2 q s))). The integral is split at
# q = |R - s| and R + s, each piece mapped by q = a + (b - a) sin^2(pi u / 2) and
# integrated with 8-point Gauss-Legendre on each half of [0, 1] in u, as in the code.
# K depends on s alone, so an RZ ring (whole ring mass) and a 3-D particle (a quarter
# model's with its mirror copies' mass) at the same distance from the axis weigh alike.
#
# Floor: scanning down from the highest wall particle + H in steps of H/25, the first z
# with phi(z, t) >= LEVEL * phi(min(z, -H), 0), then bisected 30 times (as the code);
# depth = -floor (surface at z = 0). Wall particles as in crater_axis_depth.py (not
# ejecta) of the target, material 1 as in the study's scenes.
#
# Usage: python3 disc_axis_depth.py H_M R_M LEVEL INITIAL.vtu SNAPSHOT.vtu...
#   (the code's reading: R = H, LEVEL 0.5)
import sys, math, os
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from crater_axis_depth import w3, wall_particles, highest_filled
TARGET = 1  # material id of the target in the study's scenes
GL8 = [(0.1834346424956498, 0.3626837833783620), (0.5255324099163290, 0.3137066458778873),
       (0.7966664774136267, 0.2223810344533745), (0.9602898564975363, 0.1012285362903763)]


def angle(s, q, R):
    if q + s <= R:
        return 2.0 * math.pi
    if q <= s - R or q >= s + R:
        return 0.0
    c = (q * q + s * s - R * R) / (2.0 * q * s)
    return 2.0 * math.acos(max(-1.0, min(1.0, c)))


def disc_kernel(s, dz, H, R):
    q2 = H * H - dz * dz
    if q2 <= 0.0 or s >= R + H:
        return 0.0
    if R == 0.0:
        return w3(math.sqrt(s * s + dz * dz) / H, H)
    qmax = math.sqrt(q2)
    edges = sorted([0.0, abs(R - s), R + s, qmax])
    total = 0.0
    for a, b in zip(edges, edges[1:]):
        b = min(b, qmax)
        if b <= a:
            continue
        for c in (0.25, 0.75):
            for x, w in GL8:
                for u in (c + 0.25 * x, c - 0.25 * x):
                    sn = math.sin(0.5 * math.pi * u)
                    q = a + (b - a) * sn * sn
                    jac = 0.5 * math.pi * (b - a) * math.sin(math.pi * u)
                    total += 0.25 * w * w3(math.sqrt(q * q + dz * dz) / H, H) \
                        * angle(s, q, R) * q * jac
    return total / (math.pi * R * R)


def parts(path, H, R):
    """(s, z, V) of the wall particles whose kernel reaches the disc r < R, by height."""
    return sorted(((math.sqrt(s2), zj, V) for s2, zj, V in wall_particles(path, TARGET, R + H)),
                  key=lambda p: p[1])


def field(ps, z, H, R):
    return sum(V * disc_kernel(s, z - zj, H, R) for s, zj, V in ps if abs(z - zj) < H)


def floor(ps, ini, H, R, level):
    def filled(z):
        ref = field(ini, min(z, -H), H, R)
        return ref > 0.0 and field(ps, z, H, R) >= level * ref
    if not ps:
        return float("nan")
    return highest_filled(filled, ps[-1][1] + H, ini[0][1] - H, H / 25.0, 30)


if __name__ == "__main__":
    H, R, level = float(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3])
    ini = parts(sys.argv[4], H, R)
    for f in sys.argv[5:]:
        print("%s %.4f" % (os.path.basename(f), -1e3 * floor(parts(f, H, R), ini, H, R, level)),
              flush=True)
