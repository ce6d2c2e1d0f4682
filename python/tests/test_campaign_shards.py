"""A campaign split across machines: Campaign.run(store, shard=(k, n)) runs part k of n of the
runs (as `pride bench --shard K/N`), and the parts' stores, read as one, are the whole campaign's;
a campaign file's seeds as a list or a range are those seeds' runs. Bad shards name the argument."""
import math

import pytest

import pride

CAMPAIGN = ('name = "sh"\nseeds = SEEDS\n[budget]\nevaluations = 300\n'
            '[[problem]]\nid = "s"\ntype = "sphere"\ndim = 3\n'
            '[[problem]]\nid = "f3"\ntype = "bbob-f3"\ndim = 2\ninstance = 1\n'
            '[[algorithm]]\nid = "pso"\ntype = "pso"\npop = 10\n'
            '[[algorithm]]\nid = "ga"\ntype = "ga"\npop = 10\n')


def load(tmp_path, seeds, name="c.toml"):
    path = tmp_path / name
    path.write_text(CAMPAIGN.replace("SEEDS", seeds))
    return pride.Campaign.load(str(path))


def rows(stores):
    """The runs of the stores but their wall times, in key order (a value and its bits alike)."""
    out = []
    for store in stores:
        for r in pride.read_store(store, dataframe=False):
            out.append({k: (v.tolist() if hasattr(v, "tolist") else v) for k, v in r.items() if k != "wall_ms"})
    return sorted(out, key=lambda r: (r["problem"], r["algorithm"], r["seed"]))


def csv_without_wall(text):
    lines = [line.split(",") for line in text.splitlines()]
    wall = lines[0].index("mean_wall_ms")
    return [[f for i, f in enumerate(line) if i != wall] for line in lines]


def same(a, b):
    """Equal, NaN equal to NaN (a float field of a run that has none)."""
    if isinstance(a, float) and isinstance(b, float):
        return a == b or (math.isnan(a) and math.isnan(b))
    if isinstance(a, (list, tuple)) and isinstance(b, (list, tuple)):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(same(a[k], b[k]) for k in a)
    return a == b


def test_shards_merged_are_the_whole_campaign(tmp_path):
    c = load(tmp_path, "3")
    assert c.runs == 12
    whole = tmp_path / "whole.sqlite"
    assert c.run(whole, jobs=2) == {"stored": 12, "already": 0, "total": 12}
    parts = [tmp_path / f"part{k}.sqlite" for k in (1, 2, 3)]
    for k, part in enumerate(parts, 1):
        assert c.run(part, jobs=2, shard=(k, 3)) == {"stored": 4, "already": 0, "total": 4}
        # Every third run of the ordered list (problems, algorithms, seeds): seed k of each pair.
        assert {r["seed"] for r in pride.read_store(part, dataframe=False)} == {k}
    assert same(rows(parts), rows([whole]))
    assert csv_without_wall(pride.report([str(p) for p in parts])["csv"]) == \
        csv_without_wall(pride.report(str(whole))["csv"])
    # A shard's store takes the other shard, then the whole finds every run there.
    store = tmp_path / "resumed.sqlite"
    assert c.run(store, shard=(1, 2)) == {"stored": 6, "already": 0, "total": 6}
    assert c.run(store, shard=[2, 2]) == {"stored": 6, "already": 0, "total": 6}
    assert c.run(store) == {"stored": 0, "already": 12, "total": 12}
    assert same(rows([store]), rows([whole]))


def test_listed_seeds_are_those_runs(tmp_path):
    whole = tmp_path / "whole.sqlite"
    load(tmp_path, "4", "w.toml").run(whole)
    listed = load(tmp_path, "[4, 2]", "l.toml")
    assert listed.runs == 8 and listed.seeds == 2  # seeds: how many per problem and algorithm
    listed.run(tmp_path / "l.sqlite")
    ranged = load(tmp_path, "{ from = 1, to = 3 }", "r.toml")
    assert ranged.runs == 12
    ranged.run(tmp_path / "r.sqlite", shard=(2, 2))
    ranged.run(tmp_path / "r2.sqlite", shard=(1, 2))
    by_key = {}
    for r in rows([tmp_path / "l.sqlite", tmp_path / "r.sqlite", tmp_path / "r2.sqlite"]):
        key = (r["problem"], r["algorithm"], r["seed"])
        assert key not in by_key or same(by_key[key], r)  # seed 2, listed and in the range: one run
        by_key[key] = r
    assert same([by_key[k] for k in sorted(by_key)], rows([whole]))


def test_listed_seeds_errors_name_the_file_and_key(tmp_path):
    for seeds, message in [("[]", "c.toml:2:9: 'seeds' must not be an empty list"),
                           ("[1, 1]", "c.toml:2:13: 'seeds' lists seed 1 twice"),
                           ("[0]", "'seeds': a seed must be in [1, 1000000], got 0"),
                           ("{ from = 3, to = 2 }", "'seeds' from 3 to 2 is empty")]:
        with pytest.raises(ValueError, match=message.replace("[", r"\[").replace("]", r"\]")):
            load(tmp_path, seeds)


@pytest.mark.parametrize("shard, error, words", [
    ("1/3", TypeError, "shard: expected a pair (k, n), part k of n, got str"),
    ((1,), TypeError, "shard: expected a pair (k, n), part k of n, got tuple of 1"),
    ((1, 2, 3), TypeError, "shard: expected a pair (k, n), part k of n, got tuple of 3"),
    ((1.0, 3), TypeError, "shard: expected an integer, got float"),
    ((True, 2), TypeError, "shard: expected an integer, got bool"),
    ((0, 3), ValueError, "shard: must be part k of n with 1 <= k <= n, got (0, 3)"),
    ((4, 3), ValueError, "shard: must be part k of n with 1 <= k <= n, got (4, 3)"),
    ((1, 0), ValueError, "shard: must be part k of n with 1 <= k <= n, got (1, 0)"),
    ((1, 2**63), ValueError, "shard: 9223372036854775808 is out of range"),
])
def test_bad_shards_name_the_argument(tmp_path, shard, error, words):
    c = load(tmp_path, "1")
    with pytest.raises(error) as e:
        c.run(tmp_path / "s.sqlite", shard=shard)
    assert words in str(e.value)
    assert not (tmp_path / "s.sqlite").exists()
