#!/usr/bin/env python3
"""Makes Cai and Du's (2021) three environments (tables 4-6): cai2021-env1-30x30.map, cai2021-env2-30x30.map
and cai2021-env3-60x60.map, with their .map.scen files (optimal length by check_maps.py's Dijkstra).

    python3 make_cai2021_maps.py        # rewrites the six files next to this script

The paper's maps are pictures we do not have; its text says environment 2 has the size of
environment 1 with more obstacles and narrower passages, and environment 3 is larger and denser.
Our reading (sizes and coverages are ours):
  env1: 30 x 30, rectangles 1 to 3 cells a side until 15 % of the cells are blocked;
  env2: env1's obstacles plus walls: every 6th column from column 5 is a wall with two gaps of 1 or
        2 cells at random rows, so every path threads narrow passages;
  env3: 60 x 60, rectangles 1 to 5 cells a side until 30 % of the cells are blocked.
Start at the bottom-left cell, goal at the top-right one (paper (1, 1) to (W, H)), their 3 x 3
neighbourhoods kept free, as on cai2021-50x50.map. Each map comes from Python's random.Random with
the seed below; a draw whose goal cannot be reached is thrown away and drawing goes on (the printed
attempt counts say how many), so the files are the same on every run.
"""
import os
import random

from check_maps import fewest_cells, octile_length

HERE = os.path.dirname(os.path.abspath(__file__))


def rectangles(rng, w, h, blocked, coverage, largest):
    target = round(coverage * w * h)
    while sum(map(sum, blocked)) < target:
        bw, bh = rng.randint(1, largest), rng.randint(1, largest)
        x, y = rng.randrange(w - bw + 1), rng.randrange(h - bh + 1)
        for yy in range(y, y + bh):
            for xx in range(x, x + bw):
                if sum(map(sum, blocked)) < target:
                    blocked[yy][xx] = 1


def walls(rng, w, h, blocked):
    for x in range(5, w - 3, 6):
        for y in range(h):
            blocked[y][x] = 1
        for _ in range(2):
            y = rng.randrange(1, h - 2)
            for yy in range(y, y + rng.randint(1, 2)):
                blocked[yy][x] = 0


def clear_ends(w, h, blocked):
    for cx, cy in ((0, h - 1), (w - 1, 0)):
        for y in range(max(0, cy - 1), min(h, cy + 2)):
            for x in range(max(0, cx - 1), min(w, cx + 2)):
                blocked[y][x] = 0


def draw(seed, w, h, make):
    rng = random.Random(seed)
    attempt = 0
    while True:
        attempt += 1
        blocked = [[0] * w for _ in range(h)]
        make(rng, blocked)
        clear_ends(w, h, blocked)
        free = [[not b for b in row] for row in blocked]
        length = octile_length(w, h, free, (0, h - 1), (w - 1, 0))
        if length is not None:
            return blocked, free, length, attempt


def write(name, w, h, blocked, free, length, attempt):
    with open(os.path.join(HERE, name), "w", encoding="ascii") as f:
        f.write(f"type octile\nheight {h}\nwidth {w}\nmap\n")
        for row in blocked:
            f.write("".join("@" if b else "." for b in row) + "\n")
    with open(os.path.join(HERE, name + ".scen"), "w", encoding="ascii") as f:
        f.write(f"version 1\n{int(length // 4)}\t{name}\t{w}\t{h}\t0\t{h - 1}\t{w - 1}\t0\t{length:.8f}\n")
    count = sum(map(sum, blocked))
    cells = fewest_cells(w, h, free, (0, h - 1), (w - 1, 0))
    print(f"{name}: {w}x{h}, {count} blocked ({100.0 * count / (w * h):.1f} %), attempt {attempt}, "
          f"optimal length {length:.8f}, fewest cells {cells}")


def main():
    env1 = lambda rng, b: rectangles(rng, 30, 30, b, 0.15, 3)
    blocked1, free1, length1, attempt1 = draw(3001, 30, 30, env1)
    write("cai2021-env1-30x30.map", 30, 30, blocked1, free1, length1, attempt1)

    def env2(rng, b):
        for y in range(30):
            b[y][:] = blocked1[y]
        walls(rng, 30, 30, b)

    write("cai2021-env2-30x30.map", 30, 30, *draw(3002, 30, 30, env2))
    env3 = lambda rng, b: rectangles(rng, 60, 60, b, 0.30, 5)
    write("cai2021-env3-60x60.map", 60, 60, *draw(3003, 60, 60, env3))


if __name__ == "__main__":
    main()
