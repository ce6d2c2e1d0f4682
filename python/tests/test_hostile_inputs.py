"""Inputs made to break the module from outside (docs/reliability.md): each is refused with a
one-line ValueError or TypeError naming the argument, with the command line's range and words."""
import os
import time

import numpy as np
import pytest

import pride
from conftest import cli


def one_line(excinfo):
    message = str(excinfo.value)
    assert "\n" not in message, message
    return message


def test_front_refuses_zero_variables_and_objectives_as_the_command_line():
    # Before: dim=0 ran the paper's 30 variables, objectives=0 ran M = 3.
    with pytest.raises(ValueError) as e:
        pride.front("nsga2", "zdt1", dim=0, evals=100)
    assert one_line(e) == "dim: must be an integer in [1, 1000000000000000], got 0"
    assert "--dim: must be an integer in [1, 1000000000000000], got 0" in cli(
        "front", "--algo", "nsga2", "--problem", "zdt1", "--dim", "0", check=False).stderr
    with pytest.raises(ValueError) as e:
        pride.front("nsga2", "dtlz2", objectives=0, evals=100)
    assert one_line(e) == "objectives: expected the number of objectives M of dtlz2, got '0'"
    assert "objectives: expected the number of objectives M of dtlz2, got '0'" in cli(
        "front", "--algo", "nsga2", "--problem", "dtlz2", "--objectives", "0", check=False).stderr
    with pytest.raises(ValueError, match="^dim: "):
        pride.front("nsga2", "zdt1", dim=-3, evals=100)


def test_instances_beyond_cocos_range_are_refused():
    # Before: instance 2^31 was instance 1 under another number.
    with pytest.raises(ValueError) as e:
        pride.minimize("pso", "bbob-f1", dim=2, evals=50, instance=2**31)
    assert "COCO's instances are 1 to 2147483646" in one_line(e)
    with pytest.raises(ValueError, match="COCO's instances are 1 to 2147483646"):
        pride.Problem("bbob-f1", 2, instance=2147483647)
    assert pride.Problem("bbob-f1", 2, instance=2147483646)(np.zeros(2)) != pride.Problem("bbob-f1", 2, instance=1)(
        np.zeros(2))
    with pytest.raises(ValueError, match="COCO's instances are 1 to 2147483646"):
        pride.Campaign("c", seeds=1, evals=10, problems=[{"id": "f", "problem": "bbob-f3", "dim": 2,
                                                           "instance": 2147483650}], algorithms=["pso"])


def test_seeds_have_one_limit(tmp_path):
    with pytest.raises(ValueError) as e:
        pride.Campaign("c", seeds=1_000_001, evals=10, problems=[{"id": "s", "problem": "sphere", "dim": 2}],
                       algorithms=["pso"])
    assert one_line(e) == "seeds: must be in [1, 1000000], got 1000001"
    # A count, not a seed: past 64 bits too, the campaign's words (before: "out of range (64-bit integers)").
    with pytest.raises(ValueError) as e:
        pride.Campaign("c", seeds=2**64 - 1, evals=10, problems=[{"id": "s", "problem": "sphere", "dim": 2}],
                       algorithms=["pso"])
    assert one_line(e) == "seeds: must be in [1, 1000000], got 18446744073709551615"
    toml = tmp_path / "c.toml"
    toml.write_text('name = "c"\nseeds = 1000001\n[budget]\nevaluations = 10\n[[problem]]\nid = "s"\n'
                    'type = "sphere"\ndim = 2\n[[algorithm]]\nid = "p"\ntype = "pso"\n')
    with pytest.raises(ValueError, match=r":2: 'seeds' must be in \[1, 1000000\], got 1000001"):
        pride.Campaign.load(toml)
    p = cli("bench", toml, "--out", tmp_path / "c.sqlite", check=False)
    assert p.returncode == 2 and "'seeds' must be in [1, 1000000], got 1000001" in p.stderr
    assert not (tmp_path / "c.sqlite").exists()


