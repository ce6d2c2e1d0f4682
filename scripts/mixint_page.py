#!/usr/bin/env python3
"""Regenerates docs/results/mixint.md (the mixed-variable methods on COCO's bbob-mixint suite) from
its campaign, or checks it.

    /usr/bin/python3 scripts/mixint_page.py run [--build build] [--stores DIR] [--jobs 2]
        runs (or resumes) examples/campaigns/mixint.toml into DIR/mixint.sqlite (default
        build/results) with BUILD/cli/pride, writes each run's final precision and first reaching
        of the targets 1e2 .. 1e-8 to docs/results/data/mixint-dD.csv, the date, commit and times
        to docs/results/data/mixint-meta.json, the ECDF figures to docs/results/img/, then the page.
        About 15 min on two cores.
    /usr/bin/python3 scripts/mixint_page.py render
        rewrites the page's generated blocks from docs/results/data/ alone.
    /usr/bin/python3 scripts/mixint_page.py check
        exits 1 when a generated block differs from what docs/results/data/ gives
        (python/tests/test_mixint_page.py does the same under ctest).

Statistics are results_pages.py's (the two-sided Wilcoxon rank-sum test, normal approximation
with tie and continuity corrections, and Holm's step-down correction), checked there against scipy.
"""
import csv
import datetime
import json
import math
import os
import pathlib
import re
import sqlite3
import sys
import time

REPO = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "scripts"))
import results_pages as rp  # noqa: E402

DATA = REPO / "docs" / "results" / "data"
IMG = REPO / "docs" / "results" / "img"
PAGE = REPO / "docs" / "results" / "mixint.md"
CAMPAIGN = REPO / "examples" / "campaigns" / "mixint.toml"

REFERENCE = "cmaes-margin"  # every other algorithm is tested against it
# The precisions whose first reaching each run records (COCO's targets at integer exponents).
EXPONENTS = list(range(2, -9, -1))
GROUPS = [("separable", range(1, 6)), ("moderate", range(6, 10)), ("ill-conditioned", range(10, 15)),
          ("multimodal", range(15, 20)), ("weak structure", range(20, 25))]
# COCO's final target: precisions at or below it are one value, else the last digits of f - f_opt
# (f_opt up to about 10^3) would rank runs by rounding.
FINAL_TARGET = 1e-8
ECDF_AT = [100, 1000]  # evaluations / D at which the ECDF is read, besides the budget
ERT_EXPONENT = -2  # the ERT tables' target: f_opt + 1e-2


def campaign_text(campaign=CAMPAIGN):
    return pathlib.Path(campaign).read_text()


def algorithms(campaign=CAMPAIGN):
    """The campaign's algorithm ids in its order."""
    return re.findall(r'^id = "([^"]+)"', campaign_text(campaign), re.M)


def suite(campaign=CAMPAIGN):
    """(functions, instances, dimensions) of the campaign's suite."""
    text = campaign_text(campaign)

    def ints(k):
        return [int(x) for x in re.search(rf"^{k} = \[([^\]]*)\]", text, re.M).group(1).split(",")]

    return ints("functions"), ints("instances"), ints("dimensions")


def per_dim(campaign=CAMPAIGN):
    return int(re.search(r"^evaluations_per_dim = (\d+)", campaign_text(campaign), re.M).group(1))


def subset(functions, instances, dimensions, algos, campaign=CAMPAIGN):
    """The campaign's text restricted to some of its functions, instances, dimensions and algorithms:
    its runs are the campaign's own (a run depends on its problem, algorithm, seed and budget only)."""
    head, *blocks = campaign_text(campaign).split("[[algorithm]]\n")
    for key, values in (("functions", functions), ("instances", instances), ("dimensions", dimensions)):
        head = re.sub(rf"^{key} = \[[^\]]*\]", f"{key} = [{', '.join(map(str, values))}]", head, flags=re.M)
    kept = [b for b in blocks if re.match(r'id = "([^"]+)"', b).group(1) in algos]
    return head + "".join("[[algorithm]]\n" + b for b in kept)


# ---------------------------------------------------------------------------------------------
# Export (run mode): store -> compact CSVs

