"""Constraints from Python: a user's function with subject_to (or returning (f, g)), CEC 2006 by
name, the same bits as the command line and as the named problems, ask and tell told constraint
values, and every bad input refused in one line."""
import math

import numpy as np
import pytest

import pride
from conftest import cli

CONSTRAINED = ["pso", "pso-constriction", "de", "jde", "jade", "shade", "lshade", "jso", "colshade", "cmaes", "ipop-cmaes",
               "ga", "ga-plus"]
DISC = ([-2.0, -2.0], [2.0, 2.0])


def disc_f(x):
    return x[0] * x[0] + x[1] * x[1]


def disc_g(x):  # 1 - x0 - x1 <= 0: the optimum is (0.5, 0.5), f = 0.5
    return [1.0 - x[0] - x[1]]


# CEC 2006 g06 and g11 written as the C++ suite writes them (products, not powers), so that a run
# on them equals the run on the named problem bit for bit.
def g06_f(x):
    a, b = x[0] - 10.0, x[1] - 20.0
    return a * a * a + b * b * b


def g06_g(x):
    return [-(x[0] - 5.0) * (x[0] - 5.0) - (x[1] - 5.0) * (x[1] - 5.0) + 100.0,
            (x[0] - 6.0) * (x[0] - 6.0) + (x[1] - 5.0) * (x[1] - 5.0) - 82.81]


def g11_fg(x):
    return x[0] * x[0] + (x[1] - 1.0) * (x[1] - 1.0), [x[1] - x[0] * x[0]]


@pytest.mark.parametrize("algo", ["jde", "jade", "lshade", "jso"])
def test_disc_solved_to_its_optimum(algo):
    r = pride.minimize(algo, disc_f, bounds=DISC, subject_to=disc_g, inequalities=1, evals=20_000, seed=1)
    assert r.feasible and r.violation == 0.0 and r.first_feasible >= 1
    assert r.best_f == pytest.approx(0.5, abs=1e-9)
    assert np.allclose(r.best_x, [0.5, 0.5], atol=1e-6)
    assert r.evaluations == 20_000


def test_one_function_returning_f_and_g_is_one_evaluation():
    calls = []

    def fg(x):
        calls.append(1)
        return disc_f(x), disc_g(x)

    r = pride.minimize("jade", fg, bounds=DISC, inequalities=1, evals=3000, seed=2)
    assert len(calls) == r.evaluations == 3000
    two = pride.minimize("jade", disc_f, bounds=DISC, subject_to=disc_g, inequalities=1, evals=3000, seed=2)
    assert (r.best_f, r.best_x.tobytes(), r.history.tobytes()) == (two.best_f, two.best_x.tobytes(),
                                                                   two.history.tobytes())


def test_cec2006_g06_by_name_jade_reaches_the_best_known_value():
    r = pride.minimize("jade", "cec2006-g06", evals=40_000, seed=1)
    assert r.problem == "cec2006-g06" and len(r.best_x) == 2  # its own dimension
    assert r.feasible and r.violation == 0.0 and r.first_feasible is not None
    assert abs(r.best_f - (-6961.81387558015)) < 1e-3


@pytest.mark.parametrize("algo,problem,params", [
    ("jade", "cec2006-g06", {}),
    ("lshade", "cec2006-g06", {}),
    ("pso-constriction", "cec2006-g06", {}),
    ("de", "cec2006-g01", {"constraints": "epsilon"}),
    ("pso", "cec2006-g11", {"constraints": "penalty", "penalty": 1000.0}),
    ("shade", "cec2006-g03", {}),
    ("colshade", "cec2006-g05", {}),
    ("jade", "cec2020rw-rc15", {}),
    ("colshade", "cec2020rw-rc01", {}),
    ("lshade", "bbob-constrained-f1", {"dim": 5}),
    ("pso", "bbob-constrained-f33", {"dim": 2, "instance": 4}),
])
def test_named_problem_equals_cli(algo, problem, params):
    where = {k: v for k, v in params.items() if k in ("dim", "instance")}
    params = {k: v for k, v in params.items() if k not in where}
    r = pride.minimize(algo, problem, evals=5000, seed=3, **where, **params)
    params_flags = ["--instance", where["instance"]] if "instance" in where else []
    flags = [a for k, v in params.items() for a in ("--param", f"{k}={v}")]
    want = cli("run", "--algo", algo, "--problem", problem, "--dim", len(r.best_x), "--evals", 5000, "--seed", 3,
               "--json", *params_flags, *flags)
    assert r.best_f == want["best_f"]
    assert r.best_x.tolist() == want["best_x"]
    assert r.violation == want["best_violation"]
    assert r.first_feasible == want["first_feasible"]
    assert r.evaluations == want["evaluations"]


