#!/usr/bin/env python3
"""Regenerates docs/results/zhang2025.md and docs/results/cai2021.md from nothing, or checks them.

    /usr/bin/python3 scripts/results_pages.py [--build DIR] [--jobs N] [--page zhang2025|cai2021]
        runs every campaign of the pages (examples/campaigns/zhang2025*.toml, cai2021*.toml) into
        fresh stores under DIR/results (DIR: build), writes their compact stores to
        docs/results/data/, the exact references and the processor times beside them, the figures
        to docs/results/img/, and the pages' generated blocks; prints how long it took.
    /usr/bin/python3 scripts/results_pages.py render [--page P]
        rewrites the pages' generated blocks from docs/results/data/ alone (no pride needed).
    /usr/bin/python3 scripts/results_pages.py check [--page P]
        exits 1 when a page's generated blocks differ from what docs/results/data/ gives
        (python/tests/test_results_pages.py does the same under ctest).

A generated block of a page lies between `<!-- generated: NAME -->` and `<!-- end generated: NAME -->`;
everything else on the page is prose written by hand against those blocks.

The compact store of a campaign, docs/results/data/CAMPAIGN.csv, holds one line per run with what
the tables need: problem, algorithm, seed, best (the shortest text that reads back as the stored
double; empty when no feasible path was found), optimum (the exact optimum pride stores beside every
grid run), evaluations, iterations, conv_iter (the first iteration whose best equals the run's final
best; 0 is the initial population; empty for A*, which has no history), conv_evals (the evaluations
spent by then), wall_ms, and the best path as `x,y:DIGITS` (the first cell, then one digit per step,
0..7 for the directions (1,0), (1,1), (0,1), (-1,1), (-1,0), (-1,-1), (0,-1), (1,-1), x the column,
y the row from the top). CAMPAIGN.csv is written from the SQLite store `pride bench` makes, and
every statistic computed here from it is checked against `pride report --format csv` of that store
before anything is written.

Statistics (the same formulas as experiment/report/statistics.hpp, which tests/test_statistics.cpp
checks against scipy): the two-sided Wilcoxon rank-sum test (Mann-Whitney U, normal approximation
with tie and continuity corrections), Holm's step-down correction, Kruskal-Wallis's H (tie-corrected,
chi-squared with k - 1 degrees of freedom) and Fisher's exact test (two-sided, 2 x 2).
"""
import csv
import io
import json
import math
import os
import pathlib
import shutil
import subprocess
import sys
import threading
import time

REPO = pathlib.Path(__file__).resolve().parents[1]
DATA = REPO / "docs" / "results" / "data"
IMG = REPO / "docs" / "results" / "img"
CAMPAIGNS = REPO / "examples" / "campaigns"


def map_file(name):
    """The file a page's map `name` names: relative to the top of the checkout, or, written
    `$PRIDE_DATA/...`, a map of the public data of others under the folder PRIDE_DATA names (Moving
    AI's maps, which the repository does not hold). Only the runs need the file; the pages print
    `name` as it is written."""
    prefix = "$PRIDE_DATA/"
    if not name.startswith(prefix):
        return REPO / name
    root = os.environ.get("PRIDE_DATA")
    if not root:
        sys.exit(f"{name}: set PRIDE_DATA to the folder of the public data (reference-data/README.md)")
    return pathlib.Path(root) / name[len(prefix):]

PAGES = {
    "zhang2025": {
        "page": "docs/results/zhang2025.md",
        "campaigns": ["zhang2025", "zhang2025-generations", "zhang2025-iqga"],
        "module": "zhang2025_tables",
    },
    "cai2021": {
        "page": "docs/results/cai2021.md",
        "campaigns": ["cai2021-sweep", "cai2021-sweep-iterations", "cai2021-ablation", "cai2021-ablation-iterations",
                      "cai2021-envs", "cai2021-envs-iterations"],
        "module": "cai2021_tables",
    },
}

# ---------------------------------------------------------------------------------------------
# Paths

DIRS = [(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1)]
DIGIT = {d: i for i, d in enumerate(DIRS)}
SQRT2 = math.sqrt(2.0)


