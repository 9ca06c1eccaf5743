"""The rules every door shares, through the Python door: a gap array of the
wrong shape is an error naming the axes (a transposed array solved as
another contact gave 8 patches and 3.09 GPa instead of 2 and 0.90); a gap
in millimetres warns; a, b and N are required as the CLI requires them, and
a record left at cw_params_init's placeholders warns; messages name the
input as typed; one spelling for every value (the library's aliases); an
input of the grid given to the contact points at the grid."""

import warnings

import numpy as np
import pytest

import creepwork

BASE = dict(a=7e-3, b=5e-3, N=100e3)


def gap_case():
    """Two Hertzian lobes on a 30 x 56 grid of 0.35 x 0.45 mm (doc/python.md)."""
    grid = {"kind": "gap", "nx": 30, "ny": 56, "x0": -5e-3, "y0": -12e-3, "dx": 0.35e-3,
            "dy": 0.45e-3}
    x = grid["x0"] + grid["dx"] * np.arange(30)
    y = grid["y0"] + grid["dy"] * np.arange(56)
    X, Y = np.meshgrid(x, y)  # shape (ny, nx): x along the second axis
    h = np.minimum(X ** 2 / 0.9 + (Y + 6e-3) ** 2 / 0.5, X ** 2 / 0.8 + (Y - 6e-3) ** 2 / 0.3 + 2e-6)
    return grid, h


def unit_warnings(call):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = call()
    return result, [str(w.message) for w in caught if w.category is creepwork.UnitWarning]


def test_gap_shape_must_match_the_grid():
    grid, h = gap_case()
    with creepwork.Solver(grid) as s:
        good = s.solve(N=60e3, xi_y=-3e-4, model="exact", gap=h, fields=False)
        assert good.n_patches == 2
        with pytest.raises(creepwork.InvalidInputError) as e:
            s.solve(N=60e3, xi_y=-3e-4, model="exact", gap=h.T, fields=False)
        text = str(e.value)
        assert "gap has shape (30, 56)" in text
        assert "nx = 30 cells along x and ny = 56 along y need shape (ny, nx) = (56, 30)" in text
        assert "x along the second axis" in text and "gap.T" in text
        # the same cells flat (x fastest) are the library's layout: the same bits
        flat = s.solve(N=60e3, xi_y=-3e-4, model="exact", gap=h.ravel(), fields=False)
        assert flat.Fy == good.Fy and flat.p_max == good.p_max
        with pytest.raises(creepwork.InvalidInputError, match="gap has shape"):
            s.solve(N=60e3, model="exact", gap=h[:, :29], fields=False)


def test_gap_in_millimetres_warns():
    grid, h = gap_case()
    _, quiet = unit_warnings(lambda: creepwork.solve(N=60e3, xi_x=1e-3, model="exact", gap=h,
                                                     grid=grid, fields=False))
    assert quiet == []
    spread = round(float(h.max() - h.min()) * 1e3, 6)
    _, said = unit_warnings(lambda: creepwork.solve(N=60e3, xi_x=1e-3, model="exact",
                                                    gap=h * 1e3, grid=grid, fields=False))
    assert len(said) == 1
    assert said[0].startswith("gap = %.10g m is implausible for a wheel-rail contact: its "
                              "heights span this much" % spread)
    big = dict(grid, dx=0.35, dy=0.45, x0=-5.0, y0=-12.0)
    _, cells = unit_warnings(lambda: creepwork.solve(N=60e3, model="exact", gap=h, grid=big,
                                                     fields=False))
    assert cells[0].startswith("dx = 0.35 m is implausible for a wheel-rail contact: gap cells")
    assert cells[1].startswith("dy = 0.45 m is implausible")


