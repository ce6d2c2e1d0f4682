#!/usr/bin/env python3
"""Tables of docs/results/file003.md from pride stores (what `pride report` does not give for grids:
the best path's length and turns, and the convergence iteration).

    python3 scripts/file003_tables.py STORE.sqlite [STORE.sqlite ...] [--problems ID,ID] [--algorithms ID,ID]

Per (problem, algorithm), over its runs: the hswoa value (mean, std), the best path's length (min,
mean) and turns (mean; both measured here from the stored cells, with no code shared with pride),
the mean gap to the exact optimum stored with each run, the optimal-path rate (value within 1e-9 of
the optimum), the shortest-length rate (the best path's length within 1e-9 of the least length
of any run of the problem, which is the octile optimum of the .scen file when A* is among them), the
convergence iteration (the first iteration whose best equals the run's final
best; 0 is the initial population), mean evaluations and mean wall time in ms.
"""
import json
import math
import sqlite3
import statistics
import sys


def metrics(cells):
    length, turns, prev = 0.0, 0, None
    for (x0, y0), (x1, y1) in zip(cells, cells[1:]):
        d = (x1 - x0, y1 - y0)
        length += math.sqrt(2) if d[0] and d[1] else 1.0
        if prev is not None and d != prev:
            turns += 1
        prev = d
    return length, turns


def main():
    args = sys.argv[1:]
    only_p = only_a = None
    if "--problems" in args:
        i = args.index("--problems")
        only_p = args[i + 1].split(",")
        del args[i:i + 2]
    if "--algorithms" in args:
        i = args.index("--algorithms")
        only_a = args[i + 1].split(",")
        del args[i:i + 2]
    rows = {}
    order_p, order_a = [], []
    for store in args:
        db = sqlite3.connect(store)
        for p, a, best, opt, sol, hist, evals, ms in db.execute(
                "SELECT problem, algorithm, best, optimum, solution, history, evaluations, wall_ms FROM runs "
                "ORDER BY rowid"):
            if (only_p and p not in only_p) or (only_a and a not in only_a):
                continue
            if p not in order_p:
                order_p.append(p)
            if a not in order_a:
                order_a.append(a)
            rows.setdefault((p, a), []).append((best, opt, json.loads(sol), json.loads(hist), evals, ms))
    if only_a:
        order_a = [a for a in only_a if a in order_a]
    for p in order_p:
        opt = next(r[1] for (pp, _), rs in rows.items() if pp == p for r in rs)
        shortest = min(metrics(r[2])[0] for (pp, _), rs in rows.items() if pp == p for r in rs)
        print(f"\n**{p}** (exact hswoa optimum {opt:.4f}; least length {shortest:.4f})\n")
        print("| algorithm | runs | mean value | std | min length | mean length | mean turns | mean gap | optimal "
              "| shortest length | conv. iter. | evaluations | ms |")
        print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
        for a in order_a:
            rs = rows.get((p, a))
            if not rs:
                continue
            values = [r[0] for r in rs]
            lt = [metrics(r[2]) for r in rs]
            gaps = [(r[0] - r[1]) / r[1] for r in rs]
            optimal = sum(abs(r[0] - r[1]) <= 1e-9 * max(1.0, abs(r[1])) for r in rs)
            short = sum(abs(l - shortest) <= 1e-9 for l, _ in lt)
            conv = []
            for r in rs:
                h = r[3]
                if h:
                    conv.append(next(k for k, v in enumerate(h) if v <= h[-1]))
            std = statistics.stdev(values) if len(values) > 1 else 0.0
            print(f"| {a} | {len(rs)} | {statistics.mean(values):.3f} | {std:.3f} | {min(l for l, _ in lt):.3f} | "
                  f"{statistics.mean(l for l, _ in lt):.3f} | {statistics.mean(t for _, t in lt):.2f} | "
                  f"{100 * statistics.mean(gaps):.2f} % | {100 * optimal / len(rs):.1f} % | "
                  f"{100 * short / len(rs):.1f} % | "
                  f"{f'{statistics.mean(conv):.1f}' if conv else '-'} | {statistics.mean(r[4] for r in rs):.0f} | "
                  f"{statistics.mean(r[5] for r in rs):.2f} |")


if __name__ == "__main__":
    main()
