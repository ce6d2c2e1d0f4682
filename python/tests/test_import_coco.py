"""Published runs in a store (pride.import_coco, `pride import`): COCO's DIRECT data set of BBOB 2009
imported and held against COCO's own post-processed table of it (pptables.html: aRT divided by the
best-2009 aRT, per function, dimension and target), and bad archives refused in one ValueError."""
import csv
import hashlib
import io
import math
import re
import statistics
import tarfile

import pytest

import pride
from conftest import cli, shared_data

CITATION = "P. Posik (2009), BBOB-2009 results of DIRECT, GECCO 2009 workshop, COCO data archive"


def _ert_table(store):
    """pride report --format ert-csv: (function, dim, log10(precision) * 5) -> (aRT, successes, runs)."""
    out = {}
    for r in csv.DictReader(io.StringIO(cli("report", store, "--format", "ert-csv").stdout)):
        k = round(math.log10(float(r["precision"])) * 5)
        ert = math.inf if r["ert"] in ("inf", "") else float(r["ert"])
        out[(r["function"], int(r["dim"]), k)] = (ert, int(r["successes"]), int(r["runs"]))
    return out


def _half_unit(shown):
    """Half the last shown digit's unit of a number as pptables prints it ('6.0', '1296', '1.2e5')."""
    mantissa, _, exponent = shown.partition("e")
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    return 0.5 * 10.0 ** (-decimals) * 10.0 ** int(exponent or 0)


def _pptables_rows(html, algorithm):
    """Per table of pptables.html: (fid, dim, [(target, best-2009 aRT as shown)], [(customkey or None,
    shown text)] of `algorithm` (customkey empty where none is given)'s row), the #succ column last in both."""
    tables = re.finditer(
        r"<th>&#916; f<sub>opt</sub><br><b>f(\d+), (\d+)-D</b></th>(.*?)</thead>(.*?)</table>", html, re.S)
    for m in tables:
        head = re.findall(r"<td>([^<]*)<br>([^<]*)</td>", m.group(3))
        rows = [r for r in m.group(4).split("<tr>") if f"<th>{algorithm}</th>" in r]
        if not rows:
            continue
        cells = re.findall(r'<td(?: sorttable_customkey="([^"]*)")?>(.*?)</td>', rows[0])
        yield int(m.group(1)), int(m.group(2)), head, cells


def test_direct_2009_equals_cocos_published_table(tmp_path):
    archive = shared_data("coco-archive/bbob/2009/DIRECT_posik_noiseless.tgz", "COCO's DIRECT data set")
    html = shared_data("coco-archive/bbob/2009/pptables.html", "COCO's BBOB-2009 tables").read_text("latin-1")
    store = tmp_path / "direct.sqlite"
    s = pride.import_coco(store, archive, name="DIRECT", citation=CITATION)
    # f1-f24 x 2, 3, 5, 10, 20, 40-D x instances 1-5, one run each.
    assert s == {"algorithm": "published:DIRECT", "runs": 720, "problems_matched": 0, "problems_added": 720}
    ert = _ert_table(store)
    runs = pride.read_store(store, dataframe=False)
    evaluations = {}
    for r in runs:
        fid, dim = re.fullmatch(r"published:bbob-f(\d+)-i\d+-d(\d+)", r["problem"]).groups()
        evaluations.setdefault((int(fid), int(dim)), []).append(r["evaluations"])

    checked = {"ratio": 0, "whole sum": 0, "infinite": 0, "median evaluations": 0, "#succ": 0, "blank": 0}
    worst = 0.0
    tables = 0
    for fid, dim, head, cells in _pptables_rows(html, "DIRECT posik noiseless"):
        tables += 1
        assert len(head) == len(cells) == 8
        for (target, best_shown), (key, shown) in zip(head, cells):
            where = f"f{fid} {dim}-D {target}"
            if target == "#succ":
                # cocopp's pptables: the runs that reached the final target 1e-8.
                _, successes, n = ert[(f"bbob-f{fid}", dim, -40)]
                assert shown == f"{successes}/{n}", where
                checked["#succ"] += 1
                continue
            a, _, _ = ert[(f"bbob-f{fid}", dim, round(math.log10(float(target)) * 5))]
            if not key:  # best 2009 never reached the target: no ratio shown
                assert shown == "&nbsp;" and best_shown == "&infin;", where
                checked["blank"] += 1
                continue
            if shown.startswith("&infin;") or "<b>&infin;</b>" in shown:
                assert a == math.inf, where
                checked["infinite"] += 1
                if "<i>" in shown:  # the last target: the median of the runs' evaluations (maxevals)
                    assert float(key) == statistics.median(evaluations[(fid, dim)]), where
                    checked["median evaluations"] += 1
                continue
            # aRT / best-2009 aRT = the customkey to its 6 decimals, for a best-2009 aRT within the
            # digits the header shows of it.
            ratio = float(key)
            best, half = float(best_shown), _half_unit(best_shown)
            low = a / (ratio + 5e-7)
            high = a / (ratio - 5e-7) if ratio > 5e-7 else math.inf
            assert low <= best + half and high >= best - half, (where, a, ratio, best_shown)
            worst = max(worst, abs(a / ratio - best) / best)
            checked["ratio"] += 1
            # Beyond the header's digits: best-2009's aRT is a sum of evaluations over its successes
            # (at most 15 runs), so some k <= 15 puts k * aRT / ratio on a whole number. Where the
            # 6 decimals pin aRT / ratio so closely that a wrong aRT would pass by chance with a
            # probability below 1 % (the union over k of the intervals' widths), that is required.
            width = high - low
            if sum(min(1.0, width * k) for k in range(1, 16)) < 0.01:
                assert any(math.floor(high * k) >= math.ceil(low * k) for k in range(1, 16)), (where, a, ratio)
                checked["whole sum"] += 1
    assert tables == 144  # 24 functions x 6 dimensions
    # Every cell of the 144 tables' DIRECT rows: 7 targets and #succ each.
    assert checked == {"ratio": 578, "whole sum": 416, "infinite": 426, "median evaluations": 83, "#succ": 144,
                       "blank": 4}
    print(f"pptables cells checked: {checked}; largest |aRT/ratio - shown best-2009 aRT| / best: {worst:.2e}")


