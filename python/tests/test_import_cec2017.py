"""Published runs in a store (pride.import_cec2017, `pride import --cec2017`): the CEC 2017 entrants'
own result files ($PRIDE_DATA/cec2017-results) imported, and `pride report --format cec-csv` held
against the statistics computed here from the same files and against the competition's summary
workbooks (tests/data/cec2017_results); pride's jso beside the published jSO in one report, compared
where the protocol (MaxFES = 10000 D) is the same."""
import csv
import io
import math
import re
import statistics

import pytest

import pride
from conftest import REPO, cli, shared_data

# folder -> (name, how its files are laid out: what the test parses independently of pride).
ENTRANTS = {
    "A01": "jSO",                       # blanks
    "A03": "IDEbestNsize",              # blanks, NAME_D_F, exponents as e+010
    "A05": "LSHADE_SPACMA",             # blanks
    "A06": "DES",                       # commas
    "A09": "PPSO",                      # tabs
    "A10/res_soco2010": "MOS-SOCO2011",  # a header line, labelled rows, commas (.csv)
    "A12": "EBOwithCMAR",               # blanks (.dat)
}
DIMENSIONS = (10, 30, 50, 100)


def _errors(path):
    """A result file's 14 rows of errors, a row per checkpoint, the 1e-8 rule applied."""
    rows = []
    for line in path.read_text().splitlines():
        if not line.strip() or "Run 1" in line:
            continue
        cells = line.split(",") if "," in line else line.split()
        if "FEs" in cells[0]:
            cells = cells[1:]
        rows.append([0.0 if float(c) < 1e-8 else float(c) for c in cells if c.strip()])
    assert len(rows) == 14 and all(len(r) == 51 for r in rows), path
    return rows


def _files(folder):
    """(function, dimension) -> the entrant's file."""
    out = {}
    for p in folder.iterdir():
        m = re.fullmatch(r".+_(\d+)_(\d+)\.(txt|dat|csv)", p.name)
        if m:
            a, b = int(m.group(1)), int(m.group(2))
            out[(b, a) if folder.name == "A03" else (a, b)] = p
    assert len(out) == 120, folder
    return out


def _cec_table(store):
    """pride report --format cec-csv: (problem, algorithm, checkpoint) -> the row."""
    text = cli("report", store, "--format", "cec-csv").stdout
    return {(r["problem"], r["algorithm"], r["checkpoint"]): r for r in csv.DictReader(io.StringIO(text))}


def _close(a, b, scale=0.0):
    # The store keeps f* + error: an error loses the digits below f*'s last (f* <= 3000: 5e-13). A
    # std is as exact as the mean it is around, within rounding of the values' scale (51 runs' 1e30,
    # all equal, have a std of 0, computed in doubles ~1e14).
    return math.isclose(a, b, rel_tol=1e-9, abs_tol=max(1e-8, 1e-12 * scale))


def test_entrants_cec_tables_equal_their_files_and_the_competitions_workbooks(tmp_path):
    data = shared_data("cec2017-results", "the CEC 2017 entrants' result files")
    store = tmp_path / "cec2017.sqlite"
    for k, (folder, name) in enumerate(ENTRANTS.items()):
        citation = f"{name}, CEC 2017 competition entrant's results (P-N-Suganthan/CEC2017-BoundContrained)"
        if k % 2 == 0:
            s = pride.import_cec2017(store, data / folder, name=name, citation=citation)
            assert s == {"algorithm": f"published:{name}", "runs": 6120, "problems_matched": 0 if k == 0 else 120,
                         "problems_added": 120 if k == 0 else 0}
        else:
            out = cli("import", store, "--cec2017", data / folder, "--name", name, "--citation", citation).stdout
            assert out == f"6120 runs of published:{name} imported into {store} (120 problems of the store, 0 added)\n"
    table = _cec_table(store)
    checkpoints = ["0.01", "0.02", "0.03", "0.05", "0.1", "0.2", "0.3", "0.4", "0.5", "0.6", "0.7", "0.8", "0.9",
                   "1.0"]
    compared = 0
    for folder, name in ENTRANTS.items():
        for (fid, dim), path in _files(data / folder).items():
            rows = _errors(path)
            for c, label in enumerate(checkpoints):
                r = table[(f"published:cec2017-f{fid}-d{dim}", f"published:{name}", label)]
                where = f"{name} F{fid} {dim}-D at {label}"
                assert (r["suite"], int(r["dim"]), float(r["f_opt"])) == ("cec2017", dim, 100.0 * fid), where
                assert (int(r["max_evaluations"]), int(r["runs"])) == (10000 * dim, 51), where
                assert int(r["evaluations"]) == round(float(label) * 10000 * dim), where
                errors = rows[c]
                for key, value in (("best", min(errors)), ("worst", max(errors)),
                                   ("median", statistics.median(errors)), ("mean", statistics.mean(errors)),
                                   ("std", statistics.stdev(errors))):
                    assert _close(float(r[key]), value, max(errors)), (where, key, r[key], value)
                compared += 1
    assert compared == len(ENTRANTS) * 120 * 14

    # The competition's own summary of the final errors (CEC2017_Dim_D.xlsx, tests/data/cec2017_results).
    published = 0
    with open(REPO / "tests" / "data" / "cec2017_results" / "published.tsv") as f:
        for p in csv.DictReader(f, delimiter="\t"):
            r = table[(f"published:cec2017-f{p['function']}-d{p['dim']}", f"published:{p['entrant']}", "1.0")]
            for key in ("mean", "median", "std"):
                assert _close(float(r[key]), float(p[key]), float(r["worst"])), (p, key, r[key])
            published += 1
    assert published == 3 * 4 * 30


