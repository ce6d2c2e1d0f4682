#!/usr/bin/env python3
"""The generated blocks of docs/results/zhang2025.md (Zhang et al.'s (2025) tables 5 and 6, IQGA's readings and
ablation, the exact references), from the compact stores in docs/results/data/ that
scripts/results_pages.py writes. Usage:

    /usr/bin/python3 scripts/zhang2025_tables.py [DATA_DIR]     # prints every block

Definitions, per map and algorithm, means over the runs: evaluations (every objective call, IQGA's
SITP walk scores included); generations (iterations after the initial population); length, turn
angle (degrees) and turns of the final path, measured from its cells (results_pages.path_metrics);
convergence generation: the first generation whose best equals the run's final best (0: the initial
population), and the evaluations spent by then; optimal: the share of runs whose value is the exact
optimum of the `iqga` objective (within 1e-9, as pride report); gap = (best - optimum) / |optimum|;
on front: the share of runs whose final path is a point of the exact (length, turns) Pareto front;
dL = the run's length minus the shortest front length with at most the run's turns (0 on the
front); wall ms: the run's wall time, under what else ran as the regeneration block states.
"""
import json
import pathlib
import shutil
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import results_pages as rp  # noqa: E402

PROBLEMS = {
    "zhang2025-20x20": ("examples/maps/zhang2025-20x20.map", "0,19", "19,0"),
    "zhang2025-40x40": ("examples/maps/zhang2025-40x40.map", "1,38", "38,1"),
}
ORDER = ["ga", "iaga", "icga", "iqga", "iqga-midpoint"]
VARIANTS = [  # (id, what it changes) in the order of the table
    ("iqga", "the default: random column, pm 0.1, SITP walks ranked by the objective"),
    ("iqga-midpoint", "`sitp_column=midpoint` (eq. 3's formula; the reading of earlier versions of the pages)"),
    ("iqga-pm1", "`pm=1` (every child mutated, section 2.4's reading)"),
    ("iqga-midpoint-pm1", "`sitp_column=midpoint pm=1`"),
    ("iqga-score-length", "`sitp_score=length` (SITP ranks its walks by length, at no evaluation)"),
    ("iqga-no-sitp", "`sitp=0` (random-walk initial paths)"),
    ("iqga-no-regions", "`regions=0` (one region)"),
    ("iqga-no-elite", "`elite_crossover=0` (no pairing rule)"),
    ("iqga-fixed", "`qlearning=0` (fixed 1/3 per mutation)"),
]


def group(runs):
    out = {}
    for r in runs:
        out.setdefault((r.problem, r.algorithm), []).append(r)
    return out


def front_stats(r, front):
    on = any(abs(fl - r.length) < 1e-9 and ft == r.turns for fl, ft in front)
    better = [fl for fl, ft in front if ft <= r.turns]
    dl = max(0.0, r.length - min(better)) if better else 0.0
    return on, dl


def evals_cell(rs):
    lo, hi = min(r.evaluations for r in rs), max(r.evaluations for r in rs)
    m = rp.mean(r.evaluations for r in rs)
    return f"{m:,.0f}" if lo == hi else f"{m:,.0f} ({lo:,}-{hi:,})"


def optimal_cell(rs):
    k = sum(r.optimal() for r in rs)
    return f"{rp.pct(k / len(rs))} ({k}/{len(rs)})"


def claims_tests(equal, generations):
    """The paper's comparisons of tables 5 and 6 as two-sided rank-sum tests, at both budgets."""
    rows = []
    for runs, budget in ((equal, "7,840 evaluations"), (generations, "200 generations")):
        g = group(runs)
        for pid in PROBLEMS:
            m = pid.split("-")[1]
            rows += [rp.rs_row(f"{m}: IQGA shorter than ICGA?", g, pid, "iqga", "icga", "length", budget),
                     rp.rs_row(f"{m}: IQGA fewer turns than ICGA?", g, pid, "iqga", "icga", "turns", budget),
                     rp.rs_row(f"{m}: IAGA better than GA?", g, pid, "iaga", "ga", "best", budget),
                     rp.rs_row(f"{m}: ICGA better than IAGA?", g, pid, "icga", "iaga", "best", budget),
                     rp.rs_row(f"{m}: ICGA better than GA?", g, pid, "icga", "ga", "best", budget),
                     rp.rs_row(f"{m}: IQGA converges earlier than GA?", g, pid, "iqga", "ga", "conv_iter", budget),
                     rp.rs_row(f"{m}: IQGA converges earlier than GA?", g, pid, "iqga", "ga", "conv_evals", budget)]
    return rp.tests_table(rows)


