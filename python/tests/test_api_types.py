"""Every argument of the public API, and every key of a campaign's entries, given a value of the
wrong type: a one-line TypeError or ValueError that names the argument (or key), never
pybind11's multi-line "incompatible function arguments", its "Unable to cast" RuntimeError, or a
message such as "'NoneType' object is not iterable" that names nothing.

The table below says what each argument is; the walk checks that it lists every parameter each
public function has, so that a new argument cannot go untested."""
import inspect
import re

import numpy as np
import pytest

import pride

GRID = pride.Grid(np.zeros((4, 4), dtype=int))


def f(x):
    return float(x @ x)


def f2(x):
    return [float(x @ x), float((x - 1) @ (x - 1))]


def length(cells):
    return float(len(cells))


# Wrong values for each kind of argument. `None` is listed only where it is not a valid value.
INT = ["3", 2.5, object(), [1], True]
INT_REQUIRED = INT + [None]
REAL = ["1", object(), [1.0], True]
TEXT = [5, object(), None, b"pso"]
TEXT_OPTIONAL = [5, object(), b"sitp"]  # None is the default
FLAG = ["yes", 2, object(), None]
FLAG_OPTIONAL = ["yes", 2, object()]
SEED = ["1", 1.5, object(), None, True]
CALLABLE = [5, "f", object()]
PATH = [5, object(), None, b"x.sqlite"]
LIST = [None, 5, "ab", object(), {"a": 1}]
CELL = [None, 5, "ab", (1.5, 2), (1,), (True, 1)]
GRID_ARG = [None, np.zeros((3, 3)), "map", 5]
WORLD = [5, "ab", (1.5,), ("a", 1), (True, 1.0)]  # (x, y) in metres; None is "not given"
NUMBERS = [None, "abc", object(), np.array(["a", "b"])]
POINTS = NUMBERS + [[1.0, 2.0]]  # an (n, M) set, not one point
PAIRED = POINTS + [[[1.0, 2.0, 3.0]]]  # and M = 3 against M = 2
PTS = np.array([[0.0, 2.0], [1.0, 1.0], [2.0, 0.0]])
WEIGHTS = [5, "ab", ["x", 1, 1], [None, 1, 1]]
OBJECTIVE = [5, object()]  # None is "the algorithm's default objective"
PROBLEM = [5, None, object()]
BOUNDS = [5, "ab", None, (None, 1), ("a", 1)]
INTEGERS = [5, "ab", object(), [0.5], [True]]  # None is "all real"
TABLE = [None, 5, object()]
OBJECTIVES = [5, None, [1, 2], object()]


def map_file(tmp_path):
    path = tmp_path / "m.map"
    path.write_text("0 0 0 0\n" * 4)
    return str(path)


def campaign(**kw):
    args = dict(seeds=1, evals=10, problems=[{"id": "a", "problem": "sphere", "dim": 2}], algorithms=["pso"])
    args.update(kw)
    return pride.Campaign("c", **args)


def coco_data_set(tmp_path):
    """The smallest COCO bbob data set: one run of f1 in 2-D, two lines."""
    folder = tmp_path / "coco"
    (folder / "data_f1").mkdir(parents=True, exist_ok=True)
    (folder / "bbobexp_f1.info").write_text("suite = 'bbob', funcId = 1, DIM = 2, Precision = 1.000e-08, "
                                            "algId = 'x'\n% x\ndata_f1/bbobexp_f1_DIM2.dat, 1:10|1.0e+00\n")
    (folder / "data_f1" / "bbobexp_f1_DIM2.dat").write_text(
        "% f evaluations | g evaluations | best noise-free fitness - Fopt (7.948e+01) + sum g_i+ | x\n"
        "1 0 +5.0e+00 +8.448e+01 +8.448e+01\n10 0 +1.0e+00 +8.048e+01 +8.048e+01\n")
    return str(folder)


def cec2017_entrant(tmp_path):
    """The smallest CEC 2017 entrant's folder: F1 in 10-D, one run's errors at the 14 checkpoints."""
    folder = tmp_path / "cec2017"
    folder.mkdir(exist_ok=True)
    (folder / "x_1_10.txt").write_text("".join(f"{14 - k}.5\n" for k in range(14)))
    return str(folder)


