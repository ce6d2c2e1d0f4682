#!/usr/bin/env python3
"""Regenerates docs/results/cec2020rw.md from its runs, or checks it.

    PRIDE_DATA=... PYTHONPATH=build/python /usr/bin/python3 scripts/cec2020rw_page.py run
        runs every configuration of CONFIGS on every CEC 2020 real-world problem pride has, at the
        competition's budgets with seeds 1-25 (`pride run`, two at a time), writes the final best
        f, violation and first feasible evaluation of each run to docs/results/data/cec2020rw.csv,
        then the page. Runs already in that file are kept, not run again (delete it to run them
        all: about 80 min per configuration on two cores).
    PRIDE_DATA=... PYTHONPATH=build/python /usr/bin/python3 scripts/cec2020rw_page.py render
        rewrites the page's generated blocks from the data and the entrants' published results.
    PRIDE_DATA=... PYTHONPATH=build/python /usr/bin/python3 scripts/cec2020rw_page.py check
        exits 1 when a generated block differs from what they give (python/tests/test_cec2020rw_page.py
        does the same under ctest).

The published results are the eight entrants' workbooks of the competition ($PRIDE_DATA/
cec2020-rw-results/ranking/*.xlsx: Sheet1 the final f, Sheet2 the violation, 25 runs x 57
problems) and its scores (Scoring.txt), read where they are, never copied. The scoring is
pride's (pride.cec2020rw_score, experiment/report/cec2020rw_score.hpp: the guidelines' eq. 4-9, as
the organisers' ranking script Score.m computes them).
"""
import csv
import json
import os
import pathlib
import re
import subprocess
import sys
import threading
import xml.etree.ElementTree as ET
import zipfile
from concurrent.futures import ThreadPoolExecutor

REPO = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "scripts"))
import results_pages as rp  # noqa: E402

PAGE = REPO / "docs" / "results" / "cec2020rw.md"
DATA = REPO / "docs" / "results" / "data"
RUNS = 25
# label -> `pride run` arguments: pride's configurations on the page.
CONFIGS = {
    "colshade": ["--algo", "colshade"],
    "colshade-paper": ["--algo", "colshade", "--param", "reading=paper"],
}
# The entrants' workbooks, by the names the competition's repository gives them.
ENTRANTS = ["BiPop", "COLSHADE", "DEQL", "EnMODE", "FCHA", "SASS", "VMCH", "sCMAgES"]
# Scoring.txt's code of each workbook: the organisers' ranking script (Score.m, in "Code used For
# Ranking.zip" of P-N-Suganthan/2020-RW-Constrained-Optimisation) reads the workbooks in the order
# VMCH, sCMAgES, SASS, EnMODE, COLSHADE, BiPop, FCHA, DEQL and prints these codes in the same order.
CODES = {"VMCH": "E24594", "sCMAgES": "COM108", "SASS": "COM109", "EnMODE": "E24363", "COLSHADE": "E24586",
         "BiPop": "E24443", "FCHA": "E24191", "DEQL": "E24537"}
# The 57 problems' dimensions (the guidelines' Table 4).
DIMS = [9, 11, 7, 6, 9, 38, 48, 2, 3, 3, 7, 7, 5, 10, 7, 14, 3, 4, 4, 2, 5, 9, 5, 7, 4, 22, 10, 10, 4, 3, 4, 5, 30,
        118, 153, 158, 126, 126, 126, 76, 74, 86, 86, 30, 25, 25, 25, 30, 30, 30, 59, 59, 59, 59, 64, 64, 64]
MISSING = set()  # problems pride does not have (none)
SHEET = {"m": "http://schemas.openxmlformats.org/spreadsheetml/2006/main"}


def budget(dim):
    """MaxFEs, the guidelines' eq. 1."""
    return 100000 if dim <= 10 else 200000 if dim <= 30 else 400000 if dim <= 50 else 800000 if dim <= 150 else 1000000


def results_folder():
    data = os.environ.get("PRIDE_DATA", "")
    folder = pathlib.Path(data) / "cec2020-rw-results" / "ranking"
    return folder if data and (folder / "Scoring.txt").is_file() else None


def workbook_sheet(path, number):
    """The 25 x 57 values of one sheet, runs by problems (an .xlsx is zipped XML; cells A1 .. BE25).
    A text cell (one workbook writes "nan" where it has no result) is NaN, as MATLAB's xlsread,
    which the competition's script used, reads it; an empty cell is NaN too."""
    book = zipfile.ZipFile(path)
    rows = []
    for row in ET.fromstring(book.read(f"xl/worksheets/sheet{number}.xml")).find("m:sheetData", SHEET):
        values = [float("nan")] * 57
        for cell in row:
            column = 0
            for letter in re.match(r"[A-Z]+", cell.get("r")).group(0):
                column = column * 26 + ord(letter) - 64
            v = cell.find("m:v", SHEET)
            # t="s" (a shared string), "str" or "inlineStr": text; no t or t="n": a number.
            if v is not None and column <= 57 and cell.get("t", "n") == "n":
                values[column - 1] = float(v.text)
        rows.append(values)
    return rows


