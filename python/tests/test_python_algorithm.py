"""Algorithms written in Python (pride.register_algorithm): run by minimize, plan and campaigns
beside the C++ ones, every evaluation counted and within the budget, the same run for the same
seed, and their errors one line naming the algorithm."""
import numpy as np
import pytest

import pride

ARRAY = np.zeros((6, 6), dtype=int)
ARRAY[1:5, 2] = 1


def random_search(problem, seed):
    """random search: batches of 10 uniform points"""
    rng = np.random.default_rng(seed)
    while True:
        problem.evaluate(rng.uniform(problem.lower, problem.upper, size=(10, problem.dim)))


def one_point_at_a_time(problem, seed):
    rng = np.random.default_rng(seed)
    while not problem.done:
        problem(rng.uniform(problem.lower, problem.upper))


pride.register_algorithm("py-rs", random_search)
pride.register_algorithm("py-one", one_point_at_a_time, summary="one point per iteration")


def test_registered_beside_the_cpp_ones():
    listed = {a["name"]: a for a in pride.algorithms()}
    assert listed["py-rs"]["family"] == "python"
    assert listed["py-rs"]["summary"] == "random search: batches of 10 uniform points"
    assert listed["py-one"]["summary"] == "one point per iteration"
    assert "box" in listed["py-rs"]["spaces"] and "pso" in listed


def test_minimize_counts_every_evaluation_within_the_budget():
    calls = {"n": 0}

    def f(x):
        calls["n"] += 1
        return float(np.sum(x * x))

    r = pride.minimize("py-rs", f, bounds=([-2, -2], [2, 2]), evals=95, seed=4)
    assert calls["n"] == r.evaluations == 95  # the last batch cut at the budget
    assert r.iterations == 9 and len(r.history) == 10  # iteration 0 is the first batch
    assert list(r.history_evaluations) == [10, 20, 30, 40, 50, 60, 70, 80, 90, 95]
    # The best point is the best of the points the seed draws, found by the engine's guard.
    rng = np.random.default_rng(4)
    drawn = np.vstack([rng.uniform([-2, -2], [2, 2], size=(10, 2)) for _ in range(10)])[:95]
    values = np.sum(drawn * drawn, axis=1)
    assert r.best_f == values.min() and np.array_equal(r.best_x, drawn[values.argmin()])
    assert list(r.history) == [values[: min(10 * (k + 1), 95)].min() for k in range(10)]


def test_the_same_seed_gives_the_same_run():
    a = pride.minimize("py-rs", "rastrigin", dim=4, evals=300, seed=7)
    b = pride.minimize("py-rs", "rastrigin", dim=4, evals=300, seed=7)
    c = pride.minimize("py-rs", "rastrigin", dim=4, evals=300, seed=8)
    assert a.best_f == b.best_f and np.array_equal(a.best_x, b.best_x) and np.array_equal(a.history, b.history)
    assert a.best_f != c.best_f
    assert pride.Problem("rastrigin", 4)(a.best_x) == a.best_f


def test_stopping_rules_and_a_callback():
    r = pride.minimize("py-one", "sphere", dim=2, iters=5, seed=1)
    assert r.iterations == 5 and r.evaluations == 6
    r = pride.minimize("py-rs", "sphere", dim=2, evals=10_000, target=0.5, seed=1)
    assert r.best_f <= 0.5 and r.evaluations < 10_000 and r.evaluations % 10 == 0
    seen = []
    r = pride.minimize("py-rs", "sphere", dim=2, evals=1_000, seed=1,
                       callback=lambda it, ev, best, pop, fit: seen.append((it, ev, pop.shape)) or it < 2)
    assert seen == [(0, 10, (10, 2)), (1, 20, (10, 2)), (2, 30, (10, 2))] and r.evaluations == 30


def test_campaign_runs_it_beside_cpp_algorithms(tmp_path):
    c = pride.Campaign("py", seeds=3, evals=200,
                       problems=[{"id": "sph", "problem": "sphere", "dim": 3},
                                 {"id": "g", "grid": pride.Grid(ARRAY), "start": (0, 5), "goal": (5, 0)}],
                       algorithms=["pso", "py-rs", {"id": "one", "algo": "py-one"}])
    assert c.run(tmp_path / "p.sqlite", jobs=2) == {"stored": 18, "already": 0, "total": 18}
    runs = pride.read_store(tmp_path / "p.sqlite", dataframe=False)
    assert all(r["evaluations"] == 200 for r in runs)
    for r in runs:
        if r["algorithm"] == "py-rs" and r["problem"] == "sph":
            alone = pride.minimize("py-rs", "sphere", dim=3, evals=200, seed=r["seed"])
            assert r["best"] == alone.best_f and np.array_equal(r["best_x"], alone.best_x)
        if r["algorithm"] == "py-rs" and r["problem"] == "g":  # a grid through the line encoding
            alone = pride.plan(pride.Grid(ARRAY), (0, 5), (5, 0), algo="py-rs", evals=200, seed=r["seed"])
            assert r["best"] == alone.objective_value and r["encoding"] == "line"
    rows = pride.report(tmp_path / "p.sqlite", dataframe=False)["rows"]
    assert {row["algorithm"] for row in rows} == {"pso", "py-rs", "one"}


def test_a_toml_campaign_names_it_once_registered(tmp_path):
    toml = tmp_path / "c.toml"
    toml.write_text('name = "t"\nseeds = 2\n[budget]\nevaluations = 150\n'
                    '[[problem]]\nid = "s"\ntype = "sphere"\ndim = 2\n'
                    '[[algorithm]]\nid = "rs"\ntype = "py-rs"\n')
    c = pride.Campaign.load(toml)
    assert c.run(tmp_path / "t.sqlite", jobs=2)["stored"] == 2
    runs = pride.read_store(tmp_path / "t.sqlite", dataframe=False)
    assert [r["best"] for r in runs] == [pride.minimize("py-rs", "sphere", dim=2, evals=150, seed=s).best_f
                                         for s in (1, 2)]


