"""Published runs in a store (pride.import_ioh, `pride import --ioh`): a campaign's `pride export --ioh`
read back onto its own problems equals the runs it came from, to what the files carry (each
iteration's best so far, the final value), and bad input is one ValueError or TypeError naming the
file and line or the argument."""
import math
import shutil

import pytest

import pride
from conftest import cli

CAMPAIGN = """name = "ioh"
seeds = 2
[budget]
evaluations_per_dim = 200
[[suite]]
name = "bbob"
functions = [1, 8]
instances = [1]
dimensions = [2]
[[algorithm]]
id = "pso"
type = "pso"
pop = 10
[[algorithm]]
id = "de"
type = "de"
pop = 10
"""


@pytest.fixture(scope="module")
def exported(tmp_path_factory):
    """A campaign's store (a fresh copy per test through `store`) and its IOH export."""
    folder = tmp_path_factory.mktemp("ioh")
    (folder / "c.toml").write_text(CAMPAIGN)
    cli("bench", folder / "c.toml", "--out", folder / "c.sqlite", "--jobs", "2")
    cli("export", folder / "c.sqlite", "--ioh", folder / "ioh")
    return folder


def _store(exported, tmp_path):
    store = tmp_path / "s.sqlite"
    shutil.copy(exported / "c.sqlite", store)
    return store


def _iteration_runtimes(run, f_opt, precisions):
    """Per precision, the evaluations of the first iteration whose best so far is within it."""
    out = {}
    for p in precisions:
        out[p] = next((e for v, e in zip(run["history"], run["history_evaluations"])
                       if math.isfinite(v) and v - f_opt <= p), None)
    return out


def test_export_read_back_equals_the_runs_it_came_from(exported, tmp_path):
    store = _store(exported, tmp_path)
    s = pride.import_ioh(store, exported / "ioh" / "de", name="de-ioh", citation="pride (2026), test")
    assert s == {"algorithm": "published:de-ioh", "runs": 4, "problems_matched": 2, "problems_added": 0}
    data = pride._pride.read_store(str(store))
    f_opt = {p["id"]: p["f_opt"] for p in data["problems"]}
    runs = {(r["problem"], r["algorithm"], r["seed"]): r for r in pride.read_store(store, dataframe=False)}
    imported = [k for k in runs if k[1] == "published:de-ioh"]
    assert len(imported) == 4
    for problem, _, seed in imported:
        mine, theirs = runs[(problem, "published:de-ioh", seed)], runs[(problem, "de", seed)]
        assert mine["evaluations"] == theirs["evaluations"]
        assert math.isclose(mine["best"], theirs["best"], rel_tol=1e-15, abs_tol=1e-15 * abs(f_opt[problem]))
        assert list(mine["history"]) == list(theirs["history"])
        assert list(mine["history_evaluations"]) == list(theirs["history_evaluations"])
        expected = _iteration_runtimes(theirs, f_opt[problem], data["precisions"])
        assert mine["target_hits"] == expected
    # The report's final values: the same statistics as the runs they came from.
    rows = {(r["problem"], r["algorithm"]): r for r in pride.report(store, dataframe=False)["rows"]}
    for problem in f_opt:
        mine, theirs = rows[(problem, "published:de-ioh")], rows[(problem, "de")]
        for key in ("runs", "mean_evaluations"):
            assert mine[key] == theirs[key]
        for key in ("min", "median", "mean", "max"):
            assert math.isclose(mine[key], theirs[key], rel_tol=1e-12, abs_tol=1e-12), (problem, key)
    md = cli("report", store).stdout
    assert "published:de-ioh holds published runs: pride (2026), test, read from de (iohprofiler data" in md
    # The command line reads the same folder the same way.
    other = tmp_path / "o.sqlite"
    shutil.copy(exported / "c.sqlite", other)
    out = cli("import", other, "--ioh", exported / "ioh" / "de", "--name", "de-ioh", "--citation", "c").stdout
    assert out == f"4 runs of published:de-ioh imported into {other} (2 problems of the store, 0 added)\n"


def test_bad_input_raises_one_error_naming_file_line_or_argument(exported, tmp_path):
    store = _store(exported, tmp_path)
    before = store.read_bytes()
    bad = tmp_path / "bad"
    shutil.copytree(exported / "ioh" / "pso", bad)
    dat = bad / "data_f1_Sphere" / "IOHprofiler_f1_DIM2.dat"
    lines = dat.read_text().splitlines()
    lines[2] = lines[2].split()[0] + " 1 nan 1 1"
    dat.write_text("\n".join(lines) + "\n")
    with pytest.raises(ValueError) as e:
        pride.import_ioh(store, bad, name="x", citation="c")
    assert str(e.value) == (f"{dat}:3: expected best-so-far f(x), a finite number or None, in column 3, got 'nan'")
    assert "\n" not in str(e.value)
    with pytest.raises(ValueError, match="no such folder"):
        pride.import_ioh(store, tmp_path / "none", name="x", citation="c")
    for name, citation, argument in (("", "c", "name"), ("x", "", "citation"), ("a\nb", "c", "name")):
        with pytest.raises(ValueError, match=f"^{argument}: "):
            pride.import_ioh(store, exported / "ioh" / "pso", name=name, citation=citation)
    for kwargs, argument in (({"name": 1, "citation": "c"}, "name"), ({"name": "x", "citation": None}, "citation")):
        with pytest.raises(TypeError, match=f"^{argument}: "):
            pride.import_ioh(store, exported / "ioh" / "pso", **kwargs)
    with pytest.raises(TypeError, match="^path: "):
        pride.import_ioh(store, 3, name="x", citation="c")
    assert store.read_bytes() == before


def _bowl(x):
    return float(sum((v - 0.25) ** 2 for v in x)) + 1.0


def test_a_problem_without_a_known_optimum_keeps_its_values_and_gets_no_runtimes(tmp_path):
    # A Python function without f_opt: pride's own runs on it record no runtimes, nor do the imported.
    campaign = pride.Campaign("bowl", seeds=2, evals=100, algorithms=["pso"],
                              problems=[{"id": "bowl", "function": _bowl, "bounds": (-1, 1), "dim": 2}])
    store = tmp_path / "b.sqlite"
    campaign.run(store)
    cli("export", store, "--ioh", tmp_path / "ioh")
    s = pride.import_ioh(store, tmp_path / "ioh" / "pso", name="pso-ioh", citation="c")
    assert (s["runs"], s["problems_matched"]) == (2, 1)
    assert [p["f_opt"] for p in pride._pride.read_store(str(store))["problems"]] == [None]
    runs = {(r["algorithm"], r["seed"]): r for r in pride.read_store(store, dataframe=False)}
    for seed in (1, 2):
        mine, theirs = runs[("published:pso-ioh", seed)], runs[("pso", seed)]
        assert mine["best"] == theirs["best"]  # the value as written: no optimum added or taken
        assert mine["target_hits"] == theirs["target_hits"] == {}
        assert list(mine["history"]) == list(theirs["history"])
