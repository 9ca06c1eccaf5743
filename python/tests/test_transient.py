"""creepwork.Transient: CONTACT's catt_to_cart (tests/data/transient, from
eve70a/CONTACT d431cdb) through the package, every printed digit of the
shift and the first rolling steps; a trial repeated after rewind and after
restore gives the same bits; errors name their input."""

import csv
import os

import numpy as np
import pytest

import creepwork

DX = 0.25e-3
FX = -0.657 * 0.4013 * 0.4705


def catt_to_cart(**options):
    x = -4e-3 + DX * np.arange(34)
    y = -4e-3 + DX * np.arange(33)
    h = 2.963 * (x[None, :] ** 2 + y[:, None] ** 2)  # (ny, nx): C order is [i + nx j]
    grid = {"kind": "gap", "nx": 34, "ny": 33, "x0": -4e-3, "y0": -4e-3, "dx": DX, "dy": DX}
    return creepwork.Transient(grid, gap=h, N=0.4705, G=1e6, nu=0.28, mu=0.4013, **options)


def reference():
    path = os.path.join(os.environ["CREEPWORK_TEST_DATA_DIR"], "transient", "catt_to_cart.csv")
    with open(path) as f:
        return list(csv.DictReader(f))


def test_catt_to_cart_printed_digits():
    rows = reference()[:8]
    with catt_to_cart() as t:
        for row in rows:
            shift = row["kind"] == "shift"
            r = t.step(dq=0.0 if shift else DX, Fx=FX)
            t.commit()
            value = r["xi_x"] * 1e3 if shift else r["xi_x"]
            assert "%.3E" % value == "%.3E" % float(row["value"])
            assert r["n_adhesion"] == int(row["n_adhesion"])
            assert r["n_slip"] == int(row["n_slip"])
            assert abs(r["Fx"] - FX) <= 1e-8 * 0.4013 * 0.4705


def test_trial_repeats_bitwise_after_rewind_and_restore():
    with catt_to_cart() as t:
        t.step(dq=0.0, Fx=FX)
        t.commit()
        saved = t.save()
        a = t.step(dq=DX, Fx=-0.05)
        px = t.field("px")
        t.rewind()
        with pytest.raises(creepwork.NoSolutionError, match="no step to commit"):
            t.commit()
        t.step(dq=DX, xi_x=1e-3)
        t.rewind()
        b = t.step(dq=DX, Fx=-0.05)
        assert a == b
        assert np.array_equal(px, t.field("px"))
        t.commit()
        t.restore(saved)
        c = t.step(dq=DX, Fx=-0.05)
        assert a == c
        # The traction sums to Fx; adhesion elements as counted.
        assert abs(px.sum() * DX * DX - a["Fx"]) <= 1e-12 * abs(a["Fx"])
        assert int((t.state() == creepwork.CW_STATE_ADHESION).sum()) == a["n_adhesion"]


def test_errors_name_their_input():
    with catt_to_cart() as t:
        with pytest.raises(creepwork.InvalidInputError, match="dq"):
            t.step(dq=2 * DX, xi_x=1e-3)
        with pytest.raises(creepwork.InvalidInputError, match="mu N"):
            t.step(dq=DX, Fx=-1.0)
        with pytest.raises(creepwork.UnknownOptionError):
            t.field("work_paper")
        with pytest.raises(creepwork.InvalidInputError):
            t.restore(np.zeros(3, np.uint64))
    with pytest.raises(creepwork.InvalidInputError, match="mu"):
        grid = {"kind": "gap", "nx": 34, "ny": 33, "x0": -4e-3, "y0": -4e-3, "dx": DX, "dy": DX}
        creepwork.Transient(grid, gap=np.ones((33, 34)), N=0.4705, G=1e6, nu=0.28, mu=0.0)


def test_fastsim_model_steady_start_is_the_steady_fastsim():
    """model="fastsim": FASTSIM's transient form. Its steady start is the
    steady FASTSIM of creepwork.solve on the same gap grid (another
    implementation of the march) to 1e-12 mu N; a step of dx keeps it."""
    x = -4e-3 + DX * np.arange(34)
    y = -4e-3 + DX * np.arange(33)
    h = 2.963 * (x[None, :] ** 2 + y[:, None] ** 2)
    grid = {"kind": "gap", "nx": 34, "ny": 33, "x0": -4e-3, "y0": -4e-3, "dx": DX, "dy": DX}
    contact = dict(gap=h, N=0.4705, G=1e6, nu=0.28, mu=0.4013)
    creep = dict(xi_x=1.5e-3, xi_y=-1e-3, phi=40.0)
    mu_n = 0.4013 * 0.4705
    steady = creepwork.solve(grid=grid, model="fastsim", warn=False, **contact, **creep)
    with creepwork.Transient(grid, model="fastsim", **contact) as t:
        s = t.start_steady(**creep)
        for name in ("Fx", "Fy"):
            assert abs(s[name] - getattr(steady, name)) <= 1e-12 * mu_n
        r = t.step(dq=DX, **creep)
        assert abs(r["Fx"] - s["Fx"]) <= 1e-12 * mu_n
    with pytest.raises(creepwork.InvalidInputError, match="model"):
        creepwork.Transient(grid, model="calibrated", **contact)


