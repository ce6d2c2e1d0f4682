"""Multi-objective runs from Python (pride.front, pride.plan_front, the Optimizer told (n, M)
arrays): the same runs as ``pride front``, exact budgets, the three ways of giving a function
alike, quality against the reference fronts, and one-line errors."""
import json
import os
import subprocess

import numpy as np
import pytest

import pride

PRIDE = os.environ.get("PRIDE_EXE", "")
MAPS = os.path.join(os.path.dirname(__file__), "..", "..", "examples", "maps")


def schaffer(x):
    return [x[0] ** 2, (x[0] - 2.0) ** 2]


def schaffer_rows(X):
    return np.c_[X[:, 0] ** 2, (X[:, 0] - 2.0) ** 2]


def test_a_catalog_run_is_the_command_lines():
    r = pride.front("nsga2", "zdt1", evals=3000, seed=4)
    assert r.evaluations == 3000
    assert r.f.shape[1] == 2 and r.x.shape == (r.f.shape[0], 30)
    assert r.objectives == ["f1", "f2"]
    assert np.all(np.diff(r.f[:, 0]) > 0)  # distinct, in lexicographic order, non-dominated
    assert np.all(np.diff(r.f[:, 1]) < 0)
    if PRIDE:
        out = subprocess.run([PRIDE, "front", "--algo", "nsga2", "--problem", "zdt1", "--evals", "3000",
                              "--seed", "4", "--json"], check=True, capture_output=True, text=True).stdout
        doc = json.loads(out)
        assert np.array_equal(np.array([p["f"] for p in doc["front"]]), r.f)
        assert doc["quality"]["hypervolume"] == r.quality["hypervolume"]


def test_wfg_takes_n_as_dim_and_m_as_objectives():
    # dim = n = k + l with k = 2 (M - 1): here k = 2 and l = 10; the front is f1^2 / 4 + f2^2 / 16 = 1.
    r = pride.front("nsga2", "wfg4", objectives=2, dim=12, evals=2000, seed=1)
    assert r.x.shape[1] == 12 and r.f.shape[1] == 2
    assert r.quality["nadir"].tolist() == [2.0, 4.0]
    assert 0.5 < r.quality["hypervolume_ratio"] <= 1.0
    with pytest.raises(ValueError, match=r"^wfg3: needs an even l = n - k \(distance parameters\), got l = 21$"):
        pride.front("nsga2", "wfg3", dim=25, evals=100)


def test_every_algorithm_reaches_its_front():
    for algo, problem, evals, least in (("nsga2", "zdt2", 20000, 0.97), ("smsemoa", "zdt1", 10000, 0.97),
                                        ("moead", "zdt1", 25000, 0.95), ("nsga3", "dtlz2", 30000, 0.92)):
        r = pride.front(algo, problem, evals=evals, seed=1)
        assert least < r.quality["hypervolume_ratio"] <= 1.0 + 1e-9, (algo, problem)
        assert r.quality["igd_plus"] < 0.05
        assert r.quality["exact_found"] is None
    r = pride.front("nsga3", "dtlz1", objectives=5, evals=2000)
    assert r.f.shape[1] == 5 and r.x.shape[1] == 9  # M + k - 1, k = 5
    assert pride.front("nsga2", "zdt1", evals=500, reference=False).quality is None


def test_a_constrained_problem_reports_violations_and_is_the_command_lines():
    r = pride.front("nsga2", "constr", evals=4000, seed=2)
    assert r.violation.shape == (r.f.shape[0],) and np.all(r.violation == 0.0)
    assert 1 <= r.first_feasible <= 100
    assert r.quality["hypervolume_ratio"] > 0.95
    assert not hasattr(pride.front("nsga2", "zdt1", evals=500), "violation")
    if PRIDE:
        out = subprocess.run([PRIDE, "front", "--algo", "nsga2", "--problem", "constr", "--evals", "4000",
                              "--seed", "2", "--json"], check=True, capture_output=True, text=True).stdout
        doc = json.loads(out)
        assert np.array_equal(np.array([p["f"] for p in doc["front"]]), r.f)
        assert [p["violation"] for p in doc["front"]] == list(r.violation)
        assert doc["first_feasible"] == r.first_feasible


