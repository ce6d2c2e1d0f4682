"""pride: metaheuristic optimisation at C++ speed (docs/python.md).

Every algorithm and problem of pride's registry, grid planning, rough sets and campaigns.
The names and parameters come from the engine's registry, so what ``pride list`` shows is what
this module takes::

    import pride
    r = pride.minimize("pso", "rastrigin", dim=10, evals=20_000, seed=1)
    r.best_f, r.best_x, r.history
"""

from __future__ import annotations

import numbers as _numbers
import os as _os

import numpy as _np

from . import _pride
from ._pride import AlgorithmError, BudgetExhausted, Grid

# project(VERSION) of the build that made the module (`pride --version` prints the same).
__version__ = _pride.__version__

__all__ = [
    "algorithms", "problems", "grid_names", "minimize", "Result", "Optimizer", "Problem", "Grid", "plan", "astar",
    "exact", "pareto", "roughset", "Campaign", "read_store", "report", "hypervolume", "hypervolume_contributions",
    "igd", "igd_plus", "epsilon_additive", "nondominated_sort", "crowding_distance", "attainment_surface", "front", "plan_front",
    "cec2020rw_score", "cec2017_score", "import_coco", "import_cec2017", "import_ioh", "register_algorithm", "BudgetExhausted", "AlgorithmError", "__version__",
]


def algorithms():
    """Every registered algorithm: name, family, summary, spaces and parameters (name, type,
    default, min, max, range, doc), as ``pride list --json`` gives them."""
    return _pride.algorithms()


def problems():
    """Every registered continuous problem: name, summary, dimensions, instances, suite."""
    return _pride.problems()


def grid_names():
    """The objectives, encodings, connectors and initialisations grid plans take."""
    return _pride.grid_names()


def register_algorithm(name, function, *, summary=None):
    """Registers ``function``, an algorithm written in Python, as the algorithm ``name`` (letters,
    digits, '-', '_', '.'): ``minimize``, ``plan`` and campaigns then run it by name beside pride's
    own, on boxes (registered problems, Python functions, grids through the line and free
    encodings). Each run calls ``function(problem, seed)`` once, in the process that runs it:
    ``problem.evaluate(X)`` (or ``problem(X)``) evaluates an (n, dim) batch of points in the box
    ``problem.lower``, ``problem.upper`` (a point of shape (dim,) gives a float) through pride's
    evaluation guard, so every evaluation is counted and within the run's budget, and each call
    is one iteration of the run's history. Once the run is over (budget spent, or a target, wall
    time or iteration limit met), ``evaluate`` raises ``pride.BudgetExhausted``, which ends the
    run when it leaves the function; a batch larger than what is left is evaluated as far as the
    budget goes, +inf for the rest. ``problem.dim``, ``budget`` (evaluations, None without a
    limit), ``evaluations``, ``remaining``, ``iterations``, ``best`` and ``done`` say where the run
    stands. The run's result is the best point evaluated. Draw every random number from ``seed``
    (``numpy.random.default_rng(seed)``): a run is then the same for the same seed, whatever the
    campaign's jobs. Anything else the function raises is a ``pride.AlgorithmError``, one line
    naming the algorithm, the seed and the exception; a run that evaluated nothing is one too.
    Registering a name again replaces its function; a name of pride's own is refused."""
    if not callable(function):
        raise TypeError(f"function: expected a callable, got {type(function).__name__}")
    if summary is None:
        doc = (getattr(function, "__doc__", None) or "").strip()
        summary = doc.splitlines()[0] if doc else "an algorithm written in Python"
    _pride.register_algorithm(_str("name", name), function, _str("summary", summary))


def _int(name, value, optional=True):
    """An integer keyword, or a one-line TypeError naming it (pybind11's own lists signatures)."""
    if value is None and optional:
        return None
    if isinstance(value, bool) or not isinstance(value, _numbers.Integral):
        raise TypeError(f"{name}: expected an integer, got {type(value).__name__}")
    if not -2**63 <= value < 2**63:  # the engine's integers are 64-bit
        raise ValueError(f"{name}: {value} is out of range (64-bit integers)")
    return int(value)


def _seed_count(value):
    """A campaign's seeds, a count from 1 to 1000000 (not a seed: not `--seed`'s range), in the
    words of the campaign's own check, also past 64 bits (before: "out of range (64-bit integers)")."""
    if isinstance(value, bool) or not isinstance(value, _numbers.Integral):
        raise TypeError(f"seeds: expected an integer, got {type(value).__name__}")
    if not 1 <= value <= 1_000_000:
        raise ValueError(f"seeds: must be in [1, 1000000], got {value}")
    return int(value)


def _real(name, value):
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, _numbers.Real):
        raise TypeError(f"{name}: expected a number, got {type(value).__name__}")
    return float(value)


def _reals(name, values):
    """A list of real numbers (None is not one)."""
    out = []
    for v in _list(name, values):
        if v is None:
            raise TypeError(f"{name}: expected numbers, got NoneType")
        out.append(_real(name, v))
    return out