def test_work_map_and_jacobian():
    """The work field adds up to W_step (1e-12) and W_step >= W_slip; the
    Jacobian at prescribed Fx (d xi_x / d Fx) equals a central difference of
    two trials (h = 1e-5 mu N) to 1e-6, and is the C API's (same bits)."""
    with catt_to_cart() as t:
        with pytest.raises(creepwork.NoSolutionError):
            t.jacobian()
        for k in range(4):
            t.step(dq=0.0 if k == 0 else DX, Fx=FX)
            t.commit()
        r = t.step(dq=DX, Fx=-0.5 * 0.4013 * 0.4705)
        assert abs(t.field("work").sum() / r["W_step"] - 1.0) <= 1e-12
        assert r["W_step"] >= r["W_slip"] > 0.0
        J = t.jacobian()
        h = 1e-5 * 0.4013 * 0.4705
        side = []
        for d in (h, -h):
            side.append(t.step(dq=DX, Fx=-0.5 * 0.4013 * 0.4705 + d)["xi_x"])
            t.rewind()
        fd = (side[0] - side[1]) / (2 * h)
        assert abs(fd / J[0, 0] - 1.0) <= 1e-6


def test_world_coordinates():
    """World-fixed: the shift and two steps (the contact moves two elements,
    still on the grid) give the contact-fixed creepages to 1e-6; a bad
    coordinates value names itself."""
    with catt_to_cart() as c, catt_to_cart(coordinates="world") as w:
        for k in range(3):
            a = c.step(dq=0.0 if k == 0 else DX, Fx=FX)
            b = w.step(dq=0.0 if k == 0 else DX, Fx=FX)
            c.commit()
            w.commit()
            assert abs(b["xi_x"] / a["xi_x"] - 1.0) <= 1e-6
    with pytest.raises(ValueError, match="coordinates"):
        catt_to_cart(coordinates="ground")


def test_ellipse_on_uniform_grid():
    """An elliptic contact on the exact model's uniform grid: the steady
    start equals the steady exact model (creepwork.Solver on the same grid)
    to 1e-6 mu N."""
    grid = {"kind": "uniform", "nx": 32, "ny": 24, "box_scale": 1.1}
    contact = dict(a=4e-3, b=2.5e-3, N=0.4705, G=1e6, nu=0.28, mu=0.4013)
    with creepwork.Transient(grid, **contact) as t:
        r = t.start_steady(xi_x=1e-3, xi_y=5e-4)
    with creepwork.Solver(grid) as s:
        steady = s.solve(model="exact", xi_x=1e-3, xi_y=5e-4, **contact)
    mu_n = 0.4013 * 0.4705
    assert abs(r["Fx"] - steady.Fx) <= 1e-6 * mu_n
    assert abs(r["Fy"] - steady.Fy) <= 1e-6 * mu_n


def test_wear_over_steps():
    """USFD wear over the shift and four steps (all in the mild regime, mass
    = k1 x work): each step's mass is k1 W_step (1e-12), the shift's zero;
    the accumulated map sums to the total; a bad law names itself."""
    k1 = 5.3e-9
    with catt_to_cart() as t:
        total = 0.0
        for k in range(5):
            r = t.step(dq=0.0 if k == 0 else DX, Fx=FX)
            t.commit()
            m = t.add_wear(law=0)
            if k == 0:
                assert m == 0.0
            else:
                assert abs(m / (k1 * r["W_step"]) - 1.0) <= 1e-12
            total += m
        w = t.wear()
        assert abs(w["mass"] / total - 1.0) <= 1e-12
        assert abs(w["mass_map"].sum() / total - 1.0) <= 1e-12
        with pytest.raises(ValueError, match="law"):
            t.add_wear(law=9)
        t.reset_wear()
        assert t.wear()["mass"] == 0.0


def test_fastsim_takes_work_and_wear_refuses_world_and_jacobian():
    """model="fastsim": the work field is its slip's dissipation, summing to
    W_step (1e-12) with W_slip = W_step (an explicit step); each step's USFD
    wear (mild regime) is k1 W_step (1e-12). World-fixed coordinates and the
    step Jacobian are the exact model's: refused, naming CW_MODEL_FASTSIM."""
    with pytest.raises(creepwork.InvalidInputError, match="CW_MODEL_FASTSIM"):
        catt_to_cart(model="fastsim", coordinates="world")
    with catt_to_cart(model="fastsim") as t:
        for k in range(4):
            r = t.step(dq=0.0 if k == 0 else DX, Fx=FX)
            t.commit()
            assert r["W_slip"] == r["W_step"] > 0.0
            assert abs(t.field("work").sum() / r["W_step"] - 1.0) <= 1e-12
            m = t.add_wear(law=0)
            if k > 0:
                assert abs(m / (5.3e-9 * r["W_step"]) - 1.0) <= 1e-12
        with pytest.raises(creepwork.InvalidInputError, match="CW_MODEL_FASTSIM"):
            t.jacobian()
