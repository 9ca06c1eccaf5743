"""solve_many: one C batch call for many contacts. Its totals are bitwise
those of solve() one by one (the batch's promise, and the keyword
broadcasting checked element by element); a bad contact among 10^4 gets its
own status and message while the others are solved; gaps and implausible
units come inside params arrays as they come in keywords."""

import re
import struct
import warnings

import numpy as np
import pytest

import creepwork

BASE = dict(a=7e-3, b=5e-3, N=100e3)


def same(a, b):
    return struct.pack("<d", float(a)) == struct.pack("<d", float(b))


def test_one_bad_contact_among_ten_thousand():
    n, bad = 10_000, 6_789
    rng = np.random.default_rng(2024)
    xi_x = rng.uniform(-3e-3, 3e-3, n)
    xi_y = rng.uniform(-3e-3, 3e-3, n)
    phi = rng.uniform(-2.0, 2.0, n)
    nu = np.full(n, 0.28)
    nu[bad] = 0.6
    out = creepwork.solve_many(**BASE, xi_x=xi_x, xi_y=xi_y, phi=phi, nu=nu)
    assert out.shape == (n,) and len(out) == n
    assert out.status[bad] == creepwork.CW_ERR_INVALID_INPUT
    assert np.count_nonzero(out.status) == 1 and out.ok.sum() == n - 1
    assert list(out.messages) == [(bad,)]
    assert "nu" in out.messages[(bad,)] and "0.5" in out.messages[(bad,)]
    assert np.isnan(out.Fx[bad]) and np.isnan(out.W_macro[bad])
    errors = out.errors()
    assert len(errors) == 1 and isinstance(errors[0][1], creepwork.InvalidInputError)
    with pytest.raises(creepwork.InvalidInputError, match="contact \\(6789,\\): nu"):
        out.raise_first()
    # Contacts on either side of the bad one, and a sample, as solve() gives them.
    for k in [0, bad - 1, bad + 1, n - 1] + list(rng.integers(0, n, 16)):
        if k == bad:
            continue
        r = creepwork.solve(**BASE, xi_x=xi_x[k], xi_y=xi_y[k], phi=phi[k], fields=False)
        for name in ("Fx", "Fy", "Mz", "W_macro", "adhesion_fraction"):
            assert same(getattr(out, name)[k], getattr(r, name)), (k, name)


def test_broadcasting_shapes_and_values():
    xi_x = np.linspace(-2e-3, 2e-3, 3).reshape(3, 1)
    xi_y = np.array([0.0, 1e-3, -1e-3, 2e-3])
    out = creepwork.solve_many(**BASE, xi_x=xi_x, xi_y=xi_y, phi=0.3, model="calibrated")
    assert out.Fx.shape == out.status.shape == (3, 4)
    for i in range(3):
        for j in range(4):
            r = creepwork.solve(**BASE, xi_x=xi_x[i, 0], xi_y=xi_y[j], phi=0.3,
                                model="calibrated", fields=False)
            assert same(out.Fx[i, j], r.Fx) and same(out.Mz[i, j], r.Mz)


def test_threads_do_not_change_a_bit():
    xi = np.linspace(-4e-3, 4e-3, 301)
    one = creepwork.solve_many(**BASE, xi_x=xi, xi_y=xi[::-1], phi=0.7, threads=1)
    two = creepwork.solve_many(**BASE, xi_x=xi, xi_y=xi[::-1], phi=0.7, threads=2)
    assert one.results.tobytes() == two.results.tobytes()


def test_full_mode_and_exact_model_cold():
    xi = np.array([5e-4, 1e-3, 2e-3])
    out = creepwork.solve_many(**BASE, xi_x=xi, model="exact", full=True)
    assert out.ok.all()
    for k in range(3):
        # The batch solves the exact model cold: as solve() with warm_start 0.
        r = creepwork.solve(**BASE, xi_x=xi[k], model="exact", warm_start=0)
        assert same(out.Fx[k], r.Fx) and same(out.K[k], r.K) and same(out.W_micro_paper[k],
                                                                      r.W_micro_paper)
    forces = creepwork.solve_many(**BASE, xi_x=xi)
    assert np.all(forces.K == 0.0)  # (FULL) totals need full=True


def test_params_array_and_enumeration_names():
    p = np.empty(4, creepwork.DTYPES["cw_params"])
    p[...] = creepwork.params(**BASE, xi_y=1e-3)
    p["xi_x"] = [0.0, 1e-3, 2e-3, 3e-3]
    model = np.array(["fastsim", "calibrated", "fastsim", "calibrated"])
    out = creepwork.solve_many(p, model=model)
    assert out.params["model"].tolist() == [0, 2, 0, 2]
    for k in range(4):
        r = creepwork.solve(**BASE, xi_y=1e-3, xi_x=p["xi_x"][k], model=str(model[k]),
                            fields=False)
        assert same(out.Fy[k], r.Fy)
    with pytest.raises(creepwork.UnknownOptionError, match="fastsimm"):
        creepwork.solve_many(p, model=np.array(["fastsim", "fastsimm", "exact", "exact"]))


