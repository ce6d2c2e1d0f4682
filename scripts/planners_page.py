#!/usr/bin/env python3
"""Regenerates docs/results/planners.md from its runs, or checks it.

    PYTHONPATH=build/python /usr/bin/python3 scripts/planners_page.py run
        runs every (instance, planner, seed) of the page through pride's Python module (the runs
        `pride path --gaps` makes) and writes each path's metrics to docs/results/data/planners.csv,
        then the page. Needs a build with OMPL (scripts/deps.sh installs it).
    /usr/bin/python3 scripts/planners_page.py render
        rewrites the page's generated blocks from docs/results/data/planners.csv alone.
    /usr/bin/python3 scripts/planners_page.py check
        exits 1 when a generated block differs from what the data give
        (python/tests/test_planners_page.py does the same under ctest).

The runs, all on the length objective with the gaps to the exact grid and any-angle optima
(docs/grid.md, "Polylines and their metrics"): the whole-map planners A*, JPS, Theta*, Lazy Theta*
and the exact any-angle path once each (no seed, no budget); OMPL's RRT*, Informed RRT*, BIT* and
PRM* (the grid's plane, validity checks as evaluations) and the metaheuristics ILSO (Wan and Gao 2022,
line encoding, rough-set rule walks), IQGA (Zhang et al. 2025, chains), HS-WOA (Cai and Du 2021, chains) and PSO
on the `free` encoding (three waypoints, repair connector), each with its registry defaults and a
budget of 5,000 evaluations (OMPL's planners may stop before it), seeds 1-10. Statistics: results_pages.py's rank-sum tests with Holm's
correction, checked there against scipy.
"""
import csv
import pathlib
import sys

REPO = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "scripts"))
import results_pages as rp  # noqa: E402

DATA = REPO / "docs" / "results" / "data"
PAGE = REPO / "docs" / "results" / "planners.md"
CSV = "planners.csv"


def last_scenario_line(name):
    """The start and goal of the last line (the longest bucket) of a Moving AI scenario file."""
    scen = sorted(rp.map_file("$PRIDE_DATA/movingai").glob(name + "-even-*.scen"))[0]
    fields = scen.read_text().strip().splitlines()[-1].split()
    return (int(fields[4]), int(fields[5])), (int(fields[6]), int(fields[7]))


# (id, map file, start, goal): the papers' maps corner to corner, and Moving AI maps (the public data
# of others, read from $PRIDE_DATA/movingai by the runs) with the start and goal of the last line of
# their scenario files `NAME-even-1.scen` (the runs check them against the files).
PAPER_MAPS = [
    ("wan2022-13x13", "examples/maps/wan2022-13x13.map", (0, 0), (12, 12)),
    ("zhang2025-20x20", "examples/maps/zhang2025-20x20.map", (0, 19), (19, 0)),
    ("zhang2025-40x40", "examples/maps/zhang2025-40x40.map", (1, 38), (38, 1)),
    ("cai2021-50x50", "examples/maps/cai2021-50x50.map", (0, 49), (49, 0)),
    ("cai2021-env3-60x60", "examples/maps/cai2021-env3-60x60.map", (0, 59), (59, 0)),
]
MOVINGAI = [
    ("den312d", (46, 40), (52, 37)),
    ("maze-32-32-2", (17, 5), (6, 10)),
    ("random-64-64-20", (60, 35), (10, 56)),
    ("room-64-64-8", (22, 45), (4, 47)),
    ("den520d", (177, 18), (9, 212)),
    ("Berlin_1_256", (212, 144), (78, 147)),
]
INSTANCES = PAPER_MAPS + [(m, f"$PRIDE_DATA/movingai/{m}.map", s, g) for m, s, g in MOVINGAI]

WHOLE_MAP = ["astar", "jps", "theta-star", "lazy-theta-star", "any-angle-exact"]
# (label, algorithm, encoding)
BUDGETED = [
    ("ompl:RRTstar", "ompl:RRTstar", ""),
    ("ompl:InformedRRTstar", "ompl:InformedRRTstar", ""),
    ("ompl:BITstar", "ompl:BITstar", ""),
    ("ompl:PRMstar", "ompl:PRMstar", ""),
    ("ilso", "ilso", ""),
    ("iqga", "iqga", ""),
    ("hswoa", "hswoa", ""),
    ("pso-free", "pso", "free"),
]
PLANNERS = WHOLE_MAP + [label for label, _, _ in BUDGETED]
SEEDS = range(1, 11)
EVALS = 5_000
METRICS = ["length", "turns", "total_turn_deg", "max_turn_deg", "angle_over_length", "max_curvature",
           "min_clearance", "mean_clearance"]
FIELDS = ["instance", "planner", "seed", "feasible", "evaluations", "wall_ms"] + METRICS + ["grid_gap",
                                                                                           "any_angle_gap"]