def encode_path(cells):
    (x, y), out = cells[0], []
    for (x0, y0), (x1, y1) in zip(cells, cells[1:]):
        out.append(str(DIGIT[(x1 - x0, y1 - y0)]))
    return f"{x},{y}:" + "".join(out)


def decode_path(text):
    head, steps = text.split(":")
    x, y = map(int, head.split(","))
    cells = [(x, y)]
    for c in steps:
        dx, dy = DIRS[int(c)]
        x, y = x + dx, y + dy
        cells.append((x, y))
    return cells


def path_metrics(text):
    """(length, turns, turn angle in degrees) of an encoded path, measured here with no code
    shared with pride: octile length, a turn at every change of direction, 45 degrees per eighth."""
    steps = text.split(":")[1]
    length, turns, angle, prev = 0.0, 0, 0, None
    for c in steps:
        d = int(c)
        length += SQRT2 if d & 1 else 1.0
        if prev is not None and d != prev:
            k = abs(d - prev)
            turns += 1
            angle += 45 * min(k, 8 - k)
        prev = d
    return length, turns, angle


# ---------------------------------------------------------------------------------------------
# Compact stores

FIELDS = ["problem", "algorithm", "seed", "best", "optimum", "evaluations", "iterations", "conv_iter", "conv_evals",
          "wall_ms", "path"]


class Run:
    __slots__ = ("problem", "algorithm", "seed", "best", "optimum", "evaluations", "iterations", "conv_iter",
                 "conv_evals", "wall_ms", "path", "length", "turns", "angle")

    def __init__(self, row):
        self.problem = row["problem"]
        self.algorithm = row["algorithm"]
        self.seed = int(row["seed"])
        self.best = float(row["best"]) if row["best"] else math.inf
        self.optimum = float(row["optimum"]) if row["optimum"] else None
        self.evaluations = int(row["evaluations"])
        self.iterations = int(row["iterations"])
        self.conv_iter = int(row["conv_iter"]) if row["conv_iter"] else None
        self.conv_evals = int(row["conv_evals"]) if row["conv_evals"] else None
        self.wall_ms = float(row["wall_ms"])
        self.path = row["path"]
        self.length, self.turns, self.angle = path_metrics(self.path) if self.path else (math.nan, 0, 0)

    def optimal(self):
        return self.optimum is not None and abs(self.best - self.optimum) <= 1e-9 * max(1.0, abs(self.optimum))


def read_campaign(name, data=DATA):
    with open(data / f"{name}.csv", newline="") as f:
        return [Run(row) for row in csv.DictReader(f)]


def read_meta(page, data=DATA):
    with open(data / f"{page}-meta.json") as f:
        return json.load(f)


def export_store(store, out):
    """The compact CSV of a `pride bench` store (sorted by problem, algorithm in campaign order, seed)."""
    import sqlite3
    db = sqlite3.connect(f"file:{store}?mode=ro", uri=True)
    rows = db.execute("SELECT problem, algorithm, seed, best, optimum, evaluations, iterations, history, "
                      "history_evaluations, wall_ms, solution, rowid FROM runs").fetchall()
    text = db.execute("SELECT text FROM campaign").fetchone()[0]
    db.close()
    order_a = campaign_algorithms(text)
    order_p = campaign_problems(text)
    rows.sort(key=lambda r: (order_p.index(r[0]), order_a.index(r[1]), r[2]))
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(FIELDS)
    for p, a, seed, best, opt, evals, iters, hist, hist_e, ms, sol, _ in rows:
        h, he = json.loads(hist), json.loads(hist_e)
        conv = next(k for k, v in enumerate(h) if v == h[-1]) if h else None
        cells = json.loads(sol)
        w.writerow([p, a, seed, "" if best is None else repr(best), "" if opt is None else repr(opt), evals, iters,
                    "" if conv is None else conv, "" if conv is None or not he else he[conv], f"{ms:.3f}",
                    encode_path(cells) if cells else ""])
    out.write_text(buf.getvalue())


def campaign_algorithms(text):
    """The algorithm ids of a campaign file, in its order (a small reader of the TOML we write)."""
    return _ids(text, "[[algorithm]]")


