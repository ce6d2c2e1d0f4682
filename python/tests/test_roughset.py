"""Rough sets on the reference tables: the command line's analysis, from files, arrays and labels."""
import csv

import numpy as np
import pytest

import pride
from conftest import ROUGHSET_TABLES as TABLES, roughset_as_cli as strip, reference_roughset, shared_data


@pytest.mark.parametrize("name", TABLES)
def test_reference_tables_equal_cli(name):
    path, want = reference_roughset(name)
    assert strip(pride.roughset(str(path))) == want
    with open(path) as f:
        rows = list(csv.reader(f))
    array = np.array(rows[1:], dtype=int)
    assert strip(pride.roughset(array, columns=rows[0])) == want
    labels = np.array(rows[1:], dtype=object)
    assert strip(pride.roughset(labels, columns=rows[0])) == want


def test_pawlak_p72_known_answer():
    path = shared_data("roughset/pawlak1991_p72.csv", "Pawlak's decision tables")
    r = pride.roughset(str(path))
    assert r["core"] == ["a", "b", "d"] and r["reducts"] == [["a", "b", "d"]] and r["consistent"]
    for rule in r["rules"]:
        assert rule["support"] == len(rule["objects"]) >= 1


def test_text_labels_and_errors():
    table = [["sunny", "hot", "no"], ["rain", "mild", "yes"], ["sunny", "mild", "yes"], ["rain", "hot", "no"]]
    r = pride.roughset(np.array(table, dtype=object), columns=["outlook", "temp", "play"])
    assert r["decision"] == "play" and r["core"] == ["temp"] and r["consistent"]
    assert {rule["then"] for rule in r["rules"]} == {"yes", "no"}
    with pytest.raises(ValueError, match="columns"):
        pride.roughset(np.zeros((3, 3), dtype=int), columns=["a", "b"])
    with pytest.raises(ValueError):
        pride.roughset("/nonexistent/table.csv")
