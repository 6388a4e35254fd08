#!/usr/bin/env python3
"""Runs the ```python blocks of a Markdown page in order, as one program, in OUTDIR (the working
folder while they run: the pictures they save land there). Used by scripts/python-docs.sh (which
copies the pictures into docs/images) and by test/python/test_docs.py.
    run_python_doc.py DOC.md OUTDIR"""
import os
import re
import sys


def python_blocks(markdown):
    return re.findall(r"^```python\n(.*?)^```", markdown, flags=re.S | re.M)


def run(doc, outdir):
    with open(doc) as f:
        blocks = python_blocks(f.read())
    if not blocks:
        raise SystemExit(f"{doc}: no python blocks")
    program = "\n".join(blocks)
    cwd = os.getcwd()
    os.makedirs(outdir, exist_ok=True)
    os.chdir(outdir)
    try:
        exec(compile(program, doc, "exec"), {"__name__": "__main__"})
    finally:
        os.chdir(cwd)
    return len(blocks)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    print(f"{sys.argv[1]}: ran {run(sys.argv[1], sys.argv[2])} python blocks")
