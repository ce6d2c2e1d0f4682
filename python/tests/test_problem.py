"""pride.Problem: a registered function evaluated from Python gives the values pride's runs see,
bit for bit, point by point and in batches; wrong arguments get one-line TypeError/ValueError
naming the argument."""
import math

import numpy as np
import pytest

import pride


def test_known_values_and_box():
    f = pride.Problem("sphere", 3)
    assert f(np.array([1.0, 2.0, 3.0])) == 14.0
    assert f([0, 0, 0]) == 0.0
    assert (f.name, f.dim, f.instance, f.optimum) == ("sphere", 3, 0, 0.0)
    assert list(f.lower) == [-5.12] * 3 and list(f.upper) == [5.12] * 3
    r = pride.Problem("rosenbrock", 4)
    assert r(np.ones(4)) == 0.0


def test_bbob_optimum_and_batches_match_single_points():
    f = pride.Problem("bbob-f10", 10, instance=1)
    assert f.instance == 1 and f.optimum == -54.94
    rng = np.random.default_rng(3)
    X = rng.uniform(-5, 5, size=(7, 10))
    batch = f(X)
    assert batch.shape == (7,)
    assert [f(x) for x in X] == list(batch)
    assert f(np.empty((0, 10))).shape == (0,)


def test_values_are_the_runs_values_bit_for_bit():
    r = pride.minimize("cmaes", "bbob-f10", dim=5, instance=2, evals=600, seed=4)
    f = pride.Problem("bbob-f10", 5, instance=2)
    assert f(np.array(r.best_x)) == r.best_f


def test_noisy_functions_are_seeded():
    a, b = pride.Problem("quartic-noise", 4, seed=5), pride.Problem("quartic-noise", 4, seed=5)
    x = np.full(4, 0.5)
    assert a(x) == b(x)
    assert pride.Problem("quartic-noise", 4, seed=6)(x) != a(x)


@pytest.mark.parametrize("call, error, words", [
    (lambda: pride.Problem("no-such", 3), ValueError, "problem: unknown problem 'no-such'"),
    (lambda: pride.Problem("sphere"), ValueError, "dim: give the dimension"),
    (lambda: pride.Problem("sphere", 0), ValueError, "dim:"),
    (lambda: pride.Problem(3, 3), TypeError, "name:"),
    (lambda: pride.Problem("bbob-f1", 3, instance=-1), ValueError, "instance"),
    (lambda: pride.Problem("sphere", 3)(np.zeros(4)), ValueError, "x: has 4 coordinates"),
    (lambda: pride.Problem("sphere", 3)(np.zeros((2, 4))), ValueError, "x: rows have 4 coordinates"),
    (lambda: pride.Problem("sphere", 3)(np.zeros((2, 3, 1))), ValueError, "x: must be one point"),
    (lambda: pride.Problem("sphere", 3)("abc"), TypeError, "x: expected real numbers"),
])
def test_errors_name_the_argument(call, error, words):
    with pytest.raises(error) as e:
        call()
    assert words in str(e.value)
    assert "\n" not in str(e.value)
