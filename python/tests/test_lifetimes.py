"""Arrays the module hands Python are Python's to keep: reading them after the run gives what was
handed, never freed memory (the observer's population and fitness were views of the run's own
memory, read after free once the run ended)."""
import gc

import numpy as np

import pride


def test_observer_arrays_kept_after_the_run_hold_what_was_observed():
    kept, copies = [], []

    def watch(iteration, evaluations, best_f, population, fitness):
        kept.append((population, fitness))
        copies.append((population.copy(), fitness.copy()))

    pride.minimize("pso", "sphere", dim=3, evals=200, pop=10, seed=1, callback=watch)
    gc.collect()
    pride.minimize("ga", "rastrigin", dim=5, evals=2_000, seed=2)  # reuses the freed memory, if any
    assert len(kept) == 20
    for (population, fitness), (p, v) in zip(kept, copies):
        assert population.shape == (10, 3) and fitness.shape == (10,)
        assert population.tobytes() == p.tobytes() and fitness.tobytes() == v.tobytes()
        assert not population.flags.writeable and not fitness.flags.writeable
        assert population.flags.owndata or population.base is not None  # its own memory, not the run's
    # Different iterations are different arrays, each with its own values.
    assert kept[0][0].tobytes() != kept[-1][0].tobytes()


def test_a_large_population_kept_after_the_run():
    kept, sums = [], []

    def watch(iteration, evaluations, best_f, population, fitness):
        kept.append(population)
        sums.append(float(population.sum()))

    pride.minimize("pso", "sphere", dim=200, evals=5_000 * 4, pop=5_000, seed=3, callback=watch)
    gc.collect()
    pride.minimize("pso", "sphere", dim=200, evals=5_000 * 2, pop=5_000, seed=4)
    assert [p.shape for p in kept] == [(5_000, 200)] * 4
    assert [float(p.sum()) for p in kept] == sums


def test_points_a_function_keeps_hold_what_it_was_given():
    kept, copies = [], []

    def rows(X):
        kept.append(X)
        copies.append(X.copy())
        return np.sum(X * X, axis=1)

    def one(x):
        kept.append(x)
        copies.append(x.copy())
        return float(x @ x)

    pride.minimize("ga", rows, bounds=(-1, 1), dim=3, evals=300, vectorized=True, seed=1)
    pride.minimize("ga", one, bounds=(-1, 1), dim=3, evals=300, seed=1)
    gc.collect()
    assert all(a.tobytes() == b.tobytes() for a, b in zip(kept, copies)) and len(kept) > 300


def test_asked_points_and_path_cells_kept_hold_what_was_handed():
    opt = pride.Optimizer("pso", bounds=(-1, 1), dim=3, evals=60, pop=10, seed=1)
    asked, copies = [], []
    while not opt.done:
        X = opt.ask()
        asked.append(X)
        copies.append(X.copy())
        opt.tell(np.sum(X * X, axis=1))
    opt.close()
    assert all(a.tobytes() == b.tobytes() for a, b in zip(asked, copies))

    cells, cell_copies = [], []

    def length(c):
        cells.append(c)
        cell_copies.append(c.copy())
        return float(len(c))

    pride.plan(pride.Grid(np.zeros((6, 6), dtype=int)), (0, 0), (5, 5), algo="pso", objective=length, iters=3, seed=1)
    gc.collect()
    assert cells and all(a.tobytes() == b.tobytes() for a, b in zip(cells, cell_copies))
