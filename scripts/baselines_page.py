#!/usr/bin/env python3
"""Regenerates docs/results/baselines.md (the baselines) from its campaigns, or checks it.

    /usr/bin/python3 scripts/baselines_page.py run [--build build] [--stores DIR] [--jobs 2]
        runs (or resumes) the page's campaigns into DIR (default build/results): the BBOB one
        (examples/campaigns/baselines-bbob.toml), the CEC 2017 one (baselines-cec2017.toml, needs
        PRIDE_CEC2017_DATA), L-SHADE on CEC 2022 (lshade-cec2022.toml, needs
        PRIDE_CEC2022_DATA) and jSO on CEC 2017 (jso-cec2017.toml, needs PRIDE_CEC2017_DATA);
        writes their compact data to docs/results/data/ and the figures to docs/results/img/, then
        the page. The jSO comparison reads jSO's published competition results from
        PRIDE_JSO_RESULTS, the folder of its result files jSO_F_D.txt (the A01 folder of the CEC
        2017 results collection, mirrored in github.com/dgsotiropoulos/CEC-Benchmarks,
        Collect_CEC2017_data/A01); only their summary and the test's p-values are kept.
    /usr/bin/python3 scripts/baselines_page.py render
        rewrites the page's generated blocks from docs/results/data/ alone.
    /usr/bin/python3 scripts/baselines_page.py check
        exits 1 when a generated block differs from what docs/results/data/ gives
        (python/tests/test_baselines_page.py does the same under ctest).

Statistics are results_pages.py's (the two-sided Wilcoxon rank-sum test, normal approximation
with tie and continuity corrections, and Holm's step-down correction), checked there against scipy.
"""
import csv
import io
import json
import math
import os
import pathlib
import sqlite3
import subprocess
import sys

REPO = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "scripts"))
import results_pages as rp  # noqa: E402

DATA = REPO / "docs" / "results" / "data"
IMG = REPO / "docs" / "results" / "img"
PAGE = REPO / "docs" / "results" / "baselines.md"
CAMPAIGNS = REPO / "examples" / "campaigns"

# The page's algorithms in table order (ids of baselines-bbob.toml).
ALGOS = ["cmaes", "cmaes-once", "ipop-cmaes", "bipop-cmaes", "sep-cmaes", "de", "jde", "jade", "shade", "lshade", "jso", "pso",
         "ga", "woa", "sbplx", "crs2"]
DIMS = [5, 20]
# The precisions whose first reaching each BBOB run records (COCO's targets at integer exponents).
EXPONENTS = list(range(2, -9, -1))
GROUPS = [("separable", range(1, 6)), ("moderate", range(6, 10)), ("ill-conditioned", range(10, 15)),
          ("multimodal", range(15, 20)), ("weak structure", range(20, 25))]
SOLVED = 1e-8
CEC2017_DIMS = [10, 30]
CEC2017_RUNS = 25  # baselines-cec2017.toml's seeds: a cell is shown when every algorithm has them all
# CEC 2022's F* (the official code's biases), for the official L-SHADE's errors.
CEC2022_FSTAR = [300, 400, 600, 800, 900, 1800, 2000, 2200, 2300, 2400, 2600, 2700]


# ---------------------------------------------------------------------------------------------
# Export (run mode): stores -> compact CSVs

def export_bbob(store, pride):
    fopt = f_opts(store, pride)
    db = sqlite3.connect(f"file:{store}?mode=ro", uri=True)
    rows = db.execute("SELECT problem, algorithm, best, evaluations, target_hits FROM runs").fetchall()
    db.close()
    index = [int(round((2 - e) / 0.2)) for e in EXPONENTS]  # 10^e is COCO's target number (2 - e) / 0.2
    out = {d: [] for d in DIMS}
    for problem, algo, best, evals, hits in rows:
        f, inst, d = problem.split("-")[1:]
        fn, inst, dim = int(f[1:]), int(inst[1:]), int(d[1:])
        h = json.loads(hits)
        reached = ["" if i >= len(h) or h[i] is None else str(h[i]) for i in index]
        out[dim].append([fn, inst, algo, repr(best - fopt[problem]), evals] + reached)
    for dim, rows in out.items():
        rows.sort(key=lambda r: (r[0], r[1], ALGOS.index(r[2]) if r[2] in ALGOS else 99))
        with open(DATA / f"baselines-bbob-d{dim}.csv", "w", newline="") as fh:
            w = csv.writer(fh, lineterminator="\n")
            w.writerow(["function", "instance", "algorithm", "precision", "evaluations"] +
                       [f"hit_1e{e}" for e in EXPONENTS])
            w.writerows(rows)


