"""Seeds over the command line's whole range, sizes checked before anything of that size is built,
and the smaller contracts of the module: a campaign's target is a finite number, ask() after the end
is refused as tell() is, a run that found nothing finite has no best point, ids are not empty."""
import math
import os
import re
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import pride
from conftest import cli
from test_minimize import same_bits

TOP = 2**64 - 1  # the command line's max_seed (cli/flags.hpp)


@pytest.mark.parametrize("seed", [2**63, TOP])
def test_seeds_up_to_2_64_minus_1_give_the_command_lines_bits(seed):
    r = pride.minimize("pso", "rastrigin", dim=4, evals=400, seed=seed)
    j = cli("run", "--problem", "rastrigin", "--dim", 4, "--algo", "pso", "--evals", 400, "--seed", seed, "--json")
    assert j["seed"] == seed
    assert same_bits([r.best_f], [j["best_f"]]) and same_bits(r.best_x, j["best_x"])
    assert same_bits(r.history, j["history"])
    assert r.history.tobytes() != pride.minimize("pso", "rastrigin", dim=4, evals=400, seed=seed - 1).history.tobytes()


def test_top_seed_in_ask_tell_and_plan():
    def rows(X):
        return np.sum(X * X, axis=1)

    want = pride.minimize("ga", rows, bounds=(-1, 1), dim=3, evals=200, seed=TOP, vectorized=True)
    opt = pride.Optimizer("ga", bounds=(-1, 1), dim=3, evals=200, seed=TOP)
    while not opt.done:
        opt.tell(rows(opt.ask()))
    assert opt.result.best_x.tobytes() == want.best_x.tobytes()
    g = pride.Grid(np.zeros((10, 10), dtype=int))
    r = pride.plan(g, (0, 0), (9, 9), algo="pso", iters=5, seed=TOP)
    assert r.seed == TOP and r.feasible


@pytest.mark.parametrize("seed", [-1, 2**64, -(2**70)])
def test_seeds_out_of_range_name_seed_as_the_command_line(seed):
    message = cli("run", "--problem", "sphere", "--dim", 2, "--algo", "pso", "--seed", seed, check=False).stderr
    want = message.strip().removeprefix("pride: --")
    for make in (lambda: pride.minimize("pso", "sphere", dim=2, evals=10, seed=seed),
                 lambda: pride.Optimizer("pso", bounds=(0, 1), dim=2, evals=10, seed=seed),
                 lambda: pride.plan(pride.Grid(np.zeros((3, 3))), (0, 0), (2, 2), iters=2, seed=seed)):
        with pytest.raises(ValueError) as e:
            make()
        assert str(e.value) == want


def without_memory(message):
    """A memory message without the machine's figure, which moves between two processes."""
    return re.sub(r"more than the [0-9.]+ [A-Z]+ this machine has", "more than the memory this machine has", message)


def test_a_dimension_too_large_is_refused_naming_dim_as_the_command_line():
    j = cli("run", "--problem", "sphere", "--dim", 10**12, "--algo", "pso", check=False)
    assert j.returncode == 2
    with pytest.raises(ValueError) as e:
        pride.minimize("pso", "sphere", dim=10**12)
    assert without_memory(str(e.value)) == without_memory(j.stderr.strip().removeprefix("pride: --"))
    # A function's box, and an optimizer's: "dim" too, before the bounds are built.
    f = lambda x: 0.0
    for make in (lambda: pride.minimize("pso", f, bounds=(0, 1), dim=10**12),
                 lambda: pride.Optimizer("pso", bounds=(0, 1), dim=10**12)):
        with pytest.raises(ValueError, match=r"^dim: bounds in dimension 1000000000000 needs about 48 TB of memory, "
                                             r"more than the .* this machine has$"):
            make()
    for entry in ({"id": "f", "function": f, "bounds": (0, 1), "dim": 10**12},
                  {"id": "s", "problem": "sphere", "dim": 10**12}):
        with pytest.raises(ValueError, match=r"^problems\[0\]: algorithm 'pso' on problem '.': dim: \w+ in dimension "
                                             r"1000000000000 needs about"):
            pride.Campaign("c", seeds=1, evals=10, problems=[entry], algorithms=["pso"])


SIZES = """
    import resource, time
    import pride

    def peak():
        return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss // 1024  # MB

    f = lambda x: 0.0
    calls = [
        lambda: pride.minimize("pso", "sphere", dim=3 * 10**8),
        lambda: pride.minimize("pso", f, bounds=(0, 1), dim=3 * 10**8),
        lambda: pride.Optimizer("pso", bounds=(0, 1), dim=3 * 10**8),
        lambda: pride.Campaign("c", seeds=1, evals=10, algorithms=["pso"],
                               problems=[{"id": "f", "function": f, "bounds": (0, 1), "dim": 3 * 10**8}]),
        lambda: pride.Campaign("c", seeds=1, evals=10, algorithms=["pso"],
                               problems=[{"id": "s", "problem": "sphere", "dim": 3 * 10**8}]),
        lambda: pride.minimize("pso", "sphere", dim=2, pop=10**9),
        lambda: pride.minimize("pso", f, bounds=(0, 1), dim=2, pop=10**9),
        lambda: pride.minimize("pso", "sphere", dim=2, evals=10**15),
        lambda: pride.Optimizer("pso", bounds=(0, 1), dim=2, pop=10**9),
    ]
    before = peak()
    for call in calls:
        start = time.monotonic()
        try:
            call()
            print("accepted")
        except ValueError as e:
            print(f"{time.monotonic() - start:.3f} {peak() - before} {e}")
"""