def campaign_problems(text):
    return _ids(text, "[[problem]]")


def _ids(text, table):
    ids, inside = [], False
    for line in text.splitlines():
        s = line.strip()
        if s.startswith("["):
            inside = s == table
        elif inside and s.startswith("id") and "=" in s:
            ids.append(s.split("=", 1)[1].strip().strip('"'))
            inside = False
    return ids


# ---------------------------------------------------------------------------------------------
# Statistics (experiment/report/statistics.hpp's formulas)

def mean(xs):
    xs = list(xs)
    return sum(xs) / len(xs)


def median(xs):
    s = sorted(xs)
    n = len(s)
    return s[n // 2] if n % 2 else 0.5 * (s[n // 2 - 1] + s[n // 2])


def stdev(xs):
    xs = list(xs)
    if len(xs) < 2:
        return 0.0
    m = mean(xs)
    return math.sqrt(sum((x - m) ** 2 for x in xs) / (len(xs) - 1))


def average_ranks(values):
    order = sorted(range(len(values)), key=lambda i: values[i])
    ranks = [0.0] * len(values)
    i = 0
    while i < len(order):
        j = i
        while j + 1 < len(order) and values[order[j + 1]] == values[order[i]]:
            j += 1
        for k in range(i, j + 1):
            ranks[order[k]] = 0.5 * (i + j) + 1.0
        i = j + 1
    return ranks


def _tie_sum(values):
    s = sorted(values)
    total, i = 0.0, 0
    while i < len(s):
        j = i
        while j + 1 < len(s) and s[j + 1] == s[i]:
            j += 1
        t = j - i + 1
        total += t ** 3 - t
        i = j + 1
    return total


def rank_sum(x, y):
    """Two-sided p of the Wilcoxon rank-sum (Mann-Whitney U) test, normal approximation with the tie
    and continuity corrections (scipy.stats.mannwhitneyu(method="asymptotic")); 1 when all tie."""
    x, y = list(x), list(y)
    allv = x + y
    ranks = average_ranks(allv)
    n1, n2 = float(len(x)), float(len(y))
    n = n1 + n2
    u = sum(ranks[:len(x)]) - n1 * (n1 + 1.0) / 2.0
    var = n1 * n2 / 12.0 * ((n + 1.0) - _tie_sum(allv) / (n * (n - 1.0)))
    if not var > 0.0:
        return 1.0
    z = (max(u, n1 * n2 - u) - n1 * n2 / 2.0 - 0.5) / math.sqrt(var)
    return min(1.0, math.erfc(z / math.sqrt(2.0)))


def holm(ps):
    order = sorted(range(len(ps)), key=lambda i: ps[i])
    out, running, m = [0.0] * len(ps), 0.0, len(ps)
    for i, k in enumerate(order):
        running = max(running, min(1.0, ps[k] * (m - i)))
        out[k] = running
    return out


def chi2_sf(x, df):
    """P(X > x) for X chi-squared with df degrees of freedom: the regularised upper incomplete gamma
    Q(df/2, x/2) (series below a + 1, Lentz's continued fraction above)."""
    if x <= 0:
        return 1.0
    a, z = df / 2.0, x / 2.0
    lg = math.lgamma(a)
    if z < a + 1.0:
        term = total = 1.0 / a
        ap = a
        for _ in range(10000):
            ap += 1.0
            term *= z / ap
            total += term
            if abs(term) < abs(total) * 1e-17:
                break
        return max(0.0, 1.0 - total * math.exp(-z + a * math.log(z) - lg))
    tiny = 1e-300
    b = z + 1.0 - a
    c, d = 1.0 / tiny, 1.0 / b
    h = d
    for i in range(1, 10000):
        an = -i * (i - a)
        b += 2.0
        d = an * d + b
        d = tiny if abs(d) < tiny else d
        c = b + an / c
        c = tiny if abs(c) < tiny else c
        d = 1.0 / d
        delta = d * c
        h *= delta
        if abs(delta - 1.0) < 1e-16:
            break
    return math.exp(-z + a * math.log(z) - lg) * h


def kruskal(groups):
    """Kruskal-Wallis H test (tie-corrected, as scipy.stats.kruskal): (H, p)."""
    allv = [v for g in groups for v in g]
    ranks = average_ranks(allv)
    n = len(allv)
    h, k = 0.0, 0
    for g in groups:
        r = ranks[k:k + len(g)]
        k += len(g)
        h += sum(r) ** 2 / len(g)
    h = 12.0 / (n * (n + 1.0)) * h - 3.0 * (n + 1.0)
    c = 1.0 - _tie_sum(allv) / (n ** 3 - n)
    if c <= 0:
        return 0.0, 1.0
    h /= c
    return h, chi2_sf(h, len(groups) - 1)


def friedman(blocks):
    """Friedman's test over blocks (rows: one value per treatment, lower better), ranks averaged
    within a block and the tie correction of scipy.stats.friedmanchisquare: (chi2, p, mean ranks)."""
    n, k = len(blocks), len(blocks[0])
    ranks = [average_ranks(row) for row in blocks]
    sums = [sum(r[j] for r in ranks) for j in range(k)]
    ties = sum(_tie_sum(row) for row in blocks)
    chi2 = 12.0 / (n * k * (k + 1.0)) * sum(s * s for s in sums) - 3.0 * n * (k + 1.0)
    c = 1.0 - ties / (n * k * (k * k - 1.0))
    chi2 = chi2 / c if c > 0 else 0.0
    return chi2, chi2_sf(chi2, k - 1), [s / n for s in sums]


def fisher_exact(a, b, c, d):
    """Two-sided p of Fisher's exact test on the table [[a, b], [c, d]] (as scipy.stats.fisher_exact:
    the tables no more probable than the one observed, with a relative tolerance of 1e-7)."""
    r1, r2, c1 = a + b, c + d, a + c
    n = r1 + r2
    denom = math.comb(n, c1)

    def prob(x):
        return math.comb(r1, x) * math.comb(r2, c1 - x) / denom

    p_obs = prob(a)
    lo, hi = max(0, c1 - r2), min(r1, c1)
    return min(1.0, sum(prob(x) for x in range(lo, hi + 1) if prob(x) <= p_obs * (1 + 1e-7)))


def fmt_p(p):
    return f"{p:.3g}"


def star(p):
    return f"{fmt_p(p)}{'*' if p < 0.05 else ''}"


def report_rows(runs):
    """pride report's statistics per (problem, algorithm): mean, median, std, min, optimal share and
    the Holm-corrected rank-sum p against the algorithm with the lowest median (ties: lowest mean;
    then the first by name), as experiment/report/report.cpp computes them. {problem: {algorithm: dict}}"""
    cells = {}
    for r in runs:
        cells.setdefault(r.problem, {}).setdefault(r.algorithm, []).append(r)
    out = {}
    for p in sorted(cells):
        by_a = cells[p]
        best, bm, bmean = None, 0.0, 0.0
        for a in sorted(by_a):
            v = [r.best for r in by_a[a]]
            md, mn = median(v), mean(v)
            if best is None or md < bm or (md == bm and mn < bmean):
                best, bm, bmean = a, md, mn
        rows, tested, ps = {}, [], []
        for a in sorted(by_a):
            v = [r.best for r in by_a[a]]
            rows[a] = {"mean": mean(v), "median": median(v), "std": stdev(v), "min": min(v), "best": a == best,
                       "success": mean(1.0 if r.optimal() else 0.0 for r in by_a[a]), "p_holm": None,
                       "evaluations": mean(r.evaluations for r in by_a[a])}
            if a != best:
                tested.append(a)
                ps.append(rank_sum(v, [r.best for r in by_a[best]]))
        for a, q in zip(tested, holm(ps)):
            rows[a]["p_holm"] = q
        out[p] = rows
    return out


def cross_check(store_csv, runs, label):
    """Raises when report_rows(runs) disagrees with `pride report --format csv` of the store."""
    mine = report_rows(runs)
    for row in csv.DictReader(io.StringIO(store_csv)):
        m = mine[row["problem"]][row["algorithm"]]

        def close(a, b, what):
            if not (a == b or abs(a - b) <= 1e-9 * max(1.0, abs(a), abs(b))):
                raise SystemExit(f"{label}: {row['problem']} {row['algorithm']}: {what} {a!r} here, {b!r} in pride report")

        close(m["mean"], float(row["mean"]), "mean")
        close(m["median"], float(row["median"]), "median")
        close(m["evaluations"], float(row["mean_evaluations"]), "mean evaluations")
        if row["success"]:
            close(m["success"], float(row["success"]), "optimal share")
        if (row["best"] == "1") != m["best"]:
            raise SystemExit(f"{label}: {row['problem']} {row['algorithm']}: best marked differently from pride report")
        if row["p_holm_vs_best"]:
            close(m["p_holm"], float(row["p_holm_vs_best"]), "p (Holm)")


def tests_table(rows):
    """rows: (question, comparison, measure, budget, p); Holm over the rows of this table."""
    adj = holm([r[-1] for r in rows])
    return table(["question", "comparison", "measure", "budget", "test", "p", "p (Holm over this table)"],
                 [list(r[:4]) + [r[4], fmt_p(r[5]), star(q)] for r, q in zip(rows, adj)], "lllllrr")


def kw_row(question, g, pid, algos, what, budget):
    groups = [[getattr(r, what) for r in g[(pid, a)]] for a in algos]
    h, p = kruskal(groups)
    return (question, ", ".join(algos), MEASURE[what], budget, f"Kruskal-Wallis (H = {h:.2f}, {len(algos) - 1} df)", p)


def rs_row(question, g, pid, a, b, what, budget):
    x = [getattr(r, what) for r in g[(pid, a)]]
    y = [getattr(r, what) for r in g[(pid, b)]]
    return (question, f"{a} vs {b}", MEASURE[what], budget,
            f"rank-sum (means {mean(x):,.4g} vs {mean(y):,.4g})", rank_sum(x, y))


MEASURE = {"best": "final value", "length": "final length", "turns": "final turns", "conv_iter": "conv. iter.",
           "conv_evals": "conv. evals"}


# ---------------------------------------------------------------------------------------------
# Markdown

def table(header, rows, align=None):
    """A markdown table; align: a string of l/r per column (default: first two left, rest right)."""
    align = align or ("ll" + "r" * (len(header) - 2))[:len(header)]
    out = ["| " + " | ".join(header) + " |", "|" + "|".join("---" if a == "l" else "---:" for a in align) + "|"]
    out += ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]
    return "\n".join(out)


