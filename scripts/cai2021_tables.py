#!/usr/bin/env python3
"""The generated blocks of docs/results/cai2021.md (Cai and Du's (2021) tables 1 and 3-6 with the exact
optimum beside them, the tests of its claims, processor times), from the compact stores in
docs/results/data/ that scripts/results_pages.py writes. Usage:

    /usr/bin/python3 scripts/cai2021_tables.py [DATA_DIR]     # prints every block

Columns, per (map, algorithm) over its runs: the hswoa value (length + turns) of the final path,
mean and standard deviation; its length (least, mean) and turns (mean), measured from the cells
(results_pages.path_metrics); the mean gap (value - optimum) / optimum to the exact optimum stored
with each run; optimal: the share of runs at the exact optimum (within 1e-9, as pride report);
shortest length: the share whose length is the exact shortest length of the map (`pride path --algo
exact --objective length`); conv. iter.: the first iteration whose best equals the run's final best
(0: the initial population), and conv. evals the evaluations spent by then; evaluations: mean (and
range) of the objective calls (A* does not call the objective: its node expansions are shown);
wall ms: the run's wall time, under what else ran as the regeneration block states; p: two-sided
Wilcoxon rank-sum test of the final values against the table's reference row, Holm-corrected over
the other rows of that map's table, `*` below 0.05.
"""
import json
import pathlib
import shutil
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import results_pages as rp  # noqa: E402
from zhang2025_tables import regeneration_table  # noqa: E402

PROBLEMS = {
    "map50": ("examples/maps/cai2021-50x50.map", "0,49", "49,0"),
    "env1": ("examples/maps/cai2021-env1-30x30.map", "0,29", "29,0"),
    "env2": ("examples/maps/cai2021-env2-30x30.map", "0,29", "29,0"),
    "env3": ("examples/maps/cai2021-env3-60x60.map", "0,59", "59,0"),
}
SWEEP = ["thr0", "thr1", "thr2", "thr3", "thr4", "thr6", "balance0.5", "balance0.6", "balance0.7", "balance0.9",
         "pop10", "pop30", "pop40", "pop50"]
ABLATION = ["woa", "woa-hs", "woa-balance", "hswoa"]
ENVS = ["astar", "woa", "hswoa", "ga", "iqga", "pso", "ilso", "ga-line", "iqga-line", "woa-octile", "hswoa-octile",
        "woa-elbow", "hswoa-elbow"]
CPU_ALGOS = [("astar", []), ("woa", ["--evals", "1020"]), ("hswoa", ["--evals", "1020"]), ("hswoa", ["--iters", "50"])]
CPU_REPEATS = 3
CPU_RUNS = 20


def cpu_campaign(pid, m, s, g, a, args, seeds):
    budget = f"{args[0][2:].replace('evals', 'evaluations').replace('iters', 'iterations')} = {args[1]}" if args else ""
    x, y = s.split(","), g.split(",")
    return (f'name = "cpu"\nseeds = {seeds}\n[budget]\n{budget or "iterations = 50"}\n[[problem]]\nid = "{pid}"\n'
            f'type = "grid"\nmap = "{rp.REPO / m}"\nstart = [{x[0]}, {x[1]}]\ngoal = [{y[0]}, {y[1]}]\n'
            f'objective = "hswoa"\nencoding = "chain"\n[[algorithm]]\nid = "{a}"\ntype = "{a}"\n')


def group(*campaigns):
    out = {}
    for runs in campaigns:
        for r in runs:
            out.setdefault((r.problem, r.algorithm), []).append(r)
    return out


def evals_cell(a, rs):
    lo, hi = min(r.evaluations for r in rs), max(r.evaluations for r in rs)
    m = rp.mean(r.evaluations for r in rs)
    if a == "astar":
        return f"none ({m:,.0f} expansions)"
    return f"{m:,.0f}" if lo == hi else f"{m:,.0f} ({lo:,}-{hi:,})"


