"""docs/results/cec2020rw.md says what its committed runs and the entrants' published results give:
every generated block is rendered again by scripts/cec2020rw_page.py and compared with the page.
The entrants' results are public data of others, read from $PRIDE_DATA (the test is skipped
without them); the regeneration of pride's runs is `scripts/cec2020rw_page.py run`, not a test."""
import csv
import os
import pathlib
import sys

from conftest import shared_data

REPO = pathlib.Path(os.environ.get("PRIDE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
sys.path.insert(0, str(REPO / "scripts"))
import cec2020rw_page as page  # noqa: E402


def test_the_runs_follow_the_protocol():
    path = REPO / "docs" / "results" / "data" / "cec2020rw.csv"
    assert path.stat().st_size < 1024 * 1024
    with open(path, newline="") as fh:
        rows = list(csv.DictReader(fh))
    keys = sorted((r["config"], int(r["problem"][2:]), int(r["seed"])) for r in rows)
    want = sorted((c, k, s) for c in page.CONFIGS for k in range(1, 58) if k not in page.MISSING
                  for s in range(1, page.RUNS + 1))
    assert keys == want
    for r in rows:
        k = int(r["problem"][2:])
        assert int(r["evaluations"]) == page.budget(page.DIMS[k - 1]), r
        assert float(r["violation"]) >= 0.0


def test_every_generated_block_is_what_the_data_give():
    shared_data("cec2020-rw-results/ranking", "the CEC 2020 real-world entrants' results")
    diffs = page.check()
    assert not diffs, "\n\n".join(f"block {name}:\n--- from the data\n{want}\n--- on the page\n{got}"
                                  for name, want, got in diffs)


def test_the_stored_runs_are_what_pride_computes_today():
    # Runs of the page, run again by this build: the same bits (one seed, one result).
    from conftest import cli
    with open(REPO / "docs" / "results" / "data" / "cec2020rw.csv", newline="") as fh:
        rows = {(r["config"], r["problem"], r["seed"]): r for r in csv.DictReader(fh)}
    for config, problem, seed in (("colshade", "RC08", "1"), ("colshade", "RC17", "2"), ("colshade", "RC10", "25"),
                                  ("colshade", "RC24", "3"), ("colshade-paper", "RC04", "7"),
                                  ("colshade-paper", "RC12", "11")):
        k = int(problem[2:])
        got = cli("run", *page.CONFIGS[config], "--problem", f"cec2020rw-rc{k:02}", "--dim", page.DIMS[k - 1],
                  "--evals", page.budget(page.DIMS[k - 1]), "--seed", seed, "--json")
        want = rows[(config, problem, seed)]
        assert repr(float(got["best_f"])) == want["f"]
        assert repr(float(got["best_violation"])) == want["violation"]
        assert str(got["first_feasible"] or "") == want["first_feasible"]
