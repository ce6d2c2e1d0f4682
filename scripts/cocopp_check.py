#!/usr/bin/python3
"""cocopp, run from its source, on what `pride export STORE --coco DIR` wrote, against pride's ERTs.

    /usr/bin/python3 scripts/cocopp_check.py COCOPP_SRC COCO_DIR ERT_CSV

COCOPP_SRC is the cocopp package of a numbbo/coco-postprocess checkout (its src/cocopp), COCO_DIR
the export (one folder per algorithm), ERT_CSV what `pride report STORE --format ert-csv` printed.
For every (function, dimension, algorithm, precision) of the CSV, cocopp's DataSet.detERT at that
precision must equal pride's ERT exactly (both are Price's ERT over the same runs), and cocopp must
read every run with its evaluations. Prints what it compared and exits 1 at the first difference.

cocopp from source on Debian 12's python3-numpy, -scipy and -matplotlib needs two stand-ins, made
in a temporary copy (the checkout is not touched): `cocopp/_version.py`, which its packaging would
write, and a `platformdirs` module, whose Debian version (2.6) lacks user_cache_dir(...,
ensure_exists=...). cocopp warns once that it cannot reach its online archive.
"""
import atexit
import csv
import math
import os
import shutil
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


def main():
    if len(sys.argv) != 4:
        sys.exit("usage: cocopp_check.py COCOPP_SRC COCO_DIR ERT_CSV")
    source, coco_dir, ert_csv = sys.argv[1:]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the archive, and "less than 15 instances"
        pproc = import_cocopp(source).pproc
        datasets = {}
        for algorithm in sorted(os.listdir(coco_dir)):
            for ds in pproc.DataSetList(os.path.join(coco_dir, algorithm)):
                datasets[(algorithm, int(ds.funcId), int(ds.dim))] = ds
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