def pct(x):
    return f"{100.0 * x:.0f} %"


def begin(name):
    return f"<!-- generated: {name} -->"


def end(name):
    return f"<!-- end generated: {name} -->"


def page_blocks(text):
    """{name: content} of the generated blocks of a page's text."""
    out, pos = {}, 0
    while True:
        i = text.find("<!-- generated: ", pos)
        if i < 0:
            return out
        j = text.index(" -->", i)
        name = text[i + len("<!-- generated: "):j]
        k = text.index(end(name), j)
        if name in out:
            raise ValueError(f"block {name} appears twice")
        out[name] = text[j + len(" -->"):k].strip("\n")
        pos = k


def replace_blocks(text, blocks):
    for name, content in blocks.items():
        b, e = begin(name), end(name)
        i = text.find(b)
        if i < 0:
            raise SystemExit(f"the page has no block {name}: add `{b}` and `{e}` where it belongs")
        k = text.index(e, i)
        text = text[:i] + b + "\n" + content + "\n" + text[k:]
    return text


def render(page, data=DATA):
    """{name: content} of every generated block of `page`, from the compact stores in `data`."""
    sys.path.insert(0, str(REPO / "scripts"))
    module = __import__(PAGES[page]["module"])
    campaigns = {c: read_campaign(c, data) for c in PAGES[page]["campaigns"]}
    return module.blocks(campaigns, read_meta(page, data))


