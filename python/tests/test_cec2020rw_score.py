"""pride.cec2020rw_score (the CEC 2020 real-world competition's ranking, the guidelines' eq. 4-9):
an example worked by hand, its errors, and the eight entrants' published workbooks scored equal to
the competition's own scores (Scoring.txt)."""
import os
import pathlib
import sys

import numpy as np
import pytest

import pride
from conftest import shared_data

REPO = pathlib.Path(os.environ.get("PRIDE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
sys.path.insert(0, str(REPO / "scripts"))
import cec2020rw_page as page  # noqa: E402


def test_an_example_worked_by_hand():
    # The example of tests/test_cec2020rw_score.cpp: P1 (D = 5), P2 (D = 20), three runs each.
    results = {
        "A": (np.array([[1, 3, 2], [10, 10, 10]]), np.array([[0, 0, 0], [1, 3, 2]])),
        "B": (np.array([[0.5, 4, 5], [7, 9, 8]]), np.array([[0.2, 0, 0], [0, 0, 0.5]])),
        "C": (np.array([[2, 2, 2], [6, 6, 6]]), np.zeros((2, 3))),
    }
    s = pride.cec2020rw_score(results, [5, 20])
    assert s["A"]["total"] == pytest.approx(0.016)
    assert s["B"]["best"] == pytest.approx(0.016)
    assert s["B"]["mean"] == pytest.approx(0.008 + 0.016 / 12)
    assert s["B"]["median"] == pytest.approx(0.0176)
    assert s["C"]["total"] == pytest.approx(0.5 * 0.008 / 3)
    assert [s[n]["rank"] for n in "ABC"] == [3, 2, 1]


@pytest.mark.parametrize("results, dims, error, words", [
    ([], [5], TypeError, "results: expected a dict"),
    ({"A": (np.zeros((1, 3)), np.zeros((1, 3)))}, "5", TypeError, "dims: expected a sequence"),
    ({"A": (np.zeros((1, 3)), np.zeros((1, 3)))}, [5.0], TypeError, "dims: expected integers"),
    ({"A": (np.zeros((1, 3)), np.zeros((1, 3)))}, [0], ValueError, "dims: a dimension must be >= 1"),
    ({"A": np.zeros((1, 3))}, [5], TypeError, "results['A']: expected a pair"),
    ({"A": (np.zeros((2, 3)), np.zeros((2, 3)))}, [5], ValueError, "results['A']: f and violation must be (1, runs)"),
    ({"A": (np.zeros((1, 3)), np.zeros((1, 2)))}, [5], ValueError, "same shape"),
    ({"A": (np.full((1, 3), np.inf), np.zeros((1, 3)))}, [5], ValueError, "results['A'], problem 0"),
    ({"A": (np.zeros((1, 3)), -np.ones((1, 3)))}, [5], ValueError, "the violation >= 0"),
    ({"A": (["x"], np.zeros((1, 3)))}, [5], TypeError, "results['A'][0]: expected real numbers"),
    ({}, [5], ValueError, "results: no algorithms"),
])
def test_errors_name_the_argument(results, dims, error, words):
    with pytest.raises(error) as e:
        pride.cec2020rw_score(results, dims)
    assert words in str(e.value)
    assert "\n" not in str(e.value)


def test_a_problem_without_a_result_scores_as_the_worst():
    # B has no result (NaN) on the first problem: it scores 1 there, the others as without it.
    results = {
        "A": (np.array([[1.0], [5.0]]), np.zeros((2, 1))),
        "B": (np.array([[np.nan], [5.0]]), np.zeros((2, 1))),
        "C": (np.array([[3.0], [1.0]]), np.array([[0.0], [2.0]])),
    }
    s = pride.cec2020rw_score(results, [5, 60])
    assert s["A"]["total"] == 0
    assert s["B"]["total"] == pytest.approx(0.008)
    assert s["C"]["total"] == pytest.approx(0.008 + 0.032)
    assert [s[n]["rank"] for n in "ABC"] == [1, 2, 3]


def test_text_cells_of_a_workbook_read_as_nan(tmp_path):
    # A cell holding the shared string "nan" (DEQL's workbook has 650) is NaN, not the string's index 0.
    sheet = ('<worksheet xmlns="http://schemas.openxmlformats.org/spreadsheetml/2006/main"><sheetData>'
             '<row r="1"><c r="A1"><v>2.5</v></c><c r="B1" t="s"><v>0</v></c><c r="C1" t="n"><v>7</v></c></row>'
             '</sheetData></worksheet>')
    import zipfile
    with zipfile.ZipFile(tmp_path / "w.xlsx", "w") as z:
        z.writestr("xl/worksheets/sheet1.xml", sheet)
    row = page.workbook_sheet(tmp_path / "w.xlsx", 1)[0]
    assert row[0] == 2.5 and row[2] == 7
    assert np.isnan(row[1]) and np.isnan(row[3])


def test_the_entrants_scored_equal_the_competitions_scores():
    folder = shared_data("cec2020-rw-results/ranking", "the CEC 2020 real-world entrants' results")
    books = {n: page.entrant(folder, n) for n in page.ENTRANTS}
    ours = page.score(pride, books, range(57))
    published = {row[0]: row for row in page.published_scores(folder)}
    assert len(published) == 8 and sorted(page.CODES.values()) == sorted(published)
    # DEQL's workbook has no result on 14 problems (the text "nan"): they score as its worst.
    f, v = books["DEQL"]
    assert sum(all(np.isnan(x) for x in f[j]) for j in range(57)) == 14
    # Scoring.txt's every score and rank, to the four digits it prints.
    for name, s in ours.items():
        _, best, mean, median, total, rank = published[page.CODES[name]]
        assert [f"{s[k]:.4f}" for k in ("best", "mean", "median", "total")] == \
            [f"{x:.4f}" for x in (best, mean, median, total)], name
        assert s["rank"] == rank, name