@pytest.mark.parametrize("algo", CONSTRAINED)
def test_python_function_equals_named_problem(algo):
    named = pride.minimize(algo, "cec2006-g06", evals=2000, seed=5)
    mine = pride.minimize(algo, g06_f, bounds=([13.0, 0.0], [100.0, 100.0]), subject_to=g06_g, inequalities=2,
                          evals=2000, seed=5)
    assert mine.best_f == named.best_f and mine.best_x.tobytes() == named.best_x.tobytes()
    assert mine.violation == named.violation and mine.first_feasible == named.first_feasible
    assert mine.history.tobytes() == named.history.tobytes()
    # An equality, in the (f, g) form.
    named = pride.minimize(algo, "cec2006-g11", evals=2000, seed=5)
    mine = pride.minimize(algo, g11_fg, bounds=([-1.0, -1.0], [1.0, 1.0]), equalities=1, evals=2000, seed=5)
    assert (mine.best_f, mine.violation, mine.first_feasible) == (named.best_f, named.violation, named.first_feasible)


@pytest.mark.parametrize("algo", CONSTRAINED)
def test_ask_tell_with_constraints_equals_minimize(algo):
    want = pride.minimize(algo, disc_f, bounds=DISC, subject_to=disc_g, inequalities=1, evals=600, seed=7)
    opt = pride.Optimizer(algo, bounds=DISC, inequalities=1, evals=600, seed=7)
    told = 0
    while not opt.done:
        X = opt.ask()
        assert X.shape == (1, 2)  # the engine evaluates a constrained point at a time
        opt.tell([disc_f(x) for x in X], [disc_g(x) for x in X])
        told += len(X)
    got = opt.result
    assert told == got.evaluations == want.evaluations == 600
    assert got.best_f == want.best_f and got.best_x.tobytes() == want.best_x.tobytes()
    assert got.history.tobytes() == want.history.tobytes()
    assert (got.violation, got.feasible, got.first_feasible) == (want.violation, want.feasible, want.first_feasible)


def test_ask_tell_refusals_change_nothing():
    opt = pride.Optimizer("de", bounds=DISC, inequalities=1, equalities=1, evals=30, seed=2)
    X = opt.ask()
    with pytest.raises(ValueError, match=r"^tell: g: the optimizer has 2 constraints"):
        opt.tell([1.0])
    with pytest.raises(ValueError, match=r"^tell: g: expected an \(n, 2\) array"):
        opt.tell([1.0], [0.0, 0.0])
    with pytest.raises(ValueError, match=r"^tell: expected 1 x 2 constraint values"):
        opt.tell([1.0], [[0.0, 0.0], [0.0, 0.0]])
    with pytest.raises(TypeError, match=r"^tell: g: expected real numbers"):
        opt.tell([1.0], [[None, 1.0]])
    with pytest.raises(ValueError, match=r"^tell: expected 1 values"):
        opt.tell([1.0, 2.0], [[0.0, 0.0]])
    assert opt.ask().tobytes() == X.tobytes()  # nothing was told: the same point is asked again
    opt.tell([1.0], [[math.nan, 0.0]])  # NaN: infeasible
    while not opt.done:
        X = opt.ask()
        opt.tell(X.sum(axis=1), np.c_[-X[:, 0], X[:, 1] - X[:, 0]])
    assert opt.result.evaluations == 30
    plain = pride.Optimizer("de", bounds=DISC, evals=30)
    n = len(plain.ask())
    with pytest.raises(ValueError, match=r"^tell: g was given, but the optimizer has no constraints"):
        plain.tell(np.zeros(n), np.zeros((n, 1)))
    for kwargs, match in [({"inequalities": -1}, r"^inequalities: must be an integer in \[0, 1000000\], got -1"),
                          ({"inequalities": 0}, r"^inequalities: give how many constraint values"),
                          ({"inequalities": 1, "tolerance": math.nan}, r"^tolerance: must be a finite number"),
                          ({"tolerance": 1e-3}, r"^tolerance: only with constraints"),
                          ({"inequalities": 1, "algo": "hs"}, r"^algo: hs does not handle constraints"),
                          ({"inequalities": 1, "algo": "nsga2", "objectives": 2}, r"^inequalities: nsga2 is multi")]:
        algo = kwargs.pop("algo", "de")
        with pytest.raises(ValueError, match=match):
            pride.Optimizer(algo, bounds=DISC, **kwargs)