def main_table(runs, meta):
    g = group(runs)
    rows = []
    for pid in PROBLEMS:
        front = [tuple(x) for x in meta["references"][pid]["front"]]
        for a in ORDER:
            rs = g.get((pid, a))
            if not rs:
                continue
            fs = [front_stats(r, front) for r in rs]
            rows.append([pid, a, evals_cell(rs), f"{rp.mean(r.iterations for r in rs):.1f}",
                         f"{rp.mean(r.length for r in rs):.3f}", f"{rp.mean(r.angle for r in rs):.2f}",
                         f"{rp.mean(r.turns for r in rs):.2f}", f"{rp.mean(r.conv_iter for r in rs):.1f}",
                         f"{rp.mean(r.conv_evals for r in rs):,.0f}",
                         optimal_cell(rs),
                         f"{100 * rp.mean((r.best - r.optimum) / abs(r.optimum) for r in rs):.2f} %",
                         rp.pct(rp.mean(on for on, _ in fs)), f"{rp.mean(d for _, d in fs):.3f}",
                         f"{rp.mean(r.wall_ms for r in rs):.1f}"])
    return rp.table(["map", "algorithm", "evaluations: mean (min-max)", "generations", "length", "turn angle (deg)",
                     "turns", "conv. gen.", "conv. evals", "optimal runs", "gap to optimum", "on (length, turns) front",
                     "dL", "wall ms"], rows)


def stats_table(runs):
    rep = rp.report_rows(runs)
    rows = []
    for pid in PROBLEMS:
        for a in [x for x in ORDER if x in rep[pid]]:
            r = rep[pid][a]
            rows.append([pid, a, f"{r['mean']:.6g}", f"{r['median']:.6g}", f"{r['min']:.6g}", rp.pct(r["success"]),
                         "best" if r["best"] else rp.star(r["p_holm"])])
    return rp.table(["map", "algorithm", "mean", "median", "min (best run)", "optimal runs", "p (Holm) vs best median"], rows)


def variants_table(runs, meta):
    g = group(runs)
    rows = []
    for pid in PROBLEMS:
        front = [tuple(x) for x in meta["references"][pid]["front"]]
        base = g[(pid, "iqga")]
        base_by_seed = {r.seed: r for r in base}
        others = [a for a, _ in VARIANTS if a != "iqga"]
        p_val = dict(zip(others, rp.holm([rp.rank_sum([r.best for r in g[(pid, a)]], [r.best for r in base])
                                          for a in others])))
        k0 = sum(r.optimal() for r in base)
        p_opt = dict(zip(others, rp.holm([rp.fisher_exact(sum(r.optimal() for r in g[(pid, a)]),
                                                          len(g[(pid, a)]) - sum(r.optimal() for r in g[(pid, a)]),
                                                          k0, len(base) - k0) for a in others])))
        for a, _ in VARIANTS:
            rs = g[(pid, a)]
            fs = [front_stats(r, front) for r in rs]
            differ = sum(1 for r in rs if r.path != base_by_seed[r.seed].path)
            rows.append([pid, a, evals_cell(rs), f"{rp.mean(r.iterations for r in rs):.1f}",
                         f"{rp.mean(r.length for r in rs):.3f}", f"{rp.mean(r.turns for r in rs):.2f}",
                         f"{rp.mean(r.conv_evals for r in rs):,.0f}", optimal_cell(rs),
                         f"{100 * rp.mean((r.best - r.optimum) / abs(r.optimum) for r in rs):.2f} %",
                         rp.pct(rp.mean(on for on, _ in fs)),
                         "-" if a == "iqga" else f"{differ}",
                         "-" if a == "iqga" else rp.star(p_val[a]), "-" if a == "iqga" else rp.star(p_opt[a])])
    return rp.table(["map", "variant", "evaluations: mean (min-max)", "generations", "length", "turns", "conv. evals",
                     "optimal runs", "gap", "on front", "runs with another path than iqga", "p values (Holm)",
                     "p optimal share (Holm)"], rows)


def references_table(meta):
    rows = []
    for pid in PROBLEMS:
        ref = meta["references"][pid]
        ex = ref["exact_iqga"]
        rows.append([pid, f"{ref['shortest_length']:.3f}", f"{ex['value']:.6f}",
                     f"length {ex['length']:.3f}, {ex['turns']} turn{'s' if ex['turns'] != 1 else ''}, "
                     f"penalty {ex['angle_penalty']:g}",
                     " ".join(f"({fl:.3f}, {ft})" for fl, ft in ref["front"])])
    return rp.table(["map", "shortest length", "exact iqga optimum", "its path", "(length, turns) front"], rows,
                    "llrll")


def init_table(meta):
    it = meta.get("init_table", {})
    if "error" in it:
        return (f"Not re-run: `grid_bench --init-table` stops with `{it['error']}` at this commit, so the command "
                "above leaves table 2 out and this page draws no conclusion from initial populations.")
    rows = [[r["map"], "SITP" if r["init"] == "sitp" else "random walk", r["longest"], r["shortest"], r["mean_length"],
             f"{meta['references'][r['map']]['shortest_length']:.3f}", rp.pct(float(r["feasible_share"]))]
            for r in it["rows"]]
    return rp.table(["map", "init", "longest", "shortest", "mean length", "shortest possible (exact)", "feasible"], rows)


