"""No silent mixing, from Python: a Campaign resumed on another problem under the same id (another Grid,
other bounds) is refused rather than answered "already"; a damaged store is refused before it is
trusted; names with control characters are refused as the campaign files refuse them."""
import numpy as np
import pytest

import pride

ARRAY = np.zeros((6, 6), dtype=int)
ARRAY[1:5, 2] = 1


def grid_campaign(grid, seeds=2):
    return pride.Campaign("g", seeds=seeds, iters=3,
                          problems=[{"id": "g", "grid": grid, "start": (0, 5), "goal": (5, 0)}],
                          algorithms=["pso"])


def test_another_grid_under_the_same_id_is_refused(tmp_path):
    store = tmp_path / "g.sqlite"
    assert grid_campaign(pride.Grid(ARRAY)).run(store)["stored"] == 2
    # The same cells in a new Grid: the same problem, nothing to run.
    assert grid_campaign(pride.Grid(ARRAY.copy())).run(store)["already"] == 2
    other = ARRAY.copy()
    other[0, 3] = 1
    before = store.read_bytes()
    for seeds in (2, 3):  # the same campaign, and a grown one
        with pytest.raises(ValueError, match=r"problem 'g' has another map than the stored one"):
            grid_campaign(pride.Grid(other), seeds).run(store)
    assert store.read_bytes() == before


def test_a_function_with_other_bounds_under_the_same_id_is_refused(tmp_path):
    store = tmp_path / "f.sqlite"

    def make(bounds):
        return pride.Campaign("f", seeds=1, evals=50,
                              problems=[{"id": "f", "function": lambda x: float(np.sum(x * x)), "bounds": bounds,
                                         "dim": 2}],
                              algorithms=["pso"])

    make((-1, 1)).run(store)
    assert make((-1, 1)).run(store)["already"] == 1
    with pytest.raises(ValueError, match=r"problem 'f' has other settings than the stored ones"):
        make((-2, 2)).run(store)


def test_a_damaged_store_is_refused_before_it_is_trusted(tmp_path):
    store = tmp_path / "s.sqlite"
    c = pride.Campaign("s", seeds=3, evals=50, problems=[{"id": "s", "problem": "sphere", "dim": 2}],
                       algorithms=["pso"])
    c.run(store)
    data = store.read_bytes()
    cut = tmp_path / "cut.sqlite"
    cut.write_bytes(data[: len(data) // 2])
    with pytest.raises(ValueError, match=r"damaged store: the file is truncated.*nothing was run"):
        c.run(cut)
    assert cut.read_bytes() == data[: len(data) // 2]


@pytest.mark.parametrize("name, message", [
    ("a\x1b[31mb", r"name must not contain control characters \(U\+001B"),
    ("a\x00b", r"name must not contain a NUL character"),
])
def test_control_characters_in_names_are_refused(tmp_path, name, message):
    with pytest.raises(ValueError, match=message):
        pride.Campaign(name, seeds=1, evals=10, problems=[{"id": "s", "problem": "sphere", "dim": 2}],
                       algorithms=["pso"])
    with pytest.raises(ValueError, match="problem id " + message.replace("name ", "")):
        pride.Campaign("ok", seeds=1, evals=10, problems=[{"id": name, "problem": "sphere", "dim": 2}],
                       algorithms=["pso"])
    with pytest.raises(ValueError, match="algorithm id " + message.replace("name ", "")):
        pride.Campaign("ok", seeds=1, evals=10, problems=[{"id": "s", "problem": "sphere", "dim": 2}],
                       algorithms=[{"id": name, "algo": "pso"}])