def value_table(g, pid, algos, ref, meta):
    shortest = meta["references"][pid]["shortest_length"]
    present = [a for a in algos if (pid, a) in g]
    others = [a for a in present if a != ref]
    ps = dict(zip(others, rp.holm([rp.rank_sum([r.best for r in g[(pid, a)]], [r.best for r in g[(pid, ref)]])
                                   for a in others])))
    rows = []
    for a in present:
        rs = g[(pid, a)]
        v = [r.best for r in rs]
        conv = [r for r in rs if r.conv_iter is not None]
        rows.append([a, len(rs), f"{rp.mean(v):.3f}", f"{rp.stdev(v):.3f}", f"{min(r.length for r in rs):.3f}",
                     f"{rp.mean(r.length for r in rs):.3f}", f"{rp.mean(r.turns for r in rs):.2f}",
                     f"{100 * rp.mean((r.best - r.optimum) / r.optimum for r in rs):.2f} %",
                     rp.pct(rp.mean(r.optimal() for r in rs)),
                     rp.pct(rp.mean(abs(r.length - shortest) <= 1e-9 for r in rs)),
                     f"{rp.mean(r.conv_iter for r in conv):.1f}" if conv else "-",
                     f"{rp.mean(r.conv_evals for r in conv):,.0f}" if conv else "-",
                     evals_cell(a, rs), f"{rp.mean(r.wall_ms for r in rs):.2f}",
                     "reference" if a == ref else rp.star(ps[a])])
    ref_text = meta["references"][pid]
    head = (f"**{pid}** (exact hswoa optimum {ref_text['exact_hswoa']['value']:.3f}: length "
            f"{ref_text['exact_hswoa']['length']:.3f}, {ref_text['exact_hswoa']['turns']} turns; shortest length "
            f"{shortest:.3f})\n\n")
    return head + rp.table(["algorithm", "runs", "mean value", "std", "min length", "mean length", "mean turns",
                            "mean gap", "optimal", "shortest length", "conv. iter.", "conv. evals", "evaluations",
                            "wall ms", f"p (Holm) vs {ref}"], rows, "l" + "r" * 14)


EQ, IT = "1,020 evaluations", "50 iterations"


def sweep_tests(ge, gi):
    rows = []
    thr = SWEEP[:6]
    bal = ["balance0.5", "balance0.6", "balance0.7", "thr2", "balance0.9"]
    pop = ["pop10", "thr2", "pop30", "pop40", "pop50"]
    for g, b in ((ge, EQ), (gi, IT)):
        rows.append(rp.kw_row("does thr change the result?", g, "map50", thr, "best", b))
        rows.append(rp.kw_row("does thr change when runs converge?", g, "map50", thr, "conv_iter", b))
        rows.append(rp.kw_row("does the balance change the result? (thr2: 0.8)", g, "map50", bal, "best", b))
        rows.append(rp.kw_row("does N change the result? (thr2: 20)", g, "map50", pop, "best", b))
    return rp.tests_table(rows)


def ablation_tests(ge, gi):
    rows = []
    for g, b in ((ge, EQ), (gi, IT)):
        rows.append(rp.rs_row("harmony step: shorter paths?", g, "map50", "woa-hs", "woa", "length", b))
        rows.append(rp.rs_row("harmony step: better value?", g, "map50", "woa-hs", "woa", "best", b))
        rows.append(rp.rs_row("harmony step: converges earlier?", g, "map50", "woa-hs", "woa", "conv_iter", b))
        rows.append(rp.rs_row("harmony step: converges earlier?", g, "map50", "woa-hs", "woa", "conv_evals", b))
        rows.append(rp.rs_row("both: better than WOA?", g, "map50", "hswoa", "woa", "best", b))
    return rp.tests_table(rows)


def envs_tests(ge, gi):
    rows = []
    for g, b in ((ge, EQ), (gi, IT)):
        for pid in ("env1", "env2", "env3"):
            rows.append(rp.rs_row(f"{pid}: HS-WOA better than WOA?", g, pid, "hswoa", "woa", "best", b))
            rows.append(rp.rs_row(f"{pid}: HS-WOA converges earlier?", g, pid, "hswoa", "woa", "conv_iter", b))
            rows.append(rp.rs_row(f"{pid}: HS-WOA converges earlier?", g, pid, "hswoa", "woa", "conv_evals", b))
    return rp.tests_table(rows)


