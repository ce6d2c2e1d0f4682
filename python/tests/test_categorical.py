"""Categorical variables of a Python function (``categorical=``), and typed variables with
constraints and with several objectives: the function sees its values, the result reports them,
bad declarations are one-line errors naming the argument."""
import numpy as np
import pytest

import pride

COST = [3.0, 1.0, 4.0, 0.0, 5.0]  # choice 3 is best, between two bad ones: no order to exploit
BOUNDS = ([0, 0, -2], [4, 6, 2])


def f(x):
    assert x[0] == int(x[0]) and x[1] == int(x[1]), x
    return COST[int(x[0])] + (x[1] - 2.0) ** 2 + (x[2] - 0.3) ** 2


@pytest.mark.parametrize("algo", ["ga", "ga-plus", "de", "pso"])
def test_minimize_searches_categorical_choices(algo):
    r = pride.minimize(algo, f, bounds=BOUNDS, integers=[1], categorical=[0], evals=4000, seed=4)
    assert list(r.best_x[:2]) == [3.0, 2.0]
    assert r.best_f < 1e-3


def test_ask_returns_choices_and_equals_minimize():
    want = pride.minimize("ga", f, bounds=BOUNDS, integers=[1], categorical=[0], evals=500, seed=2)
    opt = pride.Optimizer("ga", bounds=BOUNDS, integers=[1], categorical=[0], evals=500, seed=2)
    while not opt.done:
        X = opt.ask()
        assert np.array_equal(X[:, :2], np.round(X[:, :2]))
        assert X[:, 0].min() >= 0 and X[:, 0].max() <= 4
        opt.tell([f(x) for x in X])
    got = opt.result
    assert got.best_f == want.best_f and list(got.best_x) == list(want.best_x)


def test_constrained_function_receives_its_types():
    seen = []

    def g(x):
        seen.append(x[0])
        return [3.0 - x[0]]

    r = pride.minimize("de", lambda x: (x[0] - 2.6) ** 2 + x[1] ** 2, bounds=([0, -1], [9, 1]), integers=[0],
                       subject_to=g, inequalities=1, evals=3000, seed=3)
    assert all(v == int(v) for v in seen)
    assert r.best_x[0] == 3.0 and r.feasible
    assert r.best_f == pytest.approx(0.16, abs=1e-6)


def test_front_of_a_mixed_function():
    def two(x):
        assert x[0] == int(x[0]) and x[1] == int(x[1]), x
        c = int(x[0])
        return [COST[c] + (x[1] - 2) ** 2 + x[2] ** 2, COST[4 - c] + (x[1] - 4) ** 2 + (x[2] - 1) ** 2]

    r = pride.front("nsga2", two, bounds=BOUNDS, objectives=2, integers=[1], categorical=[0], evals=4000, seed=1)
    assert len(r.f) > 1
    for x, fx in zip(r.x, r.f):
        assert x[0] == int(x[0]) and x[1] == int(x[1])
        assert list(fx) == two(x)


@pytest.mark.parametrize("kw,error,match", [
    (dict(categorical="0"), TypeError, "^categorical: expected a list, got str"),
    (dict(categorical=[3]), ValueError, r"^categorical: 3 is not a coordinate of the box \(0 to 2\)"),
    (dict(categorical=[0, 0]), ValueError, "^categorical: 0 is listed twice"),
    (dict(integers=[0], categorical=[0]), ValueError, "^categorical: 0 is also listed in integers"),
    (dict(categorical=[2]), ValueError, r"variable 2 \(categorical\) needs integer bounds, got \[-2.5, 2.5\]$"),
    (dict(categorical=[1]), ValueError, r"^(function|bounds): variable 1 \(categorical\) needs bounds 0 and k - 1 "
                                        r"with k >= 2 choices, got \[1, 6\]$"),
])
def test_bad_categorical_declarations_are_refused_by_name(kw, error, match):
    bounds = ([0, 1, -2.5], [4, 6, 2.5])  # coordinate 1 starts at 1 and 2 is fractional: no categorical there
    with pytest.raises(error, match=match):
        pride.minimize("ga", f, bounds=bounds, evals=100, **kw)
    with pytest.raises(error, match=match):
        pride.Optimizer("ga", bounds=bounds, evals=100, **kw)
    with pytest.raises(ValueError, match="^categorical: only for Python functions"):
        pride.minimize("ga", "sphere", dim=2, evals=100, categorical=[0])
    with pytest.raises(ValueError, match="^integers: only for Python functions"):
        pride.front("nsga2", "zdt1", evals=100, integers=[0])


def test_the_margin_refuses_categorical_variables():
    with pytest.raises(ValueError, match=r"^cmaes: the margin takes integer and real variables; variable 0 is "
                                         r"categorical"):
        pride.minimize("cmaes", f, bounds=BOUNDS, integers=[1], categorical=[0], evals=100, margin=1)
    # Without the margin CMA-ES searches the box, and the function still receives choices.
    r = pride.minimize("cmaes", f, bounds=BOUNDS, integers=[1], categorical=[0], evals=300, seed=1)
    assert r.best_x[0] == int(r.best_x[0])


def test_the_rounding_operator_is_set_from_python():
    # The algorithms' parameter `discrete` is not the keyword `integers` that declares coordinates.
    seen = []

    def g(x):
        seen.append(x[1])
        return f(x)

    relaxed = pride.minimize("de", g, bounds=BOUNDS, integers=[1], categorical=[0], evals=300, seed=1,
                             discrete="relax")
    rounded = pride.minimize("de", g, bounds=BOUNDS, integers=[1], categorical=[0], evals=300, seed=1)
    assert all(v == int(v) for v in seen)  # the function gets integers either way
    assert relaxed.best_f != rounded.best_f or list(relaxed.best_x) != list(rounded.best_x)
    with pytest.raises(ValueError, match="^de: discrete must be round or relax"):
        pride.minimize("de", g, bounds=BOUNDS, evals=300, discrete="floor")
