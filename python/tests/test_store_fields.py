"""read_store's runs: the best value (a number) and point, iterations, COCO's target hits and a
grid run's path metrics, each equal to what the same run gives outside a campaign; report rows
flag the best algorithm as is_best, never as best."""
import numpy as np
import pytest

import pride

ARRAY = np.zeros((8, 8), dtype=int)
ARRAY[1:7, 3] = 1


@pytest.fixture(scope="module")
def store(tmp_path_factory):
    path = tmp_path_factory.mktemp("fields") / "f.sqlite"
    grid = pride.Grid(ARRAY)
    pride.Campaign("fields", seeds=2, evals=400,
                   problems=[{"id": "sph", "problem": "sphere", "dim": 3},
                             {"id": "g", "grid": grid, "start": (0, 7), "goal": (7, 0), "objective": "length",
                              "path_gaps": True}],
                   algorithms=["pso", "ga"]).run(path)
    return path, grid


def test_best_is_a_value_and_best_x_its_point(store):
    path, _ = store
    runs = pride.read_store(path, dataframe=False)
    sphere = pride.Problem("sphere", 3)
    for r in runs:
        if r["problem"] != "sph":
            assert r["best_x"] is None  # a grid run's solution is its path
            continue
        alone = pride.minimize(r["algorithm"], "sphere", dim=3, evals=400, seed=r["seed"])
        assert isinstance(r["best"], float) and r["best"] == alone.best_f
        assert r["best_x"].shape == (3,) and np.array_equal(r["best_x"], alone.best_x)
        assert sphere(r["best_x"]) == r["best"]
        assert r["iterations"] == alone.iterations and r["evaluations"] == alone.evaluations


def test_target_hits_agree_with_the_history(store):
    path, _ = store
    store_data = pride.read_store(path, dataframe=False)
    sph = [r for r in store_data if r["problem"] == "sph"]
    assert sph
    for r in sph:
        hits = r["target_hits"]
        assert list(hits) and all(isinstance(p, float) for p in hits)
        history, counts = r["history"], r["history_evaluations"]
        for precision, hit in hits.items():
            reached = np.flatnonzero(history <= precision)  # f_opt = 0
            if hit is None:
                assert reached.size == 0
            else:
                k = reached[0]
                assert (counts[k - 1] if k > 0 else 0) < hit <= counts[k]
    grid_runs = [r for r in store_data if r["problem"] == "g"]
    assert all(r["target_hits"] == {} for r in grid_runs)  # no COCO precisions on a grid


def test_path_metrics_of_grid_runs(store):
    path, grid = store
    for r in pride.read_store(path, dataframe=False):
        if r["problem"] != "g":
            assert r["path_metrics"] is None
            continue
        alone = pride.plan(grid, (0, 7), (7, 0), algo=r["algorithm"], objective="length", evals=400,
                           seed=r["seed"], gaps=True)
        m = r["path_metrics"]
        assert m["length"] == pytest.approx(alone.objective_value, rel=1e-12) == pytest.approx(r["best"], rel=1e-12)
        assert m["turns"] == alone.path_metrics["turns"]
        assert set(m) >= {"length", "turns", "total_turn_deg", "max_curvature", "min_clearance", "grid_gap"}


def test_report_flags_the_best_as_is_best(store):
    path, _ = store
    rep = pride.report(path, dataframe=False)
    for row in rep["rows"]:
        assert "best" not in row and isinstance(row["is_best"], bool)
    for problem in ("sph", "g"):
        rows = [row for row in rep["rows"] if row["problem"] == problem]
        assert sum(row["is_best"] for row in rows) == 1
        best = next(row for row in rows if row["is_best"])
        assert best["median"] == min(row["median"] for row in rows)
    assert rep["csv"].splitlines()[0].split(",")[14] == "is_best"
