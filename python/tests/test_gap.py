"""Contacts of any shape through the package: a gap grid (kind "gap") with
the gap as a numpy array. Checked against the elliptic exact model (a
Hertzian gap is the same discrete problem, header: CW_GRID_GAP), against
the definitions of the patches (their totals add up to the result's), and
against the C-ordered gap's bits for a gap in another memory order or dtype."""

import numpy as np
import pytest

import creepwork

G, NU, N = 82e9, 0.28, 60e3
CREEP = dict(xi_x=4e-4, xi_y=-3e-4, phi=0.3, mu=0.3, G=G, nu=NU)


def gap_grid(nx, ny, x0, y0, dx, dy):
    return {"kind": "gap", "nx": nx, "ny": ny, "x0": x0, "y0": y0, "dx": dx, "dy": dy}


def centres(grid):
    x = grid["x0"] + grid["dx"] * np.arange(grid["nx"])
    y = grid["y0"] + grid["dy"] * np.arange(grid["ny"])
    return np.meshgrid(x, y)  # (ny, nx): element (i, j) at [j, i], as the fields


def test_hertzian_gap_is_the_elliptic_exact_model():
    """The gap A x^2 + B y^2 on the 24 x 24 grid over 1.2 a x 1.2 b, with a, b
    from Hertz's theory for A, B, N (cw_hertz_solve), is the problem the
    elliptic exact model solves on that uniform grid: both at tolerance
    1e-12 agree to 1e-8 mu N (the C tests find 1e-11)."""
    A, B = 1 / (2 * 0.46), 1 / (2 * 0.30)
    hz = creepwork.hertz(A, B, N, G / (1 - NU))
    n, S = 24, 1.2
    grid = gap_grid(n, n, -S * hz.a + S * hz.a / n, -S * hz.b + S * hz.b / n,
                    2 * S * hz.a / n, 2 * S * hz.b / n)
    x, y = centres(grid)
    h = A * x ** 2 + B * y ** 2
    common = dict(CREEP, model="exact", tolerance=1e-12, warm_start=0)
    g = creepwork.solve(**common, N=N, gap=h, gap_len=h.size, grid=grid)
    e = creepwork.solve(**common, a=hz.a, b=hz.b, N=N,
                        grid={"kind": "uniform", "nx": n, "ny": n, "box_scale": S})
    muN = 0.3 * N
    for key in ("Fx", "Fy"):
        assert abs(getattr(g, key) - getattr(e, key)) <= 1e-8 * muN, key
    assert abs(g.Mz - e.Mz) <= 1e-8 * muN * hz.a
    assert (g.n_contact, g.n_adhesion, g.n_slip) == (e.n_contact, e.n_adhesion, e.n_slip)
    assert abs(g.normal_force - N) <= 1e-12 * N
    np.testing.assert_allclose(g.pz, e.pz, rtol=0, atol=1e-8 * e.p_max)


def test_two_lobes_are_two_patches_adding_up_to_the_totals():
    """Two paraboloids 12 mm apart across: two patches, lowest y first, whose
    normal forces, creep forces and work add up to the result's (header,
    cw_solver_get_patches: to rounding)."""
    grid = gap_grid(30, 56, -5e-3, -12e-3, 0.35e-3, 0.45e-3)
    x, y = centres(grid)
    lobe = lambda yc, lift: x ** 2 / 0.9 + (y - yc) ** 2 / 0.5 + lift
    h = np.minimum(lobe(-6e-3, 0.0), lobe(6e-3, 2e-6))
    with creepwork.Solver(grid=grid) as s:
        r = s.solve(**CREEP, model="exact", N=N, gap=h)  # gap_len follows gap
        p = s.patches()
    assert r.n_patches == 2 and p.shape == (2,)
    assert p["y_centroid"][0] < 0 < p["y_centroid"][1]
    assert abs(p["Fn"].sum() - N) <= 1e-9 * N
    for key in ("Fx", "Fy", "Mz", "W_macro"):
        total = getattr(r, key)
        assert abs(p[key].sum() - total) <= 1e-9 * (abs(total) + 1e-9), key
    assert p["n_contact"].sum() == r.n_contact


def test_fastsim_on_a_gap_grid_patches_add_up():
    """model="fastsim" on the two lobes with the semi-Hertzian normal method:
    two patches whose totals add up to the result's (header,
    cw_solver_get_patches: to rounding), the consistent work map sums to
    W_macro, and |F| <= mu N per patch (Coulomb's bound, element by element)."""
    grid = gap_grid(30, 56, -5e-3, -12e-3, 0.35e-3, 0.45e-3)
    x, y = centres(grid)
    lobe = lambda yc, lift: x ** 2 / 0.9 + (y - yc) ** 2 / 0.5 + lift
    h = np.minimum(lobe(-6e-3, 0.0), lobe(6e-3, 2e-6))
    with creepwork.Solver(grid=grid) as s:
        r = s.solve(**CREEP, model="fastsim", normal_method="semi_hertz", N=N, gap=h)
        p = s.patches()
    assert r.model == creepwork.CW_MODEL_FASTSIM
    assert r.n_patches == 2 and p.shape == (2,)
    assert abs(p["Fn"].sum() - N) <= 1e-12 * N
    for key in ("Fx", "Fy", "Mz", "W_macro"):
        total = getattr(r, key)
        assert abs(p[key].sum() - total) <= 1e-9 * (abs(total) + 1e-9), key
    assert p["n_contact"].sum() == r.n_contact
    assert np.all(np.hypot(p["Fx"], p["Fy"]) <= 0.3 * p["Fn"] * (1 + 1e-12))
    assert abs(r.W_consistent - r.W_macro) <= 1e-12 * r.W_macro