def test_sizes_are_checked_before_anything_of_that_size_is_built():
    p = subprocess.run([sys.executable, "-c", textwrap.dedent(SIZES)], capture_output=True, text=True, timeout=300,
                       env=dict(os.environ, PYTHONPATH=os.pathsep.join(x for x in sys.path if x)))
    assert p.returncode == 0, p.stderr
    lines = p.stdout.splitlines()
    assert len(lines) == 9 and "accepted" not in lines, p.stdout
    for line in lines:
        seconds, grown, message = line.split(" ", 2)
        # Refused at once, having allocated next to nothing (it was gigabytes and a minute).
        assert float(seconds) < 2.0 and int(grown) < 200, line
        assert "needs about" in message and "memory" in message, line
    # The problem's own memory first (19.2 GB: refused on a machine with less free), then the run's.
    assert re.match(r"(dim: sphere|pso: a run with population 50) in dimension 300000000 needs about",
                    lines[0].split(" ", 2)[2]), lines[0]
    assert lines[5].split(" ", 2)[2].startswith("pso: a run with population 1000000000 in dimension 2 needs about")


def test_a_campaigns_target_is_a_finite_number(tmp_path):
    args = dict(seeds=1, evals=10, problems=[{"id": "s", "problem": "sphere", "dim": 2}], algorithms=["pso"])
    for value, text in ((math.nan, "nan"), (math.inf, "inf"), (-math.inf, "-inf")):
        with pytest.raises(ValueError, match=f"^target: must be a finite number, got {re.escape(text)}$"):
            pride.Campaign("c", target=value, **args)
    # The command line refuses it in a campaign file too.
    path = tmp_path / "c.toml"
    path.write_text('name = "c"\nseeds = 1\n[budget]\nevaluations = 10\ntarget = nan\n'
                    '[[problem]]\nid = "s"\ntype = "sphere"\ndim = 2\n[[algorithm]]\nid = "pso"\ntype = "pso"\n')
    with pytest.raises(ValueError, match="'target' must be a finite number, got nan"):
        pride.Campaign.load(path)
    assert pride.Campaign("c", target=1.5, **args).name == "c"


def test_ask_after_the_end_is_refused_as_tell_is():
    opt = pride.Optimizer("pso", bounds=(0, 1), dim=2, evals=20, pop=10, seed=1)
    while not opt.done:
        opt.tell(opt.ask().sum(axis=1))
    for call, name in ((opt.ask, "ask"), (lambda: opt.tell(np.zeros(10)), "tell")):
        with pytest.raises(ValueError, match=f"^{name}: the run has ended \\(done is true\\): nothing more to {name}"):
            call()
    assert opt.result.evaluations == 20


def test_nothing_finite_found_has_no_best_point(tmp_path):
    r = pride.minimize("pso", lambda x: math.nan, bounds=(0, 1), dim=2, evals=50)
    assert r.best_x is None and r.best_f == math.inf and np.all(np.isinf(r.history))
    r = pride.minimize("pso", lambda X: np.full(len(X), np.inf), bounds=(0, 1), dim=2, evals=50, vectorized=True)
    assert r.best_x is None and r.best_f == math.inf
    opt = pride.Optimizer("ga", bounds=(0, 1), dim=2, evals=40)
    while not opt.done:
        opt.tell(np.full(len(opt.ask()), np.nan))
    assert opt.result.best_x is None
    # A campaign stores the same run: no best value (null, as the command line writes +inf).
    c = pride.Campaign("c", seeds=1, evals=50, algorithms=["pso"],
                       problems=[{"id": "n", "function": lambda x: math.nan, "bounds": (0, 1), "dim": 2}])
    c.run(tmp_path / "s.sqlite")
    (run,) = pride.read_store(tmp_path / "s.sqlite", dataframe=False)
    assert run["best"] is None
    # One finite value is a best point.
    r = pride.minimize("pso", lambda x: 1.0 if x[0] < 0.5 else math.nan, bounds=(0, 1), dim=2, evals=50, seed=1)
    assert r.best_f == 1.0 and r.best_x.shape == (2,)


def test_empty_ids_are_refused():
    p = [{"id": "s", "problem": "sphere", "dim": 2}]
    with pytest.raises(ValueError, match=r"^problems\[0\]: needs an id"):
        pride.Campaign("c", seeds=1, evals=10, problems=[{**p[0], "id": ""}], algorithms=["pso"])
    with pytest.raises(ValueError, match=r"^algorithms\[0\]: id must not be empty$"):
        pride.Campaign("c", seeds=1, evals=10, problems=p, algorithms=[{"id": "", "algo": "pso"}])
    with pytest.raises(ValueError, match="^name: a campaign needs a name$"):
        pride.Campaign("", seeds=1, evals=10, problems=p, algorithms=["pso"])


def test_a_large_grid_array_is_read_a_block_of_rows_at_a_time():
    # 3 x 10^6 cells: read as doubles 2^20 cells at a time, not as 24 MB at once; every block
    # checked and copied to its place.
    a = np.zeros((3000, 1000), dtype=np.uint8)
    a[::7, 3] = 1
    a[2999, 999] = 1
    g = pride.Grid(a)
    assert np.array_equal(g.to_array(), a)
    a[2500, 7] = 2
    with pytest.raises(ValueError, match=r"^array: cell \(7,2500\) is 2; expected 0 \(free\) or 1 \(blocked\)$"):
        pride.Grid(a)
    assert np.array_equal(pride.Grid(a.T[:, :1000] == 1).to_array(), (a.T[:, :1000] == 1).astype(np.uint8))
