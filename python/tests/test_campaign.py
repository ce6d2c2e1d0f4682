"""Campaigns from Python data (Python functions included) and TOML files, run on threads, the
store and the report read back."""
import math

import numpy as np
import pytest

import pride

ARRAY = np.zeros((6, 6), dtype=int)
ARRAY[1:5, 2] = 1


def test_campaign_from_data(tmp_path):
    calls = {"n": 0}

    def mine(x):
        calls["n"] += 1
        return float(np.sum((x - 0.5) ** 2))

    c = pride.Campaign(
        "demo", seeds=2, evals=300,
        problems=[{"id": "sph", "problem": "sphere", "dim": 3},
                  {"id": "mine", "function": mine, "bounds": (-1, 1), "dim": 2},
                  {"id": "rows", "function": lambda X: np.sum(X * X, axis=1), "bounds": ([-1, -1], [1, 1]),
                   "vectorized": True}],
        algorithms=["pso", {"id": "ga40", "algo": "ga", "pop": 40}])
    assert c.runs == 12 and c.problems == ["sph", "mine", "rows"] and c.algorithms == ["pso", "ga40"]
    store = tmp_path / "demo.sqlite"
    summary = c.run(store, jobs=2)  # Python functions under the GIL, one call at a time
    assert summary == {"stored": 12, "already": 0, "total": 12}
    assert calls["n"] == 2 * 2 * 300
    assert c.run(store, jobs=2)["already"] == 12  # resumable: nothing run twice
    runs = pride.read_store(store, dataframe=False)
    assert len(runs) == 12 and all(r["evaluations"] == 300 for r in runs)
    one = next(r for r in runs if r["problem"] == "sph" and r["algorithm"] == "pso" and r["seed"] == 1)
    assert one["best"] == pride.minimize("pso", "sphere", dim=3, evals=300, seed=1).best_f
    rep = pride.report(store, dataframe=False)
    assert {(r["problem"], r["algorithm"]) for r in rep["rows"]} == {
        (p, a) for p in ("sph", "mine", "rows") for a in ("pso", "ga40")}
    assert sum(r["is_best"] for r in rep["rows"]) == 3 and "sph" in rep["markdown"]


def test_campaign_grid_and_toml(tmp_path):
    g = pride.Grid(ARRAY)
    c = pride.Campaign("grids", seeds=1, iters=3,
                       problems=[{"id": "g", "grid": g, "start": (0, 5), "goal": (5, 0), "objective": "length"}],
                       algorithms=["ga", "astar"])
    c.run(tmp_path / "g.sqlite")
    runs = pride.read_store(tmp_path / "g.sqlite", dataframe=False)
    assert len(runs) == 2 and all(r["optimum"] is not None for r in runs)
    toml = tmp_path / "c.toml"
    toml.write_text('name = "t"\nseeds = 2\n[budget]\nevaluations = 200\n'
                    '[[problem]]\nid = "s"\ntype = "sphere"\ndim = 2\n'
                    '[[algorithm]]\nid = "p"\ntype = "pso"\npop = 10\n')
    t = pride.Campaign.load(str(toml))
    assert t.runs == 2
    t.run(tmp_path / "t.sqlite", jobs=2)
    assert len(pride.read_store(tmp_path / "t.sqlite", dataframe=False)) == 2


def test_campaign_with_a_path_objective_counts_every_call(tmp_path):
    """A function of the path as a grid problem's objective in a campaign: mixed encodings, every
    call an evaluation of some stored run, the exact optimum from its step costs; what each run
    planned on is stored."""
    g = pride.Grid(ARRAY)
    calls = {"n": 0}

    def length(cells):
        calls["n"] += 1
        steps = np.abs(np.diff(cells, axis=0)).sum(axis=1)
        return float((steps == 1).sum() + np.sqrt(2) * (steps == 2).sum())

    step = lambda previous, direction: 1.0 if direction % 2 == 0 else float(np.sqrt(2))
    c = pride.Campaign(
        "user", seeds=2, evals=120,
        problems=[{"id": "g", "grid": g, "start": (0, 5), "goal": (5, 0), "objective": length, "step_cost": step}],
        algorithms=["pso", "iqga", "hswoa", {"id": "ga-chain", "algo": "ga", "encoding": "chain"}, "astar"])
    c.run(tmp_path / "u.sqlite", jobs=2)
    runs = pride.read_store(tmp_path / "u.sqlite", dataframe=False)
    assert len(runs) == 10
    # A* evaluates nothing (its evaluations are node expansions; its value is its step costs' sum).
    assert calls["n"] == sum(r["evaluations"] for r in runs if r["algorithm"] != "astar") == 8 * 120
    encodings = {r["algorithm"]: r["encoding"] for r in runs}
    assert encodings == {"pso": "line", "iqga": "chain", "hswoa": "chain", "ga-chain": "chain", "astar": "none"}
    exact = pride.exact(g, (0, 5), (5, 0), objective="length").objective_value
    assert all(r["optimum"] == pytest.approx(exact, rel=1e-12) for r in runs)
    with pytest.raises(ValueError, match="no per-step costs"):
        pride.Campaign("u", seeds=1, evals=10, algorithms=["exact"],
                       problems=[{"id": "g", "grid": g, "start": (0, 5), "goal": (5, 0), "objective": length}])
    with pytest.raises(TypeError, match=r"^problems\[0\]: step_cost: only with an objective that is a function$"):
        pride.Campaign("u", seeds=1, evals=10, algorithms=["pso"],
                       problems=[{"id": "g", "grid": g, "start": (0, 5), "goal": (5, 0), "objective": "length",
                                  "step_cost": step}])
    with pytest.raises(TypeError, match=r"^problems\[0\]: objective: expected a name or a function"):
        pride.Campaign("u", seeds=1, evals=10, algorithms=["pso"],
                       problems=[{"id": "g", "grid": g, "start": (0, 5), "goal": (5, 0), "objective": 3}])