def ioh_folder(tmp_path):
    """The smallest IOHprofiler folder of campaign()'s problem (its first: funcId 1001): one run."""
    folder = tmp_path / "ioh"
    (folder / "data_f1001_a").mkdir(parents=True, exist_ok=True)
    (folder / "IOHprofiler_f1001_a.info").write_text(
        'suite = "pride", funcId = 1001, funcName = "a", DIM = 2, maximization = "F", algId = "x"\n%\n'
        "data_f1001_a/IOHprofiler_f1001_DIM2.dat, 1:10|0.5\n")
    (folder / "data_f1001_a" / "IOHprofiler_f1001_DIM2.dat").write_text(
        '"function evaluation" "current f(x)" "best-so-far f(x)" "current af(x)+b" "best af(x)+b"\n'
        "10 0.5 0.5 0.5 0.5\n")
    return str(folder)


# name -> (call(**overrides), {parameter: wrong values}); `call` passes valid values for the rest.
def api(tmp_path):
    mfile = map_file(tmp_path)
    store = str(tmp_path / "s.sqlite")
    campaign().run(store)
    ioh_store = str(tmp_path / "k.sqlite")  # a copy of the campaign's store, for pride.import_ioh
    campaign().run(ioh_store)
    opt = lambda: pride.Optimizer("pso", bounds=(-1, 1), dim=2, evals=20)

    return {
        "minimize": (lambda **o: pride.minimize(**{"algo": "pso", "problem": f, "bounds": (-1, 1), "dim": 2,
                                                   "evals": 20, **o}),
                     dict(algo=TEXT, problem=PROBLEM, dim=INT, bounds=BOUNDS, evals=INT, iters=INT, target=REAL,
                          wall_ms=REAL, seed=SEED, instance=INT, callback=CALLABLE, vectorized=FLAG,
                          subject_to=CALLABLE, inequalities=INT, equalities=INT, tolerance=REAL, integers=INTEGERS,
                          categorical=INTEGERS)),
        "Optimizer": (lambda **o: pride.Optimizer(**{"algo": "pso", "bounds": (-1, 1), "dim": 2, "evals": 20, **o}),
                      dict(algo=TEXT, bounds=BOUNDS, dim=INT, evals=INT, iters=INT, target=REAL, wall_ms=REAL,
                           seed=SEED, objectives=INT, inequalities=INT, equalities=INT, tolerance=REAL,
                           integers=INTEGERS, categorical=INTEGERS)),
        "front": (lambda **o: pride.front(**{"algo": "nsga2", "problem": f2, "bounds": (-1, 1), "dim": 2,
                                             "objectives": 2, "evals": 20, **o}),
                  dict(algo=TEXT, problem=PROBLEM, dim=INT, objectives=INT, bounds=BOUNDS, evals=INT, iters=INT,
                       wall_ms=REAL, seed=SEED, vectorized=FLAG, reference=FLAG, integers=INTEGERS,
                       categorical=INTEGERS)),
        "plan_front": (lambda **o: pride.plan_front(**{"grid": GRID, "start": (0, 0), "goal": (3, 3), "iters": 2, **o}),
                       dict(grid=GRID_ARG, start=CELL, goal=CELL, algo=TEXT, objectives=OBJECTIVES, encoding=TEXT,
                            init=TEXT_OPTIONAL, connector=TEXT, waypoints=INT_REQUIRED, corner_cutting=FLAG, clearance_bands=INT_REQUIRED,
                            clearance_width=INT_REQUIRED, evals=INT, iters=INT, wall_ms=REAL, seed=SEED,
                            reference=FLAG)),
        "Optimizer.tell": (lambda **o: (lambda x: x.tell(**{"values": np.zeros(len(x.ask())), **o}))(opt()),
                           dict(values=NUMBERS, g=NUMBERS[1:])),
        "Problem": (lambda **o: pride.Problem(**{"name": "sphere", "dim": 2, **o}),
                    dict(name=TEXT, dim=INT, instance=INT, seed=SEED)),
        "Grid": (lambda **o: pride.Grid(**{"array": np.zeros((2, 2)), **o}), dict(array=[None, "abc", object()])),
        "Grid.load": (lambda **o: pride.Grid.load(**{"path": mfile, "inflate": 0, **o}), dict(path=PATH, inflate=INT_REQUIRED, unknown_free=FLAG)),
        "Grid.inflated": (lambda **o: GRID.inflated(**{"radius": 1, **o}), dict(radius=INT_REQUIRED)),
        "Grid.free": (lambda **o: GRID.free(**{"x": 1, "y": 1, **o}), dict(x=INT_REQUIRED, y=INT_REQUIRED)),
        "plan": (lambda **o: pride.plan(**{"grid": GRID, "start": (0, 0), "goal": (3, 3), "iters": 2, **o}),
                 dict(grid=GRID_ARG, start=CELL, goal=CELL, start_world=WORLD, goal_world=WORLD, algo=TEXT,
                      objective=OBJECTIVE, step_cost=CALLABLE,
                      encoding=TEXT, connector=TEXT, init=TEXT, waypoints=INT_REQUIRED, weights=WEIGHTS,
                      lambda_=REAL, corner_cutting=FLAG, oracle=FLAG, gaps=FLAG, evals=INT, iters=INT, seed=SEED,
                      callback=CALLABLE)),
        "astar": (lambda **o: pride.astar(**{"grid": GRID, "start": (0, 0), "goal": (3, 3), **o}),
                  dict(grid=GRID_ARG, start=CELL, goal=CELL, objective=OBJECTIVE, corner_cutting=FLAG)),
        "exact": (lambda **o: pride.exact(**{"grid": GRID, "start": (0, 0), "goal": (3, 3), **o}),
                  dict(grid=GRID_ARG, start=CELL, goal=CELL, objective=OBJECTIVE, corner_cutting=FLAG)),
        "pareto": (lambda **o: pride.pareto(**{"grid": GRID, "start": (0, 0), "goal": (3, 3), **o}),
                   dict(grid=GRID_ARG, start=CELL, goal=CELL, objectives=OBJECTIVES, corner_cutting=FLAG)),
        "roughset": (lambda **o: pride.roughset(**{"table": [[1, 0], [0, 1]], **o}),
                     dict(table=TABLE, columns=[5, "ab", object()])),
        "Campaign": (lambda **o: campaign(**o) if "name" not in o else pride.Campaign(
                         o.pop("name"), seeds=1, evals=10, problems=[{"id": "a", "problem": "sphere", "dim": 2}],
                         algorithms=["pso"], **o),
                     dict(name=TEXT, seeds=INT_REQUIRED, problems=LIST, algorithms=LIST, evals=INT,
                          evals_per_dim=INT, iters=INT, target=REAL, precision=REAL)),
        "Campaign.load": (lambda **o: pride.Campaign.load(**o), dict(path=PATH)),
        "Campaign.run": (lambda **o: campaign().run(**{"store": store, **o}), dict(store=PATH, jobs=INT_REQUIRED, shard=[5, "ab", (1,), (1.5, 2), ("a", 1)])),
        "read_store": (lambda **o: pride.read_store(**{"path": store, **o}), dict(path=PATH, dataframe=FLAG_OPTIONAL)),
        "report": (lambda **o: pride.report(**{"path": store, "dataframe": False, **o}),
                   dict(path=PATH + [[5]], raw=FLAG, dataframe=FLAG_OPTIONAL, html=[5, object(), b"dir"])),
        "import_coco": (lambda **o: pride.import_coco(**{"store": str(tmp_path / "i.sqlite"),
                                                         "path": coco_data_set(tmp_path), "name": "x",
                                                         "citation": "c", **o}),
                        dict(store=PATH, path=PATH, name=TEXT, citation=TEXT)),
        "import_cec2017": (lambda **o: pride.import_cec2017(**{"store": str(tmp_path / "j.sqlite"),
                                                               "path": cec2017_entrant(tmp_path), "name": "x",
                                                               "citation": "c", **o}),
                           dict(store=PATH, path=PATH, name=TEXT, citation=TEXT)),
        "import_ioh": (lambda **o: pride.import_ioh(**{"store": ioh_store, "path": ioh_folder(tmp_path), "name": "x",
                                                       "citation": "c", **o}),
                       dict(store=PATH, path=PATH, name=TEXT, citation=TEXT)),
        "Result": (lambda **o: pride.Result(**o), dict(fields=[None, 5, "ab", [1, 2]])),
        "register_algorithm": (lambda **o: pride.register_algorithm(**{"name": "api-types", "function": lambda p, s: None,
                                                                       **o}),
                               dict(name=TEXT, function=CALLABLE + [None], summary=TEXT_OPTIONAL)),
        "hypervolume": (lambda **o: pride.hypervolume(**{"points": PTS, "ref": [3.0, 3.0], **o}),
                        dict(points=PAIRED, ref=NUMBERS + [[[3.0, 3.0]], [3.0]])),
        "hypervolume_contributions": (lambda **o: pride.hypervolume_contributions(**{"points": PTS, "ref": [3.0, 3.0], **o}),
                                      dict(points=PAIRED, ref=NUMBERS + [[3.0]])),
        "igd": (lambda **o: pride.igd(**{"points": PTS, "front": PTS, **o}), dict(points=PAIRED, front=PAIRED)),
        "igd_plus": (lambda **o: pride.igd_plus(**{"points": PTS, "front": PTS, **o}), dict(points=PAIRED, front=PAIRED)),
        "epsilon_additive": (lambda **o: pride.epsilon_additive(**{"points": PTS, "front": PTS, **o}),
                             dict(points=PAIRED, front=PAIRED)),
        "nondominated_sort": (lambda **o: pride.nondominated_sort(**{"points": PTS, **o}), dict(points=POINTS)),
        "crowding_distance": (lambda **o: pride.crowding_distance(**{"points": PTS, **o}), dict(points=POINTS)),
        "attainment_surface": (lambda **o: pride.attainment_surface(**{"runs": [PTS[:, :2]], "k": 1, **o}),
                               dict(runs=[None, 5, "ab", object(), [None], [[[1.0, 2.0, 3.0]]]], k=INT_REQUIRED)),
        "cec2017_score": (lambda **o: pride.cec2017_score(**{"results": {"a": np.ones((3, 1))}, "dims": [10], **o}),
                          dict(results=[None, 5, "ab", [1], {"a": 5}, {5: np.ones((3, 1))}, {"a": "x"}],
                               dims=[None, 5, "ab", [1.5], [None], [True], [20], []],
                               exclude=[None, 5, "ab", [1.5], [None]])),
        "cec2020rw_score": (lambda **o: pride.cec2020rw_score(**{"results": {"a": (np.ones((1, 3)), np.zeros((1, 3)))},
                                                                 "dims": [5], **o}),
                            dict(results=[None, 5, "ab", [1], {"a": 5}, {5: (1, 2)}, {"a": ("x", [0.0])}],
                                 dims=[None, 5, "ab", [1.5], [None], [True], [0], []],
                                 order=[None, 5, "sorted", b"given"])),
    }


