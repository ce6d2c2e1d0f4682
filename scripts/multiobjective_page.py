#!/usr/bin/env python3
"""Regenerates docs/results/multiobjective.md from its runs, or checks it.

    PYTHONPATH=build/python /usr/bin/python3 scripts/multiobjective_page.py run
        runs every (instance, algorithm, seed) of the page through pride's Python module (the runs
        `pride front --map` makes) and writes their indicators to
        docs/results/data/multiobjective-grids.csv, then the page.
    /usr/bin/python3 scripts/multiobjective_page.py render
        rewrites the page's generated blocks from docs/results/data/ alone.
    /usr/bin/python3 scripts/multiobjective_page.py check
        exits 1 when a generated block differs from what the data give
        (python/tests/test_multiobjective_page.py does the same under ctest).

    cmake --build build --target mo_bench && ./build/bench/mo_bench > docs/results/data/multiobjective-pagmo.csv
        (pagmo2 installed; the benchmark programs are built only when asked) the ZDT/DTLZ runs beside pagmo2's nsga2 and
        moead, in one process, that the page's last table reads; then `render`.

The runs: NSGA-II, MOEA/D and SMS-EMOA with their registry defaults (population 100, 100 MOEA/D
subproblems), through the `free` encoding (three waypoints, repair connector), and NSGA-II on cell
chains with the chain operators (from random walks, and from SITP walks), 20,000 evaluations
each, seeds 1-15; IQGA (Zhang et al. 2025) with its registry defaults on its own weighted objective and
space (chains, N = 40) at the same 20,000 evaluations. Indicators: engine/multiobjective.hpp's
(normalised by the exact front; hypervolume ratio with the reference point 1.1; IGD+; exact
points found). Statistics: results_pages.py's Kruskal-Wallis and two-sided rank-sum tests with
Holm's correction, checked there against scipy.
"""
import csv
import io
import math
import pathlib
import sys

REPO = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "scripts"))
import results_pages as rp  # noqa: E402

DATA = REPO / "docs" / "results" / "data"
PAGE = REPO / "docs" / "results" / "multiobjective.md"
CSV = "multiobjective-grids.csv"

# (id, map file, start, goal): the papers' maps (examples/maps/) corner to corner, and two Moving AI
# maps with a scenario line each (the public data of others, read from $PRIDE_DATA/movingai by the
# runs; the line's start and goal).
INSTANCES = [
    ("zhang2025-20x20", "examples/maps/zhang2025-20x20.map", (0, 19), (19, 0)),
    ("zhang2025-40x40", "examples/maps/zhang2025-40x40.map", (1, 38), (38, 1)),
    ("cai2021-50x50", "examples/maps/cai2021-50x50.map", (0, 49), (49, 0)),
    ("cai2021-env3-60x60", "examples/maps/cai2021-env3-60x60.map", (0, 59), (59, 0)),
    ("den312d", "$PRIDE_DATA/movingai/den312d.map", (58, 37), (4, 56)),
]
# (label, algorithm, encoding, init): the three on `free`, and NSGA-II on cell chains with the chain
# operators, from random walks and from Zhang et al.'s (2025) SITP walks.
ENTRANTS = [
    ("nsga2", "nsga2", "free", None),
    ("moead", "moead", "free", None),
    ("smsemoa", "smsemoa", "free", None),
    ("nsga2-chain", "nsga2", "chain", None),
    ("nsga2-chain-sitp", "nsga2", "chain", "sitp"),
]
MO_ALGOS = [label for label, _, _, _ in ENTRANTS]
SEEDS = range(1, 16)
EVALS = 20_000
CRITERIA = {"ltc": "length,turns,clearance", "lta": "length,turns,angle"}
FIELDS = ["instance", "criteria", "algo", "seed", "evaluations", "hv_ratio", "igd_plus", "found", "front",
          "points"]


