# Exploratory (docs/validation.md, "β in time"): which ejecta of a snapshot are
# still attached to the target, by the chain rule of docs/diagnostics.md §3.1 (two
# particles interact when |x_i - x_j| < max(h_i, h_j); an ejectum is attached when a chain
# of interacting target particles above the surface reaches one at or below it). Prints the
# ejecta split into detached and attached, and the attached ones by how fast they move,
# how broken they are and where they sit.
#
#   python3 ejecta_attached.py TARGET_MATERIAL_ID SNAPSHOT.vtu [P_IMP]
#
# P_IMP (kg m/s, the projectile's momentum) turns momenta into β terms.
# RZ snapshots hold a ring at (r, 0, z), so chains run in the (r, z) plane, as in the code.
import sys, math, os, collections
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtu_read import read

def main():
    if len(sys.argv) not in (3, 4):
        sys.exit("usage: ejecta_attached.py TARGET_ID SNAPSHOT.vtu [P_IMP]")
    target = int(sys.argv[1])
    d = read(sys.argv[2])
    p_imp = float(sys.argv[3]) if len(sys.argv) == 4 else None
    idx = [i for i, mat in enumerate(d['material']) if mat == target]
    pos, h = d['Points'], d['smoothing_length']
    above = [i for i in idx if pos[i][2] > 0.0]
    below = [i for i in idx if pos[i][2] <= 0.0]
    hmax = max(h[i] for i in above) if above else 0.0
    if hmax == 0.0:
        print("no target material above the surface")
        return
    # hash grid of the above-surface particles, cells as wide as the largest support
    cell = lambda p: (math.floor(p[0] / hmax), math.floor(p[1] / hmax), math.floor(p[2] / hmax))
    grid = collections.defaultdict(list)
    for i in above:
        grid[cell(pos[i])].append(i)

    def near(i):
        cx, cy, cz = cell(pos[i])
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    for j in grid.get((cx + dx, cy + dy, cz + dz), ()):
                        if math.dist(pos[i], pos[j]) < max(h[i], h[j]):
                            yield j

    attached = set()
    queue = collections.deque()
    for i in below:
        if pos[i][2] > -2.0 * hmax:
            for j in near(i):
                if j not in attached:
                    attached.add(j)
                    queue.append(j)
    while queue:
        for j in near(queue.popleft()):
            if j not in attached:
                attached.add(j)
                queue.append(j)

    vel, mass, dmg, rho = d['velocity'], d['mass'], d['damage'], d['density']
    ejecta = [i for i in above if vel[i][2] > 0.0]
    groups = {'detached': [i for i in ejecta if i not in attached],
              'attached': [i for i in ejecta if i in attached]}
    for name, g in groups.items():
        m = sum(mass[i] for i in g)
        pz = sum(mass[i] * vel[i][2] for i in g)
        beta = " (β term %.4f)" % (pz / p_imp) if p_imp else ""
        print("%s: %d particles, %.4g g, %.4g kg m/s%s" % (name, len(g), 1e3 * m, pz, beta))
    att = groups['attached']
    if not att:
        return
    print("attached ejecta by v_z:")
    bands = [(0, 1), (1, 10), (10, 100), (100, 1e9)]
    for lo, hi in bands:
        g = [i for i in att if lo <= vel[i][2] < hi]
        if not g:
            continue
        m = sum(mass[i] for i in g)
        pz = sum(mass[i] * vel[i][2] for i in g)
        broken = sum(mass[i] for i in g if dmg[i] >= 0.99) / m
        r = [math.hypot(pos[i][0], pos[i][1]) for i in g]
        z = [pos[i][2] for i in g]
        rho_mean = sum(mass[i] * rho[i] for i in g) / m
        print("  v_z %g-%g m/s: %d, %.4g g, %.4g kg m/s, D >= 0.99 in %.0f %% of the mass, "
              "mean density %.0f kg/m3, r %.1f-%.1f mm, z %.2f-%.2f mm"
              % (lo, hi, len(g), 1e3 * m, pz, 100 * broken, rho_mean,
                 1e3 * min(r), 1e3 * max(r), 1e3 * min(z), 1e3 * max(z)))

main()
