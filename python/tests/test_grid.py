"""Grids: from numpy arrays and map files, inflation, every grid algorithm with legal paths,
A*, the exact optimum, the Pareto front, and the command line's results."""
import numpy as np
import pytest

import pride
from conftest import cli, shared_data

ALGOS = pride.algorithms()

# 0 free, 1 blocked; rows top first, x the column.
ARRAY = np.array([
    [0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0],
    [0, 1, 1, 1, 0, 0, 0, 1, 1, 0, 0, 0],
    [0, 0, 0, 1, 0, 1, 0, 0, 1, 0, 1, 0],
    [0, 1, 0, 1, 0, 1, 1, 0, 1, 0, 1, 0],
    [0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0],
    [0, 1, 1, 1, 1, 0, 1, 1, 1, 0, 1, 0],
    [0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0],
    [1, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0],
])
START, GOAL = (0, 7 - 1), (11, 7)


def legal(grid, path, start, goal):
    a = grid.to_array()
    assert path.ndim == 2 and path.shape[1] == 2
    assert tuple(path[0]) == start and tuple(path[-1]) == goal
    for (x, y) in path:
        assert a[y, x] == 0
    for (x0, y0), (x1, y1) in zip(path[:-1], path[1:]):
        dx, dy = x1 - x0, y1 - y0
        assert max(abs(dx), abs(dy)) == 1
        if dx and dy:  # no corner cutting
            assert a[y0, x1] == 0 and a[y1, x0] == 0
    return True


def test_grid_from_array_and_inflation():
    g = pride.Grid(ARRAY)
    assert (g.width, g.height) == (12, 8)
    assert np.array_equal(g.to_array(), ARRAY)
    assert g.free(0, 0) and not g.free(1, 1)
    h = g.inflated(1)
    assert h.to_array().sum() > ARRAY.sum() and not h.free(0, 0)
    assert np.array_equal(pride.Grid(ARRAY.astype(bool)).to_array(), ARRAY)
    with pytest.raises(ValueError, match=r"array: cell \(2,0\) is 2"):
        pride.Grid(np.array([[0, 0, 2]]))
    with pytest.raises(ValueError, match="2-D"):
        pride.Grid(np.zeros(3))
    with pytest.raises(ValueError, match="inflate"):
        g.inflated(-1)


def algorithm_cases():
    for a in ALGOS:
        if "grid" in a["spaces"]:
            yield a["name"], ""  # a whole-map planner takes no encoding (a ValueError)
        if "box" in a["spaces"]:
            yield a["name"], "line"
        if "chain" in a["spaces"]:
            yield a["name"], "chain"


@pytest.mark.parametrize("algo, encoding", sorted(set(algorithm_cases())))
def test_every_grid_algorithm_plans_a_legal_path(algo, encoding):
    g = pride.Grid(ARRAY)
    # Whole-map planners take no budget, bar the sampling ones (ompl:..., when built): their
    # validity checks are evaluations.
    whole_map = any(a["name"] == algo and "grid" in a["spaces"] for a in ALGOS) and not algo.startswith("ompl:")
    budget = {} if whole_map else {"evals": 3000 if algo.startswith("ompl:") else 120}
    # The length objective: the polyline planners (theta-star, ...) take no other.
    r = pride.plan(g, START, GOAL, algo=algo, encoding=encoding, objective="length", seed=3, **budget)
    if r.feasible and len(r.path) == 0:  # a polyline planner's path: its polyline, no cells
        assert r.metrics is None and tuple(r.polyline[0]) == START and tuple(r.polyline[-1]) == GOAL
        assert r.path_metrics["length"] == pytest.approx(r.objective_value)
    elif r.feasible:
        assert legal(g, r.path, START, GOAL)
        assert r.metrics["cells"] == len(r.path)
        assert np.array_equal(r.polyline, r.path.astype(float))
    else:
        assert len(r.path) == 0 and len(r.polyline) == 0 and r.path_metrics is None
    if algo in ("astar", "exact"):
        assert r.feasible


