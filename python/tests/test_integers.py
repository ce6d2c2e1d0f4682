"""Integer variables of a Python function (``integers=``): the function and ask() see integers,
the result reports them, CMA-ES with margin searches them; bad declarations are one-line errors
naming the argument."""
import numpy as np
import pytest

import pride

BOUNDS = ([-3, 0, -2.5], [3, 5, 2.5])


def f(x):
    assert x[0] == round(x[0]) and x[1] == round(x[1]), x
    return (x[0] - 1.3) ** 2 + (x[1] - 4.0) ** 2 + x[2] ** 2


@pytest.mark.parametrize("algo,params", [("pso", {}), ("ga", {}), ("cmaes", {"margin": 1})])
def test_minimize_gives_the_function_integers(algo, params):
    r = pride.minimize(algo, f, bounds=BOUNDS, integers=[0, 1], evals=3000, seed=3, **params)
    assert r.best_x[0] == 1.0 and r.best_x[1] == 4.0
    assert r.best_f == pytest.approx(0.09, abs=1e-6)


def test_ask_returns_integers_and_equals_minimize():
    want = pride.minimize("cmaes", f, bounds=BOUNDS, integers=[0, 1], evals=600, seed=5, margin=1)
    opt = pride.Optimizer("cmaes", bounds=BOUNDS, integers=[0, 1], evals=600, seed=5, margin=1)
    while not opt.done:
        X = opt.ask()
        assert np.array_equal(X[:, :2], np.round(X[:, :2]))
        opt.tell([f(x) for x in X])
    got = opt.result
    assert got.best_f == want.best_f and list(got.best_x) == list(want.best_x)


def test_a_registered_problem_declares_its_own_integers():
    assert pride.Problem("bbob-mixint-f2", 10).types == ["integer"] * 8 + ["real"] * 2
    assert pride.Problem("sphere", 2).types == ["real", "real"]
    r = pride.minimize("cmaes", "bbob-mixint-f2", dim=10, evals=4000, seed=1, margin=1)
    assert all(v == round(v) for v in r.best_x[:8])
    with pytest.raises(ValueError, match="^integers: only for Python functions"):
        pride.minimize("cmaes", "bbob-mixint-f2", dim=10, evals=100, integers=[0])


@pytest.mark.parametrize("integers,error,match", [
    ("01", TypeError, "^integers: expected a list, got str"),
    ([0.5], TypeError, "^integers: expected an integer, got float"),
    ([3], ValueError, r"^integers: 3 is not a coordinate of the box \(0 to 2\)"),
    ([1, 1], ValueError, "^integers: 1 is listed twice"),
    ([2], ValueError, r"variable 2 \(integer\) needs integer bounds"),
])
def test_bad_integers_are_refused_by_name(integers, error, match):
    with pytest.raises(error, match=match):
        pride.minimize("pso", f, bounds=BOUNDS, integers=integers, evals=100)
    with pytest.raises(error, match=match):
        pride.Optimizer("pso", bounds=BOUNDS, integers=integers, evals=100)
