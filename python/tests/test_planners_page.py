"""docs/results/planners.md says what its committed data give: every generated block is rendered
again from docs/results/data/planners.csv by scripts/planners_page.py and compared with the page.
Needs nothing but the repository (the runs are `scripts/planners_page.py run`, not a test)."""
import os
import pathlib
import sys

REPO = pathlib.Path(os.environ.get("PRIDE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
sys.path.insert(0, str(REPO / "scripts"))

import planners_page as pp  # noqa: E402


def test_every_generated_block_is_what_the_data_give():
    diffs = pp.check(data=REPO / "docs" / "results" / "data", page=REPO / "docs" / "results" / "planners.md")
    assert not diffs, "\n\n".join(f"block {name}:\n--- from the data\n{want}\n--- on the page\n{got}"
                                  for name, want, got in diffs)


def test_the_data_hold_every_run_at_equal_evaluations():
    rows = pp.read(REPO / "docs" / "results" / "data")
    budgeted = [label for label, _, _ in pp.BUDGETED]
    assert len(rows) == len(pp.INSTANCES) * (len(pp.WHOLE_MAP) + len(budgeted) * len(pp.SEEDS))
    for r in rows:
        if r["planner"] in budgeted:
            assert int(r["evaluations"]) <= pp.EVALS
        if r["feasible"] == "1":
            # Grid and polyline paths alike are never shorter than the exact any-angle optimum, and
            # the whole-map optima have gap 0.
            assert float(r["any_angle_gap"]) >= 0.0
            if r["planner"] in ("astar", "jps"):
                assert float(r["grid_gap"]) == 0.0
            if r["planner"] == "any-angle-exact":
                assert float(r["any_angle_gap"]) == 0.0
    # Every metaheuristic run spends exactly the budget (a run stops at it); OMPL's at most.
    for r in rows:
        if r["planner"] in ("ilso", "iqga", "hswoa", "pso-free"):
            assert int(r["evaluations"]) == pp.EVALS