def export(store, data=DATA, campaign=CAMPAIGN):
    """data/mixint-dD.csv of each dimension the store holds: function, instance, algorithm, the final
    precision f - f_opt, evaluations, the first evaluation at which each precision 10^e held."""
    db = sqlite3.connect(f"file:{store}?mode=ro", uri=True)
    rows = db.execute("SELECT p.fid, p.instance, p.dim, r.algorithm, r.best, p.f_opt, r.evaluations, "
                      "r.target_hits FROM runs r JOIN problems p ON p.id = r.problem").fetchall()
    db.close()
    index = [int(round((2 - e) / 0.2)) for e in EXPONENTS]  # 10^e is COCO's target number (2 - e) / 0.2
    order = algorithms(campaign)
    out = {}
    for fid, inst, dim, algo, best, f_opt, evals, hits in rows:
        h = json.loads(hits)
        reached = ["" if i >= len(h) or h[i] is None else str(h[i]) for i in index]
        out.setdefault(dim, []).append([fid, inst, algo, repr(float(best) - float(f_opt)), evals] + reached)
    for dim, rs in out.items():
        rs.sort(key=lambda r: (r[0], r[1], order.index(r[2])))
        with open(data / f"mixint-d{dim}.csv", "w", newline="") as fh:
            w = csv.writer(fh, lineterminator="\n")
            w.writerow(["function", "instance", "algorithm", "precision", "evaluations"] +
                       [f"hit_1e{e}" for e in EXPONENTS])
            w.writerows(rs)
    return sorted(out)


# ---------------------------------------------------------------------------------------------
# Reading the compact data

def read(dim, data=DATA):
    with open(data / f"mixint-d{dim}.csv", newline="") as fh:
        return list(csv.DictReader(fh))


def read_meta(data=DATA):
    return json.loads((data / "mixint-meta.json").read_text())


def snapped(r):
    p = float(r["precision"])
    return FINAL_TARGET if p <= FINAL_TARGET else p


def fmt(x):
    return "<= 1e-8" if x <= FINAL_TARGET else f"{x:.2g}"


def hit_times(rows):
    """The evaluations at which each (run, target) pair was first reached (inf: never)."""
    return [int(r[f"hit_1e{e}"]) if r[f"hit_1e{e}"] else math.inf for r in rows for e in EXPONENTS]


def reached(rows, by):
    times = hit_times(rows)
    return sum(t <= by for t in times) / len(times)


# ---------------------------------------------------------------------------------------------
# Blocks

def made_block(data):
    m = read_meta(data)
    # A call that resumed a store did not time its runs: it says so instead of a wall time.
    wall = (f", {m['bench_seconds'] / 60:.1f} min wall with `pride bench --jobs {m['jobs']}` on {m['cores']} cores"
            if m["bench_seconds"] is not None else f" (the call resumed a store that held {m['runs_resumed']:,})")
    return f"Data made on {m['date']} at commit {m['commit']}: {m['runs']:,} runs{wall}."


def runs_block(data):
    functions, instances, dims = suite()
    n = sum(len(read(d, data)) for d in dims)
    return (f"{n:,} runs: {len(functions)} functions x {len(instances)} instances ({instances[0]}-{instances[-1]}, "
            f"one run each) x {len(dims)} dimensions ({', '.join(map(str, dims))}) x {len(algorithms())} "
            f"algorithms, {per_dim():,} D evaluations each.")


def ecdf_block(data):
    """The ECDF of all (function, instance, target) pairs read at a few budgets, per dimension."""
    _, _, dims = suite()
    budgets = ECDF_AT + [per_dim()]
    header = ["algorithm"] + [f"D = {d}, {b:,} D" for d in dims for b in budgets]
    out = []
    for a in algorithms():
        row = [f"`{a}`"]
        for d in dims:
            rs = [r for r in read(d, data) if r["algorithm"] == a]
            row += [rp.pct(reached(rs, b * d)) for b in budgets]
        out.append(row)
    return rp.table(header, out, "l" + "r" * (len(header) - 1))


def ert(rows, exponent):
    """COCO's expected running time to f_opt + 10^exponent: the evaluations of every run (to the
    hit, or all it spent) over the number of runs that hit; inf when none did. And the hits."""
    key = f"hit_1e{exponent}"
    hits = [r for r in rows if r[key]]
    spent = sum(int(r[key]) if r[key] else int(r["evaluations"]) for r in rows)
    return (spent / len(hits) if hits else math.inf), len(hits)


def ert_block(data, dim):
    """ERT / D to f_opt + 10^ERT_EXPONENT per function, with the runs that reached it."""
    rows = read(dim, data)
    functions, instances, _ = suite()
    out = []
    for fn in functions:
        row = [f"f{fn}"]
        for a in algorithms():
            e, k = ert([r for r in rows if r["algorithm"] == a and int(r["function"]) == fn], ERT_EXPONENT)
            v = e / dim
            row.append(("inf" if not k else f"{v:,.0f}" if v >= 100 else f"{v:.3g}") + f" ({k}/{len(instances)})")
        out.append(row)
    return rp.table(["function"] + [f"`{a}`" for a in algorithms()], out, "l" + "r" * len(algorithms()))