def test_size_and_load_are_required():
    with pytest.raises(TypeError, match=r"solve\(\) missing required keyword arguments: 'a', 'b', "
                                        r"'N': the contact's semi-axes and load have no sensible "
                                        r"default"):
        creepwork.solve(xi_x=1e-3)
    with pytest.raises(TypeError, match="missing required keyword argument: 'N'"):
        creepwork.solve(a=7e-3, b=5e-3, xi_x=1e-3)
    with pytest.raises(TypeError, match=r"solve_many\(\) missing required keyword argument: 'b'"):
        creepwork.solve_many(a=7e-3, N=1e5, xi_x=[1e-3, 2e-3])
    with pytest.raises(TypeError, match=r"jacobian\(\) missing"):
        creepwork.jacobian(a=7e-3, xi_x=1e-3)
    with creepwork.Solver() as s, pytest.raises(TypeError, match="'a'"):
        s.solve({"b": 5e-3, "N": 1e5})
    # normal_force is N's own name
    creepwork.solve(a=7e-3, b=5e-3, normal_force=1e5, fields=False)
    # a record keeps cw_params_init's placeholders: solved, with a warning
    r, said = unit_warnings(lambda: creepwork.solve(creepwork.params(xi_x=1e-3), fields=False))
    assert r.Fx == pytest.approx(-10393, abs=1)  # the newcomer's silent answer, now warned
    assert len(said) == 1
    assert "a, b and normal_force all hold cw_params_init's values (6 mm, 6 mm, 80 kN)" in said[0]
    _, none = unit_warnings(lambda: creepwork.solve(creepwork.params(**BASE, xi_x=1e-3),
                                                    fields=False))
    assert none == []


def test_messages_name_the_input_as_typed():
    with pytest.raises(creepwork.InvalidInputError, match=r"^N = -100000 is invalid"):
        creepwork.solve(a=7e-3, b=5e-3, N=-100e3)
    with pytest.raises(creepwork.InvalidInputError, match=r"^normal_force = -100000 is invalid"):
        creepwork.solve(a=7e-3, b=5e-3, normal_force=-100e3)
    _, said = unit_warnings(lambda: creepwork.solve(a=7e-3, b=5e-3, N=100.0, fields=False))
    assert said[0].startswith("N = 100 N is implausible")
    _, said = unit_warnings(lambda: creepwork.solve(a=7e-3, b=5e-3, normal_force=100.0,
                                                    fields=False))
    assert said[0].startswith("normal_force = 100 N is implausible")
    out = creepwork.solve_many(a=7e-3, b=5e-3, N=np.array([1e5, -1.0]))
    assert out.messages[(1,)].startswith("N = -1 is invalid")
    with pytest.raises(TypeError, match=r"nx is a field of the grid: grid=\{'nx': \.\.\.\}"):
        creepwork.solve(**BASE, nx=30)
    with pytest.raises(TypeError, match="a is a field of cw_params"):
        creepwork.Solver(grid={"a": 7e-3})


def test_one_spelling_every_value():
    """The library's aliases (cw_input_name): the same contact, to the bit."""
    ref = creepwork.solve(**BASE, xi_x=1e-3, phi=0.5, fields=False)
    assert creepwork.solve(**BASE, xi_x=1e-3, spin=0.5, fields=False).Fy == ref.Fy
    assert creepwork.solve(**BASE, xi_x=1e-3, phi=0.5, model="fast", fields=False).Fy == ref.Fy
    assert creepwork.solve(**BASE, xi_x=1e-3, phi=0.5, model="FastSim",
                           grid={"kind": "Strips"}, fields=False).Fy == ref.Fy
    grid, h = gap_case()
    one = creepwork.solve(N=60e3, model="fastsim", normal_method="semi_hertz", gap=h, grid=grid,
                          fields=False)
    two = creepwork.solve(N=60e3, model="fastsim", normal_method="semi-hertz", gap=h, grid=grid,
                          fields=False)
    assert one.Fx == two.Fx and one.p_max == two.p_max
    with pytest.raises(creepwork.UnknownOptionError, match="model = 'exakt' is not one of"):
        creepwork.solve(**BASE, model="exakt")


def test_exact_default_grid_is_the_librarys():
    r = creepwork.solve(**BASE, xi_x=1e-3, model="exact")
    assert r.state.shape == (24, 24)
    assert r.grid["kind"] == creepwork.CW_GRID_UNIFORM and r.grid["box_scale"] == 1.2