def test_nan_constraint_is_infeasible_with_infinite_violation():
    r = pride.minimize("de", disc_f, bounds=DISC, subject_to=lambda x: [math.nan], inequalities=1, evals=200)
    assert not r.feasible and r.violation == math.inf and r.first_feasible is None
    # NaN on half the box: the optimum is found in the other half.
    r = pride.minimize("jade", disc_f, bounds=DISC, subject_to=lambda x: [math.nan if x[0] < 0 else disc_g(x)[0]],
                       inequalities=1, evals=20_000, seed=1)
    assert r.feasible and r.best_f == pytest.approx(0.5, abs=1e-6)


def test_equality_tolerance():
    # h = x0 - 0.3 on [0, 1]^2 minimising x0: feasible only within the tolerance of 0.3.
    def run(tolerance):
        return pride.minimize("jade", lambda x: x[0], bounds=([0.0, 0.0], [1.0, 1.0]),
                              subject_to=lambda x: [x[0] - 0.3], equalities=1, tolerance=tolerance,
                              evals=5000, seed=1)
    loose = run(0.05)
    assert loose.feasible and loose.best_f == pytest.approx(0.25, abs=1e-6)
    default = run(None)
    assert default.feasible and default.best_f == pytest.approx(0.3 - 1e-4, abs=1e-6)


def _error(**kwargs):
    args = dict(bounds=DISC, subject_to=disc_g, inequalities=1, evals=200, seed=1)
    args.update(kwargs)
    problem = args.pop("problem", disc_f)
    algo = args.pop("algo", "de")
    return lambda: pride.minimize(algo, problem, **args)


@pytest.mark.parametrize("kwargs,error,match", [
    ({"subject_to": lambda x: [1.0, 2.0]}, ValueError, r"^subject_to: returned 2 constraint values, expected 1"),
    ({"subject_to": lambda x: [[1.0]]}, ValueError, r"^subject_to: returned 1 constraint values \(2-D\)"),
    ({"subject_to": lambda x: None}, TypeError, r"^subject_to: the constraint values: expected real numbers"),
    ({"subject_to": lambda x: "a"}, TypeError, r"^subject_to: the constraint values: expected real numbers"),
    ({"subject_to": 3}, TypeError, r"^subject_to: expected a callable, got int"),
    ({"inequalities": -1}, ValueError, r"^inequalities: must be an integer in \[0, 1000000\], got -1"),
    ({"equalities": -2}, ValueError, r"^equalities: must be an integer in \[0, 1000000\], got -2"),
    ({"inequalities": 10**7}, ValueError, r"^inequalities: must be an integer in \[0, 1000000\]"),
    ({"inequalities": 0}, ValueError, r"^inequalities: give how many constraint values"),
    ({"inequalities": None}, ValueError, r"^inequalities: give how many constraint values"),
    ({"inequalities": 1.5}, TypeError, r"^inequalities: expected an integer, got float"),
    ({"inequalities": True}, TypeError, r"^inequalities: expected an integer, got bool"),
    ({"tolerance": -1e-3}, ValueError, r"^tolerance: must be a finite number >= 0, got -0.001"),
    ({"tolerance": math.nan}, ValueError, r"^tolerance: must be a finite number >= 0, got nan"),
    ({"tolerance": math.inf}, ValueError, r"^tolerance: must be a finite number >= 0, got inf"),
    ({"tolerance": "a"}, TypeError, r"^tolerance: expected a number, got str"),
    ({"vectorized": True}, ValueError, r"^vectorized: not with constraints"),
    ({"subject_to": None, "problem": lambda x: 1.0}, TypeError, r"^problem: with inequalities or equalities and no "
                                                                r"subject_to, the function returns \(f, g\)"),
    ({"subject_to": None, "problem": lambda x: ("a", [0.0])}, TypeError, r"^problem: the function returns \(f, g\)"),
    ({"algo": "hs"}, ValueError, r"^algo: hs does not handle constraints"),
    ({"subject_to": None, "inequalities": None, "constraints": "epsilon"}, ValueError,
     r"^de: constraints says how constraints are handled; bounds has none"),
    ({"subject_to": None, "inequalities": None, "tolerance": 1e-3}, ValueError, r"^tolerance: only with constraints"),
    ({"problem": "cec2006-g06", "bounds": None}, ValueError, r"^subject_to: only for Python functions"),
    ({"problem": "cec2006-g06", "bounds": None, "subject_to": None}, ValueError,
     r"^inequalities: only for Python functions"),
    ({"problem": "cec2006-g06", "bounds": None, "subject_to": None, "inequalities": None, "dim": 3}, ValueError,
     r"^dim: cec2006-g06 has dimension 2, got 3"),
    ({"problem": "cec2006-g06", "bounds": None, "subject_to": None, "inequalities": None, "instance": 1}, ValueError,
     r"^instance: cec2006-g06 has no instances"),
    ({"problem": "cec2006-g25", "bounds": None, "subject_to": None, "inequalities": None}, ValueError,
     r"^problem: unknown problem 'cec2006-g25'"),
    ({"problem": "cec2020rw-rc58", "bounds": None, "subject_to": None, "inequalities": None}, ValueError,
     r"^problem: unknown problem 'cec2020rw-rc58'"),
    ({"problem": "bbob-constrained-f1", "bounds": None, "subject_to": None, "inequalities": None}, ValueError,
     r"^dim: give the dimension of problem 'bbob-constrained-f1'"),
    ({"problem": "bbob-constrained-f55", "bounds": None, "subject_to": None, "inequalities": None, "dim": 2},
     ValueError, r"^problem: unknown problem 'bbob-constrained-f55'"),
])
def test_bad_input_is_one_line(kwargs, error, match):
    with pytest.raises(error, match=match) as e:
        _error(**kwargs)()
    assert "\n" not in str(e.value)