def groups_block(data, dim):
    rows = read(dim, data)
    budget = per_dim() * dim
    header = ["algorithm"] + [f"{g} (f{min(fns)}-f{max(fns)})" for g, fns in GROUPS] + ["all", "solved (<= 1e-8)"]
    out = []
    for a in algorithms():
        mine = [r for r in rows if r["algorithm"] == a]
        row = [f"`{a}`"]
        for _, fns in GROUPS:
            row.append(rp.pct(reached([r for r in mine if int(r["function"]) in fns], budget)))
        row.append(rp.pct(reached(mine, budget)))
        row.append(f"{sum(snapped(r) <= FINAL_TARGET for r in mine)} / {len(mine)}")
        out.append(row)
    return rp.table(header, out, "l" + "r" * (len(header) - 1))


def comparisons(rows, algos):
    """{(function, algorithm): (Holm-adjusted p, lower)} of each algorithm against REFERENCE on every
    function, Holm over all of them; lower: its mean rank is below the reference's."""
    tests = []
    for fn in range(1, 25):
        ref = [snapped(r) for r in rows if int(r["function"]) == fn and r["algorithm"] == REFERENCE]
        for a in algos:
            if a == REFERENCE:
                continue
            mine = [snapped(r) for r in rows if int(r["function"]) == fn and r["algorithm"] == a]
            ranks = rp.average_ranks(mine + ref)
            tests.append(((fn, a), rp.rank_sum(mine, ref), rp.mean(ranks[:len(mine)]) < rp.mean(ranks[len(mine):])))
    adjusted = rp.holm([t[1] for t in tests])
    return {k: (q, lower) for (k, _, lower), q in zip(tests, adjusted)}


def medians(rows, fn, a):
    return rp.median([snapped(r) for r in rows if int(r["function"]) == fn and r["algorithm"] == a])


def tests_block(data, dim):
    rows = read(dim, data)
    algos = algorithms()
    tests = comparisons(rows, algos)
    out = []
    for fn in range(1, 25):
        row = [f"f{fn}"]
        for a in algos:
            cell = fmt(medians(rows, fn, a))
            if a != REFERENCE and tests[(fn, a)][0] < 0.05:
                cell += " (+)" if tests[(fn, a)][1] else " (-)"
            row.append(cell)
        out.append(row)
    return rp.table(["function"] + [f"`{a}`" for a in algos], out, "l" + "r" * len(algos))


def summary_block(data):
    _, _, dims = suite()
    algos = algorithms()
    out = []
    for d in dims:
        tests = comparisons(read(d, data), algos)
        for a in algos:
            if a == REFERENCE:
                continue
            mine = [v for (fn, b), v in tests.items() if b == a]
            lower = sum(q < 0.05 and low for q, low in mine)
            higher = sum(q < 0.05 and not low for q, low in mine)
            out.append([d, f"`{a}`", lower, higher, len(mine) - lower - higher])
    return rp.table(["D", "algorithm", f"lower than `{REFERENCE}`", "higher", "not told apart"], out, "rlrrr")


def round_relax_block(data):
    """DE with the rounding operator against DE relaxed, Holm over every function and dimension."""
    _, _, dims = suite()
    tests = []
    for d in dims:
        rows = read(d, data)
        for fn in range(1, 25):
            x = [snapped(r) for r in rows if int(r["function"]) == fn and r["algorithm"] == "de-round"]
            y = [snapped(r) for r in rows if int(r["function"]) == fn and r["algorithm"] == "de-relax"]
            ranks = rp.average_ranks(x + y)
            tests.append((d, fn, rp.rank_sum(x, y), rp.mean(ranks[:len(x)]) < rp.mean(ranks[len(x):])))
    adjusted = rp.holm([t[2] for t in tests])
    out = []
    for d in dims:
        mine = [(t, q) for t, q in zip(tests, adjusted) if t[0] == d]
        lower = [f"f{t[1]}" for t, q in mine if q < 0.05 and t[3]]
        higher = [f"f{t[1]}" for t, q in mine if q < 0.05 and not t[3]]
        out.append([d, ", ".join(lower) or "none", ", ".join(higher) or "none", len(mine) - len(lower) - len(higher)])
    return rp.table(["D", "`de-round` lower", "`de-round` higher", "not told apart"], out, "rllr")