def check(page, data=DATA, repo=REPO):
    """The differences between the page's generated blocks and what the data give: a list of
    (block, expected, found); empty when the page is in step with its data."""
    text = (repo / PAGES[page]["page"]).read_text()
    found = page_blocks(text)
    expected = render(page, data)
    diffs = [(n, expected.get(n), found.get(n)) for n in sorted(set(found) | set(expected))
             if expected.get(n) != found.get(n)]
    return diffs


def write_page(page):
    path = REPO / PAGES[page]["page"]
    path.write_text(replace_blocks(path.read_text(), render(page)))


# ---------------------------------------------------------------------------------------------
# Regeneration

class LoadWatch:
    """What else ran while it ran: the 1-minute load average, sampled every second
    (os.getloadavg), and the processor time the other processes of the machine took, as a share of
    all its cores: the busy time /proc/stat counts less this process's and its waited children's."""

    def __init__(self):
        self.samples, self._stop = [os.getloadavg()[0]], threading.Event()
        self._t0, self._busy0, self._own0 = time.monotonic(), _busy_seconds(), _own_seconds()
        self._thread = threading.Thread(target=self._run, daemon=True)
        self._thread.start()

    def _run(self):
        while not self._stop.wait(1.0):
            self.samples.append(os.getloadavg()[0])

    def stop(self):
        """{"load": [least, most], "other": share of the cores used by other processes}"""
        self._stop.set()
        self._thread.join()
        self.samples.append(os.getloadavg()[0])
        wall = time.monotonic() - self._t0
        other = (_busy_seconds() - self._busy0) - (_own_seconds() - self._own0)
        return {"load": [round(min(self.samples), 2), round(max(self.samples), 2)],
                "other": round(max(0.0, other) / (wall * (os.cpu_count() or 1)), 3) if wall > 0 else 0.0}