def f_opts(store, pride):
    report = csv.DictReader(io.StringIO(rp.run([pride, "report", store, "--format", "csv"])))
    return {r["problem"]: float(r["f_opt"]) for r in report if r.get("f_opt")}


def export_cec(name, store, pride):
    """Each run's error f - F* (not snapped: the page applies the CEC rule, errors < 1e-8 are 0)."""
    fopt = f_opts(store, pride)
    db = sqlite3.connect(f"file:{store}?mode=ro", uri=True)
    rows = db.execute("SELECT problem, algorithm, seed, best FROM runs").fetchall()
    db.close()
    out = []
    for problem, algo, seed, best in rows:
        _, f, d = problem.split("-")
        out.append((int(f[1:]), int(d[1:]), algo, seed, repr(best - fopt[problem])))
    out.sort(key=lambda r: (r[0], r[1], r[2], r[3]))
    with open(DATA / f"{name}.csv", "w", newline="") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(["function", "dimension", "algorithm", "run", "error"])
        w.writerows(out)


def export_jso_published(folder):
    """Summary of jSO's published final errors (the last row of each result file), and the raw
    values for the test (returned, not written)."""
    raw = {}
    for dim in (10, 30):
        for fn in range(1, 31):
            path = pathlib.Path(folder) / f"jSO_{fn}_{dim}.txt"
            last = [line for line in path.read_text().splitlines() if line.strip()][-1]
            raw[(fn, dim)] = [float(v) for v in last.split()]
    return raw


# ---------------------------------------------------------------------------------------------
# Reading the compact data

def read_bbob(dim, data=DATA):
    with open(data / f"baselines-bbob-d{dim}.csv", newline="") as fh:
        return list(csv.DictReader(fh))


def read_cec(name, data=DATA):
    out = {}
    with open(data / f"{name}.csv", newline="") as fh:
        for r in csv.DictReader(fh):
            out.setdefault((int(r["function"]), int(r["dimension"]), r["algorithm"]), []).append(float(r["error"]))
    return out


def present(rows):
    have = {r["algorithm"] for r in rows}
    return [a for a in ALGOS if a in have]


# ---------------------------------------------------------------------------------------------
# Blocks

def fmt(x):
    if x == 0:
        return "0"
    if math.isinf(x):
        return "inf"
    return f"{x:.3g}"


def solved_block(data):
    header = ["algorithm"] + [f"D = {d}: {g}" for d in DIMS for g, _ in GROUPS[:0]] + [f"solved, D = {d}" for d in DIMS]
    header += [f"{g} (D = 20)" for g, _ in GROUPS]
    per = {d: read_bbob(d, data) for d in DIMS}
    algos = present(per[DIMS[-1]])
    rows = []
    for a in algos:
        row = [f"`{a}`"]
        for d in DIMS:
            rs = [r for r in per[d] if r["algorithm"] == a]
            row.append(f"{sum(float(r['precision']) <= SOLVED for r in rs)} / {len(rs)}")
        for _, fns in GROUPS:
            rs = [r for r in per[20] if r["algorithm"] == a and int(r["function"]) in fns]
            row.append(f"{sum(float(r['precision']) <= SOLVED for r in rs)} / {len(rs)}")
        rows.append(row)
    return rp.table(header, rows, "l" + "r" * (len(header) - 1))


def ert(rows, column):
    """COCO's expected running time to the target of `column`: evaluations of all runs (to the hit,
    or all they spent) over the successful runs; inf without one."""
    spent, hits = 0, 0
    for r in rows:
        if r[column]:
            spent += int(r[column])
            hits += 1
        else:
            spent += int(r["evaluations"])
    return spent / hits if hits else math.inf


def ert_block(data, dim):
    rows = read_bbob(dim, data)
    algos = present(rows)
    out = []
    for fn in range(1, 25):
        values = [ert([r for r in rows if int(r["function"]) == fn and r["algorithm"] == a], "hit_1e-8") for a in algos]
        best = min(values)
        out.append([f"f{fn}"] + [("**" + fmt(v / dim) + "**" if v == best and v < math.inf else fmt(v / dim))
                                 for v in values])
    return rp.table(["function"] + [f"`{a}`" for a in algos], out, "l" + "r" * len(algos))


