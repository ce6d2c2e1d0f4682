"""The Python module's cost (docs/benchmarks.md, "The Python module"): a program that prints
numbers, not a test.

    PYTHONPATH=build/python /usr/bin/python3 python/bench/bench_python.py [--repeats 5] [--pride build/cli/pride]
    PYTHONPATH=build/python valgrind --tool=callgrind /usr/bin/python3 python/bench/bench_python.py \
        --part {base,bare,bare_rows,run,run_rows,own} --function {trivial,rastrigin} [--evals 10000]

1. pride.minimize("pso", "rastrigin", dim=30, evals=100_000) against the same run of the command
   line (`pride run ... --json`): the engine's wall_ms of each, and the whole call / process.
2. The overhead per evaluation of a Python function, scalar and vectorised, against the cost of
   calling that function alone on the same points (and the run's own C++ time).
3. For scale, pure-numpy PSO and WOA written here in the style of MEALPy (vectorised per
   iteration where MEALPy is; not shipped), on the same problem and budget.
"""
import argparse
import json
import statistics
import subprocess
import time

import numpy as np

import pride

DIM, EVALS, POP = 30, 100_000, 50


def rastrigin(x):
    return 10.0 * len(x) + float(np.sum(x * x - 10.0 * np.cos(2.0 * np.pi * x)))


def rastrigin_rows(X):
    return 10.0 * X.shape[1] + np.sum(X * X - 10.0 * np.cos(2.0 * np.pi * X), axis=1)


def median_ms(fn, repeats):
    """The median and the least of `repeats` wall times (the least is the one least disturbed by
    other processes on a loaded machine)."""
    times = []
    for _ in range(repeats):
        t = time.perf_counter()
        fn()
        times.append(1e3 * (time.perf_counter() - t))
    return statistics.median(times), min(times)


def numpy_pso(f_rows, dim, evals, pop, lo, hi, rng):
    """Global-best PSO, inertia 0.9 -> 0.4, c1 = c2 = 2, vmax 0.2 of the range, as pride's pso."""
    x = rng.uniform(lo, hi, (pop, dim))
    vmax = 0.2 * (hi - lo)
    v = rng.uniform(-vmax, vmax, (pop, dim))
    fx = f_rows(x)
    p, fp = x.copy(), fx.copy()
    g = p[np.argmin(fp)].copy()
    used, t, T = pop, 0, (evals - pop) // pop
    while used + pop <= evals:
        w = 0.9 - (0.9 - 0.4) * t / max(T - 1, 1)
        r1, r2 = rng.random((pop, dim)), rng.random((pop, dim))
        v = np.clip(w * v + 2.0 * r1 * (p - x) + 2.0 * r2 * (g - x), -vmax, vmax)
        x = np.clip(x + v, lo, hi)
        fx = f_rows(x)
        used += pop
        better = fx < fp
        p[better], fp[better] = x[better], fx[better]
        g = p[np.argmin(fp)].copy()
        t += 1
    return float(fp.min())


def numpy_woa(f, dim, evals, pop, lo, hi, rng):
    """WOA (Mirjalili and Lewis 2016) with MEALPy's per-whale loop over numpy vectors."""
    x = rng.uniform(lo, hi, (pop, dim))
    fx = np.array([f(w) for w in x])
    best = x[np.argmin(fx)].copy()
    fbest = float(fx.min())
    used, T = pop, (evals - pop) // pop
    for t in range(T):
        a = 2.0 - 2.0 * t / T
        for i in range(pop):
            r = rng.random()
            A, C, l = 2 * a * r - a, 2 * rng.random(), rng.uniform(-1, 1)
            if rng.random() < 0.5:
                target = best if abs(A) < 1 else x[rng.integers(pop)]
                new = target - A * np.abs(C * target - x[i])
            else:
                new = np.abs(best - x[i]) * np.exp(l) * np.cos(2 * np.pi * l) + best
            new = np.clip(new, lo, hi)
            fn = f(new)
            used += 1
            if fn < fx[i]:
                x[i], fx[i] = new, fn
                if fn < fbest:
                    best, fbest = new.copy(), fn
    return fbest


