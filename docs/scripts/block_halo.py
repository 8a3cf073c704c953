#!/usr/bin/env python3
"""Pairs across the pair passes' blocks on a Morton-ordered cubic lattice.

For a lattice of L^3 particles in Morton order, each paired with the particles within
`radius` spacings, and blocks of `rows` consecutive rows (solver/pair_blocks.rs), prints
the share of the listed (directed) pairs whose partner lies in another block, and how
many distinct particles of later blocks a block's rows list, per particle: the shares a
block would owe other blocks if each pair were evaluated once (docs/performance.md,
"Three levers of pass 2 measured on a quiet machine").

    python3 docs/scripts/block_halo.py [L] [radius] [rows]
"""
import sys


def spread(x):
    out = 0
    for b in range(21):
        out |= ((x >> b) & 1) << (3 * b)
    return out


def main():
    side = int(sys.argv[1]) if len(sys.argv) > 1 else 48
    radius = float(sys.argv[2]) if len(sys.argv) > 2 else 2.5
    rows = int(sys.argv[3]) if len(sys.argv) > 3 else 4096
    cells = [(x, y, z) for x in range(side) for y in range(side) for z in range(side)]
    code = {c: spread(c[0]) | (spread(c[1]) << 1) | (spread(c[2]) << 2) for c in cells}
    rank = {c: k for k, c in enumerate(sorted(cells, key=code.get))}
    reach = int(radius) + 1
    offsets = [
        (a, b, c)
        for a in range(-reach, reach + 1)
        for b in range(-reach, reach + 1)
        for c in range(-reach, reach + 1)
        if 0 < a * a + b * b + c * c < radius * radius
    ]
    listed = across = 0
    owed = set()
    for (x, y, z), i in rank.items():
        bi = i // rows
        for a, b, c in offsets:
            j = rank.get((x + a, y + b, z + c))
            if j is None:
                continue
            listed += 1
            bj = j // rows
            if bj != bi:
                across += 1
                if bj > bi:
                    owed.add((bi, j))
    n = len(cells)
    print(f"{n} particles, {len(offsets)} neighbours inside, blocks of {rows} rows")
    print(f"pairs across blocks: {across / listed:.3f} of the listed")
    print(f"particles of later blocks listed by a block: {len(owed) / n:.3f} per particle")


if __name__ == "__main__":
    main()