def test_campaign_budget_per_dimension_and_precision_target(tmp_path):
    c = pride.Campaign("d", seeds=2, evals_per_dim=50, precision=1e-2, algorithms=["pso"],
                       problems=[{"id": "s2", "problem": "sphere", "dim": 2},
                                 {"id": "f1", "problem": "bbob-f1", "dim": 4, "instance": 1}])
    c.run(tmp_path / "d.sqlite")
    runs = pride.read_store(tmp_path / "d.sqlite", dataframe=False)
    assert {r["problem"]: r["evaluations"] for r in runs} == {"s2": 100, "f1": 200}
    rows = pride.report(tmp_path / "d.sqlite", dataframe=False)["rows"]
    f1 = next(r for r in rows if r["problem"] == "f1")
    assert f1["f_opt"] == 79.48 and f1["precision"]
    best = [r["best"] for r in runs if r["problem"] == "f1"]
    assert f1["min"] == min(best) - 79.48
    raw = next(r for r in pride.report(tmp_path / "d.sqlite", raw=True, dataframe=False)["rows"] if r["problem"] == "f1")
    assert raw["min"] == min(best) and not raw["precision"]
    with pytest.raises(ValueError, match="^evals_per_dim: give evals or evals_per_dim, not both$"):
        pride.Campaign("d", seeds=1, evals=10, evals_per_dim=5, algorithms=["pso"],
                       problems=[{"id": "s", "problem": "sphere", "dim": 2}])
    with pytest.raises(ValueError, match="^precision: give target"):
        pride.Campaign("d", seeds=1, evals=10, target=1, precision=1e-8, algorithms=["pso"],
                       problems=[{"id": "s", "problem": "sphere", "dim": 2}])
    with pytest.raises(ValueError, match="^precision: must be a finite number > 0"):
        pride.Campaign("d", seeds=1, evals=10, precision=0, algorithms=["pso"],
                       problems=[{"id": "s", "problem": "sphere", "dim": 2}])


def test_a_function_with_its_optimum_is_reported_in_precision(tmp_path):
    shifted = lambda x: float(np.sum((x - 0.5) ** 2)) + 3.0
    c = pride.Campaign("fo", seeds=3, evals=400, algorithms=["pso", "nlopt:LN_SBPLX"],
                       problems=[{"id": "mine", "function": shifted, "bounds": (-2, 2), "dim": 3, "f_opt": 3}])
    c.run(tmp_path / "fo.sqlite")
    store = pride.read_store(tmp_path / "fo.sqlite", dataframe=False)
    rep = pride.report(tmp_path / "fo.sqlite", dataframe=False)
    for row in rep["rows"]:
        best = [r["best"] for r in store if r["algorithm"] == row["algorithm"]]
        assert row["precision"] and row["f_opt"] == 3.0 and row["min"] == min(best) - 3.0
    assert "Expected running time" in rep["markdown"]  # target hits recorded, as for the catalog's
    with pytest.raises(ValueError, match=r"^problems\[0\]: f_opt is for a function"):
        pride.Campaign("fo", seeds=1, evals=10, algorithms=["pso"],
                       problems=[{"id": "s", "problem": "sphere", "dim": 2, "f_opt": 0}])
    with pytest.raises(TypeError, match=r"^problems\[0\]: f_opt must be a number, got str$"):
        pride.Campaign("fo", seeds=1, evals=10, algorithms=["pso"],
                       problems=[{"id": "m", "function": shifted, "bounds": (-1, 1), "dim": 2, "f_opt": "3"}])
    with pytest.raises(ValueError, match=r"^problems\[0\]: f_opt must be a finite number$"):
        pride.Campaign("fo", seeds=1, evals=10, algorithms=["pso"],
                       problems=[{"id": "m", "function": shifted, "bounds": (-1, 1), "dim": 2, "f_opt": float("nan")}])