def test_a_population_out_of_range_gets_its_range():
    # Before: "pso: pop must be an integer, got 9.223372036854776e+18".
    with pytest.raises(ValueError) as e:
        pride.minimize("pso", "sphere", dim=2, evals=50, pop=2**63)
    assert one_line(e) == ("pso: pop must be an integer in [2, 1000000000000] (population size), "
                           "got 9223372036854775808")
    p = cli("run", "--problem", "sphere", "--dim", "2", "--algo", "pso", "--pop", "9223372036854775807",
            check=False)
    assert p.returncode == 2
    assert "pso: pop must be an integer in [2, 1000000000000] (population size), got" in p.stderr


def test_whole_map_planners_refuse_settings_they_do_not_use():
    grid = pride.Grid(np.zeros((10, 10), dtype=int))
    for kw, name in ((dict(encoding="free"), "encoding"), (dict(init="walk"), "init"),
                     (dict(connector="penalty"), "connector"), (dict(evals=1), "evals"), (dict(iters=3), "iters"),
                     (dict(waypoints=5), "waypoints")):
        for algo in ("astar", "theta-star", "any-angle-exact", "jps"):
            with pytest.raises(ValueError) as e:
                pride.plan(grid, (0, 0), (9, 9), algo=algo, **kw)
            assert one_line(e).startswith(f"{name}: {algo} plans on the whole map"), (algo, kw)
    assert len(pride.plan(grid, (0, 0), (9, 9), algo="astar").path) == 10


def test_a_campaign_of_planners_refuses_settings_none_of_them_uses(tmp_path):
    # Before: taken and ignored (and a budget was even required).
    grid = pride.Grid(np.zeros((10, 10), dtype=int))
    problem = {"id": "g", "grid": grid, "start": (0, 0), "goal": (9, 9), "objective": "length"}
    planners = ["astar", "theta-star"]
    whole = " (every algorithm of this campaign plans on the whole map)"
    for kw, words in ((dict(evals=10), "evals: astar plans on the whole map and evaluates no objective"),
                      (dict(iters=3), "iters: astar plans on the whole map in one search")):
        with pytest.raises(ValueError) as e:
            pride.Campaign("c", seeds=1, problems=[problem], algorithms=planners, **kw)
        assert one_line(e).startswith(words) and one_line(e).endswith(whole), kw
    for key, value in (("encoding", "free"), ("init", "walk"), ("connector", "penalty"), ("waypoints", 5)):
        with pytest.raises(ValueError) as e:
            pride.Campaign("c", seeds=1, problems=[{**problem, key: value}], algorithms=planners)
        assert one_line(e).startswith(f"problem 'g': {key}: astar plans on the whole map"), key
    pride.Campaign("c", seeds=1, problems=[problem], algorithms=planners).run(tmp_path / "c.sqlite")
    assert len(pride.read_store(tmp_path / "c.sqlite", dataframe=False)) == 2
    # Beside an algorithm that plans through an encoding, they are that algorithm's.
    pride.Campaign("c", seeds=1, evals=20, problems=[{**problem, "encoding": "free"}],
                   algorithms=planners + [{"id": "p", "algo": "pso", "pop": 4}])


def test_start_equal_to_goal_is_the_one_cell_path_for_every_planner():
    grid = pride.Grid(np.zeros((10, 10), dtype=int))
    for algo in ("astar", "jps", "theta-star", "lazy-theta-star", "any-angle-exact"):
        r = pride.plan(grid, (4, 4), (4, 4), algo=algo, objective="length")
        assert r.feasible, algo
        assert r.polyline.tolist() == [[4.0, 4.0]], algo
        assert r.path.tolist() == [[4, 4]], algo
        assert r.path_metrics["length"] == 0.0, algo


