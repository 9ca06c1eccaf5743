"""The Jacobian on a gap grid through the package against the creepwork
program (programs/cli): `creepwork solve --gap FILE --jacobian` gives the
same numbers bitwise (one library behind two interfaces)."""

import json

import numpy as np
import pytest

import creepwork
from conftest import run_cli

G, NU, N = 82e9, 0.28, 60e3
CREEP = dict(xi_x=4e-4, xi_y=-3e-4, phi=0.3, mu=0.3, G=G, nu=NU)


def centres(grid):
    x = grid["x0"] + grid["dx"] * np.arange(grid["nx"])
    y = grid["y0"] + grid["dy"] * np.arange(grid["ny"])
    return np.meshgrid(x, y)  # (ny, nx): element (i, j) at [j, i], as the fields


def binary_lobes():
    """Two lobes on a grid whose coordinates are exact binary numbers, so a
    gap file written with repr() reads back as the same grid bitwise."""
    dx, dy = 2.0 ** -12, 2.0 ** -11  # 0.244 mm, 0.488 mm
    grid = {"kind": "gap", "nx": 32, "ny": 48, "x0": -16 * dx, "y0": -24 * dy, "dx": dx, "dy": dy}
    x, y = centres(grid)
    lobe = lambda yc, lift: x ** 2 / 0.9 + (y - yc) ** 2 / 0.5 + lift
    return grid, np.minimum(lobe(-5e-3, 0.0), lobe(5e-3, 2e-6))


@pytest.mark.parametrize("model,load", [("exact", "force"), ("fastsim", "approach")])
def test_gap_jacobian_bitwise_equal_to_cli(cli, tmp_path, model, load):
    """The Jacobian on a gap grid (header: cw_solver_solve_jacobian) through
    the package equals `creepwork solve --gap FILE --jacobian` bitwise: the
    same library behind two interfaces, on the same grid (binary_lobes), as
    the CLI runs it (a full solve, then the Jacobian on that solver)."""
    grid, h = binary_lobes()
    x, y = centres(grid)
    path = tmp_path / "lobes.csv"
    with open(path, "w") as f:
        f.write("x_m,y_m,h_m\n")
        for xv, yv, hv in zip(x.ravel(), y.ravel(), h.ravel()):
            f.write("%r,%r,%r\n" % (float(xv), float(yv), float(hv)))
    keywords = dict(CREEP, model=model, gap=h)
    args = ["solve", "--gap", str(path), "--model", model, "--xi-x", repr(CREEP["xi_x"]),
            "--xi-y", repr(CREEP["xi_y"]), "--spin", repr(CREEP["phi"]), "--mu", repr(CREEP["mu"]),
            "--G", repr(G), "--nu", repr(NU), "--format", "json", "--jacobian"]
    if load == "approach":
        keywords.update(normal_load="approach", approach=40e-6, normal_method="semi_hertz")
        args += ["--approach", "4e-05", "--normal-method", "semi-hertz"]
    else:
        keywords.update(N=N)
        args += ["--N", repr(N)]
    out, _ = run_cli(cli, *args)
    expected = json.loads(out, parse_int=float)["jacobian"]
    with creepwork.Solver(grid=grid) as s:
        s.solve(**keywords)
        r = s.jacobian(**keywords)
    names = {"xi_x": "xi_x", "xi_y": "xi_y", "phi": "phi", "normal_force": "N"}
    for i, row in enumerate(creepwork.JACOBIAN_ROWS):
        for k, column in enumerate(creepwork.JACOBIAN_COLUMNS):
            got, want = r.jacobian[i, k], expected[row][names[column]]
            assert np.float64(got).tobytes() == np.float64(want).tobytes(), (row, column, got, want)
    assert r.jacobian[0, 0] < 0 and r.jacobian[1, 1] < 0  # forces oppose their creepage