def _utf8(name, value):
    """A str that has UTF-8 bytes, or a one-line ValueError naming it: a lone surrogate (what
    os.listdir and sys.argv give for a name whose bytes are not UTF-8) has none."""
    try:
        value.encode("utf-8")
    except UnicodeEncodeError:
        raise ValueError(f"{name}: not valid UTF-8 (a lone surrogate, as os.listdir gives for a name whose bytes "
                         "are not UTF-8): pride takes UTF-8 text") from None
    return value


def _str(name, value):
    if not isinstance(value, str):
        raise TypeError(f"{name}: expected a name (str), got {type(value).__name__}")
    return _utf8(name, value)


def _seed(value):
    """A seed: the command line's range, [0, 2^64 - 1], and its wording."""
    if isinstance(value, bool) or not isinstance(value, _numbers.Integral):
        raise TypeError(f"seed: expected an integer, got {type(value).__name__}")
    value = int(value)
    if not 0 <= value < 2**64:
        raise ValueError(f"seed: must be an integer in [0, 18446744073709551615], got {value}")
    return value


def _bool(name, value, optional=False):
    if value is None and optional:
        return None
    if not isinstance(value, (bool, _np.bool_)):
        raise TypeError(f"{name}: expected True or False, got {type(value).__name__}")
    return bool(value)


def _callable(name, value):
    if value is not None and not callable(value):
        raise TypeError(f"{name}: expected a callable, got {type(value).__name__}")
    return value


def _path(name, value):
    """A file's path: a str or an os.PathLike giving one."""
    if isinstance(value, _os.PathLike):
        value = _os.fspath(value)
    if not isinstance(value, str):
        raise TypeError(f"{name}: expected a path (str or os.PathLike), got {type(value).__name__}")
    return _utf8(name, value)


def _list(name, value):
    """A list or tuple (not a str, dict, set or None: their order or items are not what is meant)."""
    if not isinstance(value, (list, tuple)):
        raise TypeError(f"{name}: expected a list, got {type(value).__name__}")
    return list(value)


def _indices(name, value):
    """The ``integers`` or ``categorical`` keyword: None, or a list of coordinate indices (from 0)."""
    if value is None:
        return None
    return [_int(name, i, False) for i in _list(name, value)]


def _grid(value):
    if not isinstance(value, Grid):
        raise TypeError(f"grid: expected a pride.Grid, got {type(value).__name__}")
    return value


class Result:
    """What a run returns: best_x (numpy), best_f, evaluations, iterations, history (numpy: the
    best value after each iteration, 0 = the initial population), history_evaluations, wall_ms;
    grid plans add path ((n, 2) array of x, y), feasible, objective_value, metrics, optimum, gap;
    runs with constraints add violation (the best point's, 0 when feasible), feasible and
    first_feasible (the evaluation that first found a feasible point, None if none did)."""

    def __init__(self, fields):
        if not isinstance(fields, dict):
            raise TypeError(f"fields: expected a dict, got {type(fields).__name__}")
        self.__dict__.update(fields)

    def as_dict(self):
        return dict(self.__dict__)

    def __repr__(self):
        shown = ", ".join(
            f"{k}={v!r}" for k, v in self.__dict__.items()
            if k in ("algo", "best_f", "evaluations", "iterations", "wall_ms", "violation", "feasible", "objective_value"))
        return f"Result({shown})"


def minimize(algo, problem, *, dim=None, bounds=None, evals=None, iters=None, target=None, wall_ms=None,
             seed=1, instance=None, callback=None, vectorized=False, subject_to=None, inequalities=None,
             equalities=None, tolerance=None, integers=None, categorical=None, **params):
    """One run of ``algo`` on ``problem``: a registered problem's name (with ``dim``, and
    ``instance``) or a Python function with ``bounds=(lower, upper)``, called as ``f(x)`` with x
    of shape (dim,), or, with ``vectorized=True``, as ``f(X)`` with X of shape (n, dim) returning n
    values. ``params`` are the algorithm's parameters (see ``algorithms()``). Without evals or
    iters the budget is 10,000 evaluations per dimension. ``callback(iteration, evaluations,
    best_f, population, fitness)`` is called after every iteration with read-only copies of the
    population and its values (the callback's to keep); returning False stops the run there. The
    same seed (0 to 2^64 - 1) gives the same bits as ``pride run --seed``.

    Constraints (docs/constraints.md): ``subject_to(x)`` returns the ``inequalities`` values
    g_i(x) <= 0, then the ``equalities`` values h_j(x) = 0 (within ``tolerance``, 1e-4 by default);
    without ``subject_to``, declaring the counts means ``problem(x)`` returns ``(f, g)`` in one call.
    Either way one point is one evaluation. A NaN constraint value makes the point infeasible. The
    result then has ``violation``, ``feasible`` and ``first_feasible``; the algorithm's parameter
    ``constraints`` (deb, epsilon, penalty) chooses how points compare. The CEC 2006 problems
    ``cec2006-g01`` to ``cec2006-g24`` are taken by name, in their own dimension.

    Integer variables: ``integers`` lists the coordinates (from 0) of a Python function whose
    values are integers, with integer bounds; the function receives them as integral floats, the
    result's ``x`` has them, and CMA-ES with ``margin=1`` searches them as integers (any other
    algorithm searches the box and its points are rounded before the call). ``categorical`` lists
    coordinates whose values are unordered choices, numbered 0 to k - 1 by their bounds (0, k - 1);
    the GA family and NSGA-II vary them by uniform crossover and random resetting. Both work with
    constraints too. A registered problem declares its own (``bbob-mixint-fN``)."""
    return Result(_pride.minimize(_str("algo", algo), problem, _int("dim", dim), bounds, _int("evals", evals),
                                  _int("iters", iters), _real("target", target), _real("wall_ms", wall_ms),
                                  _seed(seed), _int("instance", instance), _callable("callback", callback),
                                  _bool("vectorized", vectorized), _callable("subject_to", subject_to),
                                  _int("inequalities", inequalities), _int("equalities", equalities),
                                  _real("tolerance", tolerance), _indices("integers", integers),
                                  _indices("categorical", categorical), params))


