"""The Python blocks of doc/python.md run: those shown as files are the
files of the tree (the doc recipe test checks and runs them); the others
run here, with numpy as np and creepwork imported, and the `>>>` blocks as
doctests, so the page cannot show code that does not work. Its recipes
print what it shows also when the python3 first on PATH has no numpy, and
a Python without numpy is told what to install."""

import doctest
import os
import re
import subprocess
import sys

import numpy as np
import pytest

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


def doc_block(source_dir, kind, name):
    return subprocess.run(["bash", os.path.join(source_dir, "scripts", "doc-block.sh"),
                           os.path.join(source_dir, "doc", "python.md"), kind, name],
                          check=True, capture_output=True, text=True).stdout


@pytest.mark.parametrize("name", ["python-quickstart", "python-fig6"])
def test_recipes_run_as_printed_with_a_python3_without_numpy_first_on_path(
        source_dir, tmp_path, name):
    """The page's recipes print what it shows although the python3 first on
    PATH has no numpy (as a pyenv or conda one often has not): a python3
    that starts without site-packages. The recipes' prefix is the staged
    package of this build."""
    if subprocess.run(["/usr/bin/python3", "-c", "import numpy"]).returncode != 0:
        pytest.skip("the recipes name Debian's /usr/bin/python3, which has no numpy here")
    shim = tmp_path / "bin" / "python3"
    shim.parent.mkdir()
    shim.write_text("#!/bin/sh\nexec %s -S \"$@\"\n" % sys.executable)
    shim.chmod(0o755)
    site = tmp_path / "home" / "opt" / "creepwork" / "lib" / "python3"
    site.mkdir(parents=True)
    (site / "site-packages").symlink_to(os.path.abspath(os.environ["PYTHONPATH"]))
    env = dict(os.environ, HOME=str(tmp_path / "home"),
               PATH="%s:%s" % (shim.parent, os.environ["PATH"]))
    del env["PYTHONPATH"]
    no_numpy = subprocess.run(["python3", "-c", "import numpy"], env=env, capture_output=True)
    assert no_numpy.returncode != 0  # the shim is what the newcomer had
    run = subprocess.run(["bash", "-euo", "pipefail", "-c", doc_block(source_dir, "recipe", name)],
                         cwd=source_dir, env=env, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert run.stdout == doc_block(source_dir, "output", name)


def test_import_without_numpy_says_what_to_install(tmp_path):
    """Without numpy the package names this Python, Debian's python3-numpy and
    pip (numpy hidden: None in sys.modules makes its import fail)."""
    run = subprocess.run([sys.executable, "-c",
                          "import sys; sys.modules['numpy'] = None; import creepwork"],
                         capture_output=True, text=True, cwd=str(tmp_path))
    assert run.returncode != 0
    last = run.stderr.strip().splitlines()[-1]
    assert last.startswith("ImportError: creepwork needs numpy"), last
    assert "python3-numpy" in last and "/usr/bin/python3" in last, last
    assert "%s -m pip install numpy" % sys.executable in last, last