def test_gap_records_in_any_memory_order():
    """A pointer field comes to solve_many inside params records: the gap of
    a creepwork.params() record is read in C order whatever the memory order
    of the array given (a Fortran-ordered array, the transpose of a
    transposed copy, a strided view of a larger array, made and dropped in
    the call), and stays readable while that array lives, after other
    arrays have come and gone: each contact's totals are bitwise solve()'s
    with the C-ordered gap."""
    grid = {"kind": "gap", "nx": 24, "ny": 40, "x0": -4.2e-3, "y0": -9e-3, "dx": 0.35e-3,
            "dy": 0.45e-3}
    x, y = np.meshgrid(grid["x0"] + grid["dx"] * np.arange(24),
                       grid["y0"] + grid["dy"] * np.arange(40))
    gaps = [x ** 2 / 0.9 + (y - yc) ** 2 / 0.5 + 0.2e-6 * np.sin(x / 0.6e-3) for yc in
            (-2e-3, 0.0, 1.5e-3)]
    larger = np.zeros((80, 72))
    larger[::2, 1::3] = gaps[2]
    given = [np.asfortranarray(gaps[0]), gaps[1].T.copy().T]
    kw = dict(N=60e3, xi_x=2e-4, xi_y=-3e-4, phi=0.4, model="fastsim", normal_method="semi_hertz")
    records = [creepwork.params(**kw, gap=g) for g in given]
    records.append(creepwork.params(**kw, gap=larger[::2, 1::3]))
    clutter = [np.full(gaps[0].shape, 7.0) for _ in range(64)]  # memory changing hands
    del clutter
    out = creepwork.solve_many(np.array(records), grid=grid)
    assert out.ok.all()
    for k, gap in enumerate(gaps):
        r = creepwork.solve(**kw, gap=gap, grid=grid, fields=False)
        for name in ("Fx", "Fy", "Mz", "normal_force", "p_max"):
            assert same(getattr(out, name)[k], getattr(r, name)), (k, name)
    assert len({out.Fy[k] for k in range(3)}) == 3  # three different contacts


def test_params_array_is_checked_for_units_as_keywords_are():
    """A params array brings its values' plausibility with it: the records
    of a call whose keywords warned (ManyResult.params) warn the same when
    given back as the params array, with no keyword at all."""
    a = np.full(40, 7e-3)
    a[[5, 22]] = 7.5  # millimetres typed as metres
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        first = creepwork.solve_many(a=a, b=a, N=100e3, xi_x=1e-3)
        with creepwork.Batch(threads=1) as batch:
            again = batch.solve(first.params)
    messages = [str(w.message) for w in caught if w.category is creepwork.UnitWarning]
    assert len(messages) == 4, messages  # a and b, by the keywords and by the records
    assert messages[:2] == messages[2:]
    assert "(2 of 40 contacts)" in messages[0]
    assert again.results.tobytes() == first.results.tobytes()


def test_batch_reuse_and_empty():
    with creepwork.Batch(threads=2) as batch:
        a = batch.solve(**BASE, xi_x=np.array([1e-3, 2e-3]))
        b = batch.solve(**BASE, xi_x=np.array([1e-3, 2e-3]))
        assert a.results.tobytes() == b.results.tobytes()
        empty = batch.solve(**BASE, xi_x=np.array([]))
        assert empty.Fx.shape == (0,)
    with pytest.raises(ValueError, match="closed"):
        batch.solve(**BASE)


def test_progress_reports_every_part_and_changes_no_bit(capsys):
    """progress: a callable sees the contacts done rise to the total, the
    totals (a bad contact among them) equal one call's bitwise; a number of
    seconds prints the CLI's line on stderr; nothing is printed without it."""
    n, bad = 2_345, 1_000
    xi_x = np.linspace(-3e-3, 3e-3, n)
    nu = np.full(n, 0.28)
    nu[bad] = 0.6
    one = creepwork.solve_many(**BASE, xi_x=xi_x, phi=0.5, nu=nu, full=True)
    seen = []
    parts = creepwork.solve_many(**BASE, xi_x=xi_x, phi=0.5, nu=nu, full=True,
                                 progress=lambda done, total: seen.append((done, total)))
    assert len(seen) == 98 and seen[-1] == (n, n)  # 24 contacts a part: ceil(2345 / 100)
    assert all(t == n for _, t in seen) and all(b > a for (a, _), (b, _) in zip(seen, seen[1:]))
    assert np.array_equal(parts.status, one.status) and list(parts.messages) == [(bad,)]
    for name in ("Fx", "Fy", "Mz", "W_macro", "K", "n_slip"):
        assert getattr(parts, name).tobytes() == getattr(one, name).tobytes(), name
    assert capsys.readouterr().err == ""
    with creepwork.Batch() as batch:
        batch.solve(**BASE, xi_x=xi_x, progress=1e-9)
    lines = capsys.readouterr().err.splitlines()
    assert 1 <= len(lines) <= 100
    assert re.fullmatch(r"creepwork: solve: %d of %d contacts done \(100 %%\), \d+ contacts/s, "
                        r"about 0 s to go" % (n, n), lines[-1]), lines[-1]
    for wrong in (0, -1.0, "often", float("nan"), 1e6):
        with pytest.raises(ValueError, match="solve_many\\(\\): progress = .* is invalid"):
            creepwork.solve_many(**BASE, xi_x=xi_x[:3], progress=wrong)