def front(algo, problem, *, dim=None, objectives=None, bounds=None, evals=None, iters=None, wall_ms=None, seed=1,
          vectorized=False, reference=True, integers=None, categorical=None, **params):
    """One run of a multi-objective ``algo`` (nsga2, nsga3, moead, smsemoa) on ``problem``: a
    catalog problem's name (zdt1, zdt2, zdt3, zdt4, zdt6, dtlz1-dtlz7, wfg1-wfg9; ``dim`` its number
    of variables n and ``objectives`` DTLZ's and WFG's M, both defaulting to the papers') or a Python function
    with ``bounds=(lower, upper)`` and ``objectives=M``, called as ``f(x)`` returning M values or,
    with ``vectorized=True``, as ``f(X)`` with X of shape (n, dim) returning an (n, M) array. The
    result's ``f`` is the non-dominated set found, an (n, M) array (distinct points, in
    lexicographic order), ``x`` their points (n, dim); ``quality`` (catalog problems, unless
    ``reference=False``) has the hypervolume, its ratio to the reference front's and IGD+, on
    objectives normalised by the reference front (docs/multiobjective.md). The constrained
    problems ``constr``, ``srn``, ``tnk``, ``c1-dtlz1`` and ``c2-dtlz2`` run by constrained
    domination (docs/constraints.md); their result also has ``violation``, one per point (0:
    feasible), and ``first_feasible``, and ``quality`` counts feasible points only. The same bits
    as ``pride front`` with the same seed. ``integers`` and ``categorical`` declare a Python
    function's integer and categorical coordinates, as in ``minimize``."""
    return Result(_pride.front(_str("algo", algo), problem, _int("dim", dim), _int("objectives", objectives), bounds,
                               _int("evals", evals), _int("iters", iters), _real("wall_ms", wall_ms), _seed(seed),
                               _bool("vectorized", vectorized), _bool("reference", reference),
                               _indices("integers", integers), _indices("categorical", categorical), params))


def plan_front(grid, start, goal, *, algo="nsga2", objectives="length,turns", encoding="line", init=None,
               connector="repair", waypoints=3, corner_cutting=False, clearance_bands=3, clearance_width=1, evals=None, iters=None,
               wall_ms=None, seed=1, reference=True, **params):
    """A multi-objective run on a grid, as ``pride front --map``: ``objectives`` two to four of
    length, turns, angle and clearance, searched through the ``line`` or ``free`` encoding, or on
    cell chains with ``encoding="chain"`` (nsga2 and nsga3: crossover at a common cell, the GA's and
    IQGA's mutations; ``init="sitp"`` for Zhang et al.'s (2025) SITP walks, else random walks). The
    result has ``f`` (n, M), ``paths`` (a list of (k, 2) arrays of (x, y)), ``legal`` (n,) and,
    unless ``reference=False``, ``quality`` against the exact front (``exact_found``: how many of
    its points the run found)."""
    if not isinstance(objectives, str):
        objectives = ",".join(_str("objectives", o) for o in _list("objectives", objectives))
    objectives = _str("objectives", objectives)
    return Result(_pride.plan_front(_grid(grid), start, goal, _str("algo", algo), objectives,
                                    _str("encoding", encoding), "" if init is None else _str("init", init),
                                    _str("connector", connector),
                                    _int("waypoints", waypoints, False), _bool("corner_cutting", corner_cutting),
                                    _int("clearance_bands", clearance_bands, False),
                                    _int("clearance_width", clearance_width, False), _int("evals", evals),
                                    _int("iters", iters), _real("wall_ms", wall_ms), _seed(seed),
                                    _bool("reference", reference), params))