def budgets(name):
    text = (rp.CAMPAIGNS / f"{name}.toml").read_text()
    lines, inside = [], False
    for line in text.splitlines():
        s = line.strip()
        if s.startswith("["):
            inside = s == "[budget]"
        elif inside and "=" in s:
            k, v = (x.strip() for x in s.split("=", 1))
            lines.append(f"{int(v):,} {k}")
    return ", ".join(lines)


def regeneration_table(meta):
    def watch(m):
        return [f"{m['load'][0]:.2f}-{m['load'][1]:.2f}", rp.pct(m["other"])]

    rows = [[f"`examples/campaigns/{c}.toml`", budgets(c), f"{m['runs']:,}", f"{m['seconds']:.1f}"] + watch(m)
            for c, m in meta["campaigns"].items()]
    rows.append(["references, figures" + (", processor times" if "cpu" in meta else ""), "", "",
                 f"{meta['extras_seconds']:.1f}"] + watch(meta["extras_watch"]))
    return (rp.table(["campaign", "budget", "runs", "seconds", "load average (1 min), least-most",
                      "other processes' share of the cores"], rows, "lllrlr") +
            f"\n\nThis page: {meta['page_seconds']:.1f} s; the whole command "
            f"({' and '.join(meta['command_pages'])}): {meta['command_seconds']:.1f} s, with `--jobs {meta['jobs']}` "
            f"on {meta['cores']} cores, at commit {meta['commit']}.")


def blocks(campaigns, meta):
    return {
        "zhang2025-regeneration": regeneration_table(meta),
        "zhang2025-references": references_table(meta),
        "zhang2025-init": init_table(meta),
        "zhang2025-equal": main_table(campaigns["zhang2025"], meta),
        "zhang2025-generations": main_table(campaigns["zhang2025-generations"], meta),
        "zhang2025-stats-equal": stats_table(campaigns["zhang2025"]),
        "zhang2025-stats-generations": stats_table(campaigns["zhang2025-generations"]),
        "zhang2025-tests": claims_tests(campaigns["zhang2025"], campaigns["zhang2025-generations"]),
        "zhang2025-iqga": variants_table(campaigns["zhang2025-iqga"], meta),
    }


def extras(pride, stores, img):
    """What the page needs beyond the campaigns: exact references, table 2, figures."""
    refs = {}
    for pid, (m, s, g) in PROBLEMS.items():
        base = [pride, "path", "--map", rp.REPO / m, "--start", s, "--goal", g, "--algo", "exact", "--json"]
        ex = json.loads(rp.run(base + ["--objective", "iqga"]))
        ln = json.loads(rp.run(base + ["--objective", "length"]))
        fr = json.loads(rp.run([pride, "pareto", "--map", rp.REPO / m, "--start", s, "--goal", g, "--objectives",
                                "length,turns", "--json"]))
        refs[pid] = {"exact_iqga": {"value": ex["objective_value"], "length": ex["metrics"]["length"],
                                    "turns": ex["metrics"]["turns"], "angle_penalty": ex["metrics"]["angle_penalty"]},
                     "shortest_length": ln["metrics"]["length"],
                     "front": [[p["length"], p["turns"]] for p in fr["front"]]}
    out = {"references": refs}
    bench = pathlib.Path(pride).parents[1] / "bench" / "grid_bench"
    if not bench.exists():  # the benchmark programs are built only when asked (PRIDE_BUILD_BENCH)
        rp.subprocess.run(["cmake", "--build", str(bench.parents[1]), "--target", "grid_bench"], check=True,
                          stdout=rp.subprocess.DEVNULL)
    p = rp.subprocess.run([str(bench), "--init-table", "--maps", str(rp.REPO / "examples" / "maps")],
                          capture_output=True, text=True)
    if p.returncode != 0:
        out["init_table"] = {"error": p.stderr.strip().splitlines()[-1] if p.stderr.strip() else f"exit {p.returncode}"}
    else:
        import csv
        import io
        out["init_table"] = {"rows": [r for r in csv.DictReader(io.StringIO(p.stdout)) if r["part"] == "init"]}
    with tempfile.TemporaryDirectory() as tmp:
        rp.run([pride, "report", stores / "zhang2025.sqlite", "--plots", tmp])
        for pid in PROBLEMS:
            for kind in ("convergence", "final", "paths"):
                shutil.copyfile(pathlib.Path(tmp) / f"{pid}-{kind}.png", img / f"{pid}-{kind}.png")
    return out


if __name__ == "__main__":
    data = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else rp.DATA
    for name, text in rp.render("zhang2025", data).items():
        print(f"{rp.begin(name)}\n{text}\n{rp.end(name)}\n")