def part(name, evals, fn_name):
    """One piece of work alone, for instruction counts under callgrind (wall times on a loaded
    machine are noise): the counts of `base` (import and points) subtracted from the others give
    the instructions per evaluation of the bare calls and of the same calls inside pride."""
    f, f_rows = {"trivial": (lambda x: 0.0, lambda X: np.zeros(len(X))),
                 "rastrigin": (rastrigin, rastrigin_rows)}[fn_name]
    points = np.random.default_rng(1).uniform(-5.12, 5.12, (evals, DIM))
    bounds = ([-5.12] * DIM, [5.12] * DIM)
    if name == "bare":
        for p in points:
            f(p)
    elif name == "bare_rows":
        for i in range(0, evals, POP):
            f_rows(points[i:i + POP])
    elif name == "run":
        pride.minimize("pso", f, bounds=bounds, evals=evals, seed=1)
    elif name == "run_rows":
        pride.minimize("pso", f_rows, bounds=bounds, evals=evals, seed=1, vectorized=True)
    elif name == "own":
        pride.minimize("pso", "sphere", dim=DIM, evals=evals, seed=1)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--pride", default="build/cli/pride")
    ap.add_argument("--part", choices=["base", "bare", "bare_rows", "run", "run_rows", "own"])
    ap.add_argument("--function", choices=["trivial", "rastrigin"], default="trivial")
    ap.add_argument("--evals", type=int, default=10_000)
    a = ap.parse_args()
    if a.part:
        return part(a.part, a.evals, a.function)
    R = a.repeats
    print(f"rastrigin, D = {DIM}, {EVALS} evaluations, pso pop {POP}; median of {R} (all times in ms)")

    # 1. The module against the command line, same run.
    engine_py, engine_cli = [], []
    call_ms, call_min = median_ms(lambda: engine_py.append(
        pride.minimize("pso", "rastrigin", dim=DIM, evals=EVALS, seed=1).wall_ms), R)

    def cli_run():
        out = subprocess.run([a.pride, "run", "--problem", "rastrigin", "--dim", str(DIM), "--algo", "pso",
                              "--evals", str(EVALS), "--seed", "1", "--json"], capture_output=True, text=True,
                             check=True)
        engine_cli.append(json.loads(out.stdout)["wall_ms"])

    process_ms, process_min = median_ms(cli_run, R)
    py, cl = statistics.median(engine_py), statistics.median(engine_cli)
    print(f"engine wall_ms, median (least): python {py:.2f} ({min(engine_py):.2f}), cli {cl:.2f} "
          f"({min(engine_cli):.2f}); python / cli {py / cl:.3f} ({min(engine_py) / min(engine_cli):.3f})")
    print(f"whole call: python {call_ms:.2f} ({call_min:.2f}), cli process {process_ms:.2f} ({process_min:.2f})")

    # 2. Python functions: overhead per evaluation over the bare calls (the least of the repeats).
    rng = np.random.default_rng(1)
    points = rng.uniform(-5.12, 5.12, (EVALS, DIM))
    bounds = ([-5.12] * DIM, [5.12] * DIM)
    us = 1e3 / EVALS
    _, own = median_ms(lambda: pride.minimize("pso", "sphere", dim=DIM, evals=EVALS, seed=1), R)
    print(f"pso's own work with a C++ sphere: {own * us:.3f} us/eval")
    for name, f, f_rows in (("trivial (returns 0)", lambda x: 0.0, lambda X: np.zeros(len(X))),
                            ("numpy rastrigin", rastrigin, rastrigin_rows)):
        _, bare = median_ms(lambda: [f(p) for p in points], R)
        _, bare_rows = median_ms(lambda: [f_rows(points[i:i + POP]) for i in range(0, EVALS, POP)], R)
        _, run = median_ms(lambda: pride.minimize("pso", f, bounds=bounds, evals=EVALS, seed=1), R)
        _, run_rows = median_ms(
            lambda: pride.minimize("pso", f_rows, bounds=bounds, evals=EVALS, seed=1, vectorized=True), R)
        print(f"{name}: scalar: bare {bare * us:.3f}, in pride {run * us:.3f}, overhead {(run - bare) * us:.3f} "
              f"us/eval; vectorised (batches of {POP}): bare {bare_rows * us:.3f}, in pride {run_rows * us:.3f}, "
              f"overhead {(run_rows - bare_rows) * us:.3f} us/eval (overheads include pso's own work)")

    # 3. Pure-numpy PSO and WOA for scale.
    lo, hi = -5.12, 5.12
    _, pso_np = median_ms(lambda: numpy_pso(rastrigin_rows, DIM, EVALS, POP, lo, hi, np.random.default_rng(1)), R)
    _, woa_np = median_ms(lambda: numpy_woa(rastrigin, DIM, EVALS, POP, lo, hi, np.random.default_rng(1)), R)
    _, woa_ms = median_ms(lambda: pride.minimize("woa", "rastrigin", dim=DIM, evals=EVALS, seed=1), R)
    call_ms = call_min
    print(f"least times: numpy pso (vectorised per iteration) {pso_np:.1f} ms vs pride pso {call_ms:.1f} ms: "
          f"{pso_np / call_ms:.1f}x")
    print(f"numpy woa (MEALPy's per-whale loop) {woa_np:.1f} ms vs pride woa {woa_ms:.1f} ms: "
          f"{woa_np / woa_ms:.1f}x")


if __name__ == "__main__":
    main()
