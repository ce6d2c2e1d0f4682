#!/usr/bin/python3
"""cocopp, run from its source, on what `pride export STORE --coco DIR` wrote.

    /usr/bin/python3 scripts/cocopp_check.py COCOPP_SRC COCO_DIR ERT_CSV
    /usr/bin/python3 scripts/cocopp_check.py COCOPP_SRC COCO_DIR --store STORE

COCOPP_SRC is the cocopp package of a numbbo/coco-postprocess checkout (its src/cocopp), COCO_DIR
the export (one folder per algorithm).

With ERT_CSV, what `pride report STORE --format ert-csv` printed (bbob campaigns): for every
(function, dimension, algorithm, precision) of the CSV, cocopp's DataSet.detERT at that precision
must equal pride's ERT exactly (both are Price's ERT over the same runs), and cocopp must read
every run with its evaluations.

With --store, the campaign store itself (bbob, bbob-mixint or bbob-constrained runs), read with sqlite3: cocopp
must read each data set as the suite's (bbob-constrained: constraints counted), with one run per
stored run in the store's order (instance, then seed): its instance, its evaluations (f
evaluations, plus as many constraint evaluations on bbob-constrained, as cocopp sums them), and at
each of cocopp's target rows the evaluations at which the run's stored COCO trace first came
within the target. Prints what it compared and exits 1 at the first difference.

cocopp from source on Debian 12's python3-numpy, -scipy and -matplotlib needs two stand-ins, made
in a temporary copy (the checkout is not touched): `cocopp/_version.py`, which its packaging would
write, and a `platformdirs` module, whose Debian version (2.6) lacks user_cache_dir(...,
ensure_exists=...). cocopp warns once that it cannot reach its online archive.
"""
import atexit
import csv
import json
import math
import os
import shutil
import sqlite3
import sys
import tempfile
import types
import warnings


def import_cocopp(source):
    """cocopp imported from the package folder `source` (its src/cocopp), through the stand-ins."""
    work = tempfile.mkdtemp(prefix="pride-cocopp-")
    atexit.register(shutil.rmtree, work, True)  # the copy goes when the script ends
    shutil.copytree(source, os.path.join(work, "cocopp"))
    with open(os.path.join(work, "cocopp", "_version.py"), "w") as f:
        f.write('__version__ = "0+source"\n')
    stand_in = types.ModuleType("platformdirs")
    stand_in.user_cache_dir = lambda *args, **kwargs: os.path.join(work, "cache")
    sys.modules["platformdirs"] = stand_in
    sys.path.insert(0, work)
    os.environ.setdefault("MPLBACKEND", "Agg")
    import cocopp
    return cocopp


