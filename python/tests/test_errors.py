"""Bad arguments (ValueError / TypeError, the command line's one-line messages), exceptions in
user functions (propagated unchanged), NaN (worse than every value), and the observer."""
import math

import numpy as np
import pytest

import pride
from conftest import cli


def cli_message(*args):
    p = cli(*args, check=False)
    assert p.returncode == 2
    line = p.stderr.strip()
    assert line.startswith("pride: ")
    return line[len("pride: "):]


@pytest.mark.parametrize("kwargs, args", [
    (dict(algo="pso", problem="sphere", dim=0), ["--problem", "sphere", "--dim", 0, "--algo", "pso"]),
    (dict(algo="nope", problem="sphere", dim=2), ["--problem", "sphere", "--dim", 2, "--algo", "nope"]),
    (dict(algo="pso", problem="nope", dim=2), ["--problem", "nope", "--dim", 2, "--algo", "pso"]),
    (dict(algo="pso", problem="sphere", dim=2, pop=1), ["--problem", "sphere", "--dim", 2, "--algo", "pso",
                                                        "--param", "pop=1"]),
    (dict(algo="pso", problem="sphere", dim=2, bogus=3), ["--problem", "sphere", "--dim", 2, "--algo", "pso",
                                                          "--param", "bogus=3"]),
    (dict(algo="astar", problem="sphere", dim=2), ["--problem", "sphere", "--dim", 2, "--algo", "astar"]),
    (dict(algo="pso", problem="sphere", dim=2, evals=0), ["--problem", "sphere", "--dim", 2, "--algo", "pso",
                                                          "--evals", 0]),
    (dict(algo="pso", problem="sphere", dim=2, seed=-1), ["--problem", "sphere", "--dim", 2, "--algo", "pso",
                                                          "--seed", -1]),
])
def test_messages_as_the_command_line(kwargs, args):
    message = cli_message("run", *args)
    algo, problem = kwargs.pop("algo"), kwargs.pop("problem")
    with pytest.raises(ValueError) as e:
        pride.minimize(algo, problem, **kwargs)
    python = str(e.value)
    # The command line names its flags (--dim, --evals, --param NAME), Python its keywords.
    expected = message
    for flag, keyword in (("--param ", "parameter "), ("--iters", "iters"), ("--evals", "evals"), ("--", "")):
        if expected.startswith(flag):
            expected = keyword + expected[len(flag):]
            break
    assert python == expected
    assert "\n" not in python


def test_type_errors():
    with pytest.raises(TypeError):
        pride.minimize("pso", 42, dim=2)
    with pytest.raises(TypeError, match="^parameter pop: expected a number, got str$"):
        pride.minimize("pso", "sphere", dim=2, pop="many")
    with pytest.raises(TypeError):
        pride.minimize("pso", lambda x: "not a number", bounds=([0, 0], [1, 1]), evals=10)
    with pytest.raises(TypeError, match="^dim: expected an integer, got str$"):
        pride.minimize("pso", "sphere", dim="two")
    with pytest.raises(TypeError, match="^evals: expected an integer, got float$"):
        pride.minimize("pso", "sphere", dim=2, evals=1e4)
    with pytest.raises(TypeError, match="^algo: "):
        pride.minimize(None, "sphere", dim=2)


def test_bounds_errors():
    f = lambda x: 0.0
    with pytest.raises(ValueError, match="bounds"):
        pride.minimize("pso", f, evals=10)
    with pytest.raises(ValueError, match="bounds"):
        pride.minimize("pso", f, bounds=([1.0], [0.0]), evals=10)
    with pytest.raises(ValueError, match="bounds"):
        pride.minimize("pso", f, bounds=([0.0, math.inf], [1.0, 2.0]), evals=10)
    with pytest.raises(ValueError, match="coordinates"):
        pride.minimize("pso", f, bounds=([0.0], [1.0, 2.0]), evals=10)
    with pytest.raises(ValueError, match="bounds"):
        pride.minimize("pso", "sphere", dim=2, bounds=([0, 0], [1, 1]))
    with pytest.raises(ValueError, match="vectorized"):
        pride.minimize("pso", lambda X: np.zeros(3), bounds=([0.0], [1.0]), evals=50, vectorized=True)


class Boom(Exception):
    pass


