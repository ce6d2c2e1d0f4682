#!/usr/bin/python3
"""Plots of a campaign store written by `pride bench` (called by `pride report --plots DIR`).

For every problem: the convergence of each algorithm (median and interquartile band over the
seeds of the best value after each iteration, against evaluations when every curve of the figure
records them, else against iterations), boxplots of the final values, and for grid problems the
best path of each algorithm on the map; for problems of several objectives (runs that store a
front), the boxplots of the hypervolume gaps, each algorithm's 25 %, 50 % and 75 % empirical
attainment surfaces (two objectives; the k-th surface of n runs for k = ceil(q n), as
framework/pareto/attainment.hpp) and the front of its median run (by hypervolume ratio), without
the reference front (pride report --html draws it). Where the problem's optimum f_opt is known (continuous
problems), values are precisions f - f_opt on a log axis (precisions below 1e-12, 0 included, are
drawn at 1e-12, and the axis says so), unless --raw. Whole-map planners (A*, exact: no history)
appear in the convergence figure as a horizontal line at their value, as do sampling planners (OMPL's,
labelled by their final value). Each figure is written as
PNG and SVG, named after the problem: pride passes each problem's file name (--names, a JSON
object of id -> name from experiment/storage/file_name.hpp's unique_file_names, so that "x/y" and "x_y"
get files of their own); without it, safe(id). --maps: a JSON object of id -> a file of the grid
problem's map as pride read it (one line of 0 and 1 per row), so that the script reads no map format
itself; a grid problem without one gets no path figure. A polyline planner's path is its polyline
(runs.polyline), drawn through the cell centres as the chains are. --uri: the SQLite URI to read
STORE with (pride's experiment/storage/reader.hpp read_only_uri).

Usage: plot_campaign.py STORE DIR [--raw] [--names NAMES.json] [--maps MAPS.json] [--uri URI]
"""
import json
import os
import sqlite3
import sys
import warnings

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_map(path):
    """The 0/1 matrix pride wrote for a grid problem's map (cli/report.cpp, as pride read the map:
    any format it reads, with the campaign's unknown cells and inflation), as a boolean array
    (True = blocked)."""
    with open(path, encoding="utf-8") as f:
        return np.array([[c == "1" for c in line.rstrip("\n")] for line in f if line.strip()])