def Problem(name, dim=None, *, instance=None, seed=1):
    """A registered continuous problem to evaluate: ``f = pride.Problem("bbob-f10", 10,
    instance=1)``; ``f(x)`` for a point of shape (dim,) gives a float, ``f(X)`` for an (n, dim)
    batch n values. ``f.lower``, ``f.upper``, ``f.optimum`` (f*, None when unknown), ``f.name``,
    ``f.dim``, ``f.instance``, ``f.types`` (each variable's, "real" or "integer"). The values are the ones pride's runs see, bit for bit; ``seed``
    seeds a noisy function's noise."""
    return _pride.Problem(_str("name", name), _int("dim", dim), _int("instance", instance), _seed(seed))


class Optimizer:
    """Ask and tell: ``X = opt.ask()`` gives the (n, dim) batch the algorithm wants evaluated,
    ``opt.tell(values)`` its n values, until ``opt.done``; then ``opt.result`` as from
    ``minimize``. The run is the one ``minimize`` makes with the same function and seed, bit for
    bit. Closing (or dropping) an optimizer mid-run stops its run. A multi-objective algorithm
    (nsga2, nsga3, moead, smsemoa) takes ``objectives=M`` and is told an (n, M) array, a row of M
    values per point; its ``result`` is the front, as from ``front``. With ``inequalities=m``
    and/or ``equalities=p`` (and ``tolerance``), an algorithm that handles constraints (pso,
    pso-constriction, the DE family) is told ``tell(values, g)``, g of shape (n, m + p); the
    engine evaluates a constrained point at a time, so such a run asks for one point per batch.
    ``integers`` and ``categorical`` as in ``minimize``: the points asked for have integer values
    there."""

    def __init__(self, algo, *, bounds, dim=None, evals=None, iters=None, target=None, wall_ms=None, seed=1,
                 objectives=None, inequalities=None, equalities=None, tolerance=None, integers=None, categorical=None,
                 **params):
        self._run = _pride.Optimizer(_str("algo", algo), bounds, _int("dim", dim), _int("evals", evals),
                                     _int("iters", iters), _real("target", target), _real("wall_ms", wall_ms),
                                     _seed(seed), _int("objectives", objectives), _int("inequalities", inequalities),
                                     _int("equalities", equalities), _real("tolerance", tolerance),
                                     _indices("integers", integers), _indices("categorical", categorical), params)
        self.algo = algo

    def ask(self):
        return self._run.ask()

    def tell(self, values, g=None):
        """The values of the points of the last ask(), one per point (M per point: an (n, M)
        array); with constraints, ``g`` of shape (n, m + p): each point's inequality values, then
        its equality values."""
        self._run.tell(values, g)

    @property
    def done(self):
        return self._run.done()

    @property
    def dim(self):
        return self._run.dimension()

    @property
    def result(self):
        return Result(self._run.result())

    def close(self):
        """Stops the run if it is still going (its thread ends); the optimizer is then unusable."""
        self._run.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


def plan(grid, start=None, goal=None, *, algo="pso", start_world=None, goal_world=None, objective=None,
         step_cost=None, encoding="", connector="repair", init="", waypoints=3, weights=None, lambda_=None,
         corner_cutting=False, oracle=False, gaps=False, evals=None, iters=None, seed=1, callback=None, **params):
    """A path on ``grid`` (a ``pride.Grid``) from ``start`` to ``goal`` ((x, y), x the column from
    the left, y the row from the top) by any grid algorithm, as ``pride path`` plans it: the
    result's ``path`` is an (n, 2) array of (x, y), with ``metrics`` and ``objective_value``;
    on a map with a world frame (a ROS map_server map: ``grid.resolution``, ``grid.origin``)
    ``start_world``/``goal_world`` ((x, y) in metres, the cell holding the point) may replace
    ``start``/``goal``, and ``path_world`` is the path's cell centres in metres (None without a frame);
    ``oracle=True`` adds the exact ``optimum`` and the ``gap``. Every path, a chain or a polyline planner's
    (``theta-star``, ``lazy-theta-star``, ``any-angle-exact``: ``path`` is then empty), comes as
    ``polyline`` ((n, 2) floats, cell (x, y)'s centre at (x, y)) with ``path_metrics`` (length,
    turns, turn angles, angle over length, maximum curvature, clearance); ``gaps=True`` adds the
    shortest grid and any-angle lengths and the path's ``grid_gap`` and ``any_angle_gap``. Without evals or iters, 50
    iterations. Without ``encoding`` the algorithm plans on its native space (chain for iqga, iaga,
    icga and the woa family, line for the others); an encoding it cannot use is a ValueError.

    ``objective`` names the objective (cells, length, weighted, iqga, hswoa); without it, length for a
    planner of polylines (its only one) and cells for every other algorithm. It may be a function of the
    path instead of a name: ``objective(cells)`` gets the
    path's cells as an (n, 2) int array of (x, y) and returns a number to minimise; every call is
    one evaluation, counted in ``evaluations`` and within the budget, with every algorithm and
    encoding. With ``step_cost(previous, direction)`` (the cost of a step in direction 0..7 after
    one in direction ``previous``, -1 for the first; directions (dx, dy) = (1,0) (1,1) (0,1)
    (-1,1) (-1,0) (-1,-1) (0,-1) (1,-1); >= 0; summing to ``objective`` on every path), ``exact``
    and ``oracle=True`` find its exact optimum; their calls of it are their own work, not
    evaluations."""
    return Result(_pride.plan(_grid(grid), start, goal, start_world, goal_world, _str("algo", algo),
                              objective if objective is None or callable(objective) else _str("objective", objective),
                              _callable("step_cost", step_cost), _str("encoding", encoding),
                              _str("connector", connector), _str("init", init), _int("waypoints", waypoints, False),
                              None if weights is None else _reals("weights", weights),
                              _real("lambda_", lambda_), _bool("corner_cutting", corner_cutting),
                              _bool("oracle", oracle), _bool("gaps", gaps), _int("evals", evals), _int("iters", iters),
                              _seed(seed),
                              _callable("callback", callback), params))