def best_and_ties(values, algos):
    """The algorithm of lowest median (ties to the table's order), its median, and the others not
    significantly worse: two-sided rank-sum p >= 0.05 against it, Holm over the row's comparisons."""
    best = min(algos, key=lambda a: (rp.median(values[a]), algos.index(a)))
    others = [a for a in algos if a != best]
    ps = rp.holm([rp.rank_sum(values[best], values[a]) for a in others])
    tied = [a for a, p in zip(others, ps) if p >= 0.05]
    return best, rp.median(values[best]), ", ".join(f"`{a}`" for a in tied) or "none"


def tests_block(data, dim):
    rows = read_bbob(dim, data)
    algos = present(rows)
    out = []
    for fn in range(1, 25):
        prec = {a: [float(r["precision"]) for r in rows if int(r["function"]) == fn and r["algorithm"] == a]
                for a in algos}
        best, med, tied = best_and_ties(prec, algos)
        out.append([f"f{fn}", f"`{best}`", fmt(med), tied])
    return rp.table(["function", "lowest median precision", "its median", "not significantly worse (Holm p >= 0.05)"],
                    out, "llrl")


def restarts_block(data):
    out = []
    for dim in DIMS:
        rows = read_bbob(dim, data)
        for fn in (3, 15, 16, 21, 22, 23):
            cells = []
            for a in ("cmaes-once", "cmaes", "ipop-cmaes", "bipop-cmaes"):
                rs = [r for r in rows if int(r["function"]) == fn and r["algorithm"] == a]
                cells.append(f"{sum(float(r['precision']) <= SOLVED for r in rs)} / {len(rs)}")
            out.append([f"f{fn}", dim] + cells)
    return rp.table(["function", "D", "`cmaes-once` (one run)", "`cmaes` (same-lambda restarts)", "`ipop-cmaes`",
                     "`bipop-cmaes`"], out, "lrrrrr")


def snap(e):
    return 0.0 if e < 1e-8 else e  # the CEC rule: errors below 1e-8 count as 0


def as_published(e):
    """An error as jSO's result files print it (6 significant digits, %g), so that the test compares
    the two at the same resolution: 100.00000012 would otherwise rank above every printed 100."""
    return float(f"{snap(e):.6g}")


def lshade_block(data):
    ours = read_cec("lshade-cec2022", data)
    official = {}
    with open(data / "lshade-official-cec2022.csv", newline="") as fh:
        for r in csv.DictReader(fh):
            official.setdefault((int(r["function"]), int(r["dimension"])), []).append(snap(float(r["error"])))
    variants = [a for a in ("lshade", "lshade-paper") if any(k[2] == a for k in ours)]
    # Only what has all its runs (a campaign resumed later fills the rest).
    keys = sorted(k for k in official if all(len(ours.get((k[0], k[1], a), [])) == len(official[k]) for a in variants))
    ps = {a: [rp.rank_sum(official[k], [snap(e) for e in ours[(k[0], k[1], a)]]) for k in keys] for a in variants}
    adj = {a: rp.holm(ps[a]) for a in variants}
    out = []
    for i, (fn, dim) in enumerate(keys):
        row = [f"F{fn}", dim, fmt(rp.median(official[(fn, dim)]))]
        for a in variants:
            mine = [snap(e) for e in ours[(fn, dim, a)]]
            row += [fmt(rp.median(mine)), f"{ps[a][i]:.3g}", f"{adj[a][i]:.3g}" + (" *" if adj[a][i] < 0.05 else "")]
        out.append(row)
    header = ["function", "D", "official median"]  # Holm over the rows shown, per variant
    for a in variants:
        header += [f"`{a}` median", "p", "p (Holm)"]
    return rp.table(header, out, "lr" + "r" * (len(header) - 2))


def jso_block(data):
    ours = read_cec("jso-cec2017", data)
    pub = {}
    with open(data / "jso-published-cec2017.csv", newline="") as fh:
        for r in csv.DictReader(fh):
            pub[(int(r["function"]), int(r["dimension"]))] = r
    # Only what has all its runs (a campaign resumed later fills the rest).
    keys = sorted(k for k in pub if len(ours.get((k[0], k[1], "jso"), [])) == int(pub[k]["runs"]))
    out = []
    for fn, dim in keys:
        mine = [as_published(e) for e in ours[(fn, dim, "jso")]]
        r = pub[(fn, dim)]
        out.append([f"F{fn}", dim, fmt(float(r["median"])), f"{fmt(float(r['mean']))} ± {fmt(float(r['std']))}",
                    fmt(rp.median(mine)), f"{fmt(rp.mean(mine))} ± {fmt(rp.stdev(mine))}", r["p"],
                    r["p_holm"] + (" *" if float(r["p_holm"]) < 0.05 else "")])
    return rp.table(["function", "D", "published median", "published mean ± std", "pride median", "pride mean ± std",
                     "p", "p (Holm)"], out, "lr" + "r" * 6)