def test_published_jso_beside_prides_jso_where_the_protocol_is_the_same(tmp_path, monkeypatch):
    results = shared_data("cec2017-results/A01", "jSO's CEC 2017 result files")
    official = shared_data("cec2017/input_data", "the official CEC 2017 data")
    monkeypatch.setenv("PRIDE_CEC2017_DATA", str(official))
    citation = "J. Brest, M. S. Maucec, B. Boskovic (2017), Single objective real-parameter optimization: algorithm jSO"
    runs = {}
    # The competition's protocol (no budget given: 10000 D), then another budget.
    for budget in ("", "[budget]\nevaluations_per_dim = 2000\n"):
        toml = tmp_path / "c.toml"
        toml.write_text(f'name = "jso-beside"\nseeds = 3\n{budget}[[suite]]\nname = "cec2017"\nfunctions = [1, 5]\n'
                        'dimensions = [10]\n[[algorithm]]\nid = "jso"\ntype = "jso"\n')
        store = tmp_path / f"s{len(runs)}.sqlite"
        cli("bench", toml, "--out", store, "--jobs", "2")
        s = pride.import_cec2017(store, results, name="jSO", citation=citation)
        # F1 and F5 in 10-D are the campaign's problems; the other 118 are added.
        assert (s["problems_matched"], s["problems_added"]) == (2, 118)
        # The campaign resumed runs none of them: they are not its runs.
        assert cli("bench", toml, "--out", store).stdout.startswith("jso-beside: 0 runs stored")
        runs[budget] = store
    same, other = runs[""], runs["[budget]\nevaluations_per_dim = 2000\n"]

    md = cli("report", same).stdout
    assert "left out of the comparison of final values" not in md
    assert "published:jSO holds published runs: " + citation in md
    table = _cec_table(same)
    for fid in (1, 5):
        for algorithm, n in (("jso", 3), ("published:jSO", 51)):
            r = table[(f"cec2017-f{fid}-d10", algorithm, "1.0")]
            assert (int(r["max_evaluations"]), int(r["runs"])) == (100000, n)
    rows = pride.report(same, dataframe=False)["rows"]
    compared = {(r["problem"], r["algorithm"]) for r in rows}
    assert {("cec2017-f1-d10", "published:jSO"), ("cec2017-f5-d10", "published:jSO"),
            ("cec2017-f1-d10", "jso")} <= compared

    md = cli("report", other).stdout
    assert ("published:jSO is left out of the comparison of final values on 2 problems (cec2017-f1-d10, "
            "cec2017-f5-d10)") in md
    assert "a mean of 100000 evaluations, the campaign's 20000" in md
    compared = {(r["problem"], r["algorithm"]) for r in pride.report(other, dataframe=False)["rows"]}
    assert ("cec2017-f1-d10", "jso") in compared and ("cec2017-f1-d10", "published:jSO") not in compared
    assert ("published:cec2017-f3-d10", "published:jSO") in compared  # a problem the campaign did not run


def test_bad_files_raise_one_value_error_naming_file_and_line(tmp_path):
    folder = tmp_path / "A99"
    folder.mkdir()
    (folder / "x_1_10.txt").write_text("".join(f"{14 - k} {15 - k}\n" for k in range(13)) + "1 inf\n")
    store = tmp_path / "s.sqlite"
    with pytest.raises(ValueError) as e:
        pride.import_cec2017(store, folder, name="x", citation="c")
    assert str(e.value) == (f"{folder / 'x_1_10.txt'}:14: run 2: expected an error f - f* (a finite number >= 0), "
                            "got 'inf'")
    assert not store.exists()
    for name, citation, argument in (("", "c", "name"), ("x", "", "citation"), ("a\nb", "c", "name")):
        with pytest.raises(ValueError, match=f"^{argument}: "):
            pride.import_cec2017(store, folder, name=name, citation=citation)
    assert not store.exists()