def blocks(data=DATA):
    _, _, dims = suite()
    b = {"mi-made": made_block(data), "mi-runs": runs_block(data), "mi-ecdf": ecdf_block(data),
         "mi-summary": summary_block(data), "mi-round-relax": round_relax_block(data)}
    for d in dims:
        b[f"mi-groups-d{d}"] = groups_block(data, d)
        b[f"mi-tests-d{d}"] = tests_block(data, d)
        b[f"mi-ert-d{d}"] = ert_block(data, d)
    return b


# ---------------------------------------------------------------------------------------------
# Figures

def ecdf_figure(dim, data=DATA, img=IMG):
    """COCO's ECDF of runtimes (evaluations / D) over all functions, instances and the 11 targets."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = read(dim, data)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    grid = [10 ** (k / 20) for k in range(0, int(20 * math.log10(per_dim())) + 1)] + [per_dim()]
    styles = ["-", "--", "-.", ":"]
    for i, a in enumerate(algorithms()):
        times = [t / dim for t in hit_times([r for r in rows if r["algorithm"] == a])]
        ax.plot(grid, [sum(t <= g for t in times) / len(times) for g in grid], label=a, linewidth=1.4,
                color=plt.cm.tab10(i % 10), linestyle=styles[i % len(styles)])
    ax.set_xscale("log")
    ax.set_xlim(1, per_dim())
    ax.set_ylim(0, 1)
    ax.set_xlabel("evaluations / D")
    ax.set_ylabel("share of (function, instance, target) pairs")
    ax.set_title(f"bbob-mixint f1-f24, D = {dim}, 15 instances, targets 1e2 .. 1e-8")
    ax.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    fig.savefig(img / f"mixint-ecdf-d{dim}.png", dpi=100)
    plt.close(fig)


# ---------------------------------------------------------------------------------------------

def count_runs(store):
    db = sqlite3.connect(f"file:{store}?mode=ro", uri=True)
    n, ms = db.execute("SELECT count(*), coalesce(sum(wall_ms), 0) FROM runs").fetchone()
    db.close()
    return n, ms


def run(build, stores, jobs):
    pride = build / "cli" / "pride"
    if not pride.exists():
        raise SystemExit(f"{pride} is not built: cmake -S . -B {build} -G Ninja && ninja -C {build} pride")
    stores.mkdir(parents=True, exist_ok=True)
    IMG.mkdir(parents=True, exist_ok=True)
    store = stores / "mixint.sqlite"
    before = count_runs(store) if store.exists() else (0, 0.0)
    t0 = time.monotonic()
    rp.run([pride, "bench", CAMPAIGN, "--jobs", jobs, "--out", store], cwd=REPO)
    seconds = time.monotonic() - t0
    dims = export(store)
    runs, run_ms = count_runs(store)
    # The wall time is this call's only when it ran every run (not when it resumed a store).
    meta = {"date": datetime.date.today().isoformat(), "commit": rp.git_commit(), "jobs": int(jobs),
            "cores": os.cpu_count(), "runs": runs, "runs_resumed": before[0],
            "bench_seconds": round(seconds, 1) if before[0] == 0 else None, "run_seconds": round(run_ms / 1000, 1)}
    (DATA / "mixint-meta.json").write_text(json.dumps(meta, indent=1, sort_keys=True) + "\n")
    print(f"mixint: {runs} runs, bench {seconds:.1f} s", flush=True)
    for d in dims:
        ecdf_figure(d)
    PAGE.write_text(rp.replace_blocks(PAGE.read_text(), blocks()))


def main(argv):
    args = list(argv)
    mode = args.pop(0) if args and args[0] in ("run", "render", "check") else None
    opts = {"--build": "build", "--stores": None, "--jobs": "2"}
    while args:
        k = args.pop(0)
        if mode is None or k not in opts or not args:
            print(__doc__, file=sys.stderr)
            return 2
        opts[k] = args.pop(0)
    if mode is None:
        print(__doc__, file=sys.stderr)
        return 2
    if mode == "render":
        PAGE.write_text(rp.replace_blocks(PAGE.read_text(), blocks()))
    elif mode == "check":
        diffs = rp.check_page(blocks(), PAGE)
        for name, _, got in diffs:
            print(f"docs/results/mixint.md: block {name} {'is missing' if got is None else 'differs from its data'}",
                  file=sys.stderr)
        return 1 if diffs else 0
    else:
        build = pathlib.Path(opts["--build"])
        build = build if build.is_absolute() else REPO / build
        stores = pathlib.Path(opts["--stores"]) if opts["--stores"] else build / "results"
        run(build, stores, opts["--jobs"])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