def test_campaign_errors(tmp_path):
    with pytest.raises(ValueError, match="unknown algorithm"):
        pride.Campaign("x", seeds=1, evals=10, problems=[{"id": "s", "problem": "sphere", "dim": 2}],
                       algorithms=["nope"])
    with pytest.raises(ValueError, match="id"):
        pride.Campaign("x", seeds=1, evals=10, problems=[{"problem": "sphere", "dim": 2}], algorithms=["pso"])
    with pytest.raises(ValueError, match="unknown key 'colour'"):
        pride.Campaign("x", seeds=1, evals=10, problems=[{"id": "s", "problem": "sphere", "dim": 2, "colour": 1}],
                       algorithms=["pso"])

    class Boom(Exception):
        pass

    def bad(x):
        raise Boom()

    c = pride.Campaign("x", seeds=2, evals=50, problems=[{"id": "b", "function": bad, "bounds": ([0], [1])}],
                       algorithms=["pso"])
    with pytest.raises(Boom):
        c.run(tmp_path / "x.sqlite", jobs=2)


def test_friedman_critical_difference_is_nemenyis(tmp_path):
    """report()["friedman"]["critical_difference"]: Nemenyi's CD = q_0.05 sqrt(k (k + 1) / (6 N))
    (Demsar 2006, q from scipy's studentized range), its groups joining algorithms whose average
    ranks differ by less, as the markdown prints them."""
    scipy_stats = pytest.importorskip("scipy.stats")
    c = pride.Campaign("cd", seeds=2, evals=200,
                       problems=[{"id": f"p{d}", "problem": "sphere", "dim": d} for d in (2, 3, 4)]
                       + [{"id": "r2", "problem": "rastrigin", "dim": 2}],
                       algorithms=["pso", "ga", "woa"])
    c.run(tmp_path / "c.sqlite", jobs=2)
    r = pride.report(tmp_path / "c.sqlite", dataframe=False)
    f = r["friedman"]
    cd = f["critical_difference"]
    k, n = len(f["algorithms"]), f["problems"]
    q = scipy_stats.studentized_range.ppf(0.95, k, np.inf) / math.sqrt(2)
    assert cd["alpha"] == 0.05
    assert cd["cd"] == pytest.approx(q * math.sqrt(k * (k + 1) / (6 * n)), rel=1e-9)
    ranks = dict(zip(f["algorithms"], f["average_ranks"]))
    for group in cd["cliques"]:
        assert len(group) >= 2
        assert max(ranks[a] for a in group) - min(ranks[a] for a in group) < cd["cd"]
    assert f"CD = {cd['cd']:.3g}" in r["markdown"]


def test_read_store_gives_cocos_trace_of_each_run(tmp_path):
    """trace_targets / trace_evaluations: (evaluations, best so far) at COCO's triggers, the
    first evaluation first, evaluations increasing and values never rising; the target trace
    holds the first evaluation that reached each power of ten above f_opt."""
    c = pride.Campaign("trace", seeds=2, evals=500,
                       problems=[{"id": "b", "problem": "bbob-f1", "dim": 2, "instance": 1}],
                       algorithms=["pso"])
    c.run(tmp_path / "c.sqlite")
    for run in pride.read_store(tmp_path / "c.sqlite", dataframe=False):
        for key in ("trace_targets", "trace_evaluations"):
            t = run[key]
            assert t.ndim == 2 and t.shape[1] == 2 and t.shape[0] >= 2
            assert t[0, 0] == 1
            assert np.all(np.diff(t[:, 0]) > 0) and np.all(np.diff(t[:, 1]) <= 0)
            assert t[-1, 0] <= run["evaluations"] and t[-1, 1] >= run["best"]
        # floor(10^(k/20)) gives 1 ... 8, then 10; 2 x {1, 2, 5} gives 2, 4, 10: 9 is no trigger
        assert list(run["trace_evaluations"][:9, 0]) == [1, 2, 3, 4, 5, 6, 7, 8, 10]
        # the last target trigger is within a twentieth of a decade of the best precision
        f_opt = 79.48  # bbob-f1, instance 1
        last, best = run["trace_targets"][-1, 1] - f_opt, run["best"] - f_opt
        assert last < 10 ** (1 / 20) * best or last <= 1e-8


def test_a_campaign_file_with_a_published_protocol(tmp_path):
    # protocol = "bbob-2009": instances 1-5, 3 trials each (docs/campaigns.md, "Published protocols").
    path = tmp_path / "p.toml"
    path.write_text('name = "p"\nprotocol = "bbob-2009"\n[budget]\nevaluations_per_dim = 20\n'
                    '[[suite]]\nname = "bbob"\nfunctions = [1]\ndimensions = [2]\n'
                    '[[algorithm]]\nid = "pso"\ntype = "pso"\n')
    c = pride.Campaign.load(path)
    assert c.seeds == 3
    assert c.runs == 5 * 3
    counts = c.run(tmp_path / "p.sqlite")
    assert (counts["already"], counts["total"]) == (0, 15)
    path.write_text(path.read_text().replace('protocol = "bbob-2009"\n', 'protocol = "bbob-2009"\nseeds = 2\n'))
    with pytest.raises(ValueError, match=r"p\.toml:2: protocol 'bbob-2009': BBOB 2009 ran 3 trials per instance"):
        pride.Campaign.load(path)
