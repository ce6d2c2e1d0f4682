"""Shared fixtures: the command line (results are compared with its JSON) and the public data of
others found through PRIDE_DATA."""
import json
import os
import pathlib
import subprocess

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]


def pride_exe():
    exe = os.environ.get("PRIDE_EXE", str(REPO / "build" / "cli" / "pride"))
    if not os.path.exists(exe):
        pytest.skip(f"the pride command is not built ({exe})")
    return exe


def shared_data(relative, what):
    """$PRIDE_DATA/relative: a file or folder of the public data written by others that the
    repository does not hold (Moving AI maps, nav2's ROS maps, jMetal's fronts, Pawlak's tables). Without
    PRIDE_DATA, or without that file under it, the test is skipped with the one line saying why."""
    root = os.environ.get("PRIDE_DATA")
    if not root:
        pytest.skip(f"needs $PRIDE_DATA/{relative} ({what}), not set")
    path = pathlib.Path(root) / relative
    if not path.exists():
        pytest.skip(f"needs $PRIDE_DATA/{relative} ({what}), not found under {root}")
    return path


def cli(*args, check=True):
    """Runs `pride ARGS`; returns the parsed JSON (with --json) or the completed process."""
    p = subprocess.run([pride_exe(), *map(str, args)], capture_output=True, text=True)
    if not check:
        return p
    assert p.returncode == 0, p.stderr
    return json.loads(p.stdout) if "--json" in args else p


ROUGHSET_TABLES = ["pawlak1991_p72.csv", "pawlak_8obj.csv"]  # the reference decision tables


def roughset_as_cli(result):
    """A roughset result with the keys `pride roughset --json` has (no table, no rule objects)."""
    out = dict(result)
    out.pop("table", None)
    if out.get("rules"):
        out["rules"] = [{k: v for k, v in r.items() if k != "objects"} for r in out["rules"]]
    return out


def reference_roughset(name):
    """A reference decision table's path ($PRIDE_DATA/roughset) and `pride roughset --json`'s answer
    on it (as roughset_as_cli)."""
    path = shared_data("roughset/" + name, "Pawlak's decision tables")
    return path, roughset_as_cli(cli("roughset", path, "--json"))


@pytest.fixture
def run_cli():
    return cli
