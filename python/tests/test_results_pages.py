"""The results pages docs/results/zhang2025.md and docs/results/cai2021.md say what their committed
data give: every generated block of a page (between `<!-- generated: NAME -->` and `<!-- end
generated: NAME -->`) is rendered again from the compact stores in docs/results/data/ by the scripts
that wrote it (scripts/results_pages.py, zhang2025_tables.py, cai2021_tables.py) and compared with the
page's text, so that neither can change without the other. Needs nothing but the repository (no
build, no pride, no scipy); the full regeneration, which runs the campaigns, is the documented
command `/usr/bin/python3 scripts/results_pages.py`, not a test."""
import csv
import os
import pathlib
import re
import sys

import pytest

REPO = pathlib.Path(os.environ.get("PRIDE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
sys.path.insert(0, str(REPO / "scripts"))

import zhang2025_tables  # noqa: E402
import cai2021_tables  # noqa: E402
import results_pages as rp  # noqa: E402

PROBLEMS = {**zhang2025_tables.PROBLEMS, **cai2021_tables.PROBLEMS}


@pytest.mark.parametrize("page", sorted(rp.PAGES))
def test_every_generated_block_is_what_the_data_give(page):
    diffs = rp.check(page, repo=REPO, data=REPO / "docs" / "results" / "data")
    assert not diffs, "\n\n".join(
        f"{rp.PAGES[page]['page']}, block {name}:\n--- rendered from docs/results/data\n{exp}\n--- on the page\n{got}"
        for name, exp, got in diffs) + "\n(regenerate: /usr/bin/python3 scripts/results_pages.py render, or in full)"


@pytest.mark.parametrize("page", sorted(rp.PAGES))
def test_the_page_has_its_blocks_and_figures(page):
    text = (REPO / rp.PAGES[page]["page"]).read_text()
    assert set(rp.page_blocks(text)) == set(rp.render(page)), "a block is missing on the page or made by no script"
    for image in re.findall(r"!\[[^]]*\]\((img/[^)]+)\)", text):
        assert (REPO / "docs" / "results" / image).is_file(), image


def test_the_stores_are_compact_and_complete():
    data = REPO / "docs" / "results" / "data"
    for f in data.iterdir():
        assert f.stat().st_size < 2 * 1024 * 1024, f"{f.name} is {f.stat().st_size} bytes"
    for page in rp.PAGES.values():
        for name in page["campaigns"]:
            toml = (rp.CAMPAIGNS / f"{name}.toml").read_text()
            seeds = int(re.search(r"^seeds\s*=\s*(\d+)", toml, re.M).group(1))
            problems, algorithms = rp.campaign_problems(toml), rp.campaign_algorithms(toml)
            with open(data / f"{name}.csv", newline="") as f:
                rows = list(csv.DictReader(f))
            keys = [(r["problem"], r["algorithm"], int(r["seed"])) for r in rows]
            assert sorted(keys) == sorted((p, a, s) for p in problems for a in algorithms for s in range(1, seeds + 1)), name


def read_map(path):
    lines = pathlib.Path(path).read_text().splitlines()
    i = lines.index("map")
    return [row for row in lines[i + 1:] if row]


def test_every_stored_path_is_legal():
    """From the problem's start to its goal, 8-connected steps on free cells, no corner cut
    (the grids' default), and the stored value is length + turns for the hswoa campaigns."""
    data = REPO / "docs" / "results" / "data"
    maps = {pid: read_map(REPO / m) for pid, (m, _, _) in PROBLEMS.items()}
    for page in rp.PAGES.values():
        for name in page["campaigns"]:
            for r in rp.read_campaign(name, data):
                m, s, g = PROBLEMS[r.problem]
                cells = rp.decode_path(r.path)
                assert cells[0] == tuple(map(int, s.split(","))) and cells[-1] == tuple(map(int, g.split(","))), \
                    (name, r.problem, r.algorithm, r.seed)
                grid = maps[r.problem]
                for (x0, y0), (x1, y1) in zip(cells, cells[1:]):
                    assert grid[y1][x1] == "." and grid[y0][x1] == "." and grid[y1][x0] == ".", \
                        (name, r.problem, r.algorithm, r.seed, (x1, y1))
                if name.startswith("cai2021"):
                    assert abs(r.best - (r.length + r.turns)) < 1e-9, (name, r.problem, r.algorithm, r.seed)


def test_the_same_run_in_two_stores_is_the_same():
    """A run depends only on (problem, algorithm and its parameters, seed): where two campaigns hold
    the same runs, their compact stores agree in everything but the wall time."""
    data = REPO / "docs" / "results" / "data"

    def runs(name, algorithm, rename=None):
        return {(r.problem, r.seed): (r.best, r.evaluations, r.iterations, r.conv_iter, r.conv_evals, r.path)
                for r in rp.read_campaign(name, data) if r.algorithm == algorithm}

    pairs = [(("zhang2025", "iqga"), ("zhang2025-iqga", "iqga")),
             (("zhang2025", "ga"), ("zhang2025-generations", "ga")),  # 7,840 evaluations are its 200 generations
             (("cai2021-sweep", "thr2"), ("cai2021-ablation", "hswoa")),
             (("cai2021-sweep-iterations", "thr2"), ("cai2021-ablation-iterations", "hswoa")),
             (("cai2021-ablation", "woa"), ("cai2021-ablation-iterations", "woa")),  # 1,020 evaluations = 50 iterations
             (("cai2021-envs", "woa"), ("cai2021-envs-iterations", "woa"))]
    for a, b in pairs:
        x, y = runs(*a), runs(*b)
        assert x and x == y, (a, b)


def test_the_statistics_are_scipys():
    """The pure-Python tests of results_pages.py against scipy 1.10's values for the same data."""
    x, y = [1, 2, 2, 3, 5, 8, 8, 9], [2, 4, 4, 6, 7, 7, 10, 11, 12]
    assert rp.rank_sum(x, y) == pytest.approx(0.22704510161078895, rel=1e-12)  # mannwhitneyu, asymptotic
    h, p = rp.kruskal([[1, 2, 2, 3, 5], [4, 4, 6, 7, 7], [8, 8, 9, 10, 1]])
    assert h == pytest.approx(5.968288288288287, rel=1e-12) and p == pytest.approx(0.050582776594302395, rel=1e-10)
    assert rp.fisher_exact(59, 1, 4, 56) == pytest.approx(7.036722677276641e-28, rel=1e-9)
    assert rp.fisher_exact(11, 49, 0, 60) == pytest.approx(0.0005905152115232917, rel=1e-9)
    assert rp.chi2_sf(16.91, 4) == pytest.approx(0.002012341523438762, rel=1e-10)
    assert rp.holm([0.01, 0.04, 0.03, 0.5]) == pytest.approx([0.04, 0.09, 0.09, 0.5])
