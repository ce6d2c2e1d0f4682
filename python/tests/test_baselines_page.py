"""docs/results/baselines.md says what its committed data give: every generated block is rendered
again from docs/results/data/ by scripts/baselines_page.py and compared with the page, and its
figures exist. Needs nothing but the repository (the regeneration, which runs the campaigns, is
`/usr/bin/python3 scripts/baselines_page.py run`, not a test)."""
import os
import pathlib
import re
import random
import sys

import pytest

REPO = pathlib.Path(os.environ.get("PRIDE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
sys.path.insert(0, str(REPO / "scripts"))

import baselines_page as bp  # noqa: E402


def test_every_generated_block_is_what_the_data_give():
    diffs = bp.check(data=REPO / "docs" / "results" / "data", page=REPO / "docs" / "results" / "baselines.md")
    assert not diffs, "\n\n".join(f"block {name}:\n--- from the data\n{want}\n--- on the page\n{got}"
                                  for name, want, got in diffs)


def test_the_figures_exist_and_the_data_are_compact():
    text = (REPO / "docs" / "results" / "baselines.md").read_text()
    images = re.findall(r"!\[[^]]*\]\((img/[^)]+)\)", text)
    assert len(images) == 2
    for image in images:
        assert (REPO / "docs" / "results" / image).stat().st_size > 10000
    for d in bp.DIMS:
        assert (REPO / "docs" / "results" / "data" / f"baselines-bbob-d{d}.csv").stat().st_size < 2 * 1024 * 1024


def test_the_bbob_data_cover_the_campaign():
    toml = (REPO / "examples" / "campaigns" / "baselines-bbob.toml").read_text()
    algos = re.findall(r'^id = "([^"]+)"', toml, re.M)
    for d in bp.DIMS:
        rows = bp.read_bbob(d, REPO / "docs" / "results" / "data")
        keys = sorted((int(r["function"]), int(r["instance"]), r["algorithm"]) for r in rows)
        assert keys == sorted((f, i, a) for f in range(1, 25) for i in range(1, 16) for a in algos)


def test_the_cec2017_data_are_the_campaigns_and_compact():
    toml = (REPO / "examples" / "campaigns" / "baselines-cec2017.toml").read_text()
    algos = set(re.findall(r'^id = "([^"]+)"', toml, re.M))
    assert f"seeds = {bp.CEC2017_RUNS}" in toml
    path = REPO / "docs" / "results" / "data" / "baselines-cec2017.csv"
    assert path.stat().st_size < 2 * 1024 * 1024
    runs = bp.read_cec("baselines-cec2017", REPO / "docs" / "results" / "data")
    assert {k[2] for k in runs} == algos
    for (fn, dim, _), errors in runs.items():
        assert 1 <= fn <= 30 and dim in bp.CEC2017_DIMS and len(errors) <= bp.CEC2017_RUNS
        assert all(e > -1e-8 for e in errors)  # f >= F* up to rounding


def test_friedman_is_scipys():
    stats = pytest.importorskip("scipy.stats")
    rng = random.Random(7)
    for k, n in ((3, 5), (16, 12), (5, 30)):
        blocks = [[rng.choice([0.0, 1.0, 2.5, rng.random()]) for _ in range(k)] for _ in range(n)]
        chi2, p, ranks = bp.rp.friedman(blocks)
        want = stats.friedmanchisquare(*[[row[j] for row in blocks] for j in range(k)])
        assert chi2 == pytest.approx(want.statistic, rel=1e-12)
        assert p == pytest.approx(want.pvalue, rel=1e-9, abs=1e-15)
        assert sum(ranks) == pytest.approx(k * (k + 1) / 2)
