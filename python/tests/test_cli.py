"""creepwork.solve against the creepwork program (programs/cli) on the same
inputs: the totals of `creepwork solve --format json` and the fields of
`creepwork solve --out DIR` (fields.csv, profile.csv, written with the
shortest decimal that reads back as the same double) are bitwise the
package's, for FASTSIM, the calibrated and the exact model, on both grids,
with the CLI's defaults for everything not given, and the Jacobian of
--jacobian likewise (the grid of the exact model given by the CLI's rule,
creepwork._params.exact_default_grid, is checked by the exact cases)."""

import csv
import json
import struct

import pytest

import creepwork
from conftest import run_cli

BASE = {"a": 7e-3, "b": 5e-3, "N": 100e3, "xi_x": 1e-3, "xi_y": 5e-4, "phi": 0.5}
# (CLI options, solve() keywords) beyond BASE.
CASES = {
    "fastsim": ([], {}),
    "calibrated": (["--model", "calibrated"], {"model": "calibrated"}),
    "exact": (["--model", "exact"], {"model": "exact"}),
    "exact_grid": (["--model", "exact", "--grid", "uniform", "--nx", 30, "--ny", 22,
                    "--box-scale", 1.1, "--tolerance", 1e-10],
                   {"model": "exact", "grid": {"kind": "uniform", "nx": 30, "ny": 22,
                                               "box_scale": 1.1}, "tolerance": 1e-10}),
    "fastsim_contact": (["--grid", "uniform", "--nx", 25, "--ny", 17, "--pressure", "elliptic",
                         "--rolling-direction", "-1", "--spin-offset", 1 / 6,
                         "--flexibility-blending", "--mu", 0.25, "--G", 79e9, "--nu", 0.3],
                        {"grid": {"kind": "uniform", "nx": 25, "ny": 17},
                         "pressure": "elliptic", "rolling_direction": -1,
                         "spin_offset": 1 / 6, "flexibility_blending": 1, "mu": 0.25,
                         "G": 79e9, "nu": 0.3}),
    "flexibilities_given": (["--L1", 5e-14, "--L2", 5.5e-14, "--L3", 4e-14],
                            {"flexibility": "given", "L1": 5e-14, "L2": 5.5e-14, "L3": 4e-14}),
}


def cli_args(extra):
    args = ["solve", "--a", BASE["a"], "--b", BASE["b"], "--N", BASE["N"], "--xi-x", BASE["xi_x"],
            "--xi-y", BASE["xi_y"], "--spin", BASE["phi"]]
    return args + [repr(v) if isinstance(v, float) else v for v in extra]


def bits(x):
    return struct.pack("<d", float(x))


def same(a, b):
    """Bitwise equality of two doubles (so -0.0 differs from 0.0)."""
    return bits(a) == bits(b)


@pytest.mark.parametrize("case", sorted(CASES))
def test_totals_bitwise_equal_to_cli_json(cli, case):
    options, keywords = CASES[case]
    out, _ = run_cli(cli, *cli_args(options), "--format", "json")
    expected = json.loads(out, parse_int=float)  # "-0" must stay -0.0
    r = creepwork.solve(**BASE, **keywords)
    compared = 0
    for name, value in expected.items():
        if name in r.totals and isinstance(value, float):
            assert same(r.totals[name], value), "%s: %r (Python) vs %r (CLI)" % (
                name, r.totals[name], value)
            compared += 1
    assert compared >= 25  # every number the CLI prints of cw_result
    for name in ("Fx", "Fy", "Mz", "W_macro"):
        assert name in expected


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


@pytest.mark.parametrize("case", ["fastsim", "calibrated", "exact", "fastsim_contact"])
def test_fields_bitwise_equal_to_cli_csv(cli, case, tmp_path):
    options, keywords = CASES[case]
    run_cli(cli, *cli_args(options), "--out", tmp_path / "out", "--no-plots")
    r = creepwork.solve(**BASE, **keywords)
    rows = read_csv(tmp_path / "out" / "fields.csv")
    ny, nx = r.state.shape
    assert len(rows) == nx * ny
    columns = {"x_m": "x", "y_m": "y", "area_m2": "area", "pz_Pa": "pz", "px_wheel_Pa": "px",
               "py_wheel_Pa": "py", "sx": "sx", "sy": "sy", "mz_wheel_N_m": "mz",
               "work_paper_J_per_m": "work_paper", "work_consistent_J_per_m": "work_consistent"}
    assert set(columns) | {"i", "j", "state"} == set(rows[0])
    for row in rows:
        i, j = int(row["i"]), int(row["j"])
        assert int(row["state"]) == r.state[j, i]
        for column, field in columns.items():
            assert same(float(row[column]), r.fields[field][j, i]), (column, i, j)
    profile = read_csv(tmp_path / "out" / "profile.csv")
    assert len(profile) == ny
    for row in profile:
        j = int(row["j"])
        assert same(float(row["y_m"]), r.profile.y[j])
        assert same(float(row["w_J_per_m_per_m"]), r.profile.w[j])
        assert same(float(row["parabola_J_per_m_per_m"]), r.profile.parabola[j])


@pytest.mark.parametrize("case", ["fastsim", "calibrated", "exact"])
def test_jacobian_bitwise_equal_to_cli(cli, case):
    options, keywords = CASES[case]
    out, _ = run_cli(cli, *cli_args(options), "--format", "json", "--jacobian")
    expected = json.loads(out, parse_int=float)["jacobian"]
    # As the CLI: a full solve, then the Jacobian on the same solver (the exact
    # model warm-starts from that solve, which moves the last bits).
    keywords = dict(keywords)
    grid = keywords.pop("grid", {"kind": "uniform", "nx": 24, "ny": 24, "box_scale": 1.2}
                        if keywords.get("model") == "exact" else None)
    with creepwork.Solver(grid) as s:
        s.solve(**BASE, **keywords)
        r = s.jacobian(**BASE, **keywords)
    cli_columns = {"xi_x": "xi_x", "xi_y": "xi_y", "phi": "phi", "normal_force": "N"}
    for i, row in enumerate(creepwork.JACOBIAN_ROWS):
        for k, column in enumerate(creepwork.JACOBIAN_COLUMNS):
            assert same(r.jacobian[i, k], expected[row][cli_columns[column]]), (row, column)
