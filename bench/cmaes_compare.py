"""pride's cmaes beside python3-cmaes 0.9.1 (Debian's; an independent implementation of the same
tutorial, Hansen 2016): the evaluations each needs to reach f - f* <= 1e-8 on sphere, ellipsoid,
rosenbrock and bbob-f10 (instance 1) in D = 10 and 40, median over 25 seeds.

Both start from a mean uniform in the box with sigma0 = 0.3 of its width (C = I: the same search
as pride's C = diag(width^2) with sigma0 = 0.3, the box being a cube), resample points outside the
box (python3-cmaes up to 100 times, then clips; pride the same), and run without restarts until
the target or the budget (10,000 D evaluations; python3-cmaes without its should_stop, pride with
TolFun and TolX off and its other stopping criteria on); evaluations are
counted at the end of the generation that reaches the target, on both sides. Both evaluate the
same functions: python3-cmaes calls pride.Problem (pride's values, bit for bit).

Usage (from the top of the checkout, after building):
    PYTHONPATH=build/python /usr/bin/python3 bench/cmaes_compare.py [--seeds 25] [--dims 10,40]
Prints one row per (function, D): the medians, their ratio, the successes, and whether the medians
agree within 10 %; exits 0 (a benchmark states, it does not fail).
"""
import argparse
import statistics
import time

import numpy as np
from cmaes import CMA

import pride

FUNCTIONS = [("sphere", None), ("ellipsoid", None), ("rosenbrock", None), ("bbob-f10", 1)]


def python_cmaes(problem, seed, budget, target):
    rng = np.random.default_rng(seed)
    lower, upper = problem.lower, problem.upper
    mean = lower + (upper - lower) * rng.random(problem.dim)
    opt = CMA(mean=mean, sigma=0.3 * float(upper[0] - lower[0]), bounds=np.column_stack([lower, upper]),
              seed=seed)
    used = 0
    while used < budget:
        xs = np.array([opt.ask() for _ in range(opt.population_size)])
        values = problem(xs)
        used += len(xs)
        opt.tell(list(zip(xs, values)))
        if values.min() <= target:
            return used
    return None


def pride_cmaes(name, dim, instance, seed, budget, target):
    r = pride.minimize("cmaes", name, dim=dim, instance=instance, evals=budget, target=target, seed=seed,
                       tol_fun=0, tol_x=0, restarts="none")
    return r.evaluations if r.best_f <= target else None


def median(values):
    # Failures count as infinitely many evaluations (the median is undefined when half fail).
    finite = sorted(v if v is not None else float("inf") for v in values)
    m = statistics.median(finite)
    return m


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--seeds", type=int, default=25)
    ap.add_argument("--dims", default="10,40")
    args = ap.parse_args()
    dims = [int(d) for d in args.dims.split(",")]
    print(f"{'function':12} {'D':>3} {'pride':>9} {'python3-cmaes':>14} {'ratio':>6} {'ok pride':>9} "
          f"{'ok cmaes':>9} {'within 10%':>10} {'time pride, cmaes (s)':>22}")
    for name, instance in FUNCTIONS:
        for dim in dims:
            problem = pride.Problem(name, dim, instance=instance)
            fstar = problem.optimum
            target = fstar + 1e-8
            budget = 10000 * dim
            t0 = time.perf_counter()
            ours = [pride_cmaes(name, dim, instance, s, budget, target) for s in range(1, args.seeds + 1)]
            t1 = time.perf_counter()
            theirs = [python_cmaes(problem, s, budget, target) for s in range(1, args.seeds + 1)]
            t2 = time.perf_counter()
            a, b = median(ours), median(theirs)
            ratio = a / b if b not in (0, float("inf")) and a != float("inf") else float("nan")
            ok = abs(ratio - 1) <= 0.10 if ratio == ratio else False
            print(f"{name:12} {dim:>3} {a:>9.0f} {b:>14.0f} {ratio:>6.3f} "
                  f"{sum(v is not None for v in ours):>6}/{args.seeds:<2} "
                  f"{sum(v is not None for v in theirs):>6}/{args.seeds:<2} {'yes' if ok else 'NO':>10} "
                  f"{t1 - t0:>10.1f} {t2 - t1:>10.1f}", flush=True)


if __name__ == "__main__":
    main()