def entrant(folder, name):
    """(f, violation) of a workbook, each a list of 57 rows (problems) of 25 runs."""
    f, v = (workbook_sheet(folder / f"{name}.xlsx", k) for k in (1, 2))
    return [[r[j] for r in f] for j in range(57)], [[r[j] for r in v] for j in range(57)]


def published_scores(folder):
    """Scoring.txt's rows: [(code, score1, score2, score3, total, rank)]."""
    rows = []
    for line in (folder / "Scoring.txt").read_text().splitlines():
        m = re.match(r"\s*(\w+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)\s+(\d+)\s*$", line)
        if m:
            rows.append((m.group(1), *map(float, m.groups()[1:5]), int(m.group(6))))
    return rows


def run_all(pride=REPO / "build" / "cli" / "pride", jobs=2):
    listed = json.loads(subprocess.check_output([str(pride), "list", "--json"], text=True))["constrained_problems"]
    problems = sorted(int(m.group(1)) for m in (re.match(r"cec2020rw-rc(\d+)$", p["name"]) for p in listed) if m)
    assert set(range(1, 58)) - set(problems) == MISSING, problems
    todo = [(label, k, s) for label in CONFIGS for k in problems for s in range(1, RUNS + 1)]
    header = ["config", "problem", "seed", "f", "violation", "first_feasible", "evaluations"]
    # Rows already made: the data file's, and those of an interrupted run (appended one by one to
    # the .partial file, so that a stopped run resumes where it was).
    done = {}
    partial = DATA / "cec2020rw.csv.partial"
    for path in (DATA / "cec2020rw.csv", partial):
        if path.is_file():
            with open(path, newline="") as fh:
                for r in csv.DictReader(fh):
                    done[(r["config"], int(r["problem"][2:]), int(r["seed"]))] = (
                        float(r["f"]), float(r["violation"]),
                        int(r["first_feasible"]) if r["first_feasible"] else None, int(r["evaluations"]))
    if not partial.is_file():
        partial.write_text(",".join(header) + "\n")
    lock = threading.Lock()

    def row(job, result):
        (label, k, seed), (f, v, first, evals) = job, result
        return [label, f"RC{k:02}", seed, repr(float(f)), repr(float(v)), "" if first is None else first, evals]

    def run(job):
        label, k, seed = job
        if job in done:
            return done[job]
        out = subprocess.check_output([str(pride), "run", *CONFIGS[label], "--problem", f"cec2020rw-rc{k:02}",
                                       "--dim", str(DIMS[k - 1]), "--evals", str(budget(DIMS[k - 1])), "--seed",
                                       str(seed), "--json"], text=True)
        r = json.loads(out)
        result = r["best_f"], r["best_violation"], r["first_feasible"], r["evaluations"]
        with lock, open(partial, "a", newline="") as fh:
            csv.writer(fh, lineterminator="\n").writerow(row(job, result))
        return result

    with ThreadPoolExecutor(jobs) as pool:
        results = list(pool.map(run, todo))
    written = DATA / "cec2020rw.csv.tmp"
    with open(written, "w", newline="") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(header)
        for job, result in zip(todo, results):
            w.writerow(row(job, result))
    written.replace(DATA / "cec2020rw.csv")
    partial.unlink()


def read(data=DATA):
    """{config: (f, violation)} as 57 lists (problems; RC24's empty) of RUNS runs, in seed order."""
    out = {}
    with open(data / "cec2020rw.csv", newline="") as fh:
        for r in csv.DictReader(fh):
            f, v = out.setdefault(r["config"], ([[] for _ in range(57)], [[] for _ in range(57)]))
            j = int(r["problem"][2:]) - 1
            f[j].append(float(r["f"]))
            v[j].append(float(r["violation"]))
    return out


def deb_ranks(f, v):
    """Average ranks in the guidelines' order (feasible by f, then infeasible by violation)."""
    return rp.average_ranks([(vi if vi > 0 else 0.0, fi if vi <= 0 else 0.0) for fi, vi in zip(f, v)])


def eight_digits(values):
    return [float(f"{x:.8g}") for x in values]


def score(pride, results, problems):
    """PM of `results` {name: (f, violation)} on `problems`, each run list taken in the order given,
    as the competition's script reads the workbooks (rows 1 and 13: best and median)."""
    return pride.cec2020rw_score({n: ([f[j] for j in problems], [v[j] for j in problems])
                                  for n, (f, v) in results.items()}, [DIMS[j] for j in problems], order="given")


def in_guidelines_order(runs):
    """pride's runs (seed order) sorted as the entrants sorted their workbooks: the guidelines' order."""
    f, v = runs
    out = ([], [])
    for j in range(57):
        pairs = sorted(zip(f[j], v[j]), key=lambda p: (p[1] != 0, p[0] if p[1] == 0 else p[1]))
        out[0].append([p[0] for p in pairs])
        out[1].append([p[1] for p in pairs])
    return out