def settings_tests(ge):
    rows = []
    for pid in ("env1", "env2", "env3"):
        for a, b, q in (("ga-line", "ga", "the line shortcut on the GA"), ("iqga-line", "iqga", "the line shortcut on IQGA"),
                        ("woa-octile", "woa", "octile walks on WOA"), ("hswoa-octile", "hswoa", "octile walks on HS-WOA"),
                        ("woa-elbow", "woa", "the elbow shortcut on WOA"),
                        ("hswoa-elbow", "hswoa", "the elbow shortcut on HS-WOA")):
            rows.append(rp.rs_row(f"{pid}: {q}", ge, pid, a, b, "best", EQ))
    return rp.tests_table(rows)


def references_table(meta):
    rows = []
    for pid in PROBLEMS:
        r = meta["references"][pid]
        ex, a = r["exact_hswoa"], r["astar"]
        rows.append([pid, f"{ex['value']:.3f}", f"{ex['length']:.3f}", ex["turns"], f"{r['shortest_length']:.3f}",
                     f"{a['length']:.3f}", a["turns"], f"{a['value']:.3f}"])
    return rp.table(["map", "exact hswoa optimum", "its length", "its turns", "shortest length", "A*'s length",
                     "A*'s turns", "A*'s hswoa value"], rows, "lrrrrrrr")


def cpu_table(meta):
    c = meta["cpu"]
    ms = c["ms"]
    ratio = {b: [ms[p][f"hswoa {b}"] / ms[p]["woa --evals 1020"] for p in PROBLEMS] for b in ("--iters 50", "--evals 1020")}
    rows = [[pid] + [f"{ms[pid][k]:.1f}" for k in c["columns"]] +
            [f"{ms[pid]['hswoa --iters 50'] / ms[pid]['woa --evals 1020']:.2f}",
             f"{ms[pid]['hswoa --evals 1020'] / ms[pid]['woa --evals 1020']:.2f}"] for pid in PROBLEMS]
    head = ["`astar`", "`woa`, 1,020 evaluations (= 50 iterations)", "`hswoa`, 1,020 evaluations", "`hswoa`, 50 iterations"]
    return (rp.table(["map"] + head + ["hswoa / woa, 50 iterations", "hswoa / woa, 1,020 evaluations"], rows,
                     "l" + "r" * (len(head) + 2)) +
            f"\n\nProcessor time (user + system) of one run, ms: that of `pride bench --jobs 1` over seeds "
            f"1..{CPU_RUNS + 1} less that over seed 1, divided by {CPU_RUNS} (start-up and the exact optimum "
            f"cancel out), each the least of {CPU_REPEATS} repetitions; one process at a time; while they ran, "
            f"other processes took {rp.pct(c['watch']['other'])} of the machine's cores (load average "
            f"{c['watch']['load'][0]:.2f}-{c['watch']['load'][1]:.2f})"
            f"{': measured under load' if c['watch']['other'] > 0.05 else ': an unloaded machine'}. "
            f"An HS-WOA run takes {min(ratio['--iters 50']):.1f} to {max(ratio['--iters 50']):.1f} times a WOA "
            f"run's processor time at 50 iterations, {min(ratio['--evals 1020']):.1f} to "
            f"{max(ratio['--evals 1020']):.1f} times at 1,020 evaluations.")


