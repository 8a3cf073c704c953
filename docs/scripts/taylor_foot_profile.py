# Exploratory (docs/verification.md, Taylor bar): the shape of the Taylor rod's
# foot from `verify taylor --out DIR`'s profile.csv (final particle or ring centres r, z).
# Per 0.5 mm of r: the highest centre (the top of the foot) and the lowest (how far the
# underside sits above the anvil), in mm.
#
#   python3 taylor_foot_profile.py DIR/profile.csv [DIR2/profile.csv ...]
import csv, sys, collections

BIN = 0.5e-3
for path in sys.argv[1:]:
    bins = collections.defaultdict(list)
    for row in csv.DictReader(open(path)):
        bins[int(float(row['r']) / BIN)].append(float(row['z']))
    print(path)
    print("  r from (mm): " + " ".join("%6.1f" % (k * BIN * 1e3) for k in sorted(bins)))
    print("  top (mm):    " + " ".join("%6.2f" % (max(bins[k]) * 1e3) for k in sorted(bins)))
    print("  bottom (mm): " + " ".join("%6.2f" % (min(bins[k]) * 1e3) for k in sorted(bins)))
