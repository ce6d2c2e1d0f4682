"""tests/data/cmawm/optuna_bbob_mixint.tsv, the runtimes of Optuna's CMA-ES with margin (Hamano et al.
2022) on bbob-mixint, is what scripts/margin_reference.py gives: the script's replay on cmaes.CMAwM
evaluates the very points Optuna's sampler does, a row of the table comes out again when its run is
repeated, and the table is consistent. The comparisons with Optuna need Debian's python3-optuna and
python3-cmaes (skipped without them)."""
import math
import os
import pathlib
import subprocess
import sys

import pytest

REPO = pathlib.Path(os.environ.get("PRIDE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
sys.path.insert(0, str(REPO / "scripts"))

import margin_reference as mr  # noqa: E402

TABLE = REPO / "tests" / "data" / "cmawm" / "optuna_bbob_mixint.tsv"


def read_table():
    lines = TABLE.read_text().splitlines()
    comments = [line for line in lines if line.startswith("#")]
    rows = [line.split("\t") for line in lines if not line.startswith("#")]
    return comments, [dict(zip(rows[0], r)) for r in rows[1:]]


def budget_per_dim(comments):
    for line in comments:
        if "budget " in line:
            return int(line.split("budget ")[1].split()[0])
    raise AssertionError("no budget in the table's header")


def test_the_replay_evaluates_the_points_optunas_sampler_evaluates():
    pytest.importorskip("optuna")
    pytest.importorskip("cmaes")
    import warnings

    warnings.filterwarnings("ignore", message=".*with_margin.*")
    # 120 evaluations are 11 generations of lambda = 10 (D = 10) and 9 of lambda = 12 (D = 20, with
    # 16 integers): past the third, where asking one live optimizer would already differ
    for function, dim, seed in ((1, 10, 4), (15, 20, 2)):
        a = mr.optuna_run(mr.Run(function, dim, seed, 120), seed, keep=True)
        b = mr.direct_run(mr.Run(function, dim, seed, 120), seed, keep=True)
        assert len(a.points) == len(b.points) == 120
        assert a.points == b.points


def test_a_row_of_the_table_comes_out_again():
    cmaes = pytest.importorskip("cmaes")
    comments, rows = read_table()
    if f"cmaes {cmaes.__version__} " not in comments[0]:
        pytest.skip(f"the table was made with another cmaes than {cmaes.__version__}")
    row = next(r for r in rows if r["function"] == "f2" and r["dim"] == "10" and r["seed"] == "3")
    run = mr.direct_run(mr.Run(2, 10, 3, budget_per_dim(comments) * 10), 3)
    assert [("" if h is None else str(h)) for h in run.hits] == [row[c] for c in row if c.startswith("evals_1e")]
    assert (f"{run.best:.6e}", str(run.evals), run.end) == (row["final_best"], row["evals_used"], row["end"])


def test_the_table_is_complete_and_consistent():
    comments, rows = read_table()
    assert any("Optuna" in line and "CMAwM" in line for line in comments)
    budget = budget_per_dim(comments)
    keys = sorted((r["function"], int(r["dim"]), int(r["instance"])) for r in rows)
    assert keys == sorted((f"f{f}", d, s) for f in (1, 2, 10, 15) for d in (10, 20) for s in range(1, 16))
    for r in rows:
        assert r["seed"] == r["instance"]
        used = int(r["evals_used"])
        hits = [int(r[c]) if r[c] else math.inf for c in r if c.startswith("evals_1e")]
        assert hits == sorted(hits)  # a smaller target is never reached first
        assert all(h <= used for h in hits if h != math.inf)
        assert r["end"] in ("target", "budget", "diverged")
        if r["end"] == "target":
            assert hits[-1] == used and float(r["final_best"]) <= 1e-8
        elif r["end"] == "budget":
            assert used == budget * int(r["dim"]) and float(r["final_best"]) > 1e-8


def test_bad_options_exit_with_status_2():
    p = subprocess.run([sys.executable, str(REPO / "scripts" / "margin_reference.py"), "--dims", "ten"],
                       capture_output=True, text=True)
    assert p.returncode == 2
    assert "--functions and --dims take comma-separated integers" in p.stderr