def astar(grid, start, goal, *, objective="cells", corner_cutting=False):
    """A* on the grid (a shortest path under ``objective``'s step costs)."""
    return plan(grid, start, goal, algo="astar", objective=objective, corner_cutting=corner_cutting)


def exact(grid, start, goal, *, objective="cells", corner_cutting=False):
    """The exact optimum of ``objective`` (the oracle; for iqga the 3-D Pareto front)."""
    return plan(grid, start, goal, algo="exact", objective=objective, corner_cutting=corner_cutting)


def pareto(grid, start, goal, *, objectives="length,turns", corner_cutting=False):
    """The exact Pareto front over ``objectives`` (length, turns, angle, clearance: two to four of
    them, as ``pride pareto``): a list of dicts with length, turns, angle_penalty and path, and
    clearance when it is one of the objectives (docs/grid.md: the cost per cell by distance band)."""
    if not isinstance(objectives, str):
        objectives = ",".join(_str("objectives", o) for o in _list("objectives", objectives))
    objectives = _str("objectives", objectives)
    return _pride.pareto(_grid(grid), start, goal, objectives, _bool("corner_cutting", corner_cutting))


def cec2017_score(results, dims=(10, 30, 50, 100), exclude=(2,)):
    """The CEC 2017 bound-constrained competition's score of ``results``, a dict {name: mean
    errors}, each a (functions, dims) array: an algorithm's mean error at MaxFES over its runs
    (errors below 1e-8 as 0) on F1, F2, ... (rows) in each dimension of ``dims`` (columns; 10, 30,
    50, 100 weigh 0.1 to 0.4). The functions of ``exclude`` are left out (F2, as the organisers
    did). Returns {name: {"se", "sr", "score1", "score2", "total", "rank"}}: SE, the weighted sum of
    mean errors, and SR, of ranks by mean error; Score1 = 50 SE_min / SE and Score2 = 50 SR_min /
    SR; total = Score1 + Score2 (higher is better) and its rank (docs/import.md)."""
    return _pride.cec2017_score(results, dims, exclude)


def cec2020rw_score(results, dims, order="guidelines"):
    """The CEC 2020 real-world constrained competition's ranking (Kumar et al. 2020, the guidelines'
    eq. 4-9, as the organisers' ranking script computes them) of ``results``, a dict {name: (f,
    violation)} whose arrays are (problems, runs): each run's final best f and its violation (0 when
    feasible; NaN where there is no result), one row per problem, ``dims`` the problems' dimensions
    (they set eq. 5's weights). The best and median runs are taken in the guidelines' order
    (``order="guidelines"``) or in the order given (``order="given"``, as the script reads the
    entrants' sorted workbooks). Returns {name: {"best", "mean", "median", "total", "rank"}}: the
    three weighted sums of normalised adjusted values, PM (``total``, lower is better) and its rank.
    Works on published results as on pride's (docs/constraints.md)."""
    return _pride.cec2020rw_score(results, dims, _str("order", order))


def hypervolume(points, ref):
    """The exact hypervolume (minimisation) of ``points``, an (n, M) array with one row per point,
    against the reference point ``ref`` (M,): 2-D sweep, 3-D dimension sweep, WFG above. Points that
    do not strictly dominate ``ref`` add nothing. No normalisation: scale the objectives first if
    they should weigh alike (docs/multiobjective.md)."""
    return _pride.hypervolume(points, ref)


def hypervolume_contributions(points, ref):
    """Each point's exclusive hypervolume contribution (n,), as SMS-EMOA uses it."""
    return _pride.hypervolume_contributions(points, ref)


def igd(points, front):
    """Inverted generational distance: the mean Euclidean distance from each row of ``front`` (a
    reference set, usually the true front sampled) to the nearest row of ``points``."""
    return _pride.igd(points, front)


