#!/usr/bin/env python3
"""Regenerates docs/results/constraints.md from its runs, or checks it.

    /usr/bin/python3 scripts/constraints_page.py [--pride PATH] run [cec2006 | bbob-constrained]
        runs examples/campaigns/cec2006-handlers.toml and bbob-constrained-handlers.toml (or the one
        named; `pride bench --jobs 2` into a temporary store, PATH or build/cli/pride), writes each
        run's final best, violation and first feasible evaluation to
        docs/results/data/cec2006-handlers.csv and bbob-constrained-handlers.csv, then the page.
        About 10 min (CEC 2006) and 4 min (bbob-constrained) on two cores.
    /usr/bin/python3 scripts/constraints_page.py render
        rewrites the page's generated blocks from the data alone.
    /usr/bin/python3 scripts/constraints_page.py check
        exits 1 when a generated block differs from what the data give
        (python/tests/test_constraints_page.py does the same under ctest).

Every handler each algorithm takes, on the same algorithm: DE, CMA-ES and the GA on CEC 2006's 24
problems and on COCO's bbob-constrained suite (54 functions, D = 5, instances 1-15), runs compared
in the CEC 2020 guidelines' order (feasible by f, or by f - f_opt on bbob-constrained, then
infeasible by violation), each handler against the same algorithm with Deb's rules by the rank-sum
test of results_pages.py, Holm's correction over every comparison of a section.
"""
import csv
import pathlib
import re
import sqlite3
import subprocess
import sys
import tempfile

REPO = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "scripts"))
import results_pages as rp  # noqa: E402

PAGE = REPO / "docs" / "results" / "constraints.md"
DATA = REPO / "docs" / "results" / "data"
CAMPAIGN = REPO / "examples" / "campaigns" / "cec2006-handlers.toml"
CSV = "cec2006-handlers.csv"
BBOB_CAMPAIGN = REPO / "examples" / "campaigns" / "bbob-constrained-handlers.toml"
BBOB_CSV = "bbob-constrained-handlers.csv"
# COCO's final target: precisions below it are one value, else the last digits of f - f_opt (f_opt
# about 10^3 on many functions) would rank runs by rounding.
FINAL_TARGET = 1e-8


def configs(campaign=CAMPAIGN):
    """(algorithm id, algorithm, handler) in the campaign's order."""
    text = campaign.read_text()
    return re.findall(r'\[\[algorithm\]\]\nid = "([^"]+)"\ntype = "([^"]+)"\nconstraints = "([^"]+)"', text)


def problems():
    return re.findall(r'\[\[problem\]\]\nid = "([^"]+)"', CAMPAIGN.read_text())


def bbob_suite():
    """(functions, instances, dimension) of the bbob-constrained campaign's suite."""
    text = BBOB_CAMPAIGN.read_text()

    def ints(k):
        return [int(x) for x in re.search(rf"^{k} = \[([^\]]*)\]", text, re.M).group(1).split(",")]

    (dim,) = ints("dimensions")
    return ints("functions"), ints("instances"), dim


def bbob_budget():
    per_dim = int(re.search(r"^evaluations_per_dim = (\d+)", BBOB_CAMPAIGN.read_text(), re.M).group(1))
    return per_dim, per_dim * bbob_suite()[2]


def bench(pride, campaign, store):
    subprocess.run([str(pride), "bench", str(campaign), "--out", str(store), "--jobs", "2"], check=True)


def run_all(pride=REPO / "build" / "cli" / "pride", sections=("cec2006", "bbob-constrained")):
    with tempfile.TemporaryDirectory() as tmp:
        if "cec2006" in sections:
            bench(pride, CAMPAIGN, pathlib.Path(tmp) / "h.sqlite")
            export(pathlib.Path(tmp) / "h.sqlite")
        if "bbob-constrained" in sections:
            bench(pride, BBOB_CAMPAIGN, pathlib.Path(tmp) / "b.sqlite")
            export_bbob(pathlib.Path(tmp) / "b.sqlite")


