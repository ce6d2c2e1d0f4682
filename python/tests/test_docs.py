"""The examples of docs/python.md, run in order in a fresh folder, as a reader would."""
import os
import pathlib
import re

from conftest import REPO


def test_docs_python_examples(tmp_path, monkeypatch):
    text = (REPO / "docs" / "python.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, flags=re.S)
    assert len(blocks) >= 5
    monkeypatch.chdir(tmp_path)
    namespace = {}
    for i, block in enumerate(blocks):
        exec(compile(block, f"docs/python.md block {i + 1}", "exec"), namespace)
    assert pathlib.Path("plan.png").stat().st_size > 1000
    assert os.path.exists("demo.sqlite")