def cec2017_cells(data):
    """{(function, D): {algorithm: snapped errors}} of the cells whose runs are all in (every
    algorithm of the campaign, CEC2017_RUNS each), and the algorithms in table order."""
    runs = read_cec("baselines-cec2017", data)
    have = {k[2] for k in runs}
    algos = [a for a in ALGOS if a in have]
    cells = {}
    for fn in range(1, 31):
        for dim in CEC2017_DIMS:
            if all(len(runs.get((fn, dim, a), [])) == CEC2017_RUNS for a in algos):
                cells[(fn, dim)] = {a: [snap(e) for e in runs[(fn, dim, a)]] for a in algos}
    return cells, algos


def cec2017_ranks_block(data):
    cells, algos = cec2017_cells(data)
    lines, columns = [], []
    for dim in CEC2017_DIMS:
        keys = sorted(k for k in cells if k[1] == dim)
        if len(keys) < 5:  # the chi-squared approximation wants more blocks than a handful
            lines.append(f"D = {dim}: {len(keys)} of 30 functions complete, too few for the test.")
            columns.append(None)
            continue
        medians = [[rp.median(cells[k][a]) for a in algos] for k in keys]
        chi2, p, ranks = rp.friedman(medians)
        lowest = [sum(row[j] == min(row) for row in medians) for j in range(len(algos))]
        columns.append((ranks, lowest))
        lines.append(f"D = {dim}: {len(keys)} of 30 functions; Friedman chi2 = {chi2:.1f} "
                     f"({len(algos) - 1} degrees of freedom), p = {rp.fmt_p(p)}.")
    header, out = ["algorithm"], []
    for dim, col in zip(CEC2017_DIMS, columns):
        if col:
            header += [f"mean rank, D = {dim}", f"lowest median, D = {dim}"]
    for j, a in enumerate(algos):
        row = [f"`{a}`"]
        for col in columns:
            if col:
                row += [f"{col[0][j]:.2f}", str(col[1][j])]
        out.append(row)
    table = rp.table(header, out, "l" + "r" * (len(header) - 1)) if len(header) > 1 else ""
    return "\n".join(lines) + ("\n\n" + table if table else "")


def cec2017_medians_block(data, dim):
    cells, algos = cec2017_cells(data)
    out = []
    for fn, d in sorted(k for k in cells if k[1] == dim):
        values = [rp.median(cells[(fn, d)][a]) for a in algos]
        best = min(values)
        out.append([f"F{fn}"] + [("**" + fmt(v) + "**" if v == best else fmt(v)) for v in values])
    if not out:
        return f"No function at D = {dim} has all its runs yet."
    return rp.table(["function"] + [f"`{a}`" for a in algos], out, "l" + "r" * len(algos))


def cec2017_tests_block(data, dim):
    cells, algos = cec2017_cells(data)
    out = []
    for fn, d in sorted(k for k in cells if k[1] == dim):
        best, med, tied = best_and_ties(cells[(fn, d)], algos)
        out.append([f"F{fn}", f"`{best}`", fmt(med), tied])
    if not out:
        return f"No function at D = {dim} has all its runs yet."
    return rp.table(["function", "lowest median error", "its median", "not significantly worse (Holm p >= 0.05)"],
                    out, "llrl")


def blocks(data=DATA):
    b = {"bbob-solved": solved_block(data), "bbob-restarts": restarts_block(data)}
    for d in DIMS:
        b[f"bbob-ert-d{d}"] = ert_block(data, d)
        b[f"bbob-tests-d{d}"] = tests_block(data, d)
    if (data / "lshade-cec2022.csv").exists():
        b["lshade"] = lshade_block(data)
    if (data / "baselines-cec2017.csv").exists():
        b["cec2017-ranks"] = cec2017_ranks_block(data)
        for d in CEC2017_DIMS:
            b[f"cec2017-medians-d{d}"] = cec2017_medians_block(data, d)
            b[f"cec2017-tests-d{d}"] = cec2017_tests_block(data, d)
    if (data / "jso-cec2017.csv").exists() and (data / "jso-published-cec2017.csv").exists():
        b["jso"] = jso_block(data)
    return b


# ---------------------------------------------------------------------------------------------
# Figures

