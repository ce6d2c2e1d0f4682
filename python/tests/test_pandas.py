"""The DataFrame paths (when pandas is installed): read_store, report and roughset from a
DataFrame give the values of the list-of-dicts form and of the command line."""
import csv
import io
import math

import numpy as np
import pytest

import pride
from conftest import ROUGHSET_TABLES as TABLES, cli, roughset_as_cli as strip, reference_roughset

pd = pytest.importorskip("pandas")

SCALARS = ["problem", "algorithm", "seed", "best", "evaluations", "wall_ms", "optimum"]


def same(frame_value, plain_value):
    """Equal, a missing value (None) reading back from a float column as NaN."""
    if plain_value is None or (isinstance(plain_value, float) and math.isnan(plain_value)):
        return frame_value is None or (isinstance(frame_value, float) and math.isnan(frame_value))
    return frame_value == plain_value


@pytest.fixture(scope="module")
def store(tmp_path_factory):
    path = tmp_path_factory.mktemp("pandas") / "c.sqlite"
    c = pride.Campaign("pd", seeds=2, evals=300,
                       problems=[{"id": "sphere", "problem": "sphere", "dim": 3},
                                 {"id": "rastrigin", "problem": "rastrigin", "dim": 2}],
                       algorithms=["pso", "ga"])
    assert c.run(path, jobs=2)["stored"] == 8
    return path


def test_read_store_dataframe_equals_the_list_and_the_cli(store):
    df = pride.read_store(store)  # a DataFrame by default when pandas is present
    assert isinstance(df, pd.DataFrame) and isinstance(pride.read_store(store, dataframe=True), pd.DataFrame)
    runs = pride.read_store(store, dataframe=False)
    assert len(df) == len(runs) == 8
    assert list(df.columns) == list(runs[0].keys())
    for row, run in zip(df.to_dict("records"), runs):
        for k in SCALARS:
            assert same(row[k], run[k]), k
        assert np.array_equal(row["history"], run["history"])
        assert np.array_equal(row["history_evaluations"], run["history_evaluations"])
    for row in df.itertuples():
        j = cli("run", "--problem", row.problem, "--dim", 3 if row.problem == "sphere" else 2, "--algo",
                row.algorithm, "--evals", 300, "--seed", row.seed, "--json")
        assert row.best == j["best_f"] and row.evaluations == j["evaluations"]
        assert np.array_equal(row.history, j["history"])


def test_report_dataframe_equals_the_list_and_the_cli_csv(store):
    r = pride.report(store)
    rows = r["rows"]
    assert isinstance(rows, pd.DataFrame) and len(rows) == 4
    plain = pride.report(store, dataframe=False)["rows"]
    assert list(rows.columns) == list(plain[0].keys())
    for row, p in zip(rows.to_dict("records"), plain):
        for k in p:
            assert same(row[k], p[k]), k
    assert r["csv"] == cli("report", store, "--format", "csv").stdout
    table = list(csv.DictReader(io.StringIO(r["csv"])))
    assert [(t["problem"], t["algorithm"]) for t in table] == list(zip(rows["problem"], rows["algorithm"]))
    for t, (_, row) in zip(table, rows.iterrows()):
        assert int(t["runs"]) == row["runs"] == 2
        for k in ("min", "mean", "median", "max"):
            assert float(t[k]) == pytest.approx(row[k], rel=1e-9, abs=1e-300), k


@pytest.mark.parametrize("name", TABLES)
def test_roughset_from_a_dataframe_equals_the_cli(name):
    path, want = reference_roughset(name)
    codes = pd.read_csv(path)  # integer columns: codes
    assert strip(pride.roughset(codes)) == want
    labels = pd.read_csv(path, dtype=str)  # text columns: labels
    assert strip(pride.roughset(labels)) == want
    assert pride.roughset(codes) == pride.roughset(codes.to_numpy(), columns=list(codes.columns))
    renamed = pride.roughset(codes, columns=[f"x{i}" for i in range(codes.shape[1])])
    assert renamed["decision"] == f"x{codes.shape[1] - 1}" and renamed["dependency"] == want["dependency"]


def test_roughset_from_a_mixed_dataframe():
    df = pd.DataFrame({"outlook": ["sunny", "rain", "sunny", "rain"], "temp": [30, 20, 20, 30],
                       "play": ["no", "yes", "yes", "no"]})
    r = pride.roughset(df)
    assert r["conditions"] == ["outlook", "temp"] and r["decision"] == "play"
    assert r["core"] == ["temp"] and r["consistent"]
    assert sorted((tuple(x["if"].items()), x["then"]) for x in r["rules"]) == [
        ((("temp", "20"),), "yes"), ((("temp", "30"),), "no")]
