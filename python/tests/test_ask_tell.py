"""Ask and tell: equal to minimize() bit for bit for every box algorithm; bad tells refused; an
optimizer dropped or closed mid-run stops its run's thread."""
import os
import time

import numpy as np
import pytest

import pride

BOX = [a["name"] for a in pride.algorithms() if "box" in a["spaces"]]
BOUNDS = ([-5.0, -4.0, -3.0], [5.0, 4.0, 3.0])


def f_rows(X):
    return (X[:, 0] - 1.0) ** 2 + X[:, 1] * X[:, 1] + np.abs(X[:, 2])


@pytest.mark.parametrize("algo", BOX)
def test_ask_tell_equals_minimize(algo):
    want = pride.minimize(algo, f_rows, bounds=BOUNDS, evals=250, seed=4, vectorized=True)
    opt = pride.Optimizer(algo, bounds=BOUNDS, evals=250, seed=4)
    told = 0
    while not opt.done:
        X = opt.ask()
        assert X.ndim == 2 and X.shape[1] == 3 and X.shape[0] >= 1
        opt.tell(f_rows(X))
        told += len(X)
    got = opt.result
    assert told == got.evaluations == want.evaluations <= 250
    assert got.best_x.tobytes() == want.best_x.tobytes()
    assert got.best_f == want.best_f
    assert got.history.tobytes() == want.history.tobytes()
    # Asking after the end is refused, as telling is (an empty batch would be told nothing).
    with pytest.raises(ValueError, match=r"^ask: the run has ended \(done is true\)"):
        opt.ask()


def test_refusals():
    opt = pride.Optimizer("pso", bounds=([0.0, 0.0], [1.0, 1.0]), evals=20, pop=10, seed=1)
    with pytest.raises(ValueError, match="tell: no points were asked for"):
        opt.tell(np.zeros(10))
    X = opt.ask()
    assert X.shape == (10, 2) and opt.ask().tobytes() == X.tobytes()  # asking again: the same points
    with pytest.raises(ValueError, match="tell: expected 10 values"):
        opt.tell(np.zeros(9))
    with pytest.raises(ValueError, match="tell: expected a 1-D array"):
        opt.tell(np.zeros((10, 2)))
    with pytest.raises(ValueError, match="result: the run has not ended"):
        opt.result
    opt.tell(np.arange(10.0))
    opt.tell(opt.ask().sum(axis=1))
    assert opt.done and opt.result.evaluations == 20
    with pytest.raises(ValueError, match="tell: the run has ended"):
        opt.tell(np.zeros(10))
    with pytest.raises(ValueError, match="pop"):
        pride.Optimizer("pso", bounds=([0.0], [1.0]), evals=20, pop=1)
    with pytest.raises(ValueError, match="bounds"):
        pride.Optimizer("pso", bounds=([1.0], [0.0]), evals=20)
    with pytest.raises(ValueError, match="algo"):
        pride.Optimizer("astar", bounds=([0.0], [1.0]), evals=20)


def test_nan_told_is_worst():
    opt = pride.Optimizer("ga", bounds=([0.0], [1.0]), evals=40, seed=2)
    while not opt.done:
        X = opt.ask()
        opt.tell(np.where(X[:, 0] < 0.5, np.nan, X[:, 0]))
    assert opt.result.best_x[0] >= 0.5


def test_dropping_or_closing_mid_run_stops_the_thread():
    threads = lambda: len(os.listdir("/proc/self/task"))  # the process's OS threads
    before = threads()
    for _ in range(20):
        opt = pride.Optimizer("pso", bounds=([0.0] * 4, [1.0] * 4), evals=10_000, seed=1)
        opt.tell(np.ones(len(opt.ask())))
        opt.ask()
        del opt  # its run waits for a tell: dropping it must end that thread, not hang
    with pride.Optimizer("woa", bounds=([0.0] * 2, [1.0] * 2), evals=1000) as opt:
        opt.ask()
    with pytest.raises(ValueError, match="closed"):
        opt.ask()
    opt.close()  # closing twice is fine
    t0 = time.time()
    while threads() > before and time.time() - t0 < 5:
        time.sleep(0.01)
    assert threads() <= before