def run_all():
    import pride  # the build's module (PYTHONPATH=build/python)

    for m, s, g in MOVINGAI:
        assert last_scenario_line(m) == (s, g), f"{m}: the scenario file's last line is not {s} to {g}"
    rows = []

    def record(name, label, seed, r):
        m = r.path_metrics or {}
        rows.append([name, label, seed, int(r.feasible), r.evaluations, f"{r.wall_ms:.3f}"] +
                    ["" if m.get(k) is None else repr(m[k]) for k in METRICS] +
                    ["" if r.grid_gap is None else repr(r.grid_gap),
                     "" if r.any_angle_gap is None else repr(r.any_angle_gap)])

    for name, path, start, goal in INSTANCES:
        grid = pride.Grid.load(str(rp.map_file(path)))
        for algo in WHOLE_MAP:
            record(name, algo, 0, pride.plan(grid, start, goal, algo=algo, objective="length", gaps=True))
        for label, algo, encoding in BUDGETED:
            for seed in SEEDS:
                r = pride.plan(grid, start, goal, algo=algo, objective="length", encoding=encoding, evals=EVALS,
                               seed=seed, gaps=True)
                record(name, label, seed, r)
        print(f"{name}: done", file=sys.stderr)
    with open(DATA / CSV, "w", newline="") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(FIELDS)
        w.writerows(rows)


def read(data=DATA):
    with open(data / CSV, newline="") as fh:
        return list(csv.DictReader(fh))


def values(rows, instance, planner, field):
    return [float(r[field]) for r in rows if r["instance"] == instance and r["planner"] == planner and r[field]]


def runs_of(rows, instance, planner):
    return [r for r in rows if r["instance"] == instance and r["planner"] == planner]


def gap_block(rows, field):
    """Median gap (%) of every planner on every instance over the runs that found a path, with their
    number beside it where some runs found none; - where no run found a path."""
    out = []
    for planner in PLANNERS:
        cells = [planner]
        for name, _, _, _ in INSTANCES:
            v = values(rows, name, planner, field)
            n = len(runs_of(rows, name, planner))
            cell = f"{100 * rp.median(v):.2f}" if v else "-"
            cells.append(cell + (f" ({len(v)}/{n})" if v and len(v) < n else ""))
        out.append(cells)
    return rp.table(["planner"] + [name for name, _, _, _ in INSTANCES], out, "l" + "r" * len(INSTANCES))


def success_block(rows):
    out = []
    for planner in PLANNERS:
        found = sum(int(r["feasible"]) for r in rows if r["planner"] == planner)
        total = sum(1 for r in rows if r["planner"] == planner)
        times = [float(r["wall_ms"]) for r in rows if r["planner"] == planner]
        evals = [int(r["evaluations"]) for r in rows if r["planner"] == planner]
        out.append([planner, f"{found} of {total}", f"{rp.median(times):.3f}", f"{max(times):.3f}",
                    f"{rp.median(evals):g}", f"{min(evals):g}", f"{max(evals):g}"])
    return rp.table(["planner", "runs that found a path", "median ms", "max ms", "median evaluations",
                     "min evaluations", "max evaluations"], out, "lrrrrrr")


def metrics_block(rows):
    """Per instance, every planner's medians of the path metrics."""
    parts = []
    for name, path, start, goal in INSTANCES:
        out = []
        for planner in PLANNERS:
            found = [r for r in runs_of(rows, name, planner) if r["feasible"] == "1"]
            if not found:
                out.append([planner, f"0/{len(runs_of(rows, name, planner))}"] + ["-"] * (1 + len(METRICS)))
                continue
            cells = [planner, f"{len(found)}/{len(runs_of(rows, name, planner))}",
                     f"{rp.median([int(r['evaluations']) for r in found]):g}"]
            for k in METRICS:
                v = [float(r[k]) for r in found if r[k]]
                cells.append(f"{rp.median(v):.4g}" if v else "-")
            out.append(cells)
        parts.append(f"**{name}** (`{path}`, {start} to {goal}):\n\n" +
                     rp.table(["planner", "found", "evaluations"] + METRICS, out, "ll" + "r" * (1 + len(METRICS))))
    return "\n\n".join(parts)


def tests_block(rows):
    """Per instance, the budgeted planner with the lowest median any-angle gap against each other
    budgeted planner: two-sided rank-sum tests, Holm over the instance's 7 comparisons."""
    labels = [label for label, _, _ in BUDGETED]
    out = []
    for name, _, _, _ in INSTANCES:
        gaps = {p: values(rows, name, p, "any_angle_gap") for p in labels}
        # A run without a path counts as the worst gap (infinite), so that failing is never better.
        for p in labels:
            gaps[p] = gaps[p] + [float("inf")] * (len(runs_of(rows, name, p)) - len(gaps[p]))
        best = min(labels, key=lambda p: (rp.median(gaps[p]), labels.index(p)))
        others = [p for p in labels if p != best]
        ps = dict(zip(others, rp.holm([rp.rank_sum(gaps[best], gaps[p]) for p in others])))
        out.append([name] + ["best" if p == best else rp.star(ps[p]) for p in labels])
    return rp.table(["instance"] + labels, out, "l" + "r" * len(labels))


def blocks(data=DATA):
    rows = read(data)
    return {
        "pl-runs": f"{len(rows):,} runs: {len(INSTANCES)} instances; {', '.join(WHOLE_MAP)} once each; "
                   f"{', '.join(label for label, _, _ in BUDGETED)} with seeds {SEEDS.start}-{SEEDS.stop - 1} and "
                   f"a budget of {EVALS:,} evaluations each.",
        "pl-success": success_block(rows),
        "pl-any-angle-gap": gap_block(rows, "any_angle_gap"),
        "pl-grid-gap": gap_block(rows, "grid_gap"),
        "pl-metrics": metrics_block(rows),
        "pl-tests": tests_block(rows),
    }


def check(data=DATA, page=PAGE):
    return rp.check_page(blocks(data), page)


if __name__ == "__main__":
    sys.exit(rp.page_main(sys.argv, __doc__, run_all, blocks, PAGE))
