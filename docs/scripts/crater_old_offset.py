# The top-layer offset an earlier crater reading subtracted, from a run's t = 0
# snapshot: the median over the radial bins of the depth of each bin's highest target
# centre, and what the untouched axis bin read against it (docs/validation.md,
# "The crater reading"). RZ snapshots: Points are (r, 0, z).
#
#   python3 docs/scripts/crater_old_offset.py DIR/snapshots/00000.vtu BIN [TARGET]
#
# BIN: the crater bin (m), A_res of the run; TARGET: the target's material id (1).
import sys
from vtu_read import read

path, b = sys.argv[1], float(sys.argv[2])
target = int(sys.argv[3]) if len(sys.argv) > 3 else 1
d = read(path)
top = {}
for p, m in zip(d['Points'], d['material']):
    if m != target:
        continue
    k = int(abs(p[0]) / b)
    top[k] = max(top.get(k, p[2]), p[2])
depths = sorted(-z for z in top.values())
offset = depths[len(depths) // 2]
axis = top[min(top)]
print('bins %d (%d with a target centre); median depth (the old offset) %.3f mm; '
      'axis bin top %.3f mm down, read %.3f mm' % (
          max(top) + 1, len(top), offset * 1e3, -axis * 1e3, (-offset - axis) * 1e3))
for lo in range(0, int((max(top) + 1) * b * 1e3) + 5, 5):
    v = sorted(-z for k, z in top.items() if lo <= k * b * 1e3 < lo + 5)
    if v:
        print('  r %2d-%2d mm: median %.2f mm, deepest %.2f mm' % (lo, lo + 5, v[len(v) // 2] * 1e3, v[-1] * 1e3))