def export(store):
    """The compact CSV of the campaign's store, in the campaign's order of problems and algorithms."""
    db = sqlite3.connect(f"file:{store}?mode=ro", uri=True)
    rows = db.execute("SELECT problem, algorithm, seed, best, best_violation, first_feasible FROM runs").fetchall()
    db.close()
    order_p = problems()
    order_a = [c[0] for c in configs()]
    rows.sort(key=lambda r: (order_p.index(r[0]), order_a.index(r[1]), r[2]))
    with open(DATA / CSV, "w", newline="") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(["problem", "algorithm", "seed", "f", "violation", "first_feasible"])
        for p, a, seed, f, v, first in rows:
            w.writerow([p, a, seed, repr(float(f)), repr(float(v)), "" if first is None else first])


def export_bbob(store):
    """The compact CSV of the bbob-constrained store: each run's final best as its precision f - f_opt
    (f_opt from the store's problems), in the order function, instance, algorithm."""
    db = sqlite3.connect(f"file:{store}?mode=ro", uri=True)
    rows = db.execute("SELECT p.fid, p.instance, r.algorithm, r.seed, r.best, p.f_opt, r.best_violation, "
                      "r.first_feasible FROM runs r JOIN problems p ON p.id = r.problem").fetchall()
    db.close()
    order_a = [c[0] for c in configs(BBOB_CAMPAIGN)]
    rows.sort(key=lambda r: (r[0], r[1], order_a.index(r[2]), r[3]))
    with open(DATA / BBOB_CSV, "w", newline="") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(["function", "instance", "algorithm", "seed", "precision", "violation", "first_feasible"])
        for fid, inst, a, seed, f, f_opt, v, first in rows:
            w.writerow([fid, inst, a, seed, repr(float(f) - float(f_opt)), repr(float(v)),
                        "" if first is None else first])


def read(data=DATA):
    """{(problem, algorithm id): [(f, violation)] in seed order}."""
    out = {}
    with open(data / CSV, newline="") as fh:
        for r in csv.DictReader(fh):
            out.setdefault((r["problem"], r["algorithm"]), []).append((float(r["f"]), float(r["violation"])))
    return out


def read_bbob(data=DATA):
    """{("fN", algorithm id): [(precision, violation)] in instance order}."""
    out = {}
    with open(data / BBOB_CSV, newline="") as fh:
        for r in csv.DictReader(fh):
            out.setdefault((f"f{r['function']}", r["algorithm"]), []).append(
                (float(r["precision"]), float(r["violation"])))
    return out


def bbob_functions():
    return [f"f{n}" for n in bbob_suite()[0]]


def key(run):
    f, v = run
    return (v, 0.0) if v > 0 else (0.0, f)


def bbob_key(run):
    f, v = run
    return (v, 0.0) if v > 0 else (0.0, max(f, FINAL_TARGET))