def test_world_coordinates_of_a_fine_frame_stay_distinct(tmp_path):
    # Before: a 1e-10 m resolution printed every cell's coordinates as 0.
    pgm = tmp_path / "m.pgm"
    pgm.write_bytes(b"P5\n4 4\n255\n" + bytes([254] * 16))
    yaml = tmp_path / "m.yaml"
    yaml.write_text("image: m.pgm\nresolution: 1e-10\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\n"
                    "free_thresh: 0.196\n")
    grid = pride.Grid.load(yaml)
    r = pride.plan(grid, (0, 0), (3, 0), algo="astar", objective="length")
    world = r.path_world
    assert len({tuple(p) for p in world.tolist()}) == len(world) == 4
    assert world[1][0] == pytest.approx(1.5e-10, rel=1e-12)


def test_nsga3_refuses_more_objectives_than_it_sets_up_in_time():
    # Before: 3000 objectives took 22 s before the first wall-clock check.
    t = time.monotonic()
    with pytest.raises(ValueError) as e:
        pride.front("nsga3", "dtlz2", objectives=3000, wall_ms=500, reference=False)
    assert time.monotonic() - t < 5
    assert one_line(e).startswith("objectives: ")
    with pytest.raises(ValueError) as e:
        pride.front("smsemoa", "dtlz2", objectives=1000, wall_ms=500, reference=False)
    assert one_line(e).startswith("objectives: ") and "pop must be at most 0" not in str(e.value)
    # NSGA-II's sorting and MOEA/D's neighbourhoods, before the first time check (before: 17 s and
    # 9.8 s under wall_ms=1000, or std::bad_alloc).
    with pytest.raises(ValueError) as e:
        pride.front("nsga2", "dtlz2", pop=40000, evals=80000, wall_ms=1000, reference=False)
    assert one_line(e).startswith("pop: NSGA-II sorts its 2N parents and children every generation")
    with pytest.raises(ValueError) as e:
        pride.front("moead", "dtlz2", pop=20000, evals=80000, wall_ms=1000, reference=False)
    assert one_line(e).startswith("pop: MOEA/D finds the neighbours of each of its 19900 subproblems")
    assert time.monotonic() - t < 10


def test_a_fifo_beside_a_store_is_refused(tmp_path):
    store = tmp_path / "s.sqlite"
    pride.Campaign("c", seeds=1, evals=20, problems=[{"id": "s", "problem": "sphere", "dim": 2}],
                   algorithms=["pso"]).run(store)
    os.mkfifo(str(store) + "-journal")
    with pytest.raises(ValueError) as e:
        pride.read_store(store, dataframe=False)
    assert one_line(e).startswith(f"{store}-journal: not a regular file (a FIFO)")


def test_ctrl_c_reaches_inside_the_exact_any_angle_search(tmp_path):
    # A search of about 4 s (98,600 convex corners) stopped 0.5 s in: before, Ctrl-C waited for its end.
    import random
    import subprocess
    import sys
    import textwrap
    random.seed(2)
    n = 760
    rows = ["".join("@" if random.random() < 0.05 else "." for _ in range(n)) for _ in range(n)]
    rows[0] = "." + rows[0][1:]
    rows[-1] = rows[-1][:-1] + "."
    m = tmp_path / "m.map"
    m.write_text(f"type octile\nheight {n}\nwidth {n}\nmap\n" + "\n".join(rows) + "\n")
    script = textwrap.dedent(f"""
        import os, signal, threading, time
        import pride
        g = pride.Grid.load({str(m)!r})
        t = time.monotonic()
        threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
        try:
            pride.plan(g, (0, 0), ({n - 1}, {n - 1}), algo="any-angle-exact", objective="length")
            print("finished", time.monotonic() - t)
        except KeyboardInterrupt:
            print("interrupted", time.monotonic() - t)
        """)
    p = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120)
    word, seconds = p.stdout.split()
    assert word == "interrupted", p.stdout + p.stderr
    assert float(seconds) < 2.0
