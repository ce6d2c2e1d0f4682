"""docs/results/multiobjective.md says what its committed data give: every generated block is
rendered again from docs/results/data/multiobjective-grids.csv by scripts/multiobjective_page.py
and compared with the page. Needs nothing but the repository (the runs are
`scripts/multiobjective_page.py run`, not a test)."""
import os
import pathlib
import sys

REPO = pathlib.Path(os.environ.get("PRIDE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
sys.path.insert(0, str(REPO / "scripts"))

import multiobjective_page as mp  # noqa: E402


def test_every_generated_block_is_what_the_data_give():
    diffs = mp.check(data=REPO / "docs" / "results" / "data", page=REPO / "docs" / "results" / "multiobjective.md")
    assert not diffs, "\n\n".join(f"block {name}:\n--- from the data\n{want}\n--- on the page\n{got}"
                                  for name, want, got in diffs)


def test_the_data_hold_every_run_at_equal_evaluations():
    rows = mp.read(REPO / "docs" / "results" / "data")
    expected = len(mp.INSTANCES) * (len(mp.CRITERIA) * len(mp.MO_ALGOS) + 1) * len(mp.SEEDS)
    assert len(rows) == expected
    assert {int(r["evaluations"]) for r in rows} == {mp.EVALS}
    for r in rows:
        assert 0 <= int(r["found"]) <= int(r["front"])
        if r["hv_ratio"]:
            assert 0.0 <= float(r["hv_ratio"]) <= 1.0 + 1e-9