def test_errors_in_the_function_are_one_line_naming_the_algorithm(tmp_path):
    def broken(problem, seed):
        problem.evaluate(np.zeros((2, problem.dim)))
        return 1 / 0

    pride.register_algorithm("py-broken", broken)
    with pytest.raises(pride.AlgorithmError) as e:
        pride.minimize("py-broken", "sphere", dim=2, evals=100, seed=3)
    text = str(e.value)
    assert "\n" not in text
    assert text.startswith("algorithm 'py-broken' (seed 3): ZeroDivisionError: division by zero (")
    assert "test_python_algorithm.py, line" in text
    c = pride.Campaign("b", seeds=2, evals=100, problems=[{"id": "s", "problem": "sphere", "dim": 2}],
                       algorithms=["pso", "py-broken"])
    with pytest.raises(pride.AlgorithmError, match=r"^algorithm 'py-broken' \(seed [12]\): ZeroDivisionError"):
        c.run(tmp_path / "b.sqlite", jobs=2)

    pride.register_algorithm("py-idle", lambda problem, seed: None)
    with pytest.raises(pride.AlgorithmError, match=r"^algorithm 'py-idle' \(seed 1\): its function returned without "
                                                   r"evaluating a point"):
        pride.minimize("py-idle", "sphere", dim=2, evals=100)


def test_bad_points_and_a_kept_problem():
    kept = []

    def outside(problem, seed):
        problem.evaluate(problem.upper + 1.0)

    def wrong_size(problem, seed):
        problem.evaluate(np.zeros((3, problem.dim + 1)))

    def keeps(problem, seed):
        kept.append(problem)
        problem.evaluate(np.zeros(problem.dim))

    for name, fn in [("py-outside", outside), ("py-size", wrong_size), ("py-keeps", keeps)]:
        pride.register_algorithm(name, fn)
    with pytest.raises(pride.AlgorithmError,
                       match=r"^algorithm 'py-outside' \(seed 1\): ValueError: X: coordinate 0 is 6.12, outside the box "
                             r"\[-5.12, 5.12\] \(.*test_python_algorithm.py, line \d+\)$"):
        pride.minimize("py-outside", "sphere", dim=2, evals=10)
    with pytest.raises(pride.AlgorithmError, match=r"ValueError: X: expected points of dimension 2, got 3"):
        pride.minimize("py-size", "sphere", dim=2, evals=10)
    r = pride.minimize("py-keeps", "sphere", dim=2, evals=10)
    assert r.evaluations == 1 and r.best_f == 0.0
    with pytest.raises(ValueError, match=r"^problem: the run of algorithm 'py-keeps' is over"):
        kept[0].evaluate(np.zeros(2))


def test_a_problem_functions_error_stays_its_own():
    def f(x):
        raise KeyError("from the problem")

    with pytest.raises(KeyError, match="from the problem"):
        pride.minimize("py-rs", f, bounds=(-1, 1), dim=2, evals=50)


def test_registration_errors():
    with pytest.raises(TypeError, match=r"^function: expected a callable, got int$"):
        pride.register_algorithm("py-x", 3)
    with pytest.raises(TypeError, match=r"^name: expected a name \(str\), got int$"):
        pride.register_algorithm(3, random_search)
    with pytest.raises(ValueError, match=r"^name: 'pso' is an algorithm of pride's own; choose another name$"):
        pride.register_algorithm("pso", random_search)
    with pytest.raises(ValueError, match=r"^name: 'my algo': expected letters, digits"):
        pride.register_algorithm("my algo", random_search)
    with pytest.raises(ValueError, match=r"^name: expected 1 to 100 characters, got 0$"):
        pride.register_algorithm("", random_search)
    with pytest.raises(ValueError, match=r"^algo: 'py-rs' is written in Python"):
        pride.Optimizer("py-rs", bounds=(-1, 1), dim=2, evals=10)
    with pytest.raises(ValueError, match=r"unknown parameter|has no parameter|pop"):
        pride.minimize("py-rs", "sphere", dim=2, evals=10, pop=3)
    with pytest.raises(ValueError, match=r"multi-objective"):
        pride.front("py-rs", "zdt1", evals=100)

    def registers(problem, seed):
        pride.register_algorithm("py-later", random_search)

    with pride.Optimizer("pso", bounds=(-1, 1), dim=2, evals=100) as opt:
        with pytest.raises(ValueError,
                           match=r"^register_algorithm: not while an Optimizer's run is going: finish or close it "
                                 r"first$"):
            pride.register_algorithm("py-late", random_search)
        finished = pride.Optimizer("pso", bounds=(-1, 1), dim=2, evals=20)
        while not finished.done:
            finished.tell(np.zeros(len(finished.ask())))
    pride.register_algorithm("py-late", random_search)  # one closed, the other's run over

    pride.register_algorithm("py-registers", registers)
    with pytest.raises(pride.AlgorithmError, match=r"ValueError: register_algorithm: not while another call"):
        pride.minimize("py-registers", "sphere", dim=2, evals=10)


def test_registering_again_replaces_the_function():
    pride.register_algorithm("py-again", random_search)
    first = pride.minimize("py-again", "sphere", dim=2, evals=20, seed=1)
    pride.register_algorithm("py-again", one_point_at_a_time)
    second = pride.minimize("py-again", "sphere", dim=2, evals=20, seed=1)
    assert first.iterations == 1 and second.iterations == 19
