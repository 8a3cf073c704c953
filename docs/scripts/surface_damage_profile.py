# Exploratory (docs/validation.md): the target's surface layer by distance from
# the axis, to compare the spall zones of two grids.
#
#   python3 surface_damage_profile.py profile SNAPSHOT.vtu [TARGET_ID RHO0 BIN_M]
#     per bin of r: the top of the target rock that has not left (not ejecta: not above
#     z = 0 while moving up; not dilated below RHO0/2, the scenes' rubble cut), the top of
#     its intact part (D <= 0.9, the scenes' spall_damage), how many of the particles in
#     the top 5 mm are fractured, their mean D, and v_z of the top particle.
#   python3 surface_damage_profile.py history RUN_DIR [TARGET_ID]
#     mean D of the target particles with -3 mm < z < 10 mm in bands of r, and the
#     highest z in each band, at 20, 40, 60, 80, 100, 200 and 400 us (snapshots every
#     20 us: 00001 ... 00020).
# Defaults: target material id 1, rho0 = 2876 kg/m^3 (basalt-study), bins of 2 mm.
import sys, math, os
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtu_read import read


def profile(path, target, rho0, bw):
    d = read(path)
    bins = {}
    for p, v, dmg, mat, rho in zip(d['Points'], d['velocity'], d['damage'], d['material'], d['density']):
        if mat != target:
            continue
        r, z = math.hypot(p[0], p[1]), p[2]
        if (z > 0 and v[2] > 0) or rho < 0.5 * rho0:
            continue
        bins.setdefault(int(r / bw), []).append((z, dmg, v[2]))
    print('r_mm   top_mm  intact_top_mm  fractured/top5mm  meanD_top5mm  vz_top_m_s')
    for k in sorted(bins)[:40]:
        col = sorted(bins[k], reverse=True)
        top = col[0][0]
        intact = [c for c in col if c[1] <= 0.9]
        it = intact[0][0] if intact else float('nan')
        top5 = [c for c in col if c[0] > top - 5e-3]
        mean_d = sum(c[1] for c in top5) / len(top5)
        broken = sum(1 for c in top5 if c[1] > 0.9)
        print('%5.0f %8.2f %12.2f %10d/%-5d %12.3f %12.2f' % (
            k * bw * 1e3, top * 1e3, it * 1e3, broken, len(top5), mean_d, col[0][2]))


def history(run, target):
    bands = [(10, 20), (20, 30), (30, 40), (40, 50), (50, 60)]
    print('t_us ' + ' '.join('D%d-%d' % b for b in bands) + '  | zmax_mm per band')
    for s in [1, 2, 3, 4, 5, 10, 20]:
        d = read(os.path.join(run, 'snapshots', '%05d.vtu' % s))
        means, tops = [], []
        for a, b in bands:
            sel = [(p[2], dmg) for p, dmg, mat in zip(d['Points'], d['damage'], d['material'])
                   if mat == target and a * 1e-3 <= math.hypot(p[0], p[1]) < b * 1e-3
                   and -3e-3 < p[2] < 10e-3]
            means.append(sum(x[1] for x in sel) / max(1, len(sel)))
            tops.append(max([x[0] for x in sel] or [float('nan')]) * 1e3)
        print('%4d ' % (s * 20) + ' '.join('%7.3f' % x for x in means)
              + '  | ' + ' '.join('%6.2f' % z for z in tops))


if __name__ == '__main__':
    mode, path = sys.argv[1], sys.argv[2]
    target = int(sys.argv[3]) if len(sys.argv) > 3 else 1
    if mode == 'profile':
        rho0 = float(sys.argv[4]) if len(sys.argv) > 4 else 2876.0
        bw = float(sys.argv[5]) if len(sys.argv) > 5 else 2e-3
        profile(path, target, rho0, bw)
    else:
        history(path, target)