def parameters(fn):
    """The parameters a public function takes by name (not **params), from its signature, or for
    a pybind11 method from its docstring's first line."""
    try:
        sig = inspect.signature(fn)
        return {n for n, p in sig.parameters.items()
                if p.kind not in (p.VAR_KEYWORD, p.VAR_POSITIONAL) and n not in ("self", "cls")}
    except (TypeError, ValueError):
        head = fn.__doc__.splitlines()[0]
        return {a.split(":")[0].strip() for a in head[head.index("(") + 1:head.rindex(")")].split(",")
                if a.strip() and not a.strip().startswith("self")}


def public_functions():
    """Every public function and method of pride, by the name the table uses."""
    out = {}
    for name in pride.__all__:
        obj = getattr(pride, name)
        if inspect.isclass(obj):
            out[name] = obj.__init__ if obj is not pride.Grid else None
            for m, member in vars(obj).items():
                if not m.startswith("_") and callable(member) and not isinstance(member, property):
                    out[f"{name}.{m}"] = getattr(obj, m)
            if obj is pride.Grid:
                for m in ("load", "inflated", "free", "to_array"):
                    out[f"Grid.{m}"] = getattr(obj, m)
        else:
            out[name] = obj
    return out


def assert_named_error(call, name, value):
    try:
        call()
    except (TypeError, ValueError) as e:
        message = str(e)
        assert "\n" not in message, f"{name}={value!r}: a message of several lines: {message!r}"
        assert "incompatible function arguments" not in message and "Unable to cast" not in message, message
        assert re.search(rf"(^|\W){re.escape(name)}(\W|$)", message), f"{name}={value!r}: {message!r} names nothing"
    except Exception as e:  # noqa: BLE001 (RuntimeError "Unable to cast", or anything else)
        pytest.fail(f"{name}={value!r}: {type(e).__name__}: {e}")
    else:
        pytest.fail(f"{name}={value!r}: accepted")


