"""Odd shapes and types from users, as an acceptance tester tries them: what is a number is taken
(any dtype, any layout), anything else is a one-line TypeError / ValueError, never a crash."""
import numpy as np
import pytest

import pride

B = ([-1.0] * 3, [1.0] * 3)


def run(f, **kw):
    return pride.minimize("pso", f, bounds=B, evals=200, seed=2, **kw)


def one_line(excinfo):
    assert "\n" not in str(excinfo.value)
    return str(excinfo.value)


def test_scalar_returns_that_are_numbers_give_the_same_run():
    want = run(lambda x: float(x @ x))
    for f in (lambda x: np.float64(x @ x), lambda x: np.array(x @ x), lambda x: np.array([x @ x])):
        assert run(f).best_f == want.best_f
    assert run(lambda x: 3).best_f == 3.0 and run(lambda x: np.int32(4)).best_f == 4.0
    assert run(lambda x: float("-inf")).best_f == float("inf")  # non-finite: worse than every value


@pytest.mark.parametrize("value, name", [([1.0], "list"), ("a", "str"), (None, "NoneType"), (1j, "complex"),
                                         ((1.0, 2.0), "tuple")])
def test_scalar_returns_that_are_not_numbers(value, name):
    with pytest.raises(TypeError) as e:
        run(lambda x: value)
    assert one_line(e) == f"the function must return one number, got {name}"


def test_vectorised_returns_of_any_dtype_and_layout():
    want = run(lambda X: np.sum(X * X, axis=1), vectorized=True)
    same = [lambda X: [float(r @ r) for r in X], lambda X: np.sum(X * X, axis=1)[:, None],
            lambda X: np.repeat(np.sum(X * X, axis=1), 2)[::2], lambda X: np.asfortranarray(np.sum(X * X, axis=1))]
    for f in same:
        assert run(f, vectorized=True).best_f == want.best_f
    f32 = run(lambda X: np.sum(X * X, axis=1).astype(np.float32), vectorized=True)
    assert f32.evaluations == 200 and f32.best_f == np.float32(f32.best_f)  # float32 values, widened exactly
    assert run(lambda X: np.arange(len(X)), vectorized=True).best_f == 0.0


@pytest.mark.parametrize("f, kind, message", [
    (lambda X: None, TypeError, "got NoneType"),
    (lambda X: np.array([None] * len(X)), TypeError, "got ndarray of dtype object"),
    (lambda X: np.ones(len(X), dtype=complex), TypeError, "got ndarray of dtype complex128"),
    (lambda X: np.array(["a"] * len(X)), TypeError, "got ndarray of dtype <U1"),
    (lambda X: (r @ r for r in X), TypeError, "got generator"),
    (lambda X: np.zeros(len(X) - 1), ValueError, "returned 49 values for 50 points"),
    (lambda X: np.zeros(len(X) + 1), ValueError, "returned 51 values for 50 points"),
    (lambda X: 1.0, ValueError, "returned 1 values for 50 points"),
])
def test_vectorised_returns_refused(f, kind, message):
    with pytest.raises(kind) as e:
        run(f, vectorized=True)
    assert message in one_line(e)


def test_bounds_of_any_dtype_and_layout():
    want = run(lambda x: float(x @ x)).best_f
    for lower, upper in [(np.full(3, -1, np.float32), np.full(3, 1, np.float32)), (np.full(3, -1), np.full(3, 1)),
                         (np.full(6, -1.0)[::2], np.full(6, 1.0)[::2])]:
        assert pride.minimize("pso", lambda x: float(x @ x), bounds=(lower, upper), evals=200, seed=2).best_f == want
    with pytest.raises(TypeError, match="bounds: lower: expected real numbers"):
        pride.minimize("pso", lambda x: 0.0, bounds=([None], [1.0]), evals=10)
    with pytest.raises(TypeError, match="bounds: upper: expected real numbers, got str"):
        pride.minimize("pso", lambda x: 0.0, bounds=([0.0], "a"), evals=10)