def test_scalar_vectorized_and_ask_tell_are_one_run():
    a = pride.front("nsga2", schaffer, bounds=([-10], [10]), objectives=2, evals=2000, seed=3)
    b = pride.front("nsga2", schaffer_rows, bounds=([-10], [10]), objectives=2, evals=2000, seed=3, vectorized=True)
    assert np.array_equal(a.f, b.f) and np.array_equal(a.x, b.x)
    assert a.quality is None  # a function has no reference front
    with pride.Optimizer("nsga2", bounds=([-10], [10]), objectives=2, evals=2000, seed=3) as opt:
        told = 0
        while not opt.done:
            X = opt.ask()
            opt.tell(schaffer_rows(X))
            told += len(X)
        assert told == 2000
        assert np.array_equal(opt.result.f, a.f)
    # Schaffer's Pareto set is [0, 2].
    assert a.x.min() > -1e-2 and a.x.max() < 2.0 + 1e-2


@pytest.mark.parametrize("encoding, init", [("free", None), ("chain", None), ("chain", "sitp")])
def test_a_grid_front_holds_legal_paths_scored_as_paths(encoding, init):
    g = pride.Grid.load(os.path.join(MAPS, "zhang2025-20x20.map"))
    r = pride.plan_front(g, (0, 0), (19, 19), objectives=["length", "turns", "clearance"], encoding=encoding,
                         init=init, evals=20000)
    exact = pride.pareto(g, (0, 0), (19, 19), objectives="length,turns,clearance")
    assert r.quality["reference_size"] == len(exact)
    assert r.objectives == ["length", "turns", "clearance"]
    assert len(r.paths) == len(r.f) == len(r.legal)
    for f, path, legal in zip(r.f, r.paths, r.legal):
        assert legal
        assert tuple(path[0]) == (0, 0) and tuple(path[-1]) == (19, 19)
        steps = np.abs(np.diff(path, axis=0)).sum(axis=1)
        assert f[0] == pytest.approx((steps == 1).sum() + (steps == 2).sum() * np.sqrt(2), rel=1e-14)
    # Every point found is weakly dominated by a point of the exact front.
    front = np.array([[p["length"], p["turns"], p["clearance"]] for p in exact])
    for f in r.f:
        assert np.any(np.all(front <= f + 1e-9, axis=1))
    if encoding == "chain":  # the chain operators reach part of this map's exact front (seed 1)
        assert r.quality["exact_found"] >= 3 and r.quality["hypervolume_ratio"] > 0.8