def igd_plus(points, front):
    """IGD+ (Ishibuchi et al. 2015): as ``igd``, counting only how far a point is worse than a
    reference point, objective by objective (Pareto compliant)."""
    return _pride.igd_plus(points, front)


def epsilon_additive(points, front):
    """The additive epsilon indicator (Zitzler et al. 2003): the least eps such that every row of
    ``front`` is weakly dominated by some row of ``points`` minus eps."""
    return _pride.epsilon_additive(points, front)


def nondominated_sort(points):
    """The front of each row of ``points`` (n,): 0 for the non-dominated ones, 1 for those
    non-dominated once front 0 is removed, and so on (Deb et al. 2002)."""
    return _pride.nondominated_sort(points)


def crowding_distance(points):
    """NSGA-II's crowding distance of the rows of ``points`` taken as one front (n,): +inf at each
    objective's ends."""
    return _pride.crowding_distance(points)


def attainment_surface(runs, k):
    """The k-th empirical attainment surface of two-objective runs (Fonseca and Fleming 1996):
    ``runs`` a list of (n_i, 2) arrays (each run's set, objectives minimised), ``k`` in 1..len(runs).
    Returns the surface's corners, an (m, 2) array in increasing f1: every point that at least k
    runs attain (a point of theirs weakly dominates it) is weakly dominated by a corner, and each
    corner is attained by k runs. k = 1 is the best surface, len(runs) the worst, (len(runs) + 1)
    // 2 the median."""
    return _pride.attainment_surface(runs, k)


def _pandas():
    try:
        import pandas
        return pandas
    except ImportError:
        return None


def roughset(table, *, columns=None):
    """Core, reducts and minimal certain rules of a decision table, as ``pride roughset --json``:
    ``table`` is a CSV file's path, a 2-D array (integers are codes, anything else is a label;
    the last column is the decision; ``columns`` names them, default a, b, c, ...) or a pandas
    DataFrame (its column names)."""
    if columns is not None:
        columns = _list("columns", columns)
    if isinstance(table, (str, _os.PathLike)):
        if columns is not None:
            raise ValueError("columns: a CSV file names its own columns (its first row)")
        return _pride.roughset_csv(_path("table", table))
    pd = _pandas()
    if pd is not None and isinstance(table, pd.DataFrame):
        columns = [str(c) for c in table.columns] if columns is None else columns
        values = table.to_numpy()
    elif table is None or isinstance(table, (dict, set, bytes)) or not hasattr(table, "__len__"):
        raise TypeError(f"table: expected a CSV file's path, a 2-D array or a DataFrame, got {type(table).__name__}")
    else:
        values = _np.asarray(table)
    if values.ndim != 2:
        raise ValueError(f"table: expected a 2-D table (rows of objects), got {values.ndim} dimensions")
    if columns is None:
        columns = [chr(ord("a") + i) if i < 26 else f"c{i}" for i in range(values.shape[1])]
    columns = [_utf8("columns", str(c)) for c in columns]
    if len(columns) != values.shape[1]:
        raise ValueError(f"columns: {len(columns)} names for {values.shape[1]} columns")
    if values.dtype.kind in "iub":
        return _pride.roughset_table(columns, values.astype(int).tolist(), False)
    if values.dtype.kind == "f" and _np.all(_np.isfinite(values)) and _np.all(values == _np.floor(values)):
        return _pride.roughset_table(columns, values.astype(int).tolist(), False)
    return _pride.roughset_table(columns, [[_utf8("table", str(v)) for v in row] for row in values], True)


class Campaign:
    """A campaign: problems x algorithms x seeds under one budget, run on threads into an SQLite
    store (resumable: runs already stored are not run again). Build it from Python data::

        pride.Campaign("demo", seeds=5, evals=10_000,
                       problems=[{"id": "sph", "problem": "sphere", "dim": 10},
                                 {"id": "mine", "function": f, "bounds": (-5, 5), "dim": 3}],
                       algorithms=["pso", {"id": "ga", "algo": "ga", "pop": 40}])

    or from a TOML file (``pride bench``'s format) with ``Campaign.load(path)``. Python functions
    are called with the GIL held, one at a time, whatever the number of jobs. The budget: ``evals``,
    or ``evals_per_dim`` (times each problem's dimension, as COCO budgets), and/or ``iters`` (none
    when every algorithm plans on the whole map, as ``astar``: such a campaign refuses one); a
    report target: ``target`` (an absolute value) or ``precision`` (f_opt + precision per problem)."""

    def __init__(self, name, *, seeds, problems, algorithms, evals=None, evals_per_dim=None, iters=None, target=None,
                 precision=None):
        self._c = _pride.campaign_from_data(_str("name", name), _seed_count(seeds), _int("evals", evals),
                                            _int("evals_per_dim", evals_per_dim), _int("iters", iters),
                                            _real("target", target), _real("precision", precision),
                                            _list("problems", problems), _list("algorithms", algorithms))

    @classmethod
    def load(cls, path):
        self = cls.__new__(cls)
        self._c = _pride.campaign_from_file(_path("path", path))
        return self

    name = property(lambda self: self._c.name)
    seeds = property(lambda self: self._c.seeds)
    runs = property(lambda self: self._c.runs)
    problems = property(lambda self: self._c.problems)
    algorithms = property(lambda self: self._c.algorithms)

    def run(self, store, *, jobs=1, shard=None):
        """Runs what ``store`` does not hold yet on ``jobs`` threads; returns the counts
        (stored, already, total). Ctrl-C stops it within a few tens of milliseconds (plus the
        evaluation of a Python function in progress): the runs that finished are stored, the ones
        running are not, and a later run() of the same store resumes. ``shard=(k, n)`` runs only
        part k of n of the runs (``pride bench --shard K/N``; the counts are the part's): the parts'
        stores, made apart and merged (``pride merge``), are the whole campaign's."""
        k, n = _shard(shard)
        return _pride.campaign_run(self._c, _path("store", store), _int("jobs", jobs, False), k, n)