def _busy_seconds():
    with open("/proc/stat") as f:
        v = [int(x) for x in f.readline().split()[1:]]
    return (v[0] + v[1] + v[2] + v[5] + v[6] + (v[7] if len(v) > 7 else 0)) / os.sysconf("SC_CLK_TCK")


def _own_seconds():
    import resource
    total = 0.0
    for who in (resource.RUSAGE_SELF, resource.RUSAGE_CHILDREN):
        u = resource.getrusage(who)
        total += u.ru_utime + u.ru_stime
    return total


def run(cmd, **kw):
    p = subprocess.run([str(c) for c in cmd], capture_output=True, text=True, **kw)
    if p.returncode != 0:
        raise SystemExit(f"failed ({p.returncode}): {' '.join(map(str, cmd))}\n{p.stderr}")
    return p.stdout


def timed_cpu(cmd, **kw):
    """(user + system seconds, stdout) of cmd, from the rusage of the waited child (microseconds)."""
    import resource
    t0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    out = run(cmd, **kw)
    t1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (t1.ru_utime - t0.ru_utime) + (t1.ru_stime - t0.ru_stime), out


def git_commit():
    try:
        c = run(["git", "-C", REPO, "rev-parse", "--short=12", "HEAD"]).strip()
        # the pages' own outputs (docs/results) do not count: the command rewrites them
        dirty = run(["git", "-C", REPO, "status", "--porcelain", "--untracked-files=no", "--", ".",
                     ":(exclude)docs/results"]).strip()
        return c + (" with uncommitted changes" if dirty else "")
    except SystemExit:
        return "unknown"


