"""The Python blocks of doc/python.md run: those shown as files are the
files of the tree (the doc recipe test checks and runs them); the others
run here, with numpy as np and creepwork imported, and the `>>>` blocks as
doctests, so the page cannot show code that does not work."""

import doctest
import os
import re

import numpy as np

import creepwork


def blocks(source_dir):
    with open(os.path.join(source_dir, "doc", "python.md")) as f:
        text = f.read()
    found = re.findall(r"(<!-- file: [^>]* -->\n)?```python\n(.*?)```", text, re.S)
    assert len(found) >= 5
    return [code for marker, code in found if not marker]


def test_code_blocks_run(source_dir, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    ran = 0
    for code in blocks(source_dir):
        if code.startswith(">>>"):
            continue
        exec(compile(code, "doc/python.md", "exec"), {"np": np, "creepwork": creepwork})
        ran += 1
    assert ran >= 2


def test_doctest_blocks_hold(source_dir):
    parser = doctest.DocTestParser()
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
    tests = 0
    for code in blocks(source_dir):
        if not code.startswith(">>>"):
            continue
        test = parser.get_doctest(code, {"creepwork": creepwork}, "doc/python.md", None, 0)
        runner.run(test)
        tests += 1
    assert tests >= 1
    assert runner.summarize(verbose=False).failed == 0
