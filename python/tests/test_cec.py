"""The CEC suites from Python: their dimensions are listed, and without the official data (which
pride does not ship) a CEC problem is refused with one ValueError naming the variable to set."""
import pytest

import pride


def test_cec_problems_list_their_dimensions():
    by_name = {p["name"]: p for p in pride.problems()}
    assert by_name["cec2017-f11"]["dims"] == [10, 30, 50, 100]
    assert by_name["cec2022-f6"]["dims"] == [10, 20]
    assert by_name["cec2017-f1"]["suite"] == "cec2017" and by_name["cec2017-f1"]["number"] == 1
    assert by_name["rastrigin"]["dims"] is None
    assert sum(p["suite"] == "cec2017" for p in by_name.values()) == 30
    assert sum(p["suite"] == "cec2022" for p in by_name.values()) == 12


def test_cec_without_data_is_one_value_error(monkeypatch):
    monkeypatch.setenv("PRIDE_CEC2022_DATA", "")
    with pytest.raises(ValueError, match=r"^cec2022-f1: needs the official cec2022 data.*PRIDE_CEC2022_DATA"):
        pride.minimize("pso", "cec2022-f1", dim=10, evals=100)


def test_cec_dimension_without_data_is_refused():
    with pytest.raises(ValueError, match=r"cec2017-f11 is defined in dimensions 10, 30, 50, 100 only, got 20"):
        pride.minimize("pso", "cec2017-f11", dim=20, evals=100)
