#!/usr/bin/env python3
"""Writes the fixed set of `pride run` and `pride path` commands whose JSON results (all fields
but wall_ms) the golden-results test holds the code to, bit for bit (tests/data/golden/).
Usage: scripts/golden_commands.py > tests/data/golden/commands.txt
Maps are named relative to the top of the checkout, Moving AI's as $PRIDE_DATA/movingai/...
(the public data of others, not in the repository: the golden test and golden_update.py read them
there, and skip those commands without PRIDE_DATA)."""
runs = []
for algo in ["pso", "pso-constriction", "ga", "ga-plus", "lso", "ilso", "nlopt:LN_SBPLX", "nlopt:GN_CRS2_LM",
             "nlopt:LN_NELDERMEAD"]:
    for problem, dim in [("sphere", 5), ("shifted-rastrigin", 10), ("rosenbrock", 4), ("shifted-ackley", 3),
                         ("schwefel", 6), ("griewank", 2), ("shifted-griewank", 7), ("rastrigin", 3),
                         ("ackley", 8), ("shifted-sphere", 4), ("shifted-rosenbrock", 5)]:
        for seed in [1, 7]:
            runs.append(f"run --problem {problem} --dim {dim} --algo {algo} --evals 2000 --seed {seed} --json")
# parameters, iteration limits and targets
runs += [
    "run --problem sphere --dim 10 --algo pso --iters 30 --pop 17 --param w_start=0.8 --param c1=1.5 --seed 3 --json",
    "run --problem rastrigin --dim 6 --algo pso-constriction --param chi=0.6 --param c=2.2 --param vmax=0.5 --evals 1500 --seed 4 --json",
    "run --problem rosenbrock --dim 5 --algo ga --param pc=0.8 --param eta_c=5 --param pm=0.3 --param elitism=3 --param tournament=4 --evals 3001 --seed 5 --json",
    "run --problem ackley --dim 5 --algo ga-plus --pop 21 --param eta_m=7 --evals 2500 --seed 6 --json",
    "run --problem sphere --dim 7 --algo ga --seed 7 --evals 200 --param pc=0.8 --json",
    "run --problem shifted-rastrigin --dim 5 --algo lso --param step=0.1 --param beta=0.3 --param gamma_per_coordinate=1 --evals 2000 --seed 8 --json",
    "run --problem griewank --dim 4 --algo ilso --param w_max=0.9 --param w_min=0.2 --param cub_first=0.25 --evals 1999 --seed 9 --json",
    "run --problem sphere --dim 3 --algo lso --param walk_init=1 --iters 12 --seed 2 --json",
    "run --problem sphere --dim 3 --algo ilso --param walk_init=0 --iters 12 --seed 2 --json",
    "run --problem sphere --dim 4 --algo pso --evals 100000 --target 1e-3 --seed 10 --json",
    "run --problem rosenbrock --dim 3 --algo nlopt:LN_SBPLX --pop 10 --param restart=0 --evals 5000 --seed 11 --json",
    "run --problem rosenbrock --dim 3 --algo nlopt:LN_COBYLA --iters 20 --seed 12 --json",
    "run --problem sphere --dim 2 --algo pso --iters 0 --seed 1 --json",
]
maps = [
    ("examples/maps/wan2022-10x10.map", "0,0", "9,9"),
    ("examples/maps/wan2022-13x13.map", "0,0", "12,12"),
    ("examples/maps/zhang2025-20x20.map", "0,19", "19,0"),
    ("examples/maps/zhang2025-40x40.map", "1,38", "38,1"),
    ("examples/maps/cai2021-50x50.map", "0,49", "49,0"),
]
paths = []
box_algos = ["pso", "pso-constriction", "ga", "ga-plus", "lso", "ilso", "nlopt:LN_SBPLX"]
objectives = ["cells", "length", "weighted", "iqga", "hswoa"]
i = 0
for m, s, g in maps:
    base = f"path --map {m} --start {s} --goal {g}"
    oracle_ok = lambda o: o != "iqga"
    paths.append(f"{base} --algo astar --json")
    for o in objectives:
        if oracle_ok(o):
            paths.append(f"{base} --algo exact --objective {o} --json")
    for enc in ["line", "free"]:
        for conn in ["repair", "penalty"]:
            for a in box_algos:
                o = objectives[i % len(objectives)]
                seed = 1 + i % 4
                i += 1
                oracle = " --oracle" if oracle_ok(o) else ""
                paths.append(f"{base} --algo {a} --encoding {enc} --connector {conn} --objective {o} --seed {seed} --iters 15{oracle} --json")
    for a in ["ga", "ga-plus"]:
        for o in objectives:
            seed = 1 + i % 3
            i += 1
            oracle = " --oracle" if oracle_ok(o) else ""
            paths.append(f"{base} --algo {a} --encoding chain --objective {o} --seed {seed} --iters 10{oracle} --json")