@pytest.mark.parametrize("kwargs, kind, message", [
    (dict(evals=-5), ValueError, "evals: must be an integer in [1, 1000000000000000], got -5"),
    (dict(evals=2**70), ValueError, "evals: 1180591620717411303424 is out of range (64-bit integers)"),
    (dict(seed=2**64), ValueError, "seed: must be an integer in [0, 18446744073709551615], got 18446744073709551616"),
    (dict(dim=-2**64), ValueError, "dim: -18446744073709551616 is out of range (64-bit integers)"),
    (dict(evals=100, iters=3), ValueError, "evals: excludes iters (give one of them)"),
    (dict(evals=100, target=float("nan")), ValueError, "target: must be a number, got nan"),
    (dict(evals=100, colour=3), ValueError, "pso: unknown parameter 'colour'"),
    (dict(evals=10.5), TypeError, "evals: expected an integer, got float"),
])
def test_bad_arguments(kwargs, kind, message):
    kwargs.setdefault("dim", 2)
    with pytest.raises(kind) as e:
        pride.minimize("pso", "sphere", **kwargs)
    assert one_line(e).startswith(message)
    with pytest.raises(ValueError) as e:
        pride.minimize("nope", "sphere", dim=2, evals=10)
    assert one_line(e).startswith("algo: unknown algorithm 'nope'")


def test_tell_of_any_dtype_and_layout_and_refusals():
    def first_result(values_of):
        o = pride.Optimizer("pso", bounds=B, evals=100, seed=1)
        while not o.done:
            X = o.ask()
            o.tell(values_of(X))
        return o.result.best_f
    want = first_result(lambda X: np.sum(X * X, axis=1))
    assert first_result(lambda X: list(np.sum(X * X, axis=1))) == want
    assert first_result(lambda X: np.repeat(np.sum(X * X, axis=1), 2)[::2]) == want
    assert first_result(lambda X: np.sum(X * X, axis=1)[:, None]) == want
    o = pride.Optimizer("pso", bounds=B, evals=100)
    n = len(o.ask())
    for bad in (np.ones(n, dtype=complex), [None] * n, "abc"):
        with pytest.raises(TypeError, match="^tell: values: expected real numbers"):
            o.tell(bad)
    o.close()
    with pytest.raises(ValueError):
        pride.Optimizer("pso", bounds=B, evals=100, iters=3)


A = np.zeros((6, 6), dtype=int)
A[1:5, 2] = 1


def test_grids_from_arrays_of_any_dtype_and_layout():
    want = pride.plan(pride.Grid(A), (0, 5), (5, 0), iters=3, seed=1)
    for a in (A.astype(bool), A.astype(float), A.astype(np.float32), A.astype(np.uint8), np.asfortranarray(A),
              A.tolist(), np.repeat(np.repeat(A, 2, axis=0), 2, axis=1)[::2, ::2]):
        g = pride.Grid(a)
        assert np.array_equal(g.to_array(), A)
        r = pride.plan(g, (0, 5), (5, 0), iters=3, seed=1)
        assert np.array_equal(r.path, want.path) and r.best_f == want.best_f
    assert np.array_equal(pride.Grid(A.T).to_array(), A.T)  # a transposed view is read as it looks


@pytest.mark.parametrize("array, kind, message", [
    (A * 2, ValueError, "array: cell (2,1) is 2; expected 0 (free) or 1 (blocked)"),
    (-A, ValueError, "array: cell (2,1) is -1; expected 0 (free) or 1 (blocked)"),
    (A * 0.5, ValueError, "array: cell (2,1) is 0.5; expected 0 (free) or 1 (blocked)"),
    (np.full((2, 2), np.nan), ValueError, "array: cell (0,0) is nan"),
    (np.zeros(5), ValueError, "array: expected a 2-D array"),
    (np.zeros((0, 5)), ValueError, "array: a map needs at least one row and one column"),
    (None, TypeError, "array: expected real numbers, got NoneType"),
    (np.array([[None, 1], [0, 0]]), TypeError, "array: expected real numbers, got ndarray of dtype object"),
    (np.zeros((3, 3), complex), TypeError, "array: expected real numbers, got ndarray of dtype complex128"),
    ("abc", TypeError, "array: expected real numbers, got str"),
    (np.broadcast_to(np.uint8(0), (200_000, 200_000)), ValueError, "array: a 200000 x 200000 map is larger"),
])
def test_grids_refused(array, kind, message):
    with pytest.raises(kind) as e:
        pride.Grid(array)
    assert one_line(e).startswith(message)


def test_plan_arguments_refused():
    g = pride.Grid(A)
    with pytest.raises(ValueError, match="^evals: excludes iters"):
        pride.plan(g, (0, 5), (5, 0), evals=10, iters=3)
    with pytest.raises(TypeError, match="^weights: expected a number, got str"):
        pride.plan(g, (0, 5), (5, 0), objective="weighted", weights=["a", 1, 1], iters=3)
    with pytest.raises(ValueError, match="^algo: unknown algorithm 'nope'"):
        pride.plan(g, (0, 5), (5, 0), algo="nope", iters=3)
