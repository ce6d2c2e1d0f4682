"""Shared fixtures: the command line (results are compared with its JSON), the shared data."""
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


def shared_data():
    return pathlib.Path(os.environ.get("PRIDE_SHARED_DATA", str(REPO.parent / "shared" / "data")))


def cli(*args, check=True):
    """Runs `pride ARGS`; returns the parsed JSON (with --json) or the completed process."""
    p = subprocess.run([pride_exe(), *map(str, args)], capture_output=True, text=True)
    if not check:
        return p
    assert p.returncode == 0, p.stderr
    return json.loads(p.stdout) if "--json" in args else p


@pytest.fixture
def run_cli():
    return cli
