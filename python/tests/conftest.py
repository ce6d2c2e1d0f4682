"""Shared fixtures: the command line (results are compared with its JSON), the reference data."""
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


def reference_data():
    """The repository's reference-data/ (public data by others, shipped with pride)."""
    return pathlib.Path(os.environ.get("PRIDE_REFERENCE_DATA", str(REPO / "reference-data")))


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
    """A reference decision table's path and `pride roughset --json`'s answer on it (as roughset_as_cli)."""
    path = reference_data() / "roughset" / name
    return path, roughset_as_cli(cli("roughset", path, "--json"))


@pytest.fixture
def run_cli():
    return cli