def run_all():
    import pride  # the build's module (PYTHONPATH=build/python)

    rows = []
    for name, path, start, goal in INSTANCES:
        grid = pride.Grid.load(str(rp.map_file(path)))
        for key, criteria in CRITERIA.items():
            exact = pride.pareto(grid, start, goal, objectives=criteria)
            for label, algo, encoding, init in ENTRANTS:
                for seed in SEEDS:
                    r = pride.plan_front(grid, start, goal, algo=algo, objectives=criteria, encoding=encoding,
                                         init=init, evals=EVALS, seed=seed)
                    q = r.quality
                    assert q["reference_size"] == len(exact)
                    rows.append([name, key, label, seed, r.evaluations, repr(q["hypervolume_ratio"]),
                                 repr(q["igd_plus"]), q["exact_found"], q["reference_size"], len(r.f)])
            if key != "lta":
                continue
            # IQGA: one path per run, on its own weighted objective over length, angle and turns.
            for seed in SEEDS:
                r = pride.plan(grid, start, goal, algo="iqga", objective="iqga", evals=EVALS, seed=seed)
                m = r.metrics
                on = any(abs(p["length"] - m["length"]) <= 1e-9 * p["length"] and p["turns"] == m["turns"]
                         and p["angle_penalty"] == m["angle_penalty"] for p in exact)
                rows.append([name, key, "iqga", seed, r.evaluations, "", "", int(on), len(exact), 1])
            print(f"{name}: done", file=sys.stderr)
    with open(DATA / CSV, "w", newline="") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(FIELDS)
        w.writerows(rows)


def read(data=DATA):
    with open(data / CSV, newline="") as fh:
        return list(csv.DictReader(fh))


def groups(rows, criteria, field):
    """{instance: {algo: [values by seed]}} of the MO algorithms."""
    out = {}
    for r in rows:
        if r["criteria"] != criteria or r["algo"] not in MO_ALGOS:
            continue
        out.setdefault(r["instance"], {}).setdefault(r["algo"], []).append(float(r[field]))
    return out


def quality_block(rows, criteria):
    hv, igd, found = (groups(rows, criteria, f) for f in ("hv_ratio", "igd_plus", "found"))
    size = {r["instance"]: int(r["front"]) for r in rows if r["criteria"] == criteria}
    header = ["instance", "exact front"] + [f"{a} HV ratio" for a in MO_ALGOS] + [f"{a} IGD+" for a in MO_ALGOS] + \
        [f"{a} found" for a in MO_ALGOS]
    out = []
    for inst, _, _, _ in INSTANCES:
        if inst not in hv:
            continue
        shown = {a: f"{rp.median(hv[inst][a]):.3f}" for a in MO_ALGOS}
        best = shown[max(MO_ALGOS, key=lambda a: rp.median(hv[inst][a]))]
        cells = [inst, size[inst]]
        cells += [f"**{shown[a]}**" if shown[a] == best else shown[a] for a in MO_ALGOS]  # ties at 3 digits: all
        cells += [f"{rp.median(igd[inst][a]):.3f}" for a in MO_ALGOS]
        cells += [f"{rp.median(found[inst][a]):g}" for a in MO_ALGOS]
        out.append(cells)
    return rp.table(header, out)


def tests_block(rows, criteria):
    hv = groups(rows, criteria, "hv_ratio")
    pairs = [(a, b) for i, a in enumerate(MO_ALGOS) for b in MO_ALGOS[i + 1:]]
    out = []
    for inst, _, _, _ in INSTANCES:
        if inst not in hv:
            continue
        _, p_kw = rp.kruskal([hv[inst][a] for a in MO_ALGOS])
        ps = rp.holm([rp.rank_sum(hv[inst][a], hv[inst][b]) for a, b in pairs])
        out.append([inst, rp.star(p_kw)] + [rp.star(p) for p in ps])
    return rp.table(["instance", "Kruskal-Wallis p"] + [f"{a} vs {b} (Holm)" for a, b in pairs], out)


