"""docs/results/mixint.md says what its committed data give: every generated block is rendered again
from docs/results/data/ by scripts/mixint_page.py and compared with the page; the data cover the
campaign (examples/campaigns/mixint.toml); and a few of its runs, run again by the pride just built,
are the stored ones bit for bit (the full regeneration is `scripts/mixint_page.py run`, not a test)."""
import csv
import os
import pathlib
import re
import subprocess
import sys

from conftest import pride_exe

REPO = pathlib.Path(os.environ.get("PRIDE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
sys.path.insert(0, str(REPO / "scripts"))
import mixint_page as mp  # noqa: E402

DATA = REPO / "docs" / "results" / "data"
PAGE = REPO / "docs" / "results" / "mixint.md"


def test_every_generated_block_is_what_the_data_give():
    diffs = mp.rp.check_page(mp.blocks(DATA), PAGE)
    assert {"mi-made", "mi-ecdf", "mi-summary", "mi-tests-d5", "mi-groups-d20"} <= set(mp.blocks(DATA))
    assert not diffs, "\n\n".join(f"block {name}:\n--- from the data\n{want}\n--- on the page\n{got}"
                                  for name, want, got in diffs)


def test_the_data_cover_the_campaign_and_are_compact():
    functions, instances, dims = mp.suite()
    assert (functions, instances) == (list(range(1, 25)), list(range(1, 16)))
    # COCO's protocol: the instances are the repetitions, one run (seed 1) on each
    assert "seeds = 1" in mp.campaign_text()
    algos = mp.algorithms()
    assert algos[0] == mp.REFERENCE and len(algos) == 6
    for d in dims:
        assert (DATA / f"mixint-d{d}.csv").stat().st_size < 512 * 1024
        rows = mp.read(d, DATA)
        assert sorted((int(r["function"]), int(r["instance"]), r["algorithm"]) for r in rows) == \
            sorted((f, i, a) for f in functions for i in instances for a in algos)
        assert all(int(r["evaluations"]) == mp.per_dim() * d for r in rows)
    images = re.findall(r"!\[[^]]*\]\((img/[^)]+)\)", PAGE.read_text())
    assert len(images) == len(dims)
    for image in images:
        assert (REPO / "docs" / "results" / image).stat().st_size > 10000


def test_the_stated_campaign_reruns_bit_for_bit(tmp_path):
    # Four cheap runs of the campaign (D = 5, 25,000 evaluations each: well under a second in all),
    # two of them ending above f_opt (f23), so that the precision itself is compared.
    exe = pride_exe()
    campaign = tmp_path / "mixint.toml"
    campaign.write_text(mp.subset([2, 23], [3], [5], ["cmaes-margin", "de-relax"]))
    store = tmp_path / "mixint.sqlite"
    subprocess.run([exe, "bench", campaign, "--out", store, "--jobs", "1"], check=True, capture_output=True)
    (tmp_path / "data").mkdir()
    assert mp.export(store, tmp_path / "data") == [5]
    again = mp.read(5, tmp_path / "data")
    assert len(again) == 4
    stored = {(r["function"], r["instance"], r["algorithm"]): r for r in mp.read(5, DATA)}
    for r in again:
        assert r == stored[(r["function"], r["instance"], r["algorithm"])]


def test_the_subset_keeps_the_budget_and_only_the_runs_asked_for():
    text = mp.subset([1], [1, 2], [10], ["ga-round"])
    assert "functions = [1]\n" in text and "instances = [1, 2]\n" in text and "dimensions = [10]\n" in text
    assert re.findall(r'^id = "([^"]+)"', text, re.M) == ["ga-round"]
    assert f"evaluations_per_dim = {mp.per_dim()}\n" in text


def test_the_command_line_refuses_an_unknown_mode_or_option(capsys):
    assert mp.main(["plot"]) == 2
    assert mp.main(["check", "--colour", "red"]) == 2
    assert mp.main([]) == 2