m, s, g = maps[1]
base = f"path --map {m} --start {s} --goal {g}"
paths += [
    f"{base} --algo pso --init walk --seed 3 --json",
    f"{base} --algo pso --init rules --seed 3 --json",
    f"{base} --algo ilso --init uniform --seed 3 --json",
    f"{base} --algo ilso --seed 4 --oracle --json",
    f"{base} --algo lso --init rules --encoding free --waypoints 5 --seed 5 --json",
    f"{base} --algo ga --init walk --encoding free --connector penalty --seed 6 --json",
    f"{base} --algo ga --objective weighted --weights 1,2,0.5 --oracle --seed 7 --json",
    f"{base} --algo pso --objective hswoa --lambda 3 --oracle --seed 8 --json",
    f"{base} --algo ga-plus --encoding chain --pop 30 --param pc=0.7 --param pm=0.4 --param tournament=3 --evals 500 --seed 9 --json",
    f"{base} --algo ga --encoding chain --param elitism=2 --evals 333 --seed 10 --json",
    f"{base} --algo pso --corner-cutting --oracle --seed 11 --json",
    f"{base} --algo astar --corner-cutting --json",
    f"{base} --algo exact --objective length --corner-cutting --json",
    "path --map $PRIDE_DATA/movingai/den312d.map --start 35,29 --goal 38,55 --algo ga --inflate 1 --oracle --seed 12 --json",
    "path --map $PRIDE_DATA/movingai/den312d.map --start 38,55 --goal 23,65 --algo pso --encoding free --inflate 1 --oracle --seed 3 --json",
    f"{base} --algo pso --evals 777 --pop 13 --seed 13 --json",
    f"{base} --algo pso-constriction --param walk_init=1 --seed 14 --json",
]
m, s, g = maps[3]
base = f"path --map {m} --start {s} --goal {g}"
paths += [
    f"{base} --algo ilso --encoding free --waypoints 4 --objective length --oracle --seed 2 --json",
    f"{base} --algo ga --encoding chain --objective iqga --pop 40 --iters 20 --seed 3 --json",
    "path --map $PRIDE_DATA/movingai/random-32-32-20.map --start 1,1 --goal 30,30 --algo pso --encoding free --objective length --oracle --seed 1 --json",
    "path --map $PRIDE_DATA/movingai/maze-32-32-4.map --start 1,1 --goal 29,29 --algo ga --encoding chain --objective length --oracle --seed 2 --json",
]
# Added with the suites and the new algorithms; appended, so that the
# lines above keep their numbers.
later = []
for algo in ["pso", "ga-plus", "woa", "woa-hs", "woa-balance", "hswoa", "hs", "iaga", "icga", "ga-q"]:
    for problem, dim, instance in [("yao-f1", 5, 0), ("yao-f5", 4, 2), ("yao-f7", 3, 0), ("yao-f8", 4, 1),
                                   ("yao-f12", 3, 0), ("yao-f14", 2, 0), ("yao-f20", 6, 0), ("levy", 4, 3),
                                   ("styblinski-tang", 3, 1), ("bbob-f3", 5, 2), ("bbob-f16", 3, 1),
                                   ("bbob-f24", 4, 7)]:
        later.append(f"run --problem {problem} --dim {dim} --instance {instance} --algo {algo} --evals 1500 --seed 3 --json")
later.append("run --problem rastrigin --dim 6 --instance 4 --algo nlopt:LN_SBPLX --evals 1000 --seed 2 --json")
for m, s, g in maps:
    base = f"path --map {m} --start {s} --goal {g}"
    later.append(f"{base} --algo exact --objective iqga --json")
    later.append(f"{base} --algo iqga --encoding chain --objective iqga --iters 10 --oracle --seed 2 --json")
    for a in ["iaga", "icga"]:
        later.append(f"{base} --algo {a} --encoding chain --objective length --iters 10 --oracle --seed 3 --json")
    later.append(f"{base} --algo ga --encoding chain --init sitp --objective iqga --iters 10 --oracle --seed 4 --json")
    later.append(f"{base} --algo pso --init sitp --objective cells --iters 10 --oracle --seed 5 --json")
# Added later: WOA and HS-WOA on chains and Cai and Du's (2021) maps, IQGA's
# ablation flags, IAGA's pm floor off, ga-sga, threads and the largest seed; appended.
f3 = ("examples/maps/cai2021-50x50.map", "0,49", "49,0")
for a in ["woa", "woa-hs", "woa-balance", "hswoa"]:
    later.append(f"path --map {f3[0]} --start {f3[1]} --goal {f3[2]} --encoding chain --objective hswoa --algo {a} --iters 10 --seed 1 --json")
for m, s, g in [("examples/maps/cai2021-env1-30x30.map", "0,29", "29,0"), ("examples/maps/cai2021-env2-30x30.map", "0,29", "29,0"),
                ("examples/maps/cai2021-env3-60x60.map", "0,59", "59,0")]:
    base = f"path --map {m} --start {s} --goal {g}"
    later.append(f"{base} --encoding chain --objective hswoa --algo hswoa --iters 10 --oracle --seed 1 --json")
    later.append(f"{base} --algo exact --objective hswoa --json")
    later.append(f"{base} --algo astar --json")
f2 = "path --map examples/maps/zhang2025-20x20.map --start 0,19 --goal 19,0 --algo iqga --encoding chain --objective iqga --iters 20"
for flag in ["regions", "elite_crossover", "qlearning", "sitp"]:
    later.append(f"{f2} --param {flag}=0 --seed 3 --json")
later.append("run --problem rastrigin --dim 10 --algo iaga --evals 5000 --param pm_min=0 --seed 3 --json")
for problem, dim, evals, seed in [("rastrigin", 10, 5000, 1), ("rastrigin", 10, 5000, 7), ("rosenbrock", 5, 3000, 3)]:
    later.append(f"run --problem {problem} --dim {dim} --algo ga-sga --evals {evals} --seed {seed} --json")
for t in [1, 2]:
    later.append(f"path --map examples/maps/zhang2025-40x40.map --start 1,38 --goal 38,1 --algo pso --iters 10 --threads {t} --seed 4 --json")
later.append("run --problem sphere --dim 2 --algo pso --evals 100 --seed 18446744073709551615 --json")
for c in runs + paths + later:
    print(c)
