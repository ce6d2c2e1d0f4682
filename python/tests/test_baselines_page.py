"""docs/results/baselines.md says what its committed data give: every generated block is rendered
again from docs/results/data/ by scripts/baselines_page.py and compared with the page, and its
figures exist. Needs nothing but the repository (the regeneration, which runs the campaigns, is
`/usr/bin/python3 scripts/baselines_page.py run`, not a test)."""
import os
import pathlib
import re
import sys

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