def test_the_table_covers_every_public_function_and_parameter(tmp_path):
    table = api(tmp_path)
    # Functions without parameters (or properties) need no row.
    no_parameters = {"algorithms", "problems", "grid_names", "Result.as_dict", "Optimizer.ask", "Optimizer.close",
                     "Grid.to_array", "BudgetExhausted", "AlgorithmError", "__version__"}
    for name, fn in public_functions().items():
        if name in no_parameters or fn is None and name == "Grid":
            continue
        assert name in table, f"{name} has no row in the table of argument types"
        assert parameters(fn) == set(table[name][1]), name
    assert parameters(pride.Grid.load) == {"path", "inflate", "unknown_free"}
    assert parameters(pride.Grid.free) == {"x", "y"}


def test_every_argument_of_a_wrong_type_is_named(tmp_path):
    table = api(tmp_path)
    for fn_name, (call, kinds) in table.items():
        if fn_name not in ("Campaign.load", "Result"):
            call()  # the valid call works
        for name, wrong in kinds.items():
            for value in wrong:
                assert_named_error(lambda: call(**{name: value}), name, value)


def test_algorithm_parameters_of_a_wrong_type_are_named():
    for value in ("many", None, [40], object()):
        assert_named_error(lambda: pride.minimize("pso", "sphere", dim=2, evals=20, pop=value), "pop", value)
        assert_named_error(lambda: pride.Optimizer("pso", bounds=(-1, 1), dim=2, evals=20, pop=value), "pop", value)
        assert_named_error(lambda: pride.plan(GRID, (0, 0), (3, 3), iters=2, pop=value), "pop", value)


