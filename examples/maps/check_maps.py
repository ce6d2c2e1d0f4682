#!/usr/bin/env python3
"""Independent check of the bundled maps (no code shared with the C++ library).

For every NAME.map here with a NAME.map.scen next to it: reads the Moving AI map, checks that the
scenario's size matches and that start and goal are free and connected, and recomputes with its own
Dijkstra the optimal octile length (orthogonal step 1, diagonal sqrt(2), no corner cutting: a
diagonal step needs both orthogonally adjacent cells free) and the fewest cells of a path (start and
goal included). Exit status 1 when a recorded optimal length differs by more than 1e-6.

    python3 check_maps.py [--write] [--movingai DIR]

--write rewrites each .map.scen with the recomputed length; --movingai DIR also checks this
Dijkstra against the optimal lengths recorded in the Moving AI scenario files of DIR.
"""
import heapq
import math
import os
import sys
from collections import deque

FREE = set(".GS")
BLOCKED = set("@OTW")
MOVES = [(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1)]


def read_map(path):
    with open(path, encoding="ascii") as f:
        lines = f.read().splitlines()
    assert lines[0].split() == ["type", "octile"], path
    h = int(lines[1].split()[1])
    w = int(lines[2].split()[1])
    assert lines[3].strip() == "map", path
    rows = [r.rstrip() for r in lines[4:4 + h]]
    assert len(rows) == h and all(len(r) == w for r in rows), path
    assert all(c in FREE | BLOCKED for r in rows for c in r), path
    return w, h, [[c in FREE for c in r] for r in rows]  # grid[y][x] is True when free


def steps(w, h, free, x, y):
    for dx, dy in MOVES:
        nx, ny = x + dx, y + dy
        if not (0 <= nx < w and 0 <= ny < h and free[ny][nx]):
            continue
        if dx and dy and not (free[y][nx] and free[ny][x]):
            continue  # no corner cutting
        yield nx, ny, (math.sqrt(2) if dx and dy else 1.0)


def octile_length(w, h, free, start, goal):
    dist = {start: 0.0}
    heap = [(0.0, start)]
    while heap:
        d, (x, y) = heapq.heappop(heap)
        if (x, y) == goal:
            return d
        if d > dist[(x, y)]:
            continue
        for nx, ny, c in steps(w, h, free, x, y):
            nd = d + c
            if nd < dist.get((nx, ny), math.inf) - 1e-12:
                dist[(nx, ny)] = nd
                heapq.heappush(heap, (nd, (nx, ny)))
    return None


def fewest_cells(w, h, free, start, goal):
    seen = {start: 1}
    queue = deque([start])
    while queue:
        x, y = queue.popleft()
        if (x, y) == goal:
            return seen[(x, y)]
        for nx, ny, _ in steps(w, h, free, x, y):
            if (nx, ny) not in seen:
                seen[(nx, ny)] = seen[(x, y)] + 1
                queue.append((nx, ny))
    return None


def read_scen(path):
    with open(path, encoding="ascii") as f:
        lines = [l for l in f.read().splitlines() if l.strip()]
    assert lines[0].split() in (["version", "1"], ["version", "1.0"]), path
    out = []
    for l in lines[1:]:
        b, m, w, h, sx, sy, gx, gy, opt = l.split()
        out.append((m, int(w), int(h), (int(sx), int(sy)), (int(gx), int(gy)), float(opt)))
    return out


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    write = "--write" in sys.argv
    bad = 0
    for name in sorted(os.listdir(here)):
        if not name.endswith(".map"):
            continue
        w, h, free = read_map(os.path.join(here, name))
        scen_path = os.path.join(here, name + ".scen")
        blocked = sum(not c for r in free for c in r)
        for m, sw, sh, start, goal, opt in read_scen(scen_path):
            assert m == name and (sw, sh) == (w, h), scen_path
            for c in (start, goal):
                assert 0 <= c[0] < w and 0 <= c[1] < h and free[c[1]][c[0]], (scen_path, c)
            length = octile_length(w, h, free, start, goal)
            cells = fewest_cells(w, h, free, start, goal)
            assert length is not None, (scen_path, "start and goal are not connected")
            ok = abs(length - opt) <= 1e-6
            bad += not ok
            print(f"{name}: {w}x{h}, {blocked} blocked ({100.0 * blocked / (w * h):.1f}%), start {start}, goal {goal}, "
                  f"optimal length {length:.8f}{'' if ok else f' (recorded {opt:.8f}: WRONG)'}, fewest cells {cells}")
            if write:
                with open(scen_path, "w", encoding="ascii") as f:
                    f.write(f"version 1\n{int(length // 4)}\t{name}\t{w}\t{h}\t{start[0]}\t{start[1]}\t"
                            f"{goal[0]}\t{goal[1]}\t{length:.8f}\n")
    if "--movingai" in sys.argv:
        d = sys.argv[sys.argv.index("--movingai") + 1]
        worst = 0.0
        count = 0
        for name in sorted(os.listdir(d)):
            if not name.endswith(".scen"):
                continue
            entries = read_scen(os.path.join(d, name))
            mapname = entries[0][0]
            w, h, free = read_map(os.path.join(d, mapname))
            for m, sw, sh, start, goal, opt in entries[::max(1, len(entries) // 20)]:
                worst = max(worst, abs(octile_length(w, h, free, start, goal) - opt))
                count += 1
        print(f"Moving AI: {count} scenario lines checked, largest difference {worst:.2e}")
        bad += worst > 1e-6
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