def _shard(value):
    """``shard=(k, n)``: part k of n, 1 <= k <= n (None: the whole campaign, (1, 1))."""
    if value is None:
        return 1, 1
    if not isinstance(value, (tuple, list)) or len(value) != 2:
        raise TypeError(f"shard: expected a pair (k, n), part k of n, got {type(value).__name__}"
                        + (f" of {len(value)}" if isinstance(value, (tuple, list)) else ""))
    k, n = (_int("shard", v, False) for v in value)
    if not 1 <= k <= n:
        raise ValueError(f"shard: must be part k of n with 1 <= k <= n, got ({k}, {n})")
    return k, n


def read_store(path, *, dataframe=None):
    """The runs of a campaign store: a DataFrame when pandas is present (or ``dataframe=True``),
    else a list of dicts (problem, algorithm, seed; ``best``, the run's best value, a number (None
    when no feasible value was found; the report's flag of the best algorithm is ``is_best``);
    ``best_x``, the best point, a numpy array (None for grid, multi-objective and published runs);
    evaluations, ``iterations`` (None in a store without them), wall_ms, optimum, history,
    history_evaluations, encoding; ``path_metrics``: a grid run's path metrics, a dict (length,
    turns, total_turn_deg, angle_over_length, max_curvature, min_clearance, mean_clearance, and
    grid_gap, any_angle_gap with ``path_gaps``), None for other runs; ``target_hits``: {precision:
    the evaluations after which best - f_opt <= precision first held, None where never}, COCO's
    precisions on problems with a known f_opt, {} elsewhere; COCO's trace: ``trace_targets`` and ``trace_evaluations``,
    (n, 2) arrays of rows (evaluations, best so far) at COCO's target and evaluation triggers
    (on a problem with constraints COCO's logged value, max(f, f_opt) + violation, over every
    point);
    ``front``: a multi-objective run's non-dominated set, an (n, M) array, None for other runs;
    ``violation`` and ``first_feasible``: on a problem with constraints, the best point's
    violation, 0 when feasible, and the evaluation that first found a feasible point, None
    otherwise; a run whose best is infeasible has ``best`` None)."""
    store = _pride.read_store(_path("path", path))
    dataframe = _bool("dataframe", dataframe, optional=True)
    pd = _pandas()
    if dataframe or (dataframe is None and pd is not None):
        if pd is None:
            raise ImportError("read_store(dataframe=True) needs pandas")
        return pd.DataFrame(store["runs"])
    return store["runs"]


def import_coco(store, path, *, name, citation):
    """Adds a COCO bbob data set's runs to the campaign store ``store`` (created when absent) as the
    published algorithm ``published:NAME`` (``pride import STORE --coco PATH``): read-only runs that
    reports compare with the campaign's, never run again. ``path`` is the data set's folder (its
    .info, .dat and .tdat files) or a .tgz/.tar.gz/.tar archive of it, as COCO's data archive
    publishes them, extracted here with the standard library into a temporary folder; the store
    then records the archive's name and SHA-256 (of a folder: its files'). ``citation`` says whose
    runs they are. Returns a dict: algorithm, runs, problems_matched (the store's own problems the
    runs were found on), problems_added. Bad input raises ValueError naming the file and line;
    then nothing is written."""
    import hashlib
    import tarfile
    import tempfile

    store = _path("store", store)
    path = _path("path", path)
    name = _str("name", name)
    citation = _str("citation", citation)
    if _os.path.isdir(path) or not _os.path.exists(path):
        return _pride.import_coco(store, path, name, citation, None, None)
    try:
        archive = tarfile.open(path)
    except (tarfile.TarError, OSError) as e:
        raise ValueError(f"{path}: not a folder nor a readable .tgz/.tar archive ({e})") from None
    digest = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            digest.update(block)
    with archive, tempfile.TemporaryDirectory(prefix="pride-import-") as folder:
        members = archive.getmembers()
        for m in members:  # nothing outside the folder, no links: a data set holds files and folders
            target = _os.path.realpath(_os.path.join(folder, m.name))
            if not (m.isfile() or m.isdir()) or not target.startswith(_os.path.realpath(folder) + _os.sep):
                raise ValueError(f"{path}: member {m.name!r} is not a file or folder inside the archive")
        archive.extractall(folder, members=members)
        entries = _os.listdir(folder)
        # An archive of one folder (DIRECT/...): that folder is the data set.
        root = _os.path.join(folder, entries[0]) if len(entries) == 1 else folder
        if not _os.path.isdir(root):
            root = folder
        return _pride.import_coco(store, root, name, citation, _os.path.basename(path), digest.hexdigest())


