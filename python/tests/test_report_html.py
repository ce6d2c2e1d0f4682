"""pride.report(store, html=DIR): the HTML report of `pride report --html`, the same page."""
import pathlib
import re

import numpy as np
import pytest

import pride
from conftest import REPO, cli

MAP = REPO / "examples" / "maps" / "zhang2025-20x20.map"


@pytest.fixture(scope="module")
def store(tmp_path_factory):
    folder = tmp_path_factory.mktemp("html")
    toml = folder / "c.toml"
    toml.write_text('name = "py-html"\nseeds = 3\n[budget]\nevaluations = 400\n'
                    '[[suite]]\nname = "bbob"\nfunctions = [1]\ninstances = [1]\ndimensions = [2]\n'
                    f'[[problem]]\nid = "map"\ntype = "grid"\nmap = "{MAP}"\nstart = [0, 19]\ngoal = [19, 0]\n'
                    '[[algorithm]]\nid = "pso"\ntype = "pso"\n[[algorithm]]\nid = "ga"\ntype = "ga"\n')
    path = folder / "c.sqlite"
    pride.Campaign.load(str(toml)).run(path, jobs=2)
    return path


def without_date(html):
    return re.sub(r"<th>report made</th><td>[^<]*</td>", "", html)


def test_report_html_is_the_command_lines_page(store, tmp_path):
    r = pride.report(store, html=tmp_path / "py", dataframe=False)
    assert r["html"] == str(tmp_path / "py" / "index.html")
    assert {x["problem"] for x in r["rows"]} == {"bbob-f1-i1-d2", "map"}
    cli("report", store, "--html", tmp_path / "cli")
    py, line = tmp_path / "py", tmp_path / "cli"
    assert sorted(p.name for p in py.iterdir()) == sorted(p.name for p in line.iterdir())
    assert without_date((py / "index.html").read_text()) == without_date((line / "index.html").read_text())
    figures = re.findall(r'<img src="([^"]+)"', (py / "index.html").read_text())
    assert "paths-map.svg" in figures and "pareto-map.svg" in figures and "ecdf-all.svg" in figures
    assert all((py / f).read_text().startswith("<?xml") for f in figures)


def test_report_html_raw_and_a_map_given_in_code(tmp_path):
    grid = np.zeros((6, 6), dtype=int)
    grid[1:5, 2] = 1
    c = pride.Campaign("code-map", seeds=2, iters=4,
                       problems=[{"id": "g", "grid": pride.Grid(grid), "start": (0, 5), "goal": (5, 0)}],
                       algorithms=["ga", "astar"])
    c.run(tmp_path / "g.sqlite")
    r = pride.report(tmp_path / "g.sqlite", html=str(tmp_path / "page"), raw=True, dataframe=False)
    html = pathlib.Path(r["html"]).read_text()
    assert "The map was given in code" in html and "f as run (--raw)" in html
    assert "algorithm &quot;astar&quot;: astar" in html  # the campaign as pride describes it


@pytest.mark.parametrize("html, error, words", [
    (3, TypeError, "html: expected a folder (str or os.PathLike), got int"),
    (b"page", TypeError, "html: expected a folder (str or os.PathLike), got bytes"),
    ("", ValueError, "html: expected a folder, got ''"),
])
def test_report_html_refuses_what_is_not_a_folder(store, html, error, words):
    with pytest.raises(error) as e:
        pride.report(store, html=html)
    assert str(e.value) == words


def test_report_html_errors_name_the_argument(store, tmp_path):
    with pytest.raises(ValueError, match=r"^html: draws one store; join several"):
        pride.report([store, store], html=tmp_path / "x")
    a_file = tmp_path / "a-file"
    a_file.write_text("text")
    with pytest.raises(ValueError, match=r"^html: .*a-file: exists and is not a folder$"):
        pride.report(store, html=a_file)
    with pytest.raises(ValueError, match=r"^html: .*cannot create the folder"):
        pride.report(store, html=a_file / "sub")
    assert not (tmp_path / "x").exists() and a_file.read_text() == "text"
