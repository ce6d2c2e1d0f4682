#!/usr/bin/env python3
"""File 002's tables 5 and 6 from a `pride bench examples/campaigns/file002.toml` store, with what
the paper lacks: the gap to the exact iqga optimum and the distance to the exact (length, turns)
Pareto front (docs/results/file002.md). Usage:
    scripts/file002_tables.py STORE.sqlite PRIDE_BINARY
Per algorithm and map, the means over the runs of: length, turn angle (degrees), turns (eq. 11),
convergence generation (the first generation whose best equals the run's final best; history[0]
is the initial population, generation 0), wall ms, gap = (best - opt) / |opt| to the iqga optimum,
the share of runs on the (length, turns) front, and dL = length - (the shortest front length with
at most the run's turns): how much shorter a path with no more turns exists (0 on the front)."""
import json, math, sqlite3, subprocess, sys

SQRT2 = math.sqrt(2.0)
DIRS = {(1, 0): 0, (1, 1): 1, (0, 1): 2, (-1, 1): 3, (-1, 0): 4, (-1, -1): 5, (0, -1): 6, (1, -1): 7}


def metrics(path):
    length, turns, angle, prev = 0.0, 0, 0, None
    for a, b in zip(path, path[1:]):
        d = DIRS[(b[0] - a[0], b[1] - a[1])]
        length += SQRT2 if d & 1 else 1.0
        if prev is not None and d != prev:
            k = abs(d - prev)
            k = min(k, 8 - k)
            turns += 1
            angle += 45 * k
        prev = d
    return length, turns, angle


def front(pride, problem):
    m, s, g = problem
    out = subprocess.run([pride, "pareto", "--map", m, "--start", s, "--goal", g, "--objectives", "length,turns",
                          "--json"], capture_output=True, text=True, check=True).stdout
    return [(p["length"], p["turns"]) for p in json.loads(out)["front"]]


def main():
    store, pride = sys.argv[1], sys.argv[2]
    db = sqlite3.connect(store)
    problems = {pid: (m, s, g)
                for pid, m, s, g in db.execute("select id, map, start, goal from problems")}
    print("| map | algorithm | runs | length | turn angle (deg) | turns | convergence gen. | ms | gap to iqga optimum | on (length, turns) front | dL to front |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for pid in sorted(problems):
        f = front(pride, problems[pid])
        algos = [a for (a,) in db.execute("select distinct algorithm from runs where problem = ? order by rowid", (pid,))]
        for algo in algos:
            rows = db.execute("select solution, history, wall_ms, best, optimum from runs where problem = ? and "
                              "algorithm = ? order by seed", (pid, algo)).fetchall()
            L = T = A = C = W = G = on = dl = 0.0
            for sol, hist, ms, best, opt in rows:
                length, turns, angle = metrics(json.loads(sol))
                h = json.loads(hist)
                conv = next(i for i, v in enumerate(h) if v == h[-1])
                L += length; T += turns; A += angle; C += conv; W += ms
                G += (best - opt) / abs(opt)
                better = [fl for fl, ft in f if ft <= turns]
                d = max(0.0, length - min(better)) if better else 0.0
                dl += d
                on += 1 if any(abs(fl - length) < 1e-9 and ft == turns for fl, ft in f) else 0
            n = len(rows)
            print(f"| {pid} | {algo} | {n} | {L / n:.3f} | {A / n:.2f} | {T / n:.2f} | {C / n:.2f} | {W / n:.1f} | "
                  f"{100 * G / n:.2f} % | {100 * on / n:.0f} % | {dl / n:.3f} |")


if __name__ == "__main__":
    main()