def import_cec2017(store, path, *, name, citation):
    """Adds one CEC 2017 entrant's published results to the campaign store ``store`` (created when
    absent) as the published algorithm ``published:NAME`` (``pride import STORE --cec2017 PATH``):
    ``path`` is the entrant's folder of NAME_F_D.txt files (14 checkpoints x 51 runs' errors f - f*
    per function and dimension, as the competition collected them). Each run is stored as pride's
    CEC 2017 campaigns store theirs (MaxFES = 10000 D, the final error, the 14 checkpoints), on the
    store's own problem where it has the function and dimension. ``citation`` says whose runs they
    are. Returns a dict: algorithm, runs, problems_matched, problems_added. Bad input raises
    ValueError naming the file and line; then nothing is written."""
    return _pride.import_cec2017(*_published_arguments(store, path, name, citation))


def _published_arguments(store, path, name, citation):
    """The arguments of an import of published files, checked: (store, path, name, citation)."""
    store = _path("store", store)
    path = _path("path", path)
    name = _str("name", name)
    citation = _str("citation", citation)
    if not name or any(c in name for c in "\n\r\t"):
        raise ValueError(f"name: expected the published algorithm's name (one line), got {name!r}")
    if not citation:
        raise ValueError("citation: expected whose runs these are and where they were published, got ''")
    return store, path, name, citation


def import_ioh(store, path, *, name, citation):
    """Adds one algorithm's IOHprofiler files, as ``pride export --ioh`` writes them (its folder of
    .info and .dat files), to the campaign store ``store`` as the published algorithm
    ``published:NAME`` (``pride import STORE --ioh PATH``): read-only runs on the store's own
    problems, which reports compare with the campaign's where the protocol is the same. The store
    must hold the campaign the files were exported from (its problems: a function, dimension or
    instance it has not is refused). ``citation`` says whose runs they are. Returns a dict:
    algorithm, runs, problems_matched, problems_added (0). Bad input raises ValueError naming the
    file and line; then nothing is written."""
    return _pride.import_ioh(*_published_arguments(store, path, name, citation))


def report(path, *, raw=False, dataframe=None, html=None):
    """The report of a campaign store (``pride report``): ``rows`` (per problem and algorithm:
    min, mean, std, median, max, ``is_best`` (True for the problem's algorithm of lowest median,
    which the others' p_holm and a12 are against; the best value is ``min``), p_holm, f_opt,
    precision, ...) as a DataFrame when pandas
    is present, ``friedman`` and the rendered ``markdown`` and ``csv``, as a dict. Where a
    problem's optimum f_opt is known, min to max are precisions f - f_opt (``precision`` True),
    unless ``raw=True`` (``pride report --raw``). ``path`` may be a list of stores of one campaign
    run in parts, read as one (``pride report A B``). ``html=DIR`` also writes the HTML report
    of one store into the folder DIR (``pride report --html DIR``) and gives its index.html as
    ``html``. On problems with constraints, runs are compared by Deb's order, each row's
    ``feasible_runs`` counts the runs whose best is feasible (min to max are over them; None for
    problems without constraints), and ``feasibility`` lists per problem and algorithm ``runs``,
    ``feasible``, ``median_first_feasible`` and ``median_violation``."""
    paths = [_path("path", p) for p in path] if isinstance(path, (list, tuple)) else [_path("path", path)]
    raw = _bool("raw", raw)
    dataframe = _bool("dataframe", dataframe, optional=True)
    if html is not None:
        if not isinstance(html, (str, _os.PathLike)):
            raise TypeError(f"html: expected a folder (str or os.PathLike), got {type(html).__name__}")
        html = _os.fspath(html)
        if not isinstance(html, str):
            raise TypeError(f"html: expected a folder (str or os.PathLike), got {type(html).__name__}")
        if not html:
            raise ValueError("html: expected a folder, got ''")
        _utf8("html", html)
        if len(paths) != 1:
            raise ValueError("html: draws one store; join several into one with pride merge first")
    r = _pride.report(paths, raw)
    if html is not None:
        r["html"] = _pride.report_html(paths[0], html, raw)["index"]
    pd = _pandas()
    if dataframe or (dataframe is None and pd is not None):
        if pd is None:
            raise ImportError("report(dataframe=True) needs pandas")
        r["rows"] = pd.DataFrame(r["rows"])
    return r
