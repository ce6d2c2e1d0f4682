"""pride.hypervolume and the other indicators of framework/pareto/ from Python: hand-computed
values, Debian's python3-deap hypervolume as the oracle on random fronts (M = 2, 3, 5; skipped
when deap is not installed), and one-line errors naming the argument."""
import numpy as np
import pytest

import pride


def test_hand_computed_sets():
    # The staircase (0, 2), (1, 1), (2, 0) against (3, 3): the union of [0,3]x[2,3], [1,3]x[1,3]
    # and [2,3]x[0,3] has area 3 + 2 + 1 = 6; each point alone covers one unit square no other does.
    points = np.array([[0.0, 2.0], [1.0, 1.0], [2.0, 0.0]])
    assert pride.hypervolume(points, [3.0, 3.0]) == 6.0
    assert list(pride.hypervolume_contributions(points, [3.0, 3.0])) == [1.0, 1.0, 1.0]
    # Against itself, every distance indicator is 0; shifted by 0.5 in each objective, epsilon is 0.5.
    assert pride.igd(points, points) == 0.0
    assert pride.igd_plus(points, points) == 0.0
    assert pride.epsilon_additive(points + 0.5, points) == 0.5
    # IGD+ counts only how much worse: (0.5, 0.5) worse everywhere is sqrt(0.5) from each point.
    assert pride.igd_plus(points + 0.5, points) == pytest.approx(np.sqrt(0.5))
    assert list(pride.nondominated_sort([[0, 0], [1, 1], [0, 2], [2, 2]])) == [0, 1, 1, 2]
    d = pride.crowding_distance(points)
    assert np.isinf(d[0]) and np.isinf(d[2]) and d[1] == 2.0


@pytest.mark.parametrize("m", [2, 3, 5])
def test_hypervolume_is_deaps(m):
    hv = pytest.importorskip("deap.tools._hypervolume.hv")
    rng = np.random.default_rng(m)
    for n in (1, 8, 40):
        points = np.abs(rng.normal(size=(n, m))) + 1e-3
        points *= ((1.0 + 0.3 * rng.random(n)) / np.linalg.norm(points, axis=1))[:, None]
        ref = np.full(m, 1.5)
        assert pride.hypervolume(points, ref) == pytest.approx(hv.hypervolume(points, ref), rel=1e-12)


def test_errors_name_the_argument():
    with pytest.raises(TypeError, match=r"^points: expected real numbers, got NoneType$"):
        pride.hypervolume(None, [1.0, 1.0])
    with pytest.raises(ValueError, match=r"^points: must be an \(n, M\) array"):
        pride.hypervolume([1.0, 2.0], [3.0, 3.0])
    with pytest.raises(ValueError, match=r"^points: 3 objectives, ref: 2 \(they must be equal\)$"):
        pride.hypervolume([[1.0, 2.0, 3.0]], [3.0, 3.0])
    with pytest.raises(ValueError, match=r"^ref: must be one point"):
        pride.hypervolume([[1.0, 2.0]], [[3.0, 3.0]])
    with pytest.raises(ValueError, match=r"^points: 2 objectives, front: 3 \(they must be equal\)$"):
        pride.igd([[1.0, 2.0]], [[1.0, 2.0, 3.0]])
    with pytest.raises(TypeError, match=r"^front: expected real numbers"):
        pride.igd_plus([[1.0, 2.0]], "front")
    with pytest.raises(ValueError, match="NaN"):
        pride.nondominated_sort([[1.0, float("nan")]])


def test_attainment_surfaces_by_hand_and_by_brute_force():
    runs = [np.array([[1.0, 5.0], [3.0, 2.0]]), np.array([[2.0, 4.0]]), np.array([[4.0, 1.0]])]
    assert pride.attainment_surface(runs, 1).tolist() == [[1, 5], [2, 4], [3, 2], [4, 1]]
    assert pride.attainment_surface(runs, 2).tolist() == [[2, 5], [3, 4], [4, 2]]
    assert pride.attainment_surface(runs, 3).tolist() == [[4, 4]]
    rng = np.random.default_rng(5)
    for _ in range(50):
        runs = [rng.integers(0, 6, size=(rng.integers(0, 5), 2)).astype(float) for _ in range(rng.integers(1, 5))]
        for k in range(1, len(runs) + 1):
            s = pride.attainment_surface(runs, k)
            for x in np.arange(-0.5, 6.5, 0.5):
                for y in np.arange(-0.5, 6.5, 0.5):
                    count = sum(bool(len(a)) and bool(np.any((a[:, 0] <= x) & (a[:, 1] <= y))) for a in runs)
                    covered = bool(len(s)) and bool(np.any((s[:, 0] <= x) & (s[:, 1] <= y)))
                    assert covered == (count >= k)


def test_attainment_surface_errors_name_the_argument():
    with pytest.raises(ValueError, match=r"^k: must be in \[1, 1\]"):
        pride.attainment_surface([np.zeros((1, 2))], 2)
    with pytest.raises(ValueError, match=r"^runs\[0\]: must be an \(n, 2\) array"):
        pride.attainment_surface([np.zeros((1, 3))], 1)
    with pytest.raises(TypeError, match="^runs: expected a list"):
        pride.attainment_surface(np.zeros((1, 2)), 1)