def published_block(pride, folder):
    """The eight entrants scored by pride from their workbooks, beside Scoring.txt's rows."""
    books = {n: entrant(folder, n) for n in ENTRANTS}
    ours = score(pride, books, range(57))
    theirs = {row[0]: row for row in published_scores(folder)}
    rows = []
    for n, s in sorted(ours.items(), key=lambda kv: kv[1]["total"]):
        _, a, b, c, t, rank = theirs[CODES[n]]
        rows.append([n, f"{s['best']:.4f}", f"{s['mean']:.4f}", f"{s['median']:.4f}", f"{s['total']:.4f}", s["rank"],
                     CODES[n], f"{a:.4f}", f"{b:.4f}", f"{c:.4f}", f"{t:.4f}", rank])
    return rp.table(["entrant", "best", "mean", "median", "PM", "rank", "code", "best", "mean", "median", "PM",
                     "rank"], rows, "lrrrrrlrrrrr")


def score_block(pride, folder, runs):
    problems = [j for j in range(57) if j + 1 not in MISSING]
    results = {n: entrant(folder, n) for n in ENTRANTS}
    results.update({f"pride {label}": in_guidelines_order(fv) for label, fv in runs.items()})
    s = score(pride, results, problems)
    rows = [[n, f"{x['best']:.4f}", f"{x['mean']:.4f}", f"{x['median']:.4f}", f"{x['total']:.4f}", x["rank"]]
            for n, x in sorted(s.items(), key=lambda kv: (kv[1]["total"], kv[0]))]
    return rp.table(["algorithm", "best", "mean", "median", "PM", "rank"], rows, "lrrrrr")


def colshade_block(folder, runs, labels=("colshade", "colshade-paper")):
    """pride's colshade readings beside the published COLSHADE, problem by problem: rank-sum tests
    on the guidelines' order, Holm's correction over the problems, for each reading apart."""
    pf, pv = entrant(folder, "COLSHADE")
    labels = [label for label in labels if label in runs]
    problems = [j for j in range(57) if j + 1 not in MISSING]

    def median(f, v):
        feasible = [x for x, y in zip(f, v) if y <= 0]
        return f"{rp.median(feasible):.8g}" if feasible else "-"

    columns = {}
    summaries = []
    for label in labels:
        of, ov = runs[label]
        ranks = [deb_ranks(pf[j] + eight_digits(of[j]), pv[j] + ov[j]) for j in problems]
        ps = [rp.rank_sum(r[:len(pf[j])], r[len(pf[j]):]) for j, r in zip(problems, ranks)]
        apart = better = 0
        cells = []
        for j, r, q in zip(problems, ranks, rp.holm(ps)):
            ours = rp.mean(r[len(pf[j]):]) < rp.mean(r[:len(pf[j])])
            apart += q < 0.05
            better += q < 0.05 and ours
            cells.append([f"{sum(y <= 0 for y in ov[j])}/{len(ov[j])}", median(of[j], ov[j]), rp.fmt_p(q),
                          ("better" if ours else "worse") if q < 0.05 else ""])
        columns[label] = cells
        summaries.append(f"pride {label}: told apart (Holm-adjusted p < 0.05) on {apart} of {len(problems)} "
                         f"problems ({better} with pride better); not told apart on {len(problems) - apart}.")
    rows = []
    for i, j in enumerate(problems):
        rows.append([f"RC{j + 1:02}", DIMS[j], f"{budget(DIMS[j]):,}", f"{sum(y <= 0 for y in pv[j])}/{len(pv[j])}",
                     median(pf[j], pv[j])] + [c for label in labels for c in columns[label][i]])
    head = ["problem", "D", "MaxFEs", "published: feasible", "median f"]
    for label in labels:
        head += [f"{label}: feasible", "median f", "Holm p", ""]
    return "\n".join(f"- {line}" for line in summaries) + "\n\n" + rp.table(
        head, rows, "lrrrr" + "rrrl" * len(labels))


def blocks(data=DATA):
    folder = results_folder()
    if folder is None:
        raise SystemExit("cec2020rw_page: the entrants' results are not at $PRIDE_DATA/cec2020-rw-results (set PRIDE_DATA)")
    import pride
    runs = read(data)
    count = sum(len(f[j]) for f, _ in runs.values() for j in range(57))
    return {
        "rw-runs": f"{count:,} runs of pride: {', '.join(runs)} on the {57 - len(MISSING)} problems pride has, "
                   f"seeds 1-{RUNS}, each at the competition's MaxFEs.",
        "rw-published": published_block(pride, folder),
        "rw-score": score_block(pride, folder, runs),
        "rw-colshade": colshade_block(folder, runs),
    }


def check(data=DATA, page=PAGE):
    return rp.check_page(blocks(data), page)


if __name__ == "__main__":
    sys.exit(rp.page_main(sys.argv, __doc__, run_all, blocks, PAGE))
