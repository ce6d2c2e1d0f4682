#!/usr/bin/env python3
"""pride's lshade against the official L-SHADE on CEC 2022 (docs/results/data/lshade-official-cec2022.csv):
the same functions, dimension and budget as the official driver (D = 10: 200,000 evaluations; D = 20:
1,000,000), 30 seeds each; per function the median and mean error f - F* of both and the two-sided
Mann-Whitney U test's p value (normal approximation with the tie correction; no SciPy needed). A
sanity check, not the statistical study. Needs the official data folder (input_data of the CEC 2022
package) for pride's cec2022-fN.

Usage: scripts/lshade_cec2022_check.py DATA_FOLDER [--pride build/cli/pride] [--dim 10] [--reading code]"""
import argparse
import csv
import json
import math
import os
import pathlib
import statistics
import subprocess

top = pathlib.Path(__file__).resolve().parents[1]
parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("data", help="the CEC 2022 package's input_data folder (PRIDE_CEC2022_DATA)")
parser.add_argument("--pride", default=str(top / "build" / "cli" / "pride"))
parser.add_argument("--dim", type=int, choices=(10, 20), default=10)
parser.add_argument("--reading", choices=("code", "paper"), default="code")
parser.add_argument("--runs", type=int, default=30)
args = parser.parse_args()

F_STAR = [300, 400, 600, 800, 900, 1800, 2000, 2200, 2300, 2400, 2600, 2700]
EVALS = {10: 200_000, 20: 1_000_000}[args.dim]
env = dict(os.environ, PRIDE_CEC2022_DATA=args.data)

official = {}
with open(top / "docs" / "results" / "data" / "lshade-official-cec2022.csv") as f:
    for row in csv.DictReader(f):
        if int(row["dimension"]) == args.dim:
            official.setdefault(int(row["function"]), []).append(float(row["error"]))


def mann_whitney_p(a, b):
    """Two-sided p of the U test, normal approximation with the tie correction."""
    pooled = sorted([(v, 0) for v in a] + [(v, 1) for v in b])
    ranks, ties, i = [0.0] * len(pooled), 0.0, 0
    while i < len(pooled):
        j = i
        while j + 1 < len(pooled) and pooled[j + 1][0] == pooled[i][0]:
            j += 1
        for k in range(i, j + 1):
            ranks[k] = (i + j) / 2 + 1
        ties += (j - i + 1) ** 3 - (j - i + 1)
        i = j + 1
    n1, n2 = len(a), len(b)
    n = n1 + n2
    u = sum(r for r, (_, group) in zip(ranks, pooled) if group == 0) - n1 * (n1 + 1) / 2
    sd = math.sqrt(n1 * n2 / 12 * ((n + 1) - ties / (n * (n - 1))))
    return 1.0 if sd == 0 else math.erfc(abs(u - n1 * n2 / 2) / sd / math.sqrt(2))


print(f"lshade reading={args.reading}, D = {args.dim}, {EVALS} evaluations, seeds 1..{args.runs}")
print("| F | official median | pride median | official mean | pride mean | U test p |")
print("|---|---:|---:|---:|---:|---:|")
for fn in range(1, 13):
    errors = []
    for seed in range(1, args.runs + 1):
        command = [args.pride, "run", "--problem", f"cec2022-f{fn}", "--dim", str(args.dim), "--algo", "lshade",
                   "--param", f"reading={args.reading}", "--evals", str(EVALS), "--seed", str(seed), "--json"]
        out = subprocess.run(command, capture_output=True, text=True, env=env, check=True).stdout
        errors.append(json.loads(out)["best_f"] - F_STAR[fn - 1])
    ref = official[fn]
    print(f"| F{fn} | {statistics.median(ref):.6g} | {statistics.median(errors):.6g} | {statistics.mean(ref):.6g} "
          f"| {statistics.mean(errors):.6g} | {mann_whitney_p(ref, errors):.3g} |", flush=True)