def regenerate(pages, build, jobs):
    t_all = time.monotonic()
    pride = build / "cli" / "pride"
    if not pride.exists():
        raise SystemExit(f"{pride} is not built: cmake -S . -B {build} -G Ninja && cmake --build {build} -j2")
    stores = build / "results"
    stores.mkdir(parents=True, exist_ok=True)
    DATA.mkdir(parents=True, exist_ok=True)
    IMG.mkdir(parents=True, exist_ok=True)
    sys.path.insert(0, str(REPO / "scripts"))
    metas, commit = {}, git_commit()
    for page in pages:
        t_page = time.monotonic()
        module = __import__(PAGES[page]["module"])
        meta = {"commit": commit, "jobs": jobs, "cores": os.cpu_count(), "campaigns": {}}
        for c in PAGES[page]["campaigns"]:
            store = stores / f"{c}.sqlite"
            for suffix in ("", "-wal", "-shm"):
                pathlib.Path(f"{store}{suffix}").unlink(missing_ok=True)
            watch, t0 = LoadWatch(), time.monotonic()
            run([pride, "bench", CAMPAIGNS / f"{c}.toml", "--jobs", jobs, "--out", store], cwd=REPO)
            seconds, load = time.monotonic() - t0, watch.stop()
            export_store(store, DATA / f"{c}.csv")
            runs = read_campaign(c)
            cross_check(run([pride, "report", store, "--format", "csv"]), runs, c)
            meta["campaigns"][c] = {"runs": len(runs), "seconds": round(seconds, 1), **load}
            print(f"{c}: {len(runs)} runs in {seconds:.1f} s (load average {load['load'][0]}-{load['load'][1]}, "
                  f"other processes {100 * load['other']:.0f} % of the cores)", flush=True)
        watch, t0 = LoadWatch(), time.monotonic()
        meta.update(module.extras(pride, stores, IMG))
        meta["extras_seconds"] = round(time.monotonic() - t0, 1)
        meta["extras_watch"] = watch.stop()
        meta["page_seconds"] = round(time.monotonic() - t_page, 1)
        metas[page] = meta
        (DATA / f"{page}-meta.json").write_text(json.dumps(meta, indent=1, sort_keys=True) + "\n")
    total = round(time.monotonic() - t_all, 1)
    for page, meta in metas.items():
        meta["command_seconds"] = total
        meta["command_pages"] = sorted(pages)
        (DATA / f"{page}-meta.json").write_text(json.dumps(meta, indent=1, sort_keys=True) + "\n")
        write_page(page)
        print(f"{PAGES[page]['page']}: written ({meta['page_seconds']} s)")
    print(f"all done in {total} s")


def main(argv):
    args = list(argv)
    mode = args.pop(0) if args and args[0] in ("render", "check") else "run"
    opts = {"--build": "build", "--jobs": "2", "--page": None}
    while args:
        k = args.pop(0)
        if k not in opts or not args:
            raise SystemExit(__doc__)
        opts[k] = args.pop(0)
    pages = [opts["--page"]] if opts["--page"] else list(PAGES)
    for p in pages:
        if p not in PAGES:
            raise SystemExit(f"--page: {p} is not one of {', '.join(PAGES)}")
    if mode == "render":
        for p in pages:
            write_page(p)
    elif mode == "check":
        bad = 0
        for p in pages:
            for name, exp, got in check(p):
                bad += 1
                print(f"{PAGES[p]['page']}: block {name} differs from its data "
                      f"({'missing on the page' if got is None else 'not made by the script' if exp is None else 'changed'})")
        if bad:
            print("regenerate with: /usr/bin/python3 scripts/results_pages.py render (or run it in full)")
            return 1
    else:
        build = pathlib.Path(opts["--build"])
        regenerate(pages, build if build.is_absolute() else REPO / build, int(opts["--jobs"]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))


def check_page(want, page):
    """The generated blocks of `page` (a path) that differ from `want` ({name: content}):
    [(name, wanted, found)]."""
    found = page_blocks(page.read_text())
    return [(n, want.get(n), found.get(n)) for n in sorted(set(found) | set(want)) if want.get(n) != found.get(n)]


def page_main(argv, doc, run_all, blocks, page):
    """The command line of a generated results page: `run` (run_all, then render), `render` (the
    page's blocks from the data) or `check` (exit 1 when a block differs from what the data give)."""
    if argv[1:] == ["run"]:
        run_all()
        page.write_text(replace_blocks(page.read_text(), blocks()))
    elif argv[1:] == ["render"]:
        page.write_text(replace_blocks(page.read_text(), blocks()))
    elif argv[1:] == ["check"]:
        diffs = check_page(blocks(), page)
        for name, _, _ in diffs:
            print(f"block {name} differs from what the data give", file=sys.stderr)
        return 1 if diffs else 0
    else:
        print(doc, file=sys.stderr)
        return 2
    return 0