def test_errors_are_one_line_and_name_the_argument():
    with pytest.raises(ValueError, match="^algo: pso optimises one objective"):
        pride.front("pso", "zdt1")
    with pytest.raises(ValueError, match="^objectives: a Python function needs objectives=M"):
        pride.front("nsga2", schaffer, bounds=([0], [1]), evals=100)
    with pytest.raises(ValueError, match="returned 1 values, expected M = 2"):
        pride.front("nsga2", lambda x: [1.0], bounds=([0], [1]), objectives=2, evals=100)
    with pytest.raises(ValueError, match="^vectorized: the function must return an array of shape"):
        pride.front("nsga2", lambda X: X, bounds=([0], [1]), objectives=2, evals=100, vectorized=True)
    with pytest.raises(ValueError, match="^zdt1: has 2 objectives"):
        pride.front("nsga2", "zdt1", objectives=3)
    with pytest.raises(ValueError, match="^problem: unknown multi-objective problem 'sphere'"):
        pride.front("nsga2", "sphere")
    with pytest.raises(ValueError, match="^bounds: only for Python functions"):
        pride.front("nsga2", "zdt1", bounds=([0], [1]))
    with pytest.raises(ValueError, match="^objectives: nsga2 is multi-objective"):
        pride.Optimizer("nsga2", bounds=([0], [1]), evals=100)
    with pytest.raises(ValueError, match="^objectives: pso optimises one objective"):
        pride.Optimizer("pso", bounds=([0], [1]), evals=100, objectives=2)
    with pride.Optimizer("nsga2", bounds=([0], [1]), evals=100, objectives=2) as opt:
        X = opt.ask()
        with pytest.raises(ValueError, match=r"^tell: expected an \(n, 2\) array"):
            opt.tell(np.zeros(len(X)))
    g = pride.Grid(np.zeros((4, 4), dtype=int))
    with pytest.raises(ValueError, match="^encoding: unknown encoding 'tree'"):
        pride.plan_front(g, (0, 0), (3, 3), encoding="tree")
    with pytest.raises(ValueError, match="^algo: moead has no chain operators"):
        pride.plan_front(g, (0, 0), (3, 3), encoding="chain", algo="moead")
    with pytest.raises(ValueError, match="^init: chains start from random walks"):
        pride.plan_front(g, (0, 0), (3, 3), encoding="chain", init="uniform")
    with pytest.raises(TypeError, match="^init: "):
        pride.plan_front(g, (0, 0), (3, 3), encoding="chain", init=3)
    with pytest.raises(ValueError, match="^objectives: "):
        pride.plan_front(g, (0, 0), (3, 3), objectives="length")


def test_a_users_exception_comes_through_unchanged():
    def broken(x):
        raise KeyError("mine")

    with pytest.raises(KeyError, match="mine"):
        pride.front("nsga2", broken, bounds=([0], [1]), objectives=2, evals=100)


def test_a_python_campaign_stores_multiobjective_runs(tmp_path):
    grid = pride.Grid.load(os.path.join(MAPS, "zhang2025-20x20.map"))
    c = pride.Campaign("mo", seeds=2, evals=1500, algorithms=["nsga2"],
                       problems=[{"id": "zdt1", "problem": "zdt1"},
                                 {"id": "dtlz1", "problem": "dtlz1", "objectives": 4},
                                 {"id": "g", "grid": grid, "start": (0, 19), "goal": (19, 0),
                                  "objectives": ["length", "turns"], "encoding": "free"}])
    store = str(tmp_path / "mo.sqlite")
    c.run(store)
    runs = pride.read_store(store, dataframe=False)
    runs = runs["runs"] if isinstance(runs, dict) else runs
    by = {(r["problem"], r["seed"]): r for r in runs}
    assert len(by) == 6
    direct = pride.front("nsga2", "zdt1", evals=1500, seed=2)
    assert by[("zdt1", 2)]["best"] == 1.0 - direct.quality["hypervolume_ratio"]
    assert np.array_equal(by[("zdt1", 2)]["front"], direct.f)  # the stored front, as an (n, M) array
    assert by[("dtlz1", 1)]["front"].shape[1] == 4
    on_grid = pride.plan_front(grid, (0, 19), (19, 0), objectives="length,turns", encoding="free", evals=1500, seed=1)
    assert by[("g", 1)]["best"] == 1.0 - on_grid.quality["hypervolume_ratio"]
    # A single-objective store's runs have no front.
    plain = pride.Campaign("so", seeds=1, evals=20, algorithms=["pso"], problems=[{"id": "s", "problem": "sphere", "dim": 2}])
    plain.run(str(tmp_path / "so.sqlite"))
    assert pride.read_store(str(tmp_path / "so.sqlite"), dataframe=False)[0]["front"] is None
    with pytest.raises(ValueError, match="objectives: only for multi-objective problems"):
        pride.Campaign("bad", seeds=1, evals=10, algorithms=["pso"],
                       problems=[{"id": "s", "problem": "sphere", "dim": 2, "objectives": 2}])
    with pytest.raises(ValueError, match="pso optimises one objective"):
        pride.Campaign("bad", seeds=1, evals=10, algorithms=["pso"], problems=[{"id": "z", "problem": "zdt1"}])
