"""pride's colshade on the CEC 2020 real-world constrained problems beside the published COLSHADE
runs (Gurrola-Ramos et al. 2020; the competition's workbook, $PRIDE_DATA/cec2020-rw-results/
ranking/COLSHADE.xlsx: 25 runs per problem, Sheet1 the final f, Sheet2 the violation).

Each problem runs at the competition's budget (the guidelines' eq. 1: 1e5 evaluations for D <= 10,
2e5 for D <= 30, 4e5 for D <= 50, 8e5 for D <= 150, 1e6 above) with seeds 1..runs. The workbook
holds 8 significant digits, so pride's f is compared at that precision. Both samples are put in
Deb's order (feasible points by f, then infeasible ones by violation; equal keys share their mean
rank) and the ranks compared by a two-sided Mann-Whitney U test per problem (scipy), without a
correction over the problems: a correction could only make fewer problems told apart.

Usage (from the top of the checkout, after building; about 25 min for 25 runs on 2 cores):
    PRIDE_DATA=... /usr/bin/python3 bench/colshade_cec2020rw.py [--runs 25] [--jobs 2] [--problems 1,15]
Prints one row per problem and a summary; exits 0 (a benchmark states, it does not fail), or 2
with one line when the data or the program is missing.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np
from scipy.stats import mannwhitneyu

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts"))
from cec2020rw_page import budget, deb_ranks, eight_digits, workbook_sheet  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--runs", type=int, default=25)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--problems", default="", help="comma-separated numbers (default: every one pride has)")
    parser.add_argument("--pride", default="build/cli/pride")
    args = parser.parse_args()
    data = os.environ.get("PRIDE_DATA", "")
    book = os.path.join(data, "cec2020-rw-results", "ranking", "COLSHADE.xlsx")
    if not data or not os.path.isfile(book):
        sys.exit(print(f"colshade_cec2020rw: no published runs at '{book}' (set PRIDE_DATA)", file=sys.stderr) or 2)
    if not os.access(args.pride, os.X_OK):
        sys.exit(print(f"colshade_cec2020rw: --pride '{args.pride}' is not a program", file=sys.stderr) or 2)

    listed = json.loads(subprocess.check_output([args.pride, "list", "--json"], text=True))["constrained_problems"]
    problems = []
    for item in listed:
        m = re.match(r"cec2020rw-rc(\d+)$", item["name"])
        if m:
            problems.append((int(m.group(1)), int(re.search(r"\(dim = (\d+)\)", item["summary"]).group(1))))
    wanted = {int(p) for p in args.problems.split(",") if p}
    problems = [p for p in problems if not wanted or p[0] in wanted]

    def run(job):
        k, dim, seed = job
        out = subprocess.check_output([args.pride, "run", "--algo", "colshade", "--problem", f"cec2020rw-rc{k:02}",
                                       "--dim", str(dim), "--evals", str(budget(dim)), "--seed", str(seed), "--json"],
                                      text=True)
        r = json.loads(out)
        return r["best_f"], r["best_violation"], r["wall_ms"]

    jobs = [(k, dim, s) for k, dim in problems for s in range(1, args.runs + 1)]
    start = time.time()
    with ThreadPoolExecutor(args.jobs) as pool:
        results = dict(zip(jobs, pool.map(run, jobs)))

    published_f, published_v = np.array(workbook_sheet(book, 1)), np.array(workbook_sheet(book, 2))
    print("| problem | D | evaluations | published: feasible, median f | pride: feasible, median f | p | |")
    print("|---|---:|---:|---|---|---:|---|")
    apart = better = 0
    for k, dim in problems:
        pf, pv = published_f[:, k - 1], published_v[:, k - 1]
        of = np.array(eight_digits([results[(k, dim, s)][0] for s in range(1, args.runs + 1)]))
        ov = np.array([results[(k, dim, s)][1] for s in range(1, args.runs + 1)])
        ranks = np.array(deb_ranks(list(np.concatenate([pf, of])), list(np.concatenate([pv, ov]))))
        ours, theirs = ranks[len(pf):], ranks[:len(pf)]
        p = 1.0 if np.all(ranks == ranks[0]) else mannwhitneyu(theirs, ours, alternative="two-sided").pvalue
        verdict = ""
        if p < 0.05:
            apart += 1
            better += ours.mean() < theirs.mean()
            verdict = "pride better" if ours.mean() < theirs.mean() else "pride worse"

        def median(f, v):
            return f"{np.median(f[v <= 0]):.8g}" if np.any(v <= 0) else "-"

        print(f"| RC{k:02} | {dim} | {budget(dim)} | {np.sum(pv <= 0)}/{len(pv)}, {median(pf, pv)} | "
              f"{np.sum(ov <= 0)}/{args.runs}, {median(of, ov)} | {p:.3g} | {verdict} |")
    print(f"\nnot told apart (p >= 0.05): {len(problems) - apart} of {len(problems)}; told apart: {apart} "
          f"({better} with pride better); {args.runs} runs each; {time.time() - start:.0f} s")


if __name__ == "__main__":
    main()