def safe(name):
    """An id as a file name, as experiment/campaign.hpp's file_name(): per character, and a leading '.'."""
    keep = set(b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789.-")
    s = "".join(chr(b) if b in keep else "_" for b in (name or "_").encode())  # per byte, as C++
    return "_" + s[1:] if s.startswith(".") else s


class Damaged(Exception):
    """A store whose values are not what pride bench writes."""


class CannotWrite(Exception):
    """A figure that cannot be written: its file and the system's reason."""


def save(fig, folder, stem):
    for ext in ("png", "svg"):
        path = os.path.join(folder, f"{stem}.{ext}")
        try:
            fig.savefig(path, dpi=120, bbox_inches="tight")
        except OSError as e:
            raise CannotWrite(f"{path}: cannot write: {e.strerror or e}") from e
    plt.close(fig)


def is_number(v):
    return v is None or (isinstance(v, (int, float)) and not isinstance(v, bool))


def valid_numbers(v):
    return isinstance(v, list) and all(is_number(x) for x in v)


def valid_front(v):
    """A multi-objective run's solution: its objectives' names, hypervolume ratio and front."""
    names, front = v.get("objectives"), v.get("front")
    if not (isinstance(names, list) and len(names) >= 2 and all(isinstance(n, str) for n in names)):
        return False
    if not (is_number(v.get("hypervolume_ratio")) and v.get("hypervolume_ratio") is not None):
        return False
    return isinstance(front, list) and all(
        isinstance(p, dict) and valid_numbers(p.get("f")) and len(p["f"]) == len(names) and None not in p["f"]
        for p in front)


def valid_solution(v):
    """A point (a list of numbers), a path (a list of [x, y] cells) or a front (valid_front)."""
    if isinstance(v, dict):
        return valid_front(v)
    if not isinstance(v, list):
        return False
    return all(is_number(x) for x in v) or all(
        isinstance(c, list) and len(c) == 2 and all(isinstance(x, int) for x in c) for c in v)


def attainment_surface(sets, k):
    """The corners of the k-th attainment surface of two-objective sets (lists of (f1, f2)), in
    increasing f1: at each f1, the k-th smallest of the runs' best f2 so far (attainment.hpp)."""
    points = sorted((p[0], p[1], i) for i, s in enumerate(sets) for p in s)
    best, corners, last, at = [np.inf] * len(sets), [], np.inf, 0
    while at < len(points):
        x = points[at][0]
        while at < len(points) and points[at][0] == x:
            best[points[at][2]] = min(best[points[at][2]], points[at][1])
            at += 1
        y = sorted(best)[k - 1]
        if y < last:
            corners.append((x, y))
            last = y
    return corners


def plot_fronts(problem, algorithms, folder, stem):
    """Attainment surfaces (two objectives) and each algorithm's median front, from the runs' fronts."""
    names = next(iter(algorithms.values()))[0][2]["objectives"]
    styles = {0.25: ":", 0.5: "-", 0.75: "--"}
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    if len(names) == 2:
        fig, ax = plt.subplots(figsize=(6.4, 4.2))
        surfaces = {}
        for algorithm, rs in sorted(algorithms.items()):
            sets = [[p["f"] for p in r[2]["front"]] for r in rs]
            for q in styles:
                k = max(1, int(np.ceil(q * len(sets))))
                surfaces[algorithm, q, k] = attainment_surface(sets, k)
        corners = [c for s in surfaces.values() for c in s]
        right = max((c[0] for c in corners), default=0.0)
        top = max((c[1] for c in corners), default=0.0)
        for index, algorithm in enumerate(sorted(algorithms)):
            for (a, q, k), s in surfaces.items():
                if a != algorithm or not s:
                    continue
                # The staircase from above its first corner out to the right of its last.
                x = [s[0][0]] + [c[0] for c in s] + [right]
                y = [top] + [c[1] for c in s] + [s[-1][1]]
                ax.step(x, y, where="post", linestyle=styles[q], color=colours[index % len(colours)],
                        label=f"{algorithm}: {100 * q:g} % (k = {k} of {len(algorithms[algorithm])})")
        ax.set_xlabel(names[0])
        ax.set_ylabel(names[1])
        ax.set_title(f"{problem}: empirical attainment surfaces (k = ceil(q n))", fontsize="medium")
        ax.legend(fontsize="small")
        save(fig, folder, f"{stem}-attainment")
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    markers = ["D", "s", "x", "o"]
    for index, (algorithm, rs) in enumerate(sorted(algorithms.items())):
        # The median run by hypervolume ratio: best first, ties by seed; of two middle ones the better.
        ranked = sorted(rs, key=lambda r: (-r[2]["hypervolume_ratio"], r[0]))
        median = ranked[(len(ranked) - 1) // 2]
        f = np.array([p["f"] for p in median[2]["front"]], dtype=float).reshape(-1, len(names))
        ax.plot(f[:, 0], f[:, 1], markers[index % len(markers)], color=colours[index % len(colours)],
                label=f"{algorithm} (seed {median[0]}, HV ratio {median[2]['hypervolume_ratio']:.4g})")
    ax.set_xlabel(names[0])
    ax.set_ylabel(names[1])
    projection = f"; objectives 1 and 2 of {len(names)}" if len(names) > 2 else ""
    ax.set_title(f"{problem}: fronts of the median runs{projection}", fontsize="medium")
    ax.legend(fontsize="small")
    save(fig, folder, f"{stem}-fronts")


def main():
    store, folder, options = (sys.argv[1], sys.argv[2], sys.argv[3:]) if len(sys.argv) >= 3 else ("", "", ["?"])
    raw, file_names, map_files, uri = False, {}, {}, None
    while options:
        option = options.pop(0)
        if option == "--raw":
            raw = True
        elif option == "--names" and options:
            with open(options.pop(0), encoding="utf-8") as f:
                file_names = json.load(f)
        elif option == "--maps" and options:
            with open(options.pop(0), encoding="utf-8") as f:
                map_files = json.load(f)
        elif option == "--uri" and options:
            uri = options.pop(0)
        else:
            sys.exit("usage: plot_campaign.py STORE DIR [--raw] [--names NAMES.json] [--maps MAPS.json] [--uri URI]")
    # pride passes the URI it read the store with (read-only, or immutable on a read-only folder).
    db = sqlite3.connect(uri or f"file:{store}?mode=ro", uri=True)
    columns = {row[1] for row in db.execute("PRAGMA table_info(problems)")}
    f_opt_column = "f_opt" if "f_opt" in columns else "NULL"
    problems = {row[0]: row[1:] for row in db.execute(f"SELECT id, type, map, start, goal, {f_opt_column} FROM problems")}
    # The planners that evaluate no objective (algorithms.evaluates = 0): "whole map" in the legends,
    # as the report's notes name them; another run without a history is its final value.
    whole_map = set()
    if db.execute("SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = 'algorithms'").fetchone():
        whole_map = {row[0] for row in db.execute("SELECT id FROM algorithms WHERE evaluates = 0")}
    # runs.polyline: a polyline planner's path (store schema 5), NULL for chains and older stores.
    polyline_column = "polyline" if "polyline" in {row[1] for row in db.execute("PRAGMA table_info(runs)")} else "NULL"
    runs = db.execute(
        f"SELECT problem, algorithm, seed, best, solution, history, history_evaluations, {polyline_column} FROM runs "
        "ORDER BY problem, algorithm, seed").fetchall()
    by_problem = {}
    for problem, algorithm, seed, best, solution, history, history_evaluations, polyline in runs:
        row = f"runs row (problem '{problem}', algorithm '{algorithm}', seed {seed})"
        parsed = []
        for column, text, check in (("solution", solution, valid_solution), ("history", history, valid_numbers),
                                    ("history_evaluations", history_evaluations, valid_numbers)):
            try:
                value = json.loads(text)
            except (TypeError, ValueError):
                value = None
            if not check(value):
                raise Damaged(f"{store}: damaged store: {row}, column {column}: not what pride bench writes")
            parsed.append(value)
        if best is not None and not isinstance(best, (int, float)):
            raise Damaged(f"{store}: damaged store: {row}, column best: not a number")
        vertices = None
        if polyline is not None:
            try:
                vertices = json.loads(polyline)
            except (TypeError, ValueError):
                vertices = None
            if not (isinstance(vertices, list) and all(isinstance(v, list) and len(v) == 2 and all(
                    is_number(c) for c in v) for v in vertices)):
                raise Damaged(f"{store}: damaged store: {row}, column polyline: not what pride bench writes")
        by_problem.setdefault(problem, {}).setdefault(algorithm, []).append((seed, best, *parsed, vertices))
    floor = 1e-12
    for problem, algorithms in by_problem.items():
        stem = file_names.get(problem) or safe(problem)
        info = problems.get(problem)
        f_opt = info[4] if info and isinstance(info[4], (int, float)) and np.isfinite(info[4]) else None
        precision = f_opt is not None and not raw

        # Several objectives: every run stores a front (its value is the hypervolume gap).
        if all(isinstance(r[2], dict) for rs in algorithms.values() for r in rs):
            names = {tuple(r[2]["objectives"]) for rs in algorithms.values() for r in rs}
            if len(names) > 1:
                raise Damaged(f"{store}: damaged store: problem '{problem}': its runs' fronts have different "
                              f"objectives ({'; '.join(', '.join(n) for n in sorted(names))})")
            fig, ax = plt.subplots(figsize=(6.4, 4.2))
            labels = sorted(algorithms)
            ax.boxplot([[r[1] for r in algorithms[a] if r[1] is not None] or [np.nan] for a in labels],
                       labels=labels)
            ax.set_ylabel("final hypervolume gap 1 - HV / HV_ref")
            ax.set_title(problem)
            save(fig, folder, f"{stem}-final")
            plot_fronts(problem, algorithms, folder, stem)
            continue

        def shown(v):
            """A value as drawn: its precision (floored for the log axis) where f_opt is known."""
            if v is None:
                return np.inf
            return max(v - f_opt, floor) if precision else v

        # Convergence: median and interquartile band of the best value after each iteration; x in
        # evaluations only when every curve records them (else iterations for all, never mixed).
        fig, ax = plt.subplots(figsize=(6.4, 4.2))
        positive, smallest, largest, floored = True, np.inf, 0.0, False
        # Line styles cycle as well as colours, so that algorithms with equal curves stay visible.
        styles = ["-", "--", ":", "-."]
        curves = {a: rs for a, rs in algorithms.items() if all(r[3] for r in rs)}
        by_evaluations = bool(curves) and all(all(r[4] for r in rs) for rs in curves.values())
        for index, (algorithm, rs) in enumerate(sorted(algorithms.items())):
            style = styles[index % len(styles)]
            if algorithm not in curves:  # a whole-map planner: its value, as a line
                finals = [shown(r[1]) for r in rs]
                if finals and np.all(np.isfinite(finals)):
                    value = float(np.median(finals))
                    floored = floored or (precision and value <= floor)
                    ax.axhline(value, linestyle=style, color="grey", linewidth=1.2, label=f"{algorithm} ({'whole map' if algorithm in whole_map else 'final value, no history'})")
                    positive = positive and value > 0
                    smallest, largest = min(smallest, value), max(largest, value)
                continue
            length = min(len(r[3]) for r in rs)
            values = np.array([[shown(v) for v in r[3][:length]] for r in rs], dtype=float)
            x = np.array(rs[0][4][:length], dtype=float) if by_evaluations else np.arange(length)
            median = np.median(values, axis=0)
            low, high = np.percentile(values, 25, axis=0), np.percentile(values, 75, axis=0)
            finite = values[np.isfinite(values)]
            positive = positive and bool(np.all(finite > 0))
            floored = floored or (precision and bool(np.any(finite <= floor)))
            if finite.size:
                smallest, largest = min(smallest, finite.min()), max(largest, finite.max())
            ax.plot(x, median, label=algorithm, linestyle=style, linewidth=1.8)
            ax.fill_between(x, low, high, alpha=0.25)
        ax.set_xlabel("evaluations" if by_evaluations else "iteration")
        what = "precision f - f_opt" if precision else "best value"
        ax.set_ylabel(f"{what} (median, IQR band)")
        # Precisions always on a log axis; raw values where they are positive and span decades.
        if precision or (positive and largest > 10 * smallest):
            ax.set_yscale("log")
        ax.set_title(problem + (f" (precisions <= {floor:g} drawn at {floor:g})" if floored else ""),
                     fontsize="medium")
        ax.legend()
        save(fig, folder, f"{stem}-convergence")
        # Final values.
        fig, ax = plt.subplots(figsize=(6.4, 4.2))
        names = sorted(algorithms)
        finals = [[shown(r[1]) for r in algorithms[a] if r[1] is not None] or [np.nan] for a in names]
        ax.boxplot(finals, labels=names)
        ax.set_ylabel(f"final {what}")
        if precision:
            ax.set_yscale("log")
        ax.set_title(problem)
        save(fig, folder, f"{stem}-final")
        # Grid problems: each algorithm's best path on the map.
        if info and info[0] == "grid" and problem in map_files:
            blocked = read_map(map_files[problem])
            fig, ax = plt.subplots(figsize=(6.4, 6.4 * blocked.shape[0] / blocked.shape[1]))
            ax.imshow(blocked, cmap="Greys", vmin=0, vmax=1.4, origin="upper",
                      extent=(-0.5, blocked.shape[1] - 0.5, blocked.shape[0] - 0.5, -0.5))
            for index, algorithm in enumerate(names):
                feasible = [r for r in algorithms[algorithm] if r[1] is not None and (r[2] or r[5])]
                if not feasible:
                    continue
                best = min(feasible, key=lambda r: (r[1], r[0]))
                path = np.array(best[5] or best[2], dtype=float)
                ax.plot(path[:, 0], path[:, 1], linewidth=2, linestyle=styles[index % len(styles)],
                        label=f"{algorithm} ({best[1]:.4g}, seed {best[0]})")
            sx, sy = map(int, info[2].split(","))
            gx, gy = map(int, info[3].split(","))
            ax.plot([sx], [sy], "o", color="green", markersize=8)
            ax.plot([gx], [gy], "o", color="red", markersize=8)
            ax.set_title(f"{problem}: best path of each algorithm")
            ax.legend(fontsize="small", loc="best")
            save(fig, folder, f"{stem}-paths")


if __name__ == "__main__":
    # One clear line on failure, never a traceback; library warnings are not for the user.
    warnings.simplefilter("ignore")
    try:
        main()
    except (Damaged, CannotWrite) as e:
        print(e, file=sys.stderr)
        sys.exit(2)
    except Exception as e:  # noqa: BLE001
        print(f"plot_campaign.py: {type(e).__name__}: {e}".splitlines()[0], file=sys.stderr)
        sys.exit(1)
