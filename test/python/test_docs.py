"""docs/python.md runs: its Python blocks, in order, as one program (scripts/run_python_doc.py),
save the pictures the page shows."""

import os
import re
import sys

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import run_python_doc  # noqa: E402


def test_the_python_walkthrough_runs_and_saves_its_pictures(tmp_path, capsys):
    doc = os.path.join(ROOT, "docs", "python.md")
    assert run_python_doc.run(doc, tmp_path) >= 4
    with open(doc) as f:
        pictures = re.findall(r"\]\(images/(python-[\w-]+\.png)\)", f.read())
    assert len(pictures) == 3
    for name in pictures:
        assert (tmp_path / name).stat().st_size > 1000, name
    out = capsys.readouterr().out
    assert "caught:" in out  # the diff test caught the 30 K change
