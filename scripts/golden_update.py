#!/usr/bin/env python3
"""Re-records tests/data/golden/expected.jsonl from tests/data/golden/commands.txt with the pride
command given (default build/cli/pride), run from the top of the checkout, wall_ms removed as the
golden test removes it. Prints the line numbers that changed, so that the commit updating the golden
file can say which results changed and why. The commands on Moving AI maps name them
$PRIDE_DATA/movingai/...: without PRIDE_DATA their lines are kept as recorded, and one line says so.
Usage: scripts/golden_update.py [PRIDE]"""
import os
import pathlib
import re
import subprocess
import sys

top = pathlib.Path(__file__).resolve().parents[1]
pride = sys.argv[1] if len(sys.argv) > 1 else str(top / "build" / "cli" / "pride")
golden = top / "tests" / "data" / "golden"
commands = (golden / "commands.txt").read_text().splitlines()
old = (golden / "expected.jsonl").read_text().splitlines()
wall = re.compile(r'"wall_ms": [^,}]*(, )?')
new = []
data = os.environ.get("PRIDE_DATA")
kept = 0
for i, command in enumerate(commands):
    if "$PRIDE_DATA/" in command:
        if not data:
            new.append(old[i])
            kept += 1
            continue
        command = command.replace("$PRIDE_DATA", data)
    p = subprocess.run([pride, *command.split()], cwd=top, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"line {i + 1}: pride {command}: exit {p.returncode}: {p.stderr.strip()}")
    new.append(wall.sub("", p.stdout).rstrip("\r\n"))
    if i >= len(old) or old[i] != new[-1]:
        print(f"line {i + 1}: {command}")
(golden / "expected.jsonl").write_text("".join(line + "\n" for line in new))
if kept:
    print(f"skipped: {kept} commands need $PRIDE_DATA/movingai (Moving AI maps), not set; their lines kept")