# Campaign entries: a valid entry of each kind, and wrong values for each of its keys.
PROBLEM_KEYS = [
    ({"id": "a", "problem": "sphere", "dim": 2},
     dict(id=[5, None, ""], problem=[5, None], dim=["2", 2.5, None], instance=["1", 1.5])),
    ({"id": "f", "function": f, "bounds": (-1, 1), "dim": 2},
     dict(function=[5, "f"], bounds=[5, "ab", None, ("a", 1)], vectorized=["yes", 1], f_opt=["0", True],
          dim=["2", 2.5])),
    ({"id": "g", "grid": GRID, "start": (0, 0), "goal": (3, 3)},
     dict(grid=[5, None, np.zeros((2, 2))], start=[5, "ab", (1.5, 2), None], goal=[5, (1,)], objective=[5, object()],
          encoding=[5], connector=[5], init=[5], waypoints=["3", 2.5], weights=[5, "ab", ["x", 1, 1]],
          lambda_=["1"], corner_cutting=["yes", 1])),
    ({"id": "u", "grid": GRID, "start": (0, 0), "goal": (3, 3), "objective": length}, dict(step_cost=[5, "c"])),
]


def test_every_key_of_a_campaign_entry_of_a_wrong_type_is_named(tmp_path):
    mfile = map_file(tmp_path)
    for valid, keys in PROBLEM_KEYS + [({"id": "m", "grid": mfile, "start": (0, 0), "goal": (3, 3)},
                                        dict(inflate=["1", 1.5], grid=[b"m.map"], unknown_free=["yes", 1], path_gaps=["yes", 1]))]:
        campaign(problems=[valid])  # the valid entry is taken
        for key, wrong in keys.items():
            name = "lambda" if key == "lambda_" else key
            for value in wrong:
                assert_named_error(lambda: campaign(problems=[{**valid, name: value}]), name, value)
    assert_named_error(lambda: campaign(problems=[{"id": "a", "problem": "sphere", "dim": 2, 5: 1}]), "problems[0]", 5)
    assert_named_error(lambda: campaign(problems=[5]), "problems[0]", 5)
    for value in (5, None, ["pso"]):
        assert_named_error(lambda: campaign(algorithms=[value]), "algorithms[0]", value)
    for key, wrong in dict(id=[5, ""], algo=[5, None], params=[5, "x", {1: 2}], pop=["x", None]).items():
        for value in wrong:
            assert_named_error(lambda: campaign(algorithms=[{"algo": "pso", key: value}]),
                               "algorithms[0]" if key in ("params", "algo") else key, value)


