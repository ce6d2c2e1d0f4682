#!/usr/bin/env python3
"""Reference runs of Optuna's CMA-ES with margin on COCO's bbob-mixint suite.

CMA-ES with margin (Hamano, Saito, Nomura and Shirakawa, GECCO 2022) as Optuna
ships it: ``optuna.samplers.CmaEsSampler(with_margin=True, seed=s)``, which builds
``cmaes.CMAwM``. The table it writes lets pride's own implementation be compared
with Optuna's as distributions of runtimes (evaluations to each target).

Optuna 3.1 re-reads every trial on every sample, so one run costs time quadratic
in its evaluations (measured here: 10,000 trials of f1 in D = 20 took 47 s, the
last 2,000 of them 20 s); the 30 runs of f10 and f15 in D = 20 alone, which use
their whole budget, would take over an hour of CPU at 1,000 D evaluations each.
The table is therefore produced by driving
``cmaes.CMAwM`` directly, doing exactly what the sampler does (optuna/samplers/
_cmaes.py, ``sample_relative`` and ``_init_optimizer``):

* trial 0 is Optuna's start-up trial, drawn by ``RandomSampler(seed=s)``: each
  integer uniform on [lo - 0.5, hi + 0.5] then rounded, each float uniform on
  [-5, 5]; it counts as one evaluation and is never told to CMAwM;
* CMAwM gets mean = middle of the bounds, sigma0 = min(upper - lower) / 6
  (= 1/6 here: the binary variables have the narrowest range),
  bounds = [lo, hi] per variable (no half steps: ``transform_step=False``),
  steps 1 for integers and 0 for floats, ``n_max_resampling`` = 10 D and the
  default population size; no restarts (Optuna's default ``restart_strategy``);
* the sampler's ``RandomState(s)`` is consumed in Optuna's order: until the
  first generation has been told (trials 1 .. lambda + 1) every trial builds a
  new optimizer and draws its seed ``randint(1, 2**31 - 2)``, and every trial
  then reseeds the optimizer's generator with ``randint(1, 2**16) + trial``
  before its single ``ask``; a generation is told at the first trial after its
  lambda points were evaluated, with the ``x_for_tell`` values;
* the optimizer is pickled after each tell and every trial asks a fresh
  unpickled copy, as Optuna restores it from the trial's system attributes
  (asking one live object gives other points in the last bits after a few
  generations);
* the point evaluated is ``x_for_eval`` with integers as integers and floats
  passed through Optuna's untransform (which maps 5.0 to the float below it).

``--check`` shows that this is the same algorithm: for f1, D = 10, seeds 1-3 and
300 evaluations it runs Optuna's sampler itself and the direct loop and compares
every evaluated point and value (exit status 1 on any difference). Run whole,
Optuna's sampler on f2, D = 10, seed 14 stopped, like the replay, with cmaes's
1e32 assertion after 14,921 evaluations with the same hitting times (142 s CPU).

The objective is f(x) - f* with f = pride.Problem("bbob-mixint-fN", D, instance=s);
run s uses instance s and seed s, and stops when f - f* <= 1e-8 or at the budget.

Usage (from the repository root, with the Python module built):

    PYTHONPATH=build/python /usr/bin/python3 scripts/margin_reference.py --budget-per-dim 2000 \\
        > tests/data/cmawm/optuna_bbob_mixint.tsv
    PYTHONPATH=build/python /usr/bin/python3 scripts/margin_reference.py --check

Options: --functions 1,2,10,15  --dims 10,20  --runs 15  --budget-per-dim N.
"""

import argparse
import math
import pickle
import sys
import time

import numpy as np

import pride

TARGETS = [10.0**k for k in range(2, -9, -1)]
FINAL_TARGET = 1e-8