@pytest.mark.parametrize("algo", ["pso", "ga", "nlopt:LN_SBPLX", "hs"])
def test_exception_in_user_function_propagates_unchanged(algo):
    if algo not in {a["name"] for a in pride.algorithms()}:
        pytest.skip(algo + " is not in this build")
    boom = Boom("at evaluation 7")
    calls = {"n": 0}

    def f(x):
        calls["n"] += 1
        if calls["n"] == 7:
            raise boom
        return float(x @ x)

    with pytest.raises(Boom) as e:
        pride.minimize(algo, f, bounds=([-1.0] * 3, [1.0] * 3), evals=1000)
    assert e.value is boom and calls["n"] == 7
    with pytest.raises(Boom):
        pride.minimize(algo, lambda X: (_ for _ in ()).throw(Boom()), bounds=([-1.0] * 3, [1.0] * 3), evals=100,
                       vectorized=True)


def test_nan_is_worse_than_every_value():
    def f(x):
        return math.nan if x[0] < 0.5 else float(x[0])

    r = pride.minimize("pso", f, bounds=([0.0], [1.0]), evals=500, seed=1)
    assert r.best_x[0] >= 0.5 and r.best_f == r.best_x[0]
    r = pride.minimize("pso", lambda x: math.nan, bounds=([0.0], [1.0]), evals=50)
    assert r.best_f == math.inf and np.all(np.isinf(r.history))


def test_callback_sees_the_population_and_stops_the_run():
    seen = []

    def watch(iteration, evaluations, best_f, population, fitness):
        assert population.shape == (10, 4) and fitness.shape == (10,)
        assert not population.flags.writeable and not fitness.flags.writeable
        with pytest.raises(ValueError):
            population[0, 0] = 1.0
        assert best_f == min(min(fitness), seen[-1][2]) if seen else best_f == min(fitness)
        seen.append((iteration, evaluations, best_f, population.copy()))
        return None if iteration < 3 else False  # None (no return) goes on

    r = pride.minimize("pso", "sphere", dim=4, evals=10_000, pop=10, seed=5, callback=watch)
    assert [s[0] for s in seen] == [0, 1, 2, 3]
    assert [s[1] for s in seen] == [10, 20, 30, 40]
    assert r.iterations == 3 and r.evaluations == 40
    assert list(r.history) == [s[2] for s in seen]
    # The same run as unobserved, up to where it stopped (the schedule is the 10,000 evaluations').
    full = pride.minimize("pso", "sphere", dim=4, evals=10_000, pop=10, seed=5)
    assert full.history[:4].tobytes() == r.history.tobytes()


def test_callback_exception_and_observing_nlopt():
    def bad(*args):
        raise Boom()

    with pytest.raises(Boom):
        pride.minimize("pso", "sphere", dim=2, evals=200, callback=bad)
    iterations = []
    pride.minimize("nlopt:LN_SBPLX", "sphere", dim=2, evals=200, callback=lambda i, *rest: iterations.append(i))
    assert iterations and iterations[0] == 0
    stopped = pride.minimize("nlopt:LN_SBPLX", "sphere", dim=2, evals=10_000, callback=lambda i, *rest: i < 2)
    assert stopped.evaluations < 10_000


def test_the_gil_is_released_during_cpp_work():
    import threading

    ticks, stop = [0], threading.Event()

    def other():
        while not stop.is_set():
            ticks[0] += 1

    t = threading.Thread(target=other)
    t.start()
    try:
        before = ticks[0]
        pride.minimize("pso", "sphere", dim=30, evals=300_000, seed=1)
        during = ticks[0] - before  # another Python thread ran while C++ worked
    finally:
        stop.set()
        t.join()
    assert during > 0


def test_ctrl_c_ends_a_run_of_a_python_function():
    import signal

    calls = {"n": 0}

    def f(x):
        calls["n"] += 1
        if calls["n"] == 5:
            signal.raise_signal(signal.SIGINT)
        return float(x @ x)

    with pytest.raises(KeyboardInterrupt):
        pride.minimize("pso", f, bounds=([-1.0] * 2, [1.0] * 2), evals=100_000)
    assert calls["n"] < 10


def test_choice_parameters():
    """A choice parameter takes one of its names as a str; its names are listed."""
    ga = next(a for a in pride.algorithms() if a["name"] == "ga")
    shortcut = next(p for p in ga["params"] if p["name"] == "shortcut")
    assert shortcut["type"] == "choice"
    assert shortcut["choices"] == ["none", "line", "elbow"]
    assert shortcut["default"] == "none"
    with pytest.raises(TypeError, match=r"^parameter shortcut: expected one of none, line or elbow \(a str\), got int$"):
        pride.minimize("ga", "sphere", dim=2, evals=10, shortcut=1)
    with pytest.raises(ValueError, match="^ga: shortcut is a setting of the chain space"):
        pride.minimize("ga", "sphere", dim=2, evals=10, shortcut="line")
