# Position, velocity, density, pressure, smoothing length and deviatoric stress of chosen
# particles (by id) through the snapshots of one RZ run (docs/verification.md, RZ,
# "Axisymmetric (RZ) geometry", the axis jet). RZ snapshots store (r, 0, z); the columns are r, z, v_r,
# v_z (m/s), rho (kg/m^3), P (GPa; the undamaged EOS pressure), h (mm) and S_rr, S_zz,
# S_rz (GPa).
#
# Usage: python3 particle_track.py ID[,ID...] RUN_DIR FIRST LAST [STRIDE]
#   (FIRST, LAST, STRIDE index the sorted snapshot list, as a Python slice)
import sys, os
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtu_read import read, snapshots


def main():
    ids = [int(x) for x in sys.argv[1].split(",")]
    stride = int(sys.argv[5]) if len(sys.argv) > 5 else 1
    files = snapshots(sys.argv[2])[
        int(sys.argv[3]):int(sys.argv[4]):stride]
    for f in files:
        d = read(f)
        idx = {i: k for k, i in enumerate(d["id"])}
        out = []
        for i in ids:
            k = idx[i]
            p, v, s = d["Points"][k], d["velocity"][k], d["deviatoric_stress"][k]
            out.append("id%d r%.3f z%.3f vr%5.0f vz%6.0f rho%5.0f P%5.2f h%.3f "
                       "Srr%5.2f Szz%5.2f Srz%5.2f"
                       % (i, p[0] * 1e3, p[2] * 1e3, v[0], v[2], d["density"][k],
                          d["pressure"][k] / 1e9, d["smoothing_length"][k] * 1e3,
                          s[0] / 1e9, s[8] / 1e9, s[2] / 1e9))
        print(os.path.basename(f)[:5], " | ".join(out))


if __name__ == "__main__":
    main()