def test_nothing_where_a_list_is_expected():
    for name in ("problems", "algorithms"):
        with pytest.raises(TypeError, match=f"^{name}: expected a list, got NoneType$"):
            campaign(**{name: None})
    with pytest.raises(TypeError, match="^columns: expected a list, got int$"):
        pride.roughset([[1, 0], [0, 1]], columns=5)
    with pytest.raises(TypeError, match="^weights: expected a list, got NoneType$|^weights: expected numbers"):
        pride.plan(GRID, (0, 0), (3, 3), iters=2, objective="weighted", weights=[None, 1, 1])


# A str that has no UTF-8 bytes: a lone surrogate, what os.listdir and sys.argv give for a name
# whose bytes are not UTF-8 (b"\xff" decoded with surrogateescape).
SURROGATE = "a\udcffb"


def takes_str(wrong):
    """Whether the table's wrong values are those of an argument that takes a str (a name, a
    path, an objective's name, a problem's name)."""
    return any(isinstance(v, bytes) for v in wrong) or any(wrong is k for k in (OBJECTIVE, OBJECTIVES, PROBLEM, TABLE))


def test_every_str_argument_without_utf8_is_named(tmp_path):
    table = api(tmp_path)
    tried = set()
    for fn_name, (call, kinds) in table.items():
        for name, wrong in kinds.items():
            if takes_str(wrong):
                tried.add(f"{fn_name}({name})")
                assert_named_error(lambda: call(**{name: SURROGATE}), name, SURROGATE)
                if name == "path" and fn_name == "report":
                    assert_named_error(lambda: call(path=[SURROGATE]), name, SURROGATE)
    # Every function the table lists with a str argument was tried (a sample of them named here).
    for expected in ("minimize(algo)", "minimize(problem)", "Grid.load(path)", "read_store(path)",
                     "Campaign.load(path)", "Campaign.run(store)", "Campaign(name)", "plan(objective)",
                     "report(html)", "roughset(table)", "plan_front(objectives)", "pareto(objectives)"):
        assert expected in tried, expected
    # Keyword parameters: their names and a choice's value.
    assert_named_error(lambda: pride.minimize("pso", "sphere", dim=2, evals=20, **{SURROGATE: 1}), "parameter names",
                       SURROGATE)
    assert_named_error(lambda: pride.front("nsga2", "zdt1", evals=20, reference=False, tournament=SURROGATE),
                       "parameter tournament", SURROGATE)
    assert_named_error(lambda: pride.roughset([[1, 0], [0, 1]], columns=[SURROGATE, "d"]), "columns", SURROGATE)
    assert_named_error(lambda: pride.roughset([["x", SURROGATE], ["y", "z"]]), "table", SURROGATE)
    # Campaign entries: ids, names, maps, objectives, algorithms.
    mfile = map_file(tmp_path)
    for entry, key in (({"id": SURROGATE, "problem": "sphere", "dim": 2}, "id"),
                       ({"id": "a", "problem": SURROGATE, "dim": 2}, "problem"),
                       ({"id": "g", "grid": SURROGATE, "start": (0, 0), "goal": (3, 3)}, "grid"),
                       ({"id": "g", "grid": mfile, "start": (0, 0), "goal": (3, 3), "objective": SURROGATE},
                        "objective"),
                       ({"id": "g", "grid": GRID, "start": (0, 0), "goal": (3, 3), "objectives": SURROGATE},
                        "objectives"),
                       ({"id": "g", "grid": GRID, "start": (0, 0), "goal": (3, 3), "encoding": SURROGATE},
                        "encoding"),
                       ({"id": "a", "problem": "sphere", "dim": 2, SURROGATE: 1}, "problems[0]")):
        assert_named_error(lambda: campaign(problems=[entry]), key, SURROGATE)
    assert_named_error(lambda: campaign(algorithms=[SURROGATE]), "algorithms[0]", SURROGATE)
    for entry, key in (({"algo": SURROGATE}, "algo"), ({"algo": "pso", "id": SURROGATE}, "id"),
                       ({"algo": "pso", SURROGATE: 1}, "algorithms[0]")):
        assert_named_error(lambda: campaign(algorithms=[entry]), key, SURROGATE)