def test_exception_in_subject_to_propagates_unchanged():
    def g(x):
        raise ZeroDivisionError("mine")

    with pytest.raises(ZeroDivisionError, match="^mine$"):
        _error(subject_to=g)()
    # The module is still usable, and a handler parameter works on constraints.
    r = _error(constraints="epsilon")()
    assert r.feasible and r.evaluations == 200


def test_campaign_on_a_constrained_problem_records_violations(tmp_path):
    # Each run's violation and first feasible evaluation are those of minimize() for its seed; the
    # report adds a feasibility table and counts the feasible runs of each row.
    c = pride.Campaign("con", seeds=3, evals=300,
                       problems=[{"id": "g06", "problem": "cec2006-g06", "dim": 2}],
                       algorithms=[{"id": "de", "algo": "de", "pop": 10},
                                   {"id": "weak", "algo": "de", "pop": 10, "constraints": "penalty", "penalty": 1.0}])
    c.run(tmp_path / "c.sqlite")
    runs = pride.read_store(tmp_path / "c.sqlite", dataframe=False)
    assert len(runs) == 6
    for run in runs:
        params = {} if run["algorithm"] == "de" else {"constraints": "penalty", "penalty": 1.0}
        want = pride.minimize("de", "cec2006-g06", evals=300, seed=run["seed"], pop=10, **params)
        assert run["violation"] == want.violation
        assert run["first_feasible"] == want.first_feasible
        assert run["best"] == (want.best_f if want.feasible else None)
    r = pride.report(tmp_path / "c.sqlite", dataframe=False)
    assert [(f["algorithm"], f["runs"]) for f in r["feasibility"]] == [("de", 3), ("weak", 3)]
    for f, row in zip(r["feasibility"], r["rows"]):
        assert row["feasible_runs"] == f["feasible"] == sum(
            1 for run in runs if run["algorithm"] == f["algorithm"] and run["violation"] == 0)
    assert "Deb's order" in r["markdown"]


@pytest.mark.parametrize("problem,algo,match", [
    ({"id": "b", "problem": "bbob-constrained-f1", "dim": 1}, "de", "bbob-constrained-f1 takes a dimension from 2 to 40"),
    ({"id": "g", "problem": "cec2006-g06", "dim": 3}, "de", "cec2006-g06 has dimension 2, got 3"),
    ({"id": "g", "problem": "cec2006-g06", "dim": 2}, "hs", "hs does not handle constraints"),
])
def test_campaign_on_a_constrained_problem_refuses_in_one_line(problem, algo, match):
    with pytest.raises(ValueError, match=match) as e:
        pride.Campaign("x", seeds=1, evals=100, problems=[problem], algorithms=[algo])
    assert "\n" not in str(e.value)