def ecdf_figure(dim, data=DATA, img=IMG):
    """COCO's ECDF of runtimes (evaluations / D) over all functions, instances and the 11 targets."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = read_bbob(dim, data)
    algos = present(rows)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    budget = 10000
    grid = [10 ** (k / 20) for k in range(0, 20 * 4 + 1)]
    styles = ["-", "--", "-.", ":"]
    for i, a in enumerate(algos):
        times = []
        rs = [r for r in rows if r["algorithm"] == a]
        for r in rs:
            for e in EXPONENTS:
                v = r[f"hit_1e{e}"]
                times.append(int(v) / dim if v else math.inf)
        n = len(times)
        ys = [sum(t <= g for t in times) / n for g in grid]
        ax.plot(grid, ys, label=a, linewidth=1.3, color=plt.cm.tab20(i % 20), linestyle=styles[i % len(styles)])
    ax.set_xscale("log")
    ax.set_xlim(1, budget)
    ax.set_ylim(0, 1)
    ax.set_xlabel("evaluations / D")
    ax.set_ylabel("share of (function, instance, target) pairs")
    ax.set_title(f"BBOB f1-f24, D = {dim}, 15 instances, targets 1e2 .. 1e-8")
    ax.legend(fontsize=7, ncol=3, loc="upper left")
    fig.tight_layout()
    fig.savefig(img / f"baselines-ecdf-d{dim}.png", dpi=100)
    plt.close(fig)


# ---------------------------------------------------------------------------------------------

def check(data=DATA, page=PAGE):
    text = page.read_text()
    have, want = rp.page_blocks(text), blocks(data)
    return [(n, want.get(n), have.get(n)) for n in sorted(set(have) | set(want)) if want.get(n) != have.get(n)]


def write_page():
    PAGE.write_text(rp.replace_blocks(PAGE.read_text(), blocks()))


def export_jso(folder):
    """jSO's published summary beside the rank-sum test of pride's runs against the published ones
    (only the functions whose runs are all in), to data/jso-published-cec2017.csv."""
    raw = export_jso_published(folder)
    ours = read_cec("jso-cec2017")
    keys = sorted(k for k in raw if len(ours.get((k[0], k[1], "jso"), [])) == len(raw[k]))
    ps = [rp.rank_sum([snap(v) for v in raw[k]], [as_published(e) for e in ours[(k[0], k[1], "jso")]]) for k in keys]
    adj = rp.holm(ps)
    with open(DATA / "jso-published-cec2017.csv", "w", newline="") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(["function", "dimension", "runs", "best", "median", "mean", "std", "worst", "p", "p_holm"])
        tested = {k: (f"{p:.3g}", f"{q:.3g}") for k, p, q in zip(keys, ps, adj)}
        for k in sorted(raw):
            v = [snap(x) for x in raw[k]]
            p, q = tested.get(k, ("", ""))
            w.writerow([k[0], k[1], len(v), repr(min(v)), repr(rp.median(v)), repr(rp.mean(v)), repr(rp.stdev(v)),
                        repr(max(v)), p, q])


def run(build, stores, jobs):
    pride = build / "cli" / "pride"
    stores.mkdir(parents=True, exist_ok=True)
    IMG.mkdir(parents=True, exist_ok=True)
    for name in ("baselines-bbob", "baselines-cec2017", "lshade-cec2022", "jso-cec2017"):
        store = stores / f"{name}.sqlite"
        rp.run([pride, "bench", CAMPAIGNS / f"{name}.toml", "--jobs", jobs, "--out", store], cwd=REPO)
    export_bbob(stores / "baselines-bbob.sqlite", pride)
    export_cec("baselines-cec2017", stores / "baselines-cec2017.sqlite", pride)
    export_cec("lshade-cec2022", stores / "lshade-cec2022.sqlite", pride)
    export_cec("jso-cec2017", stores / "jso-cec2017.sqlite", pride)
    export_jso(os.environ["PRIDE_JSO_RESULTS"])
    for d in DIMS:
        ecdf_figure(d)
    write_page()


def main(argv):
    args = list(argv)
    mode = args.pop(0) if args and args[0] in ("run", "render", "check") else "run"
    opts = {"--build": "build", "--stores": None, "--jobs": "2"}
    while args:
        k = args.pop(0)
        if k not in opts or not args:
            raise SystemExit(__doc__)
        opts[k] = args.pop(0)
    if mode == "render":
        write_page()
    elif mode == "check":
        bad = check()
        for name, _, got in bad:
            print(f"docs/results/baselines.md: block {name} {'is missing' if got is None else 'differs from its data'}")
        return 1 if bad else 0
    else:
        build = pathlib.Path(opts["--build"])
        build = build if build.is_absolute() else REPO / build
        stores = pathlib.Path(opts["--stores"]) if opts["--stores"] else build / "results"
        run(build, stores, opts["--jobs"])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
