"""minimize(): every registered box algorithm on a registered problem (the CLI's JSON, bit for
bit) and on Python functions, scalar and vectorised; the registry as data."""
import numpy as np
import pytest

import pride
from conftest import cli

BOX = [a["name"] for a in pride.algorithms() if "box" in a["spaces"]]


def same_bits(a, b):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and a.tobytes() == b.tobytes()


def test_registry_as_data():
    algos = {a["name"]: a for a in pride.algorithms()}
    assert {"pso", "ga", "astar", "exact"} <= algos.keys()
    pop = next(p for p in algos["pso"]["params"] if p["name"] == "pop")
    assert pop["type"] == "integer" and pop["default"] == 50 and pop["min"] == 2
    listed = cli("list", "--json")
    assert [a["name"] for a in listed["algorithms"]] == list(algos)
    assert [p["name"] for p in pride.problems()] == [p["name"] for p in listed["problems"]]
    rastrigin = next(p for p in pride.problems() if p["name"] == "rastrigin")
    assert rastrigin["min_dim"] == 1 and rastrigin["fixed_dim"] is None
    assert {o["name"] for o in pride.grid_names()["objectives"]} >= {"cells", "length", "iqga"}


@pytest.mark.parametrize("algo", BOX)
def test_registered_problem_equals_cli(algo):
    r = pride.minimize(algo, "rastrigin", dim=4, evals=400, seed=3)
    j = cli("run", "--problem", "rastrigin", "--dim", 4, "--algo", algo, "--evals", 400, "--seed", 3, "--json")
    assert same_bits([r.best_f], [j["best_f"]])
    assert same_bits(r.best_x, j["best_x"])
    assert same_bits(r.history, j["history"])
    assert r.evaluations == j["evaluations"] <= 400
    assert isinstance(r.best_x, np.ndarray) and r.wall_ms >= 0


def sphere3(x):
    return x[0] * x[0] + x[1] * x[1] + x[2] * x[2]


def sphere3_rows(X):
    return X[:, 0] * X[:, 0] + X[:, 1] * X[:, 1] + X[:, 2] * X[:, 2]


@pytest.mark.parametrize("algo", BOX)
def test_python_function_scalar_and_vectorised(algo):
    bounds = ([-5.0, -4.0, -3.0], [5.0, 4.0, 3.0])
    calls = {"n": 0}

    def f(x):
        calls["n"] += 1
        assert x.shape == (3,)
        return sphere3(x)

    s = pride.minimize(algo, f, bounds=bounds, evals=300, seed=2)
    v = pride.minimize(algo, sphere3_rows, bounds=bounds, evals=300, seed=2, vectorized=True)
    assert calls["n"] == s.evaluations <= 300
    assert v.evaluations == s.evaluations
    assert same_bits(s.best_x, v.best_x) and same_bits(s.history, v.history) and s.best_f == v.best_f
    assert s.best_f == sphere3(s.best_x)
    assert np.all(s.best_x >= bounds[0]) and np.all(s.best_x <= bounds[1])


def test_same_seed_same_bits_other_seed_differs():
    a = pride.minimize("pso", "sphere", dim=5, evals=1000, seed=7)
    b = pride.minimize("pso", "sphere", dim=5, evals=1000, seed=7)
    c = pride.minimize("pso", "sphere", dim=5, evals=1000, seed=8)
    assert same_bits(a.best_x, b.best_x) and not same_bits(a.best_x, c.best_x)


def test_params_iters_instance_and_fixed_dim():
    r = pride.minimize("pso", "sphere", dim=3, iters=4, pop=10, seed=1)
    assert r.iterations == 4 and r.evaluations == 50 and len(r.history) == 5
    j = cli("run", "--problem", "bbob-f3", "--dim", 5, "--instance", 2, "--algo", "ga", "--evals", 500,
            "--param", "pop=20", "--seed", 4, "--json")
    r = pride.minimize("ga", "bbob-f3", dim=5, instance=2, evals=500, pop=20, seed=4)
    assert same_bits([r.best_f], [j["best_f"]]) and r.instance == 2
    fixed = next((p for p in pride.problems() if p["fixed_dim"]), None)
    if fixed:
        r = pride.minimize("pso", fixed["name"], evals=200)
        assert len(r.best_x) == fixed["fixed_dim"]


def test_scalar_bounds_broadcast_and_default_budget():
    r = pride.minimize("pso", lambda x: float(np.sum(x * x)), bounds=(-1, 1), dim=2, pop=10)
    assert len(r.best_x) == 2 and r.evaluations == 20_000  # 10,000 per dimension