def test_gap_in_any_memory_order_is_read_in_c_order():
    """The gap is read as the (ny, nx) array it is, element (i, j) at [j, i]
    (header: [i + j*nx]), whatever its memory order: a Fortran-ordered copy,
    the transpose of a transposed copy and a strided slice of a larger array
    give the C-ordered array's results bitwise; so does a float32 gap the
    float32 values as doubles. The gap is not symmetric (a ripple along x,
    the lobes 2 um apart in height), so a transposed or strided read would
    change the contact."""
    grid = gap_grid(30, 56, -5e-3, -12e-3, 0.35e-3, 0.45e-3)
    x, y = centres(grid)
    lobe = lambda yc, lift: x ** 2 / 0.9 + (y - yc) ** 2 / 0.5 + lift
    h = np.minimum(lobe(-6e-3, 0.0), lobe(6e-3, 2e-6)) + 0.3e-6 * np.sin(x / 0.7e-3)
    larger = np.zeros((3 * 56, 2 * 30))
    larger[1::3, ::2] = h
    single = h.astype(np.float32)
    kw = dict(CREEP, N=N, model="fastsim", normal_method="semi_hertz")
    with creepwork.Solver(grid=grid) as s:
        ref = s.solve(**kw, gap=h)
        base = s.solve(**kw, gap=single.astype(np.float64))
        cases = [("Fortran order", np.asfortranarray(h), ref),
                 ("transposed copy", h.T.copy().T, ref),
                 ("slice", larger[1::3, ::2], ref),
                 ("float32", single, base)]
        for name, gap, expected in cases:
            assert not gap.flags.c_contiguous or gap.dtype != np.float64, name
            r = s.solve(**kw, gap=gap)
            for key in ("Fx", "Fy", "Mz", "normal_force", "p_max"):
                assert getattr(r, key) == getattr(expected, key), (name, key)
            assert np.array_equal(r.pz, expected.pz), name
    assert ref.n_patches == 2 and base.Fx != ref.Fx  # the float32 gap is another gap


def test_one_patch_off_a_gap_grid_and_errors_name_the_input():
    """Off a gap grid the contact is one patch with the result's totals; a gap
    on another grid, or another model on a gap grid, raise InvalidInputError
    naming the input."""
    with creepwork.Solver() as s:
        r = s.solve(a=7e-3, b=5e-3, N=N, **CREEP)
        p = s.patches()
        assert p.shape == (1,) and p["Fx"][0] == r.Fx and p["Fn"][0] == N
        with pytest.raises(creepwork.InvalidInputError, match="gap"):
            s.solve(a=7e-3, b=5e-3, N=N, gap=np.zeros(400), gap_len=400, **CREEP)
    grid = gap_grid(8, 8, -2e-3, -2e-3, 0.5e-3, 0.5e-3)
    x, y = centres(grid)
    h = x ** 2 + y ** 2
    with pytest.raises(creepwork.InvalidInputError, match="model = calibrated"):
        creepwork.solve(**CREEP, model="calibrated", N=N, gap=h, gap_len=h.size, grid=grid)


def test_gap_of_the_wrong_shape_is_an_error():
    """The gap's layout is the fields': (ny, nx), x along the second axis;
    the transposed array is refused, not solved as another contact."""
    grid = gap_grid(30, 56, -5e-3, -12e-3, 0.35e-3, 0.45e-3)
    x, y = centres(grid)
    h = x ** 2 / 0.9 + y ** 2 / 0.5
    assert h.shape == (56, 30)
    creepwork.solve(**CREEP, model="exact", N=60e3, gap=h, grid=grid, fields=False)
    with pytest.raises(creepwork.InvalidInputError, match=r"need shape \(ny, nx\) = \(56, 30\)"):
        creepwork.solve(**CREEP, model="exact", N=60e3, gap=h.T, grid=grid, fields=False)


def test_gap_jacobian_needs_a_load():
    """normal_force = 0: no derivative by N there (header,
    cw_solver_solve_jacobian): an error naming the load as typed, N or
    normal_force, for both models."""
    grid = gap_grid(30, 56, -5e-3, -12e-3, 0.35e-3, 0.45e-3)
    x, y = centres(grid)
    h = x ** 2 / 0.9 + y ** 2 / 0.5
    for model in ("exact", "fastsim"):
        with pytest.raises(creepwork.InvalidInputError) as e:
            creepwork.jacobian(**CREEP, model=model, N=0.0, gap=h, grid=grid)
        assert str(e.value).startswith("N = 0: ")
        with pytest.raises(creepwork.InvalidInputError) as e:
            creepwork.jacobian(**CREEP, model=model, normal_force=0.0, gap=h, grid=grid)
        assert str(e.value).startswith("normal_force = 0: ")