class Run:
    """One problem with its evaluation counter and first hitting times."""

    def __init__(self, function, dim, instance, budget):
        self.problem = pride.Problem(f"bbob-mixint-f{function}", dim, instance=instance)
        self.budget = budget
        self.evals = 0
        self.best = math.inf
        self.hits = [None] * len(TARGETS)
        self.points = []  # kept only when comparing with Optuna
        self.end = None  # why the run stopped: "target", "budget" or "diverged"

    def __call__(self, x, keep=False):
        value = float(self.problem(np.asarray(x, dtype=float))) - self.problem.optimum
        self.evals += 1
        if keep:
            self.points.append((list(map(float, x)), value))
        if value < self.best:
            self.best = value
            for k, target in enumerate(TARGETS):
                if self.hits[k] is None and value <= target:
                    self.hits[k] = self.evals
        return value

    def done(self):
        if self.best <= FINAL_TARGET:
            self.end = "target"
        elif self.evals >= self.budget:
            self.end = "budget"
        return self.end is not None


def integer_count(dim):
    # COCO's bbob-mixint: the first 4D/5 variables are integers, the rest continuous.
    return 4 * dim // 5


def untransform(x, dim):
    """Optuna's _SearchSpaceTransform.untransform for our distributions."""
    n_int = integer_count(dim)
    out = []
    for i, v in enumerate(x):
        if i < n_int:
            out.append(float(int(v)))  # on the grid already: x_for_eval is a grid value
        else:
            out.append(min(float(v), float(np.nextafter(5.0, 4.0))))
    return out


def startup_point(problem, seed):
    """Optuna's RandomSampler(seed) drawing trial 0, one parameter at a time."""
    rng = np.random.RandomState(seed)
    n_int = integer_count(problem.dim)
    x = []
    for i in range(problem.dim):
        if i < n_int:
            lo, hi = int(problem.lower[i]), int(problem.upper[i])
            v = rng.uniform(lo - 0.5, hi + 0.5)
            x.append(float(int(np.clip(np.round(v - lo) + lo, lo, hi))))
        else:
            v = rng.uniform(-5.0, 5.0)
            x.append(min(v, float(np.nextafter(5.0, 4.0))))
    return x


def direct_run(run, seed, keep=False):
    """Optuna's with-margin sampler, replayed on cmaes.CMAwM (see the docstring)."""
    from cmaes import CMAwM

    problem = run.problem
    dim = problem.dim
    n_int = integer_count(dim)
    lower = np.array([problem.lower[i] if i < n_int else -5.0 for i in range(dim)], float)
    upper = np.array([problem.upper[i] if i < n_int else 5.0 for i in range(dim)], float)
    bounds = np.stack([lower, upper], axis=1)
    steps = np.array([1.0 if i < n_int else 0.0 for i in range(dim)])
    cma_rng = np.random.RandomState(seed)

    def new_optimizer():
        return CMAwM(
            mean=lower + (upper - lower) / 2,
            sigma=max(float(np.min((upper - lower) / 6)), 1e-10),
            bounds=bounds,
            steps=steps,
            seed=cma_rng.randint(1, 2**31 - 2),
            n_max_resampling=10 * dim,
        )

    run(startup_point(problem, seed), keep)
    # Optuna keeps the optimizer pickled after each tell and unpickles a fresh copy
    # for every trial; asking one live object instead gives points that differ in
    # the last bits from the third generation on (cmaes caches the eigendecomposition
    # and rebuilds C from it), so the copies are kept.
    stored = None
    pending = []
    trial = 1
    while not run.done():
        if stored is None:
            # Optuna rebuilds the optimizer (drawing a seed) until one has been stored.
            optimizer = new_optimizer()
        else:
            optimizer = pickle.loads(stored)
        try:
            if len(pending) >= optimizer.population_size:
                optimizer.tell(pending[: optimizer.population_size])
                pending = pending[optimizer.population_size :]
                stored = pickle.dumps(optimizer)
            optimizer._rng.seed(cma_rng.randint(1, 2**16) + trial)
            x_eval, x_tell = optimizer.ask()
        except AssertionError:
            # cmaes refuses points beyond 1e32 once the search has diverged; Optuna's
            # study.optimize raises the same error there, which ends the run.
            run.end = "diverged"
            break
        pending.append((x_tell, run(untransform(x_eval, dim), keep)))
        trial += 1
    return run


