"""Solver and Result: array shapes and orientation, fields filled in place,
fields consistent with the totals (the header's definitions), warm starts,
the Jacobian against central differences, params records reused."""

import struct

import numpy as np

import creepwork

BASE = dict(a=7e-3, b=5e-3, N=100e3, xi_x=1e-3, xi_y=5e-4, phi=0.5)
UNIFORM = {"kind": "uniform", "nx": 30, "ny": 20, "box_scale": 1.2}


def same(a, b):
    return struct.pack("<d", float(a)) == struct.pack("<d", float(b))


def test_shape_is_ny_nx_with_x_along_the_rows():
    """On a 30 x 20 uniform grid over [-1.2a, 1.2a] x [-1.2b, 1.2b], element
    (i, j) is at [j, i]: x = -1.2a + (i + 1/2) dx along axis 1, y likewise
    along axis 0 (the grid's definition in the header)."""
    r = creepwork.solve(**BASE, grid=UNIFORM)
    assert r.pz.shape == r.state.shape == (20, 30)
    a, b = BASE["a"], BASE["b"]
    x = -1.2 * a + (np.arange(30) + 0.5) * (2.4 * a / 30)
    y = -1.2 * b + (np.arange(20) + 0.5) * (2.4 * b / 20)
    np.testing.assert_allclose(r.x, np.broadcast_to(x, (20, 30)), rtol=0, atol=1e-15)
    np.testing.assert_allclose(r.y, np.broadcast_to(y[:, None], (20, 30)), rtol=0, atol=1e-15)
    assert r.pz.flags.c_contiguous and r.state.dtype == np.intc


def test_fields_sum_to_the_totals():
    """The header: Fx, Fy are the sums of px, py times the area; mz sums to Mz;
    W_consistent and W_micro_paper are the sums of their maps; the profile
    w(y) integrates over the strips to W_consistent (strip width 2b/ny on
    Kalker's grid)."""
    r = creepwork.solve(**BASE)
    scale = abs(r.Fx) + abs(r.Fy)
    assert abs((r.px * r.area).sum() - r.Fx) <= 1e-12 * scale
    assert abs((r.py * r.area).sum() - r.Fy) <= 1e-12 * scale
    assert abs(r.mz.sum() - r.Mz) <= 1e-12 * abs(r.Mz)
    assert abs(r.work_consistent.sum() - r.W_consistent) <= 1e-12 * r.W_consistent
    assert abs(r.work_paper.sum() - r.W_micro_paper) <= 1e-12 * r.W_micro_paper
    assert abs((r.profile.w * 2 * BASE["b"] / 20).sum() - r.W_consistent) <= 1e-12 * r.W_consistent
    counts = [(r.state == s).sum() for s in (creepwork.CW_STATE_ADHESION, creepwork.CW_STATE_SLIP)]
    assert counts == [r.n_adhesion, r.n_slip]
    assert np.all(r.area[r.state == creepwork.CW_STATE_EXTERIOR] == 0)


def test_fields_are_filled_in_place():
    r = creepwork.solve(**BASE)
    # One block, each field a view into it: the library wrote there, no copy.
    assert r.pz.base is not None and r.pz.base is r.px.base
    with creepwork.Solver() as s:
        s.solve(**BASE)
        out = np.empty((20, 20))
        assert s.field("work_consistent", out=out) is out
        assert out.tobytes() == r.work_consistent.tobytes()
        state = np.empty((20, 20), np.intc)
        assert s.state(out=state) is state and np.array_equal(state, r.state)


def test_solver_reuse_and_params_record():
    p = creepwork.params(**BASE)
    with creepwork.Solver() as s:
        first = s.solve(p, fields=False)
        p["xi_x"] = 2e-3
        second = s.solve(p, fields=False)
        override = s.solve(p, xi_x=1e-3, fields=False)
        again = s.result()
    assert same(first.Fx, override.Fx) and same(again.Fx, override.Fx)
    assert same(second.Fx, creepwork.solve(**{**BASE, "xi_x": 2e-3}, fields=False).Fx)
    assert same(first.Fx, creepwork.solve({"a": 7e-3, "b": 5e-3}, N=100e3, xi_x=1e-3,
                                          xi_y=5e-4, phi=0.5, fields=False).Fx)


def test_exact_warm_start_equals_cold_to_the_tolerance():
    """cw_solver_solve: with warm_start the answer equals a cold start's to the
    tolerance (1e-10 here), in fewer or as many iterations."""
    grid = {"kind": "uniform", "nx": 24, "ny": 24, "box_scale": 1.2}
    with creepwork.Solver(grid) as s:
        s.prepare("exact")
        for xi in (1e-3, 1.1e-3, 1.2e-3):
            warm = s.solve(dict(BASE, xi_x=xi), model="exact", tolerance=1e-10, fields=False)
            cold = creepwork.solve(dict(BASE, xi_x=xi), model="exact", tolerance=1e-10,
                                   warm_start=0, grid=grid, fields=False)
            for name in ("Fx", "Fy", "Mz"):
                assert abs(getattr(warm, name) - getattr(cold, name)) <= \
                    1e-7 * (abs(cold.Fx) + abs(cold.Fy))
            assert warm.iterations <= cold.iterations


def test_jacobian_against_central_differences():
    """Each column of the Jacobian against (f(x + h) - f(x - h)) / 2h of
    solve() (an independent estimate; FASTSIM's march is smooth where no
    element changes state, so h = 1e-6 relative agrees to ~1e-5)."""
    point = dict(BASE, xi_x=2e-3, xi_y=1e-3, phi=0.8)
    r = creepwork.jacobian(**point)
    plain = creepwork.solve(**point, fields=False)
    for name in ("Fx", "Fy", "Mz", "W_macro"):
        assert same(getattr(r, name), getattr(plain, name))
    assert r.jacobian.shape == (4, 4)
    assert creepwork.JACOBIAN_ROWS == ("Fx", "Fy", "Mz", "W_macro")
    assert creepwork.JACOBIAN_COLUMNS == ("xi_x", "xi_y", "phi", "normal_force")
    for k, column in enumerate(creepwork.JACOBIAN_COLUMNS):
        key = "N" if column == "normal_force" else column
        h = 1e-6 * abs(point[key])
        up = creepwork.solve(**dict(point, **{key: point[key] + h}), fields=False)
        down = creepwork.solve(**dict(point, **{key: point[key] - h}), fields=False)
        for i, row in enumerate(creepwork.JACOBIAN_ROWS):
            fd = (getattr(up, row) - getattr(down, row)) / (2 * h)
            scale = np.abs(r.jacobian[i]).max()
            assert abs(r.jacobian[i, k] - fd) <= 1e-5 * scale, (row, column, r.jacobian[i, k], fd)


def test_result_documentation_lists_every_total():
    doc = creepwork.Result.__doc__
    for name in creepwork.DTYPES["cw_result"].names[1:]:
        assert "\n      %s " % name in doc
    assert "normal_force" in creepwork.solve.__doc__ and "[m]" in creepwork.solve.__doc__