def test_astar_exact_and_oracle():
    g = pride.Grid(ARRAY)
    a = pride.astar(g, START, GOAL, objective="length")
    e = pride.exact(g, START, GOAL, objective="length")
    assert legal(g, a.path, START, GOAL) and legal(g, e.path, START, GOAL)
    assert a.objective_value == pytest.approx(e.objective_value)
    r = pride.plan(g, START, GOAL, algo="ga", objective="length", iters=5, oracle=True, seed=1)
    assert r.optimum == pytest.approx(e.objective_value) and r.gap >= 0


def test_pareto_front():
    g = pride.Grid(ARRAY)
    front = pride.pareto(g, START, GOAL, objectives="length,turns")
    assert front and all(legal(g, p["path"], START, GOAL) for p in front)
    lengths = [p["length"] for p in front]
    turns = [p["turns"] for p in front]
    assert lengths == sorted(lengths) and turns == sorted(turns, reverse=True)
    assert front[0]["length"] == pytest.approx(pride.exact(g, START, GOAL, objective="length").objective_value)


def test_pareto_front_with_clearance():
    # Clearance (docs/grid.md): cells beside an obstacle cost 3, then 2 and 1 by distance band. The
    # front trades length for it: its ends are the shortest path and the least clearance, and a
    # point's clearance is what its path pays (start and goal included).
    g = pride.Grid(ARRAY)
    front = pride.pareto(g, START, GOAL, objectives="length,clearance")
    assert front and all("clearance" in p and legal(g, p["path"], START, GOAL) for p in front)
    lengths = [p["length"] for p in front]
    clearance = [p["clearance"] for p in front]
    assert lengths == sorted(lengths) and clearance == sorted(clearance, reverse=True)
    assert front[0]["length"] == pytest.approx(pride.exact(g, START, GOAL, objective="length").objective_value)
    assert "clearance" not in pride.pareto(g, START, GOAL, objectives="length,turns")[0]


def test_bad_grid_arguments():
    g = pride.Grid(ARRAY)
    with pytest.raises(ValueError, match="start"):
        pride.plan(g, (1, 1), GOAL, algo="astar")
    with pytest.raises(ValueError, match="goal"):
        pride.plan(g, START, (50, 0), algo="astar")
    with pytest.raises(ValueError, match="encoding"):
        pride.plan(g, START, GOAL, encoding="spiral")
    with pytest.raises(TypeError, match="start"):
        pride.plan(g, "0,6", GOAL)
    with pytest.raises(ValueError, match="objectives"):
        pride.pareto(g, START, GOAL, objectives="length,colour")


def test_map_file_equals_cli():
    path = shared_data("movingai/random-32-32-10.map", "Moving AI maps")
    g = pride.Grid.load(str(path))
    a = g.to_array()
    free = [(x, y) for y in range(g.height) for x in range(g.width) if a[y, x] == 0]
    start, goal = free[0], free[-1]
    for algo, extra in (("pso", ["--iters", 5]), ("ga", ["--iters", 5, "--encoding", "chain"]), ("astar", [])):
        kw = {"iters": 5} if extra else {}
        if "chain" in extra:
            kw["encoding"] = "chain"
        r = pride.plan(g, start, goal, algo=algo, seed=2, objective="length", **kw)
        j = cli("path", "--map", path, "--start", "%d,%d" % start, "--goal", "%d,%d" % goal, "--algo", algo,
                "--seed", 2, "--objective", "length", "--json", *extra)
        assert r.path.tolist() == j["path"]
        assert r.objective_value == j["objective_value"] and r.history.tolist() == j["history"]
    inflated = pride.Grid.load(str(path), inflate=1)
    assert inflated.to_array().sum() > a.sum()


def test_plan_observer_on_boxes_refused_on_chains():
    g = pride.Grid(ARRAY)
    seen = []
    r = pride.plan(g, START, GOAL, algo="pso", iters=4, pop=6, seed=1,
                   callback=lambda i, e, f, pop, fit: seen.append((i, pop.shape)))
    assert [s[0] for s in seen] == [0, 1, 2, 3, 4] and seen[0][1][0] == 6 and r.iterations == 4
    with pytest.raises(ValueError, match="observer: only box runs are observed"):
        pride.plan(g, START, GOAL, algo="ga", encoding="chain", iters=2, callback=lambda *a: None)
    with pytest.raises(ValueError, match="observer"):
        pride.plan(g, START, GOAL, algo="astar", callback=lambda *a: None)