def blocks(campaigns, meta):
    gs, gsi = group(campaigns["cai2021-sweep"]), group(campaigns["cai2021-sweep-iterations"])
    ga, gai = group(campaigns["cai2021-ablation"]), group(campaigns["cai2021-ablation-iterations"])
    ge = group(campaigns["cai2021-envs"])
    gei = group(campaigns["cai2021-envs-iterations"])
    return {
        "cai2021-regeneration": regeneration_table(meta),
        "cai2021-references": references_table(meta),
        "cai2021-sweep-equal": value_table(gs, "map50", SWEEP, "thr2", meta),
        "cai2021-sweep-iterations": value_table(gsi, "map50", SWEEP, "thr2", meta),
        "cai2021-sweep-tests": sweep_tests(gs, gsi),
        "cai2021-ablation-equal": value_table(ga, "map50", ABLATION, "hswoa", meta),
        "cai2021-ablation-iterations": value_table(gai, "map50", ABLATION, "hswoa", meta),
        "cai2021-ablation-tests": ablation_tests(ga, gai),
        "cai2021-envs-equal": "\n\n".join(value_table(ge, p, ENVS, "hswoa", meta) for p in ("env1", "env2", "env3")),
        "cai2021-envs-iterations": "\n\n".join(value_table(gei, p, ENVS, "hswoa", meta)
                                               for p in ("env1", "env2", "env3")),
        "cai2021-envs-tests": envs_tests(ge, gei),
        "cai2021-settings-tests": settings_tests(ge),
        "cai2021-cpu": cpu_table(meta),
    }


def extras(pride, stores, img):
    """Exact references, A*'s paths, processor times, figures."""
    refs = {}
    for pid, (m, s, g) in PROBLEMS.items():
        base = [pride, "path", "--map", rp.REPO / m, "--start", s, "--goal", g, "--json"]
        ex = json.loads(rp.run(base + ["--algo", "exact", "--objective", "hswoa"]))
        ln = json.loads(rp.run(base + ["--algo", "exact", "--objective", "length"]))
        a = json.loads(rp.run(base + ["--algo", "astar", "--objective", "hswoa"]))
        refs[pid] = {"exact_hswoa": {"value": ex["objective_value"], "length": ex["metrics"]["length"],
                                     "turns": ex["metrics"]["turns"]},
                     "shortest_length": ln["metrics"]["length"],
                     "astar": {"value": a["objective_value"], "length": a["metrics"]["length"],
                               "turns": a["metrics"]["turns"]}}
    watch = rp.LoadWatch()
    columns = [" ".join([a] + args) for a, args in CPU_ALGOS]
    ms = {}
    with tempfile.TemporaryDirectory() as tmp:
        for pid, (m, s, g) in PROBLEMS.items():
            ms[pid] = {}
            for k, ((a, args), col) in enumerate(zip(CPU_ALGOS, columns)):
                # the marginal processor time of a run: a campaign of 1 + CPU_RUNS seeds less one of 1,
                # each the least of CPU_REPEATS repetitions (a fresh store each time)
                cpu = []
                for seeds in (1, 1 + CPU_RUNS):
                    f = pathlib.Path(tmp) / f"{pid}-{k}-{seeds}.toml"
                    f.write_text(cpu_campaign(pid, m, s, g, a, args, seeds))
                    times = []
                    for rep in range(CPU_REPEATS):
                        store = pathlib.Path(tmp) / f"{pid}-{k}-{seeds}-{rep}.sqlite"
                        times.append(rp.timed_cpu([pride, "bench", f, "--jobs", 1, "--out", store])[0])
                    cpu.append(min(times))
                ms[pid][col] = round(1000.0 * (cpu[1] - cpu[0]) / CPU_RUNS, 2)
    cpu = {"columns": columns, "ms": ms, "watch": watch.stop()}
    with tempfile.TemporaryDirectory() as tmp:
        rp.run([pride, "report", stores / "cai2021-envs.sqlite", "--plots", tmp])
        for pid in ("env1", "env2", "env3"):
            for kind in ("convergence", "paths"):
                shutil.copyfile(pathlib.Path(tmp) / f"{pid}-{kind}.png", img / f"cai2021-{pid}-{kind}.png")
    with tempfile.TemporaryDirectory() as tmp:
        rp.run([pride, "report", stores / "cai2021-ablation.sqlite", "--plots", tmp])
        shutil.copyfile(pathlib.Path(tmp) / "map50-convergence.png", img / "cai2021-map50-convergence.png")
    return {"references": refs, "cpu": cpu}


if __name__ == "__main__":
    data = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else rp.DATA
    for name, text in rp.render("cai2021", data).items():
        print(f"{rp.begin(name)}\n{text}\n{rp.end(name)}\n")
