"""docs/results/constraints.md says what its committed data give: every generated block of both its
sections (CEC 2006, bbob-constrained) is rendered again by scripts/constraints_page.py and compared
with the page, and the data cover the campaigns (the regeneration, which runs them, is
`scripts/constraints_page.py run`, not a test)."""
import csv
import os
import pathlib
import sys

REPO = pathlib.Path(os.environ.get("PRIDE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
sys.path.insert(0, str(REPO / "scripts"))
import constraints_page as page  # noqa: E402


def test_every_generated_block_is_what_the_data_give():
    diffs = page.check()
    assert {name for name, _, _ in diffs} <= set(page.blocks())
    assert {"ch-tests", "cb-tests"} <= set(page.blocks())
    assert not diffs, "\n\n".join(f"block {name}:\n--- from the data\n{want}\n--- on the page\n{got}"
                                  for name, want, got in diffs)


def test_the_data_cover_the_campaign_and_are_compact():
    path = REPO / "docs" / "results" / "data" / page.CSV
    assert path.stat().st_size < 1024 * 1024
    with open(path, newline="") as fh:
        keys = sorted((r["problem"], r["algorithm"], int(r["seed"])) for r in csv.DictReader(fh))
    assert "seeds = 25" in page.CAMPAIGN.read_text()
    assert keys == sorted((p, c[0], s) for p in page.problems() for c in page.configs() for s in range(1, 26))
    assert len(page.configs()) == 12 and len(page.problems()) == 24


def test_the_bbob_constrained_data_cover_its_campaign_and_are_compact():
    path = REPO / "docs" / "results" / "data" / page.BBOB_CSV
    assert path.stat().st_size < 1024 * 1024
    with open(path, newline="") as fh:
        keys = sorted((int(r["function"]), int(r["instance"]), r["algorithm"], int(r["seed"]))
                      for r in csv.DictReader(fh))
    functions, instances, dim = page.bbob_suite()
    assert (functions, instances, dim) == (list(range(1, 55)), list(range(1, 16)), 5)
    # COCO's protocol: the instances are the repetitions, one run (seed 1) on each
    assert "seeds = 1" in page.BBOB_CAMPAIGN.read_text()
    assert page.configs(page.BBOB_CAMPAIGN) == page.configs()
    assert keys == sorted((f, i, c[0], 1) for f in functions for i in instances for c in page.configs())