def test_archive_provenance_and_second_import_refused(tmp_path):
    archive = shared_data("coco-archive/bbob/2009/DIRECT_posik_noiseless.tgz", "COCO's DIRECT data set")
    store = tmp_path / "direct.sqlite"
    pride.import_coco(store, archive, name="DIRECT", citation=CITATION)
    import sqlite3

    with sqlite3.connect(store) as db:
        row = db.execute("SELECT algorithm, format, source, sha256, citation FROM published").fetchall()
    assert row == [("published:DIRECT", "coco-bbob", "DIRECT_posik_noiseless.tgz",
                    hashlib.sha256(archive.read_bytes()).hexdigest(), CITATION)]
    before = store.read_bytes()
    with pytest.raises(ValueError, match=r"holds the algorithm 'published:DIRECT' already, imported from "
                                         r"DIRECT_posik_noiseless.tgz"):
        pride.import_coco(store, archive, name="DIRECT", citation=CITATION)
    assert store.read_bytes() == before


def test_bad_archives_are_one_value_error(tmp_path):
    bad = tmp_path / "bad.tgz"
    bad.write_bytes(b"not an archive")
    with pytest.raises(ValueError, match=r"bad.tgz: not a folder nor a readable"):
        pride.import_coco(tmp_path / "s.sqlite", bad, name="X", citation="c")
    # A member outside the folder is refused before anything is extracted.
    evil = tmp_path / "evil.tar"
    with tarfile.open(evil, "w") as t:
        info = tarfile.TarInfo("../outside.info")
        info.size = 1
        t.addfile(info, io.BytesIO(b"x"))
    with pytest.raises(ValueError, match=r"member '../outside.info' is not a file or folder inside"):
        pride.import_coco(tmp_path / "s.sqlite", evil, name="X", citation="c")
    assert not (tmp_path / "outside.info").exists() and not (tmp_path / "s.sqlite").exists()
    with pytest.raises(ValueError, match=r"no such folder"):
        pride.import_coco(tmp_path / "s.sqlite", tmp_path / "none", name="X", citation="c")
    with pytest.raises(TypeError, match=r"citation: expected a name"):
        pride.import_coco(tmp_path / "s.sqlite", tmp_path, name="X", citation=None)


def test_a_folder_is_read_as_cocopp_reads_it(tmp_path):
    """Two .dat lines of one run (f - f_opt 5 after 1 evaluation, 1 after 10; the .tdat's last line
    at 12): its hits of COCO's 51 precisions, evaluations and final value; the folder's digest."""
    import sqlite3

    folder = tmp_path / "coco"
    (folder / "data_f1").mkdir(parents=True)
    (folder / "bbobexp_f1.info").write_text(
        "funcId = 1, DIM = 2, Precision = 1.000e-008, algId = 'x'\n% 2009's format\n"
        "data_f1\\bbobexp_f1_DIM2.dat, 1:12|9.9e-001\n")
    (folder / "data_f1" / "bbobexp_f1_DIM2.dat").write_text(
        "% function evaluation | noise-free fitness - Fopt (7.948000000000e+001) | best noise-free fitness - Fopt\n"
        "1 +5.0e+000 +5.0e+000 +8.448e+001 +8.448e+001\n10 +1.0e+000 +1.0e+000 +8.048e+001 +8.048e+001\n")
    (folder / "data_f1" / "bbobexp_f1_DIM2.tdat").write_text(
        "% function evaluation | noise-free fitness - Fopt (7.948000000000e+001) | best noise-free fitness - Fopt\n"
        "1 +5.0e+000 +5.0e+000 +8.448e+001 +8.448e+001\n12 +3.0e+000 +1.0e+000 +8.248e+001 +8.048e+001\n")
    store = tmp_path / "s.sqlite"
    assert pride.import_coco(store, folder, name="x", citation="c") == {
        "algorithm": "published:x", "runs": 1, "problems_matched": 0, "problems_added": 1}
    with sqlite3.connect(store) as db:
        problem, seed, best, evaluations, hits = db.execute(
            "SELECT problem, seed, best, evaluations, target_hits FROM runs").fetchone()
        source, sha = db.execute("SELECT source, sha256 FROM published").fetchone()
        f_opt, fid, instance = db.execute("SELECT f_opt, fid, instance FROM problems").fetchone()
    assert (problem, seed, evaluations, fid, instance, f_opt) == ("published:bbob-f1-i1-d2", 1, 12, 1, 1, 79.48)
    assert best == pytest.approx(80.48)
    # Precisions 10^(2 - k/5): within 5 from k = 7 (10^0.6 = 3.98 is not), within 1 from k = 10 (10^0 = 1).
    assert hits == "[" + ", ".join(["1"] * 7 + ["10"] * 4 + ["null"] * 40) + "]"
    # The folder's digest: each file's path in it and content, by path, as length-prefixed fields.
    digest = hashlib.sha256()
    for path in sorted(p for p in folder.rglob("*") if p.is_file()):
        for field in (path.relative_to(folder).as_posix().encode(), path.read_bytes()):
            digest.update(len(field).to_bytes(8, "little") + field)
    assert (source, sha) == ("coco", digest.hexdigest())
