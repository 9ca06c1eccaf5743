"""The example inputs installed with the program (examples/data): the gap
file three_lobes.csv is what its Python program and the awk generator of
doc/input-schema.md write, byte for byte (the page's two recipes, run on a
copy), and solving it gives three patches, the same bitwise through the
creepwork program and the package."""

import json
import os
import shutil
import subprocess

import numpy as np

import creepwork
from conftest import run_cli


def examples(source_dir):
    return os.path.join(source_dir, "examples", "data")


def recipe(source_dir, name):
    return subprocess.run(["bash", os.path.join(source_dir, "scripts", "doc-block.sh"),
                           os.path.join(source_dir, "doc", "input-schema.md"), "recipe", name],
                          check=True, capture_output=True, text=True).stdout


def test_generators_write_the_shipped_gap_file(source_dir, tmp_path):
    """gap-file-python and gap-file-shell as printed, from the top of a copy,
    against an installed prefix that holds the shipped file (cmp exits 1 on
    a differing byte)."""
    clone = tmp_path / "clone"
    (clone / "examples" / "data").mkdir(parents=True)
    shutil.copy(os.path.join(examples(source_dir), "three_lobes.py"), clone / "examples" / "data")
    installed = tmp_path / "home" / "opt" / "creepwork" / "share" / "creepwork"
    installed.mkdir(parents=True)
    (installed / "examples").symlink_to(examples(source_dir))
    env = dict(os.environ, HOME=str(tmp_path / "home"))
    for name in ("gap-file-python", "gap-file-shell"):
        run = subprocess.run(["bash", "-euo", "pipefail", "-c", recipe(source_dir, name)],
                             cwd=clone, env=env, capture_output=True, text=True)
        assert run.returncode == 0, (name, run.stdout, run.stderr)
    with open(clone / "gaps" / "three_lobes.csv") as f:
        lines = f.read().splitlines()
    assert lines[0] == "x_m,y_m,h_m" and len(lines) == 1 + 31 * 57


def test_three_lobes_solve_through_the_program_and_the_package(source_dir, cli):
    """doc/cli.md's example: three separate patches carrying N between them;
    the package on the file's grid gives the program's totals bitwise."""
    path = os.path.join(examples(source_dir), "three_lobes.csv")
    out, _ = run_cli(cli, "solve", "--gap", path, "--N", "30e3", "--xi-x", "1e-3",
                     "--xi-y", "-5e-4", "--spin", "0.2", "--format", "json")
    program = json.loads(out, parse_int=float)
    assert program["n_patches"] == 3
    loads = [p["Fn"] for p in program["patches"]]
    assert all(f > 0.05 * 30e3 for f in loads) and abs(sum(loads) - 30e3) < 1e-6 * 30e3
    x, y, h = np.loadtxt(path, delimiter=",", skiprows=1, unpack=True)
    xs, ys = np.unique(x), np.unique(y)
    grid = {"kind": "gap", "nx": xs.size, "ny": ys.size, "x0": xs[0], "y0": ys[0],
            "dx": (xs[-1] - xs[0]) / (xs.size - 1), "dy": (ys[-1] - ys[0]) / (ys.size - 1)}
    gap = np.empty((ys.size, xs.size))
    gap[np.searchsorted(ys, y), np.searchsorted(xs, x)] = h
    r = creepwork.solve(grid=grid, gap=gap, N=30e3, xi_x=1e-3, xi_y=-5e-4, phi=0.2,
                        model="exact")
    for key in ("Fx", "Fy", "Mz", "p_max", "approach"):
        assert getattr(r, key) == program[key], key
    assert r.n_patches == 3
