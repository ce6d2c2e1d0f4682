#!/usr/bin/env python3
"""Regenerates docs/results/constraints.md from its runs, or checks it.

    /usr/bin/python3 scripts/constraints_page.py run
        runs examples/campaigns/cec2006-handlers.toml (`pride bench --jobs 2` into a temporary
        store), writes each run's final best f, violation and first feasible evaluation to
        docs/results/data/cec2006-handlers.csv, then the page. About 10 min on two cores.
    /usr/bin/python3 scripts/constraints_page.py render
        rewrites the page's generated blocks from the data alone.
    /usr/bin/python3 scripts/constraints_page.py check
        exits 1 when a generated block differs from what the data give
        (python/tests/test_constraints_page.py does the same under ctest).

Every handler each algorithm takes, on the same algorithm: DE, CMA-ES and the GA on CEC 2006's 24
problems, runs compared in the CEC 2020 guidelines' order (feasible by f, then infeasible by
violation), each handler against the same algorithm with Deb's rules by the rank-sum test of
results_pages.py, Holm's correction over every comparison of the page.
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


def configs():
    """(algorithm id, algorithm, handler) in the campaign's order."""
    text = CAMPAIGN.read_text()
    return re.findall(r'\[\[algorithm\]\]\nid = "([^"]+)"\ntype = "([^"]+)"\nconstraints = "([^"]+)"', text)


def problems():
    return re.findall(r'\[\[problem\]\]\nid = "([^"]+)"', CAMPAIGN.read_text())


def run_all(pride=REPO / "build" / "cli" / "pride"):
    with tempfile.TemporaryDirectory() as tmp:
        store = pathlib.Path(tmp) / "h.sqlite"
        subprocess.run([str(pride), "bench", str(CAMPAIGN), "--out", str(store), "--jobs", "2"], check=True)
        export(store)


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


def read(data=DATA):
    """{(problem, algorithm id): [(f, violation)] in seed order}."""
    out = {}
    with open(data / CSV, newline="") as fh:
        for r in csv.DictReader(fh):
            out.setdefault((r["problem"], r["algorithm"]), []).append((float(r["f"]), float(r["violation"])))
    return out


def key(run):
    f, v = run
    return (v, 0.0) if v > 0 else (0.0, f)


def median_cell(runs):
    """The guidelines' median run (the 13th of 25 in their order): its f, or its violation."""
    f, v = sorted(runs, key=key)[(len(runs) - 1) // 2]
    return f"{f:.6g}" if v == 0 else f"nu {v:.2g}"


def comparisons(runs):
    """[(algorithm, handler id, problem, p, sign)] of each handler against its algorithm's deb."""
    out = []
    for cid, algo, handler in configs():
        if handler == "deb":
            continue
        base = f"{algo}-deb"
        for p in problems():
            a, b = runs[(p, cid)], runs[(p, base)]
            ranks = rp.average_ranks([key(r) for r in a + b])
            pa, pb = ranks[:len(a)], ranks[len(a):]
            out.append((algo, cid, p, rp.rank_sum(pa, pb), rp.mean(pa) < rp.mean(pb)))
    return out


def feasible_block(runs):
    ids = [c[0] for c in configs()]
    rows = [[p] + [sum(v == 0 for _, v in runs[(p, c)]) for c in ids] for p in problems()]
    return rp.table(["problem"] + ids, rows, "l" + "r" * len(ids))


def median_block(runs):
    ids = [c[0] for c in configs()]
    rows = [[p] + [median_cell(runs[(p, c)]) for c in ids] for p in problems()]
    return rp.table(["problem"] + ids, rows, "l" + "r" * len(ids))


def tests_block(runs):
    tests = comparisons(runs)
    adjusted = rp.holm([t[3] for t in tests])
    summary = {}
    for (algo, cid, _, _, better), q in zip(tests, adjusted):
        s = summary.setdefault(cid, [algo, 0, 0])
        if q < 0.05:
            s[1 if better else 2] += 1
    rows = [[cid, f"{algo}-deb", b, w, len(problems()) - b - w] for cid, (algo, b, w) in summary.items()]
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
    return {
        "ch-runs": f"{sum(len(v) for v in runs.values()):,} runs: {len(problems())} problems x {len(configs())} "
                   f"configurations x {', '.join(map(str, sorted(seeds)))} seeds, 50,000 evaluations each.",
        "ch-feasible": feasible_block(runs),
        "ch-median": median_block(runs),
        "ch-tests": tests_block(runs),
    }


def check(data=DATA, page=PAGE):
    return rp.check_page(blocks(data), page)


if __name__ == "__main__":
    sys.exit(rp.page_main(sys.argv, __doc__, run_all, blocks, PAGE))
