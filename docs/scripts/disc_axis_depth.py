# Crater depth from the target's volume fraction averaged over a disc of radius R about
# the impact axis (docs/verification.md, RZ, "Session 27"). crater_axis_depth.py reads the
# field phi on the axis line alone, where the kernel falls steeply with a particle's
# distance from the axis, so a few particles that stay close to it (3-D) or a column that
# moves out evenly (RZ rings) decide it. Here phi is averaged over the disc r < R at each
# height: at NR radii (equal areas) and, for each, over the azimuth, which turns every
# particle into a ring through it. The azimuthal average of the 3-D Wendland C2 kernel
# is the same for an RZ ring and for a 3-D particle (or a quarter model's, with its
# mirror copies' mass) at the same distance s from the axis, so one formula serves both.
# Floor = highest z where phi_D(z, t) >= LEVEL * phi_D(min(z, -H), 0); depth = -floor
# (surface at z = 0); wall particles as in crater_axis_depth.py (not ejecta) of the
# target, material 1 as in the study's scenes.
#
# Usage: python3 disc_axis_depth.py H_M R_M LEVEL INITIAL.vtu SNAPSHOT.vtu...
import sys, math, os
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from crater_axis_depth import w3, wall_particles, highest_filled
NT, NR = 24, 4
TARGET = 1  # material id of the target in the study's scenes


def parts(path, H, R):
    """(s, z, V) of the wall particles whose kernel reaches the disc r < R."""
    return [(math.sqrt(s2), zj, V) for s2, zj, V in wall_particles(path, TARGET, R + H)]


def field(ps, z, H, R):
    # Disc quadrature: NR radii at the midpoints of equal-area annuli, equal weights.
    tot = 0.0
    for k in range(NR):
        rho_k = R * math.sqrt((k + 0.5) / NR)
        for s, zj, V in ps:
            dz = z - zj
            if abs(dz) >= H or abs(s - rho_k) >= H:
                continue
            acc = 0.0
            for t in range(NT):
                c = math.cos(math.pi * (t + 0.5) / NT)
                r = math.sqrt(max(s * s + rho_k * rho_k - 2 * s * rho_k * c + dz * dz, 0.0))
                acc += w3(r / H, H)
            tot += V * acc / NT
    return tot / NR


def floor(ps, ini, H, R, level):
    def filled(z):
        return field(ps, z, H, R) >= level * field(ini, min(z, -H), H, R)
    return highest_filled(filled, 0.0, -0.03, 2.5e-4, 12)


if __name__ == "__main__":
    H, R, level = float(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3])
    ini = parts(sys.argv[4], H, R)
    for f in sys.argv[5:]:
        print("%s %.3f" % (os.path.basename(f), -1e3 * floor(parts(f, H, R), ini, H, R, level)),
              flush=True)