def iqga_block(rows):
    out = []
    for inst, _, _, _ in INSTANCES:
        iq = [r for r in rows if r["instance"] == inst and r["algo"] == "iqga"]
        if not iq:
            continue
        size = int(iq[0]["front"])
        hits = sum(int(r["found"]) for r in iq)
        found = groups(rows, "lta", "found")[inst]
        cells = [inst, size, f"{hits} of {len(iq)}"]
        cells += [f"{rp.median(found[a]):g} ({min(found[a]):g}-{max(found[a]):g})" for a in MO_ALGOS]
        out.append(cells)
    return rp.table(["instance", "exact front", "IQGA runs on the front"] + [f"{a}: points found" for a in MO_ALGOS],
                    out)


PAGMO_CSV = "multiobjective-pagmo.csv"
PAGMO_PAIRS = [("nsga2", "pagmo-nsga2"), ("moead", "pagmo-moead")]


def pagmo_rows(data=DATA):
    """bench/mo_bench's runs: {(problem, algo): [rows]}, problems in the file's order."""
    out, problems = {}, []
    with open(data / PAGMO_CSV, newline="") as fh:
        for r in csv.DictReader(fh):
            if r["problem"] not in problems:
                problems.append(r["problem"])
            out.setdefault((r["problem"], r["algo"]), []).append(r)
    return out, problems


def pagmo_block(data=DATA):
    runs, problems = pagmo_rows(data)
    # One family of tests per indicator: each pair on each problem, Holm-corrected over all of them.
    keys = [(prob, a, b) for a, b in PAGMO_PAIRS for prob in problems]
    hv = {k: [float(r["hv_ratio"]) for r in runs[k]] for k in runs}
    ps = rp.holm([rp.rank_sum(hv[(prob, a)], hv[(prob, b)]) for prob, a, b in keys])

    def spread(v):  # the median, and the range over the runs that a median alone hides
        return f"{rp.median(v):.4f} ({min(v):.3f}-{max(v):.3f})"

    def ns(rows):  # framework cost per evaluation: (wall - bare) / evaluations
        return rp.median([(float(r["wall_ms"]) - float(r["bare_ms"])) * 1e6 / float(r["fevals"]) for r in rows])

    out = []
    for (prob, a, b), p in zip(keys, ps):
        ra, rb = runs[(prob, a)], runs[(prob, b)]
        na, nb = ns(ra), ns(rb)
        out.append([prob, f"{a} / {b}", len(ra), spread(hv[(prob, a)]), spread(hv[(prob, b)]),
                    rp.star(p), f"{na:.0f}", f"{nb:.0f}", f"{nb / na:.1f}x"])
    return rp.table(["problem", "pride / pagmo2", "runs each", "pride HV ratio (min-max)", "pagmo2 HV ratio (min-max)",
                     f"rank-sum p (Holm, {len(keys)} tests)", "pride ns per evaluation", "pagmo2 ns per evaluation",
                     "pagmo2 / pride"], out)


def blocks(data=DATA):
    rows = read(data)
    runs = sum(1 for _ in rows)
    return {
        "mo-runs": f"{runs:,} runs: {len(INSTANCES)} instances; " + ", ".join(MO_ALGOS) +
                   f" on two sets of criteria and IQGA on one, {len(SEEDS)} seeds each, {EVALS:,} evaluations per run.",
        "mo-quality-ltc": quality_block(rows, "ltc"),
        "mo-tests-ltc": tests_block(rows, "ltc"),
        "mo-quality-lta": quality_block(rows, "lta"),
        "mo-tests-lta": tests_block(rows, "lta"),
        "mo-iqga": iqga_block(rows),
        "mo-pagmo": pagmo_block(data),
    }


def check(data=DATA, page=PAGE):
    return rp.check_page(blocks(data), page)


if __name__ == "__main__":
    sys.exit(rp.page_main(sys.argv, __doc__, run_all, blocks, PAGE))