def optuna_run(run, seed, keep=False):
    """The same run through Optuna's sampler itself (for --check)."""
    import optuna

    optuna.logging.set_verbosity(optuna.logging.WARNING)
    problem = run.problem
    n_int = integer_count(problem.dim)

    def objective(trial):
        x = []
        for i in range(problem.dim):
            if i < n_int:
                x.append(trial.suggest_int(f"x{i:02}", int(problem.lower[i]), int(problem.upper[i])))
            else:
                x.append(trial.suggest_float(f"x{i:02}", -5.0, 5.0))
        return run(x, keep)

    sampler = optuna.samplers.CmaEsSampler(with_margin=True, seed=seed)
    study = optuna.create_study(sampler=sampler, direction="minimize")
    while not run.done():
        study.optimize(objective, n_trials=1)
    return run


def check(evals=300, seeds=(1, 2, 3), function=1, dim=10):
    import warnings

    warnings.filterwarnings("ignore", message=".*with_margin.*")
    ok = True
    for seed in seeds:
        a = optuna_run(Run(function, dim, seed, evals), seed, keep=True)
        b = direct_run(Run(function, dim, seed, evals), seed, keep=True)
        same = len(a.points) == len(b.points)
        first = None
        for k, (pa, pb) in enumerate(zip(a.points, b.points)):
            if pa[0] != pb[0] or pa[1] != pb[1]:
                same, first = False, k
                break
        ok = ok and same
        print(
            f"f{function} D={dim} seed={seed}: optuna {len(a.points)} points, best {a.best:.3e}; "
            f"direct {len(b.points)} points, best {b.best:.3e}; "
            + ("identical" if same else f"differ (first at evaluation {first})")
        )
    return ok


def header(budget_per_dim, options=""):
    """The '#' lines that say what produced the table."""
    import datetime

    import cmaes
    import optuna

    command = "PYTHONPATH=build/python /usr/bin/python3 scripts/margin_reference.py"
    command += f" {options}" if options else ""
    today = datetime.datetime.now(datetime.timezone.utc).date().isoformat()
    return "\n".join(
        [
            f"# Optuna {optuna.__version__} CmaEsSampler(with_margin=True, seed=s) replayed on cmaes "
            f"{cmaes.__version__} CMAwM (Debian 12 packages; see the script's docstring and --check),",
            f"# on pride's bbob-mixint: run s = instance s = seed s; budget {budget_per_dim} D evaluations "
            "or until f - f* <= 1e-8.",
            "# evals_1eK: evaluation at which f - f* first was <= 1eK (empty: never); final_best: "
            "best f - f* of the run;",
            "# end: target (1e-8 reached), budget, or diverged (cmaes's assertion that points stay "
            "below 1e32 failed, as it would inside Optuna).",
            f"# Produced {today} by: {command}",
        ]
    )


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--functions", default="1,2,10,15")
    parser.add_argument("--dims", default="10,20")
    parser.add_argument("--runs", type=int, default=15)
    parser.add_argument("--budget-per-dim", type=int, default=2000)
    parser.add_argument("--check", action="store_true")
    args = parser.parse_args()
    try:
        functions = [int(v) for v in args.functions.split(",")]
        dims = [int(v) for v in args.dims.split(",")]
    except ValueError:
        parser.error("--functions and --dims take comma-separated integers")
    if args.check:
        sys.exit(0 if check() else 1)

    print(header(args.budget_per_dim, " ".join(sys.argv[1:])))
    cols = ["function", "dim", "instance", "seed"]
    cols += [f"evals_1e{int(round(math.log10(t))):+d}" for t in TARGETS]
    cols += ["final_best", "evals_used", "end"]
    print("\t".join(cols))
    for function in functions:
        for dim in dims:
            for s in range(1, args.runs + 1):
                start = time.process_time()
                run = direct_run(Run(function, dim, s, args.budget_per_dim * dim), s)
                row = [f"f{function}", str(dim), str(s), str(s)]
                row += ["" if h is None else str(h) for h in run.hits]
                row += [f"{run.best:.6e}", str(run.evals), run.end]
                print("\t".join(row), flush=True)
                print(
                    f"f{function} D={dim} s={s}: {run.evals} evals, best {run.best:.3e}, "
                    f"{time.process_time() - start:.1f} s",
                    file=sys.stderr,
                )


if __name__ == "__main__":
    main()
