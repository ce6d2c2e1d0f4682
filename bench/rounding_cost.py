#!/usr/bin/python3
"""What the typed space's rounding operator costs per evaluation: `pride run` of each algorithm on
bbob-mixint-f1 (D = 40: 32 integer coordinates, the cheapest function of the suite, so that the
operator's share is the largest) with `discrete=round` and with `discrete=relax`, 200,000
evaluations, seeds 1-3 in turn, the least wall time of `--reps` runs of each; prints ns per
evaluation and the ratio round / relax.

    /usr/bin/python3 bench/rounding_cost.py [--algos pso,de,ga] [--reps 12] [--pride build/cli/pride]
"""
import argparse
import json
import pathlib
import subprocess
import sys


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--algos", default="pso,de,ga")
    parser.add_argument("--reps", type=int, default=12)
    parser.add_argument("--pride", default=str(pathlib.Path(__file__).resolve().parents[1] / "build" / "cli" / "pride"))
    args = parser.parse_args()
    if args.reps < 1:
        parser.error("--reps must be at least 1")
    algos = [a for a in args.algos.split(",") if a]
    evaluations = 200000
    best = {}
    for rep in range(args.reps):
        for algo in algos:  # interleaved, so that a busy moment weighs on both sides
            for mode in ("round", "relax"):
                out = subprocess.run([args.pride, "run", "--algo", algo, "--param", f"discrete={mode}", "--problem",
                                      "bbob-mixint-f1", "--dim", "40", "--evals", str(evaluations), "--seed",
                                      str(rep % 3 + 1), "--json"], capture_output=True, text=True)
                if out.returncode != 0:
                    sys.exit(out.stderr.strip())
                wall = json.loads(out.stdout)["wall_ms"]
                best[(algo, mode)] = min(best.get((algo, mode), float("inf")), wall)
    print("algo,round_ns,relax_ns,ratio")
    for algo in algos:
        r, x = (best[(algo, m)] * 1e6 / evaluations for m in ("round", "relax"))
        print(f"{algo},{r:.0f},{x:.0f},{r / x:.3f}")


if __name__ == "__main__":
    main()
