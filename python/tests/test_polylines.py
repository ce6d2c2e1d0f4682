"""Polyline planners (theta-star, lazy-theta-star, any-angle-exact) and the metrics every planned
path gets in Python: plan()'s polyline, path_metrics and, with gaps=True, the gaps to the shortest
grid and any-angle lengths."""
import math

import numpy as np
import pytest

import pride

ROWS = np.zeros((10, 10))
ROWS[2:8, 4] = 1  # a wall with ways round it


def test_polyline_planners_and_metrics():
    g = pride.Grid(ROWS)
    astar = pride.plan(g, (0, 5), (9, 5), algo="astar", objective="length", gaps=True)
    exact = pride.plan(g, (0, 5), (9, 5), algo="any-angle-exact", objective="length", gaps=True)
    theta = pride.plan(g, (0, 5), (9, 5), algo="theta-star", objective="length", gaps=True)
    for r in (exact, theta):
        assert r.feasible and len(r.path) == 0
        assert r.polyline.dtype == np.float64 and r.polyline.shape[1] == 2
        assert tuple(r.polyline[0]) == (0.0, 5.0) and tuple(r.polyline[-1]) == (9.0, 5.0)
        assert r.path_metrics["length"] == pytest.approx(r.objective_value, rel=1e-12)
        assert r.grid_gap < 0 and r.any_angle_gap >= 0
    assert exact.any_angle_gap == 0.0
    assert exact.objective_value <= theta.objective_value <= astar.objective_value
    # A chain's polyline is its cells, its metrics the chain's.
    assert np.array_equal(astar.polyline, astar.path.astype(float))
    assert astar.path_metrics["turns"] == astar.metrics["turns"]
    assert astar.path_metrics["total_turn_deg"] == astar.metrics["turn_angle_deg"]
    assert astar.grid_gap == 0.0
    assert astar.path_metrics["min_clearance"] == 0.5
    # Without gaps=True: no gap keys.
    plain = pride.plan(g, (0, 5), (9, 5), algo="lazy-theta-star")  # length: a polyline planner's default
    assert plain.objective == "length"
    assert plain.objective_value == pytest.approx(plain.path_metrics["length"], rel=1e-12)
    assert not hasattr(plain, "grid_gap")
    assert math.isfinite(plain.path_metrics["max_curvature"])


def test_polyline_planners_errors():
    g = pride.Grid(ROWS)
    with pytest.raises(ValueError, match="^objective: theta-star plans polylines, whose value is their length"):
        pride.plan(g, (0, 5), (9, 5), algo="theta-star", objective="cells")
    with pytest.raises(TypeError, match="^step_cost: only with an objective that is a function"):
        pride.plan(g, (0, 5), (9, 5), algo="astar", step_cost=lambda previous, direction: 1.0)
    with pytest.raises(TypeError, match="^gaps: "):
        pride.plan(g, (0, 5), (9, 5), algo="astar", gaps="yes")