def read_datasets(source, coco_dir):
    """cocopp's DataSets of the export by (algorithm folder, function, dimension), and cocopp."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the archive, and "less than 15 instances"
        cocopp = import_cocopp(source)
        datasets = {}
        for algorithm in sorted(os.listdir(coco_dir)):
            for ds in cocopp.pproc.DataSetList(os.path.join(coco_dir, algorithm)):
                datasets[(algorithm, int(ds.funcId), int(ds.dim))] = ds
    return cocopp, datasets


def stored_runs(store):
    """The store's runs on COCO's suites, by (algorithm, function, dimension), each list in the
    export's order: (instance, seed, evaluations, f_opt, trace_targets as (evaluations, value)),
    and the suite."""
    db = sqlite3.connect(f"file:{store}?mode=ro", uri=True)
    rows = db.execute(
        "SELECT r.algorithm, p.fid, p.dim, p.instance, r.seed, r.evaluations, p.f_opt, r.trace_targets, p.suite "
        "FROM runs r JOIN problems p ON p.id = r.problem WHERE p.suite IN ('bbob', 'bbob-mixint', 'bbob-constrained') "
        "ORDER BY r.algorithm, p.fid, p.dim, p.instance, r.seed").fetchall()
    db.close()
    runs, suites = {}, set()
    for algorithm, fid, dim, instance, seed, evaluations, f_opt, trace, suite in rows:
        flat = json.loads(trace)
        points = [(flat[k], math.inf if flat[k + 1] is None else flat[k + 1]) for k in range(0, len(flat), 2)]
        runs.setdefault((algorithm, fid, dim), []).append((instance, seed, evaluations, f_opt, points))
        suites.add(suite)
    if len(suites) != 1:
        sys.exit(f"{store}: runs of {len(suites)} COCO suites")
    return runs, suites.pop()


def check_store(source, coco_dir, store):
    cocopp, datasets = read_datasets(source, coco_dir)
    runs, suite = stored_runs(store)
    constrained = suite == "bbob-constrained"
    counted = 2 if constrained else 1  # cocopp's evaluations: f evaluations + constraint evaluations
    compared = 0
    for key, want in sorted(runs.items()):
        ds = datasets.get(key)
        if ds is None:
            sys.exit(f"cocopp read no data of {key}")
        if ds.suite_name != suite or bool(cocopp.testbedsettings.current_testbed.has_constraints) != constrained:
            sys.exit(f"{key}: cocopp read suite {ds.suite_name!r}, the store's is {suite!r}")
        instances = [run[0] for run in want]
        if list(ds.instancenumbers) != instances:
            sys.exit(f"{key}: cocopp read instances {list(ds.instancenumbers)}, the store's runs {instances}")
        # The .info's entries give f evaluations; the .tdat's last lines f + g evaluations.
        evaluations = [run[2] for run in want]
        if [int(m) for m in ds.readmaxevals] != evaluations:
            sys.exit(f"{key}: cocopp read evaluations {list(ds.readmaxevals)} in the .info, the store's runs "
                     f"{evaluations}")
        maxevals = [counted * e for e in evaluations]
        if [int(m) for m in ds.maxfgevals[:len(want)]] != maxevals:
            sys.exit(f"{key}: cocopp read evaluations {list(ds.maxfgevals)}, the store's runs {maxevals}")
        # cocopp aligns each count column on its targets apart: the f evaluations (and on
        # bbob-constrained the constraint evaluations, equal here) at which each run first came
        # within each target. (Its sum of the two, DataSet.evals, adds to a target's f evaluations
        # the constraint evaluations of the row it finds with a tolerance of 1e-14, which is below
        # the rounding of targets above 64: there it takes the next easier target's row, and the
        # first row takes the last's. And its constraint column, read again by a rewound reader,
        # gives a target the run never reached the run's last count rather than nan; the sum is
        # nan there all the same. That is cocopp's reading of COCO's own files too.)
        columns = [("f", ds.evals_function), ("g", ds.evals_constraints)] if constrained else [("f", ds.evals)]
        if constrained:  # and their sum, where cocopp's tolerance holds
            columns.append(("f + g", [row for row in ds.evals if row[0] <= 32]))
        for name, rows in columns:
            for row in rows:
                target = row[0]
                for j, (instance, seed, evaluations, f_opt, points) in enumerate(want):
                    first = next((e for e, value in points if value - f_opt <= target), None)
                    theirs = row[1 + j]
                    ours = math.nan if first is None else first * (2 if name == "f + g" else 1)
                    if first is None and name == "g" and theirs == evaluations:
                        ours = theirs
                    if not (theirs == ours or (math.isnan(theirs) and math.isnan(ours))):
                        sys.exit(f"{key}, instance {instance}, seed {seed}, target {target!r}: cocopp read {theirs!r} "
                                 f"{name} evaluations, the stored trace gives {ours!r}")
                    compared += 1
    print(f"cocopp read {len(datasets)} {suite} data sets; {sum(len(v) for v in runs.values())} runs and "
          f"{compared} (run, target) evaluations equal to the store's")


def main():
    if len(sys.argv) == 5 and sys.argv[3] == "--store":
        check_store(sys.argv[1], sys.argv[2], sys.argv[4])
        return
    if len(sys.argv) != 4:
        sys.exit("usage: cocopp_check.py COCOPP_SRC COCO_DIR ERT_CSV | --store STORE")
    source, coco_dir, ert_csv = sys.argv[1:]
    _, datasets = read_datasets(source, coco_dir)
    compared = 0
    with open(ert_csv, newline="") as f:
        for row in csv.DictReader(f):
            if not row["function"].startswith("bbob-f"):
                continue
            key = (row["algorithm"], int(row["function"][len("bbob-f"):]), int(row["dim"]))
            ds = datasets.get(key)
            if ds is None:
                sys.exit(f"cocopp read no data of {key}")
            if len(ds.maxevals) != int(row["runs"]):
                sys.exit(f"{key}: cocopp read {len(ds.maxevals)} runs, pride reports {row['runs']}")
            precision = float(row["precision"])
            # cocopp's rows are at numpy.power(10, i / 5), which may differ from pride's
            # std::pow(10, x) in the last bit (10^1.8: ...336 against ...33): ask for the row of
            # this very target, not the next one down.
            theirs = float(ds.detERT([precision * (1 + 1e-12)])[0])
            ours = float(row["ert"])
            if not (theirs == ours or (math.isinf(theirs) and math.isinf(ours))):
                sys.exit(f"{key} at precision {precision}: cocopp's ERT {theirs!r}, pride's {ours!r}")
            compared += 1
    if compared == 0:
        sys.exit("no bbob ERT in " + ert_csv)
    print(f"cocopp read {len(datasets)} data sets; {compared} ERTs equal to pride's")


if __name__ == "__main__":
    main()
