# Exploratory (docs/validation.md, "Why the spall zone shrinks with resolution"):
# does the rock around the crater yield before its flaws can activate?
#
#   python3 spall_yield.py RUN_DIR N3D [R_LO R_HI Z_LO]
#   python3 spall_yield.py --state SNAPSHOT.vtu [R_LO R_HI Z_LO Z_HI]
#
# The second form reads one snapshot: how many target rings in the band (default
# -6 mm < z < 2 mm) are fractured (D > 0.9) and their mean plastic strain.
#
# Reads every snapshot of an RZ run (fine snapshot cadence wanted, e.g. 0.5 us) and follows
# the target rings that start in the band R_LO < r < R_HI, z > Z_LO (defaults 20 mm, 30 mm,
# -6 mm: the experiment's spall annulus, 42-55 mm across). Per snapshot it prints the
# band's pressure and largest principal stress sigma_1 = max eig((1 - D) S - P I) (tension
# positive, hoop entry included), the von Mises stress sqrt(3 J2) against the Lundborg
# yield strength of the study (Y0 26.5 MPa, mu 0.6, Y_M 300 MPa) and the plastic strain.
# At the end it compares, ring by ring, the largest sigma_1 each intact ring reached with
# the Benz-Asphaug flaws it can hold: the flaws (k = 2.7e41 m^-3, m = 10) are dealt over
# the N3D particles of the 3-D body (`sph-impact check` prints N3D), so a ring's weakest
# flaw is below strain eps with probability 1 - exp(-k (V/N3D) eps^m), V the target's
# volume; eps = sigma_1/E with E = 53.1 GPa (paper section 3.3). The expected number of rings
# that could have activated a flaw is printed beside the number that fractured (D > 0.9).
import sys, os, math
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtu_read import read, snapshots

K_WEIBULL, M_WEIBULL, E_YOUNG = 2.7e41, 10.0, 53.1e9
V_TARGET = math.pi * 0.06165 ** 2 * 0.1233
Y0, MU, YM = 26.5e6, 0.6, 300e6
TARGET = 1


def eig_max(a):
    """Largest eigenvalue of a symmetric 3x3 matrix (trigonometric solution)."""
    p1 = a[0][1] ** 2 + a[0][2] ** 2 + a[1][2] ** 2
    q = (a[0][0] + a[1][1] + a[2][2]) / 3
    if p1 == 0:
        return max(a[0][0], a[1][1], a[2][2])
    p = math.sqrt(((a[0][0] - q) ** 2 + (a[1][1] - q) ** 2 + (a[2][2] - q) ** 2 + 2 * p1) / 6)
    b = [[(a[i][j] - (q if i == j else 0.0)) / p for j in range(3)] for i in range(3)]
    det = (b[0][0] * (b[1][1] * b[2][2] - b[1][2] * b[2][1])
           - b[0][1] * (b[1][0] * b[2][2] - b[1][2] * b[2][0])
           + b[0][2] * (b[1][0] * b[2][1] - b[1][1] * b[2][0]))
    return q + 2 * p * math.cos(math.acos(max(-1.0, min(1.0, det / 2))) / 3)


def lundborg(p):
    """The study's intact yield strength; linear to zero in tension (the scenes' default)."""
    if p >= 0:
        return Y0 + MU * p / (1 + MU * p / (YM - Y0))
    return max(0.0, Y0 + MU * p)


def ring_state(d, i):
    s = d['deviatoric_stress'][i]
    p, dmg = d['pressure'][i], d['damage'][i]
    sig = [[(1 - dmg) * s[3 * a + b] - (p if a == b else 0.0) for b in range(3)] for a in range(3)]
    vm = math.sqrt(1.5 * sum(x * x for x in s))
    return p, eig_max(sig), vm, d['plastic_strain'][i], dmg


def median(x):
    x = sorted(x)
    return x[len(x) // 2]


def state(path, r_lo=0.020, r_hi=0.030, z_lo=-0.006, z_hi=0.002):
    d = read(path)
    sel = [i for i, p in enumerate(d['Points'])
           if d['material'][i] == TARGET and r_lo < p[0] < r_hi and z_lo < p[2] < z_hi]
    broken = sum(1 for i in sel if d['damage'][i] > 0.9)
    print('%s: %d rings, fractured (D > 0.9) %d (%.1f %%), mean plastic strain %.3f' % (
        path, len(sel), broken, 100.0 * broken / len(sel), sum(d['plastic_strain'][i] for i in sel) / len(sel)))


def main():
    if sys.argv[1] == '--state':
        state(sys.argv[2], *(float(x) for x in sys.argv[3:7]))
        return
    run, n3d = sys.argv[1], float(sys.argv[2])
    r_lo, r_hi, z_lo = (float(x) for x in (sys.argv[3:6] if len(sys.argv) > 5 else (0.020, 0.030, -0.006)))
    snaps = snapshots(run)
    d0 = read(snaps[0])
    band = [d0['id'][i] for i, p in enumerate(d0['Points'])
            if d0['material'][i] == TARGET and r_lo < p[0] < r_hi and p[2] > z_lo]
    print('%d rings in %.0f < r < %.0f mm, z > %.1f mm' % (len(band), r_lo * 1e3, r_hi * 1e3, z_lo * 1e3))
    print('snapshot  P med/max MPa  sigma_1 med/max MPa  at yield  mean eps_p  fractured')
    peak = {k: -math.inf for k in band}
    last = {}
    for path in snaps:
        d = read(path)
        where = {k: i for i, k in enumerate(d['id'])}
        rows = {k: ring_state(d, where[k]) for k in band if k in where}
        for k, (p, s1, vm, ep, dmg) in rows.items():
            if dmg < 0.1:
                peak[k] = max(peak[k], s1)
        last = rows
        ps = [x[0] for x in rows.values()]
        s1s = [x[1] for x in rows.values() if x[4] < 0.1] or [float('nan')]
        at_yield = sum(1 for x in rows.values() if x[4] < 0.1 and x[2] > 0.97 * lundborg(x[0]) > 0)
        print('%s  %6.1f %6.1f   %7.1f %7.1f   %4d   %.4f   %d' % (
            os.path.basename(path), median(ps) / 1e6, max(ps) / 1e6, median(s1s) / 1e6, max(s1s) / 1e6,
            at_yield, sum(x[3] for x in rows.values()) / len(rows), sum(1 for x in rows.values() if x[4] > 0.9)))
    vol = V_TARGET / n3d
    sigma_med = E_YOUNG * (K_WEIBULL * vol / math.log(2)) ** (-1 / M_WEIBULL)
    expected = sum(1 - math.exp(-K_WEIBULL * vol * (max(s, 0.0) / E_YOUNG) ** M_WEIBULL)
                   for s in peak.values() if s > -math.inf)
    peaks = [s for s in peak.values() if s > -math.inf]
    print('median weakest-flaw stress of a ring: %.1f MPa (V/N3D = (%.2f mm)^3)' % (sigma_med / 1e6, vol ** (1 / 3) * 1e3))
    print('largest sigma_1 reached by intact rings: median %.1f, max %.1f MPa' % (median(peaks) / 1e6, max(peaks) / 1e6))
    print('rings that could activate a flaw at their largest sigma_1: %.1f expected; fractured (D > 0.9) at the end: %d of %d' % (
        expected, sum(1 for x in last.values() if x[4] > 0.9), len(last)))


if __name__ == '__main__':
    main()