def median_cell(runs):
    """The guidelines' median run (the 13th of 25 in their order): its f, or its violation."""
    f, v = sorted(runs, key=key)[(len(runs) - 1) // 2]
    return f"{f:.6g}" if v == 0 else f"nu {v:.2g}"


def bbob_median_cell(runs):
    """The median run (the 8th of 15) in the guidelines' order: its precision, or its violation."""
    f, v = sorted(runs, key=bbob_key)[(len(runs) - 1) // 2]
    if v > 0:
        return f"nu {v:.2g}"
    return "< 1e-8" if f < FINAL_TARGET else f"{f:.2g}"


def comparisons(runs, units=None, campaign=CAMPAIGN, order=key):
    """[(algorithm, handler id, problem, p, sign)] of each handler against its algorithm's deb."""
    out = []
    for cid, algo, handler in configs(campaign):
        if handler == "deb":
            continue
        base = f"{algo}-deb"
        for p in units or problems():
            a, b = runs[(p, cid)], runs[(p, base)]
            ranks = rp.average_ranks([order(r) for r in a + b])
            pa, pb = ranks[:len(a)], ranks[len(a):]
            out.append((algo, cid, p, rp.rank_sum(pa, pb), rp.mean(pa) < rp.mean(pb)))
    return out


def feasible_block(runs, units=None, campaign=CAMPAIGN, head="problem"):
    ids = [c[0] for c in configs(campaign)]
    rows = [[p] + [sum(v == 0 for _, v in runs[(p, c)]) for c in ids] for p in units or problems()]
    return rp.table([head] + ids, rows, "l" + "r" * len(ids))


def median_block(runs, units=None, campaign=CAMPAIGN, head="problem", cell=median_cell):
    ids = [c[0] for c in configs(campaign)]
    rows = [[p] + [cell(runs[(p, c)]) for c in ids] for p in units or problems()]
    return rp.table([head] + ids, rows, "l" + "r" * len(ids))


def tests_block(runs, units=None, campaign=CAMPAIGN, order=key):
    units = units or problems()
    tests = comparisons(runs, units, campaign, order)
    adjusted = rp.holm([t[3] for t in tests])
    summary = {}
    for (algo, cid, _, _, better), q in zip(tests, adjusted):
        s = summary.setdefault(cid, [algo, 0, 0])
        if q < 0.05:
            s[1 if better else 2] += 1
    rows = [[cid, f"{algo}-deb", b, w, len(units) - b - w] for cid, (algo, b, w) in summary.items()]
    detail = []
    for (algo, cid, p, pv, better), q in zip(tests, adjusted):
        if q < 0.05:
            detail.append(f"{p} {cid} {'better' if better else 'worse'} (Holm p {rp.fmt_p(q)})")
    return (f"{len(tests)} comparisons, Holm-adjusted p < 0.05 counted:\n\n" +
            rp.table(["handler", "against", "better", "worse", "not told apart"], rows, "llrrr") +
            "\n\nTold apart: " + ("; ".join(detail) if detail else "none") + ".")


def blocks(data=DATA):
    runs = read(data)
    seeds = {len(v) for v in runs.values()}
    b = bbob_blocks(data)
    return {
        "ch-runs": f"{sum(len(v) for v in runs.values()):,} runs: {len(problems())} problems x {len(configs())} "
                   f"configurations x {', '.join(map(str, sorted(seeds)))} seeds, 50,000 evaluations each.",
        "ch-feasible": feasible_block(runs),
        "ch-median": median_block(runs),
        "ch-tests": tests_block(runs),
        **b,
    }


def bbob_blocks(data=DATA):
    runs = read_bbob(data)
    functions, instances, dim = bbob_suite()
    units = bbob_functions()
    per_dim, budget = bbob_budget()
    runs_each = {len(v) for v in runs.values()}
    c = BBOB_CAMPAIGN
    return {
        "cb-runs": f"{sum(len(v) for v in runs.values()):,} runs: {len(functions)} functions x "
                   f"{', '.join(map(str, sorted(runs_each)))} instances ({instances[0]}-{instances[-1]}, one run "
                   f"each) x {len(configs(c))} configurations, D = {dim}, {budget:,} evaluations "
                   f"({per_dim:,} x D) each.",
        "cb-feasible": feasible_block(runs, units, c, "function"),
        "cb-median": median_block(runs, units, c, "function", bbob_median_cell),
        "cb-tests": tests_block(runs, units, c, bbob_key),
    }


def check(data=DATA, page=PAGE):
    return rp.check_page(blocks(data), page)


def main(argv):
    """`--pride PATH` (before the mode) runs that executable instead of build/cli/pride; `run
    SECTION` runs one section's campaign only."""
    pride = REPO / "build" / "cli" / "pride"
    if len(argv) > 2 and argv[1] == "--pride":
        pride = pathlib.Path(argv[2]).resolve()
        argv = argv[:1] + argv[3:]
    if len(argv) == 3 and argv[1] == "run" and argv[2] in ("cec2006", "bbob-constrained"):
        run_all(pride, (argv[2],))
        PAGE.write_text(rp.replace_blocks(PAGE.read_text(), blocks()))
        return 0
    return rp.page_main(argv, __doc__, lambda: run_all(pride), blocks, PAGE)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