def test_plan_uses_the_algorithms_native_space():
    """Without an encoding each algorithm plans on its paper's space; one it cannot use is refused."""
    g = pride.Grid(ARRAY)
    assert pride.plan(g, START, GOAL, algo="pso", evals=60, seed=1).encoding == "line"
    assert pride.plan(g, START, GOAL, algo="iqga", objective="iqga", evals=200, seed=1).encoding == "chain"
    assert pride.plan(g, START, GOAL, algo="hswoa", objective="hswoa", evals=60, seed=1).encoding == "chain"
    assert pride.plan(g, START, GOAL, algo="ga", encoding="chain", evals=60, seed=1).encoding == "chain"
    with pytest.raises(ValueError, match="^encoding line: iqga runs on chain, not on line"):
        pride.plan(g, START, GOAL, algo="iqga", encoding="line", evals=60)
    with pytest.raises(TypeError, match=r"^parameter shortcut: expected one of none, line or elbow \(a str\), got int$"):
        pride.plan(g, START, GOAL, algo="hswoa", evals=60, shortcut=1)
    r = pride.plan(g, START, GOAL, algo="hswoa", evals=60, seed=1, shortcut="elbow", walks="octile")
    assert r.feasible and r.evaluations == 60


def test_a_function_as_the_objective_every_call_counted():
    """A callable on the path's cells is the objective: every call an evaluation, for every grid
    algorithm and encoding; with its per-step form, exact finds its optimum."""
    g = pride.Grid(ARRAY)
    calls = []
    kept = []

    def length(cells):
        calls.append(len(cells))
        kept.append(cells)  # the arrays are the function's to keep
        steps = np.abs(np.diff(cells, axis=0)).sum(axis=1)
        return float((steps == 1).sum() + np.sqrt(2) * (steps == 2).sum())

    for a in ALGOS:
        if "grid" in a["spaces"] or a["name"].startswith("nlopt:") and a["name"] != "nlopt:LN_SBPLX":
            continue
        encodings = (["line", "free"] if "box" in a["spaces"] else []) + (["chain"] if "chain" in a["spaces"] else [])
        for encoding in encodings:
            calls.clear()
            r = pride.plan(g, START, GOAL, algo=a["name"], objective=length, encoding=encoding, evals=90, seed=2)
            assert len(calls) == r.evaluations == 90, (a["name"], encoding)
            if r.feasible:
                assert r.objective_value == pytest.approx(r.metrics["length"], abs=1e-12)
    assert all(k.dtype.kind == "i" and k.shape[1] == 2 for k in kept)
    step = lambda previous, direction: 1.0 if direction % 2 == 0 else float(np.sqrt(2))
    calls.clear()
    exact = pride.plan(g, START, GOAL, algo="exact", objective=length, step_cost=step)
    astar = pride.plan(g, START, GOAL, algo="astar", objective=length, step_cost=step)
    by_name = pride.plan(g, START, GOAL, algo="exact", objective="length")
    assert exact.optimum == pytest.approx(by_name.optimum, rel=1e-12)
    assert astar.objective_value == pytest.approx(by_name.optimum, rel=1e-12)
    with_oracle = pride.plan(g, START, GOAL, algo="ga", objective=length, step_cost=step, oracle=True, evals=90)
    assert with_oracle.gap >= 0
    assert len(calls) == 90  # the planners and the oracle use the step costs: no call of the objective
    with pytest.raises(ValueError, match="^step_cost: the per-step costs give an optimum of 1[0-9.]*, but a run "
                                         "found a path the objective values at [0-9.]*: the two must agree"):
        pride.plan(g, START, GOAL, algo="ga", objective=length, step_cost=lambda p, d: 10.0, oracle=True, evals=90)
    with pytest.raises(ValueError, match="no per-step costs"):
        pride.plan(g, START, GOAL, algo="exact", objective=length)
    with pytest.raises(TypeError, match="^objective: the function must return one number, got str$"):
        pride.plan(g, START, GOAL, algo="pso", objective=lambda cells: "short", evals=10)
    with pytest.raises(TypeError, match="^step_cost: only with an objective that is a function$"):
        pride.plan(g, START, GOAL, algo="exact", objective="length", step_cost=step)
    with pytest.raises(ZeroDivisionError):
        pride.plan(g, START, GOAL, algo="ga", objective=lambda cells: 1 / 0, evals=10)
