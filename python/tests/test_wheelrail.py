"""creepwork.WheelRail against CONTACT's module 1 on the Manchester benchmark
(case A-2.2, right wheel at y_ws = 3 mm, 10 kN: FN 9774 N, FX -417.5 N,
FS -2902 N, p_max 713.2 N/mm^2, z_ws 0.1143 mm; CONTACT's
examples/mbench_a22_right.ref_out): forces within 1 % of the load, p_max
within 3 %; the height prescribed gives the same forces; the patch's fields
add up to its forces (their definition) and its wear on a rail grid to
passes x the volume per distance, and two patches' wear adds up as the
header says; the fast model is within 3 % of mu Fn of the exact one; errors
name the input; implausible units warn."""

import ctypes
import os
import warnings

import numpy as np
import pytest

import creepwork
from creepwork._library import DTYPES, address, defaults, lib

DATA = os.path.join(os.environ.get("CREEPWORK_SOURCE_DIR", "."), "tests", "wheelrail", "data")
RAIL = os.path.join(DATA, "MBench_UIC60_v3.prr")
WHEEL = os.path.join(DATA, "MBench_S1002_v3.prw")
MOTION = dict(y=3e-3, yaw=0.0072, roll=-0.00018030, vs=2.0, vpitch=-4.34515030)


def test_benchmark_against_contact():
    with creepwork.WheelRail(RAIL, WHEEL) as w:
        totals, patches = w.solve(Fz=1e4, **MOTION)
        assert totals["n_patches"] == len(patches) == 1
        assert totals["z"] == pytest.approx(0.1143e-3, abs=0.05e-6)
        assert totals["Fz"] == pytest.approx(1e4, rel=1e-6)
        p = patches[0]
        assert p["Fn"] == pytest.approx(9774.0, abs=100)
        assert p["Fx"] == pytest.approx(-417.5, abs=100)
        assert p["Fs"] == pytest.approx(-2902.0, abs=100)
        assert p["p_max"] == pytest.approx(713.2e6, rel=0.03)
        again, same = w.solve(**dict(MOTION, z=totals["z"]))
        assert again["evaluations"] == 1
        assert same[0]["Fn"] == pytest.approx(p["Fn"], rel=1e-6)


def test_errors_name_the_input():
    with pytest.raises(creepwork.InvalidInputError, match="no/such/rail.prr"):
        creepwork.WheelRail("no/such/rail.prr", WHEEL)
    with pytest.raises(creepwork.InvalidInputError, match="mu"):
        creepwork.WheelRail(RAIL, WHEEL, mu=-1.0)
    with pytest.raises(TypeError, match="gauge"):
        creepwork.WheelRail(RAIL, WHEEL, gauge=1.435)
    with creepwork.WheelRail(RAIL, WHEEL, side=creepwork.CW_WHEELRAIL_LEFT) as w:
        with pytest.raises(creepwork.InvalidInputError, match="Fz"):
            w.solve(Fz=-1.0, **MOTION)
    w.close()
    with pytest.raises(ValueError, match="closed"):
        w.solve(Fz=1e4)


def test_friction_law_in_full_sliding():
    """CONTACT's tractcurv law (mu_kin 0.14, mu_e1 0.19, s_h1 1.25 m/s) at 20 %
    creepage and 10 m/s: the patch slides everywhere and carries mu(s) Fn at
    its rigid slip speed s = |(cksi, ceta)| veloc (the closed form of sliding
    friction; the elastic slip moves it by 7.3e-5 here, 3e-4 asserted), with
    the exact model and with the fast model (1.2e-4 here); a bad term of the
    law is refused by name with either."""
    law = dict(friction_law=creepwork.CW_FRICTION_EXPONENTIAL, mu=0.14, mu_e1=0.19, s_h1=1.25)
    fast = dict(model=creepwork.CW_MODEL_FASTSIM, normal_method=creepwork.CW_NORMAL_SEMI_HERTZ)
    for model in ({}, fast):
        with creepwork.WheelRail(RAIL, WHEEL, **model, **law) as w:
            _, patches = w.solve(Fz=1e4, **dict(MOTION, vs=10.0, vpitch=-0.8 * 10.0 / 0.46))
        p = patches[0]
        assert p["n_adhesion"] == 0
        s = np.hypot(p["cksi"], p["ceta"]) * p["veloc"]
        mu = 0.14 + 0.19 * np.exp(-np.log(2.0) * s / 1.25)
        assert np.hypot(p["Fx"], p["Fs"]) / p["Fn"] == pytest.approx(mu, rel=3e-4)
        with pytest.raises(creepwork.InvalidInputError, match="s_h1"):
            with creepwork.WheelRail(RAIL, WHEEL, **model, **dict(law, s_h1=0.0)) as w:
                w.solve(Fz=1e4, **dict(MOTION, vs=10.0, vpitch=-0.8 * 10.0 / 0.46))


def test_memory_and_layer_equal_the_cli(cli):
    """Friction memory (with CONTACT's tractcurv law) and CONTACT's tractcurv
    layer as keywords: the patch's forces equal, bitwise, creepwork
    wheelrail's with --memory-distance, --memory-s0, --layer-h, --layer-G;
    the layer moves them, and so does the memory where the patch slides;
    invalid values are refused by name and a layer in mm typed as m warns."""
    import json

    from conftest import run_cli

    fields = dict(friction_law=creepwork.CW_FRICTION_EXPONENTIAL, mu=0.14, mu_e1=0.19, s_h1=1.25,
                  memory_distance=3e-4, memory_s0=1e-3, layer_h=1.25e-3, layer_G=8.2e9)
    motion = dict(MOTION, yaw=0.0003, vs=10.0, vpitch=5 * MOTION["vpitch"])  # partial slip
    with creepwork.WheelRail(RAIL, WHEEL, **fields) as w:
        _, patches = w.solve(Fz=1e4, **motion)
    with creepwork.WheelRail(RAIL, WHEEL, **dict(fields, layer_h=0.0, layer_G=0.0)) as w:
        _, bare = w.solve(Fz=1e4, **motion)
    out, _ = run_cli(cli, "wheelrail", "--wheel-profile", WHEEL, "--rail-profile", RAIL,
                     "--y-shift", motion["y"], "--yaw", motion["yaw"], "--roll", motion["roll"],
                     "--V", motion["vs"], "--pitch-rate", repr(motion["vpitch"]), "--Fz", "1e4",
                     "--friction-law", "exponential", "--mu", "0.14", "--mu-e1", "0.19",
                     "--s-h1", "1.25", "--memory-distance", "3e-4", "--memory-s0", "1e-3",
                     "--layer-h", "1.25e-3", "--layer-G", "8.2e9", "--format", "json")
    q = json.loads(out)["patches"][0]
    p = patches[0]
    assert (p["Fn"], p["Fx"], p["Fs"]) == (q["Fn"], q["Fx_rail"], q["Fs_rail"])
    assert abs(p["Fx"] - bare[0]["Fx"]) > 0.01 * 0.14 * p["Fn"]
    # at 5 % creepage (slip speeds about 0.5 m/s) 1 mm of memory holds mu up
    sliding = dict(motion, vpitch=0.95 * motion["vpitch"])
    forces = []
    for memory in (1e-3, 0.0):
        with creepwork.WheelRail(RAIL, WHEEL, **dict(fields, memory_distance=memory)) as w:
            forces.append(w.solve(Fz=1e4, **sliding)[1][0]["Fx"])
    assert abs(forces[0] - forces[1]) > 0.05 * abs(forces[1])
    for name, value in (("memory_distance", -1e-4), ("memory_s0", -1.0), ("layer_G", -1.0)):
        with pytest.raises(creepwork.InvalidInputError, match=name):
            creepwork.WheelRail(RAIL, WHEEL, **dict(fields, **{name: value}))
    with pytest.warns(creepwork.UnitWarning, match="layer_h = 1.25 m"):
        creepwork.WheelRail(RAIL, WHEEL, **dict(fields, layer_h=1.25)).close()


def test_implausible_units_warn():
    with creepwork.WheelRail(RAIL, WHEEL) as w:
        with pytest.warns(creepwork.UnitWarning, match="Fz = 10 N"):
            w.solve(Fz=10.0, **MOTION)
    with pytest.warns(creepwork.UnitWarning, match="G = 82000 Pa"):
        creepwork.WheelRail(RAIL, WHEEL, G=82000.0).close()


def test_misplaced_wheel_warns():
    """A measured MiniProf wheel (y from its flange back) placed as if its
    origin were on the tread: at 2 mm its flange tip rides on the rail crown,
    the wheelset lifted by the flange height (the file's Sh = 27.97 mm).
    Warned, with the cause; wheel_y_offset = -0.07 (the flange back's place)
    runs it on its tread, silently. A 25 mm shift warns as the CLI does."""
    whl = os.path.join(DATA, "right-wheel-v1-pre-dry.whl")
    with pytest.warns(creepwork.UnitWarning, match="wheel_y_offset = 0 m is implausible") as caught:
        w = creepwork.WheelRail(RAIL, whl, model=creepwork.CW_MODEL_FASTSIM,
                                normal_method=creepwork.CW_NORMAL_SEMI_HERTZ)
    assert len(caught) == 1 and "flange_back_position = -70.0 mm" in str(caught[0].message)
    with w, pytest.warns(creepwork.UnitWarning, match="rides on its flange tip") as solved:
        totals, _ = w.solve(Fz=80e3, y=2e-3, vs=1.0, vpitch=-1 / 0.46)
    assert totals["z"] == pytest.approx(-27.9698e-3, abs=0.5e-3)
    assert len(solved) == 1  # the profile's warning is not repeated
    assert str(solved[0].message).startswith("z = -0.0276")
    with warnings.catch_warnings():
        warnings.simplefilter("error", creepwork.UnitWarning)
        with creepwork.WheelRail(RAIL, whl, wheel_y_offset=-0.07, model=creepwork.CW_MODEL_FASTSIM,
                                 normal_method=creepwork.CW_NORMAL_SEMI_HERTZ) as fixed:
            totals, _ = fixed.solve(Fz=80e3, y=2e-3, vs=1.0, vpitch=-1 / 0.46)
    assert abs(totals["z"]) < 2e-3
    with creepwork.WheelRail(RAIL, WHEEL) as w:
        with pytest.warns(creepwork.UnitWarning, match=r"y = 0.025 m is implausible for a "
                                                       r"wheel-rail contact: lateral shifts stay "
                                                       r"within \+-20 mm"):
            w.solve(Fz=1e4, **dict(MOTION, y=25e-3))


def test_patch_fields_and_wear():
    with creepwork.WheelRail(RAIL, WHEEL) as w:
        _, patches = w.solve(Fz=1e4, **MOTION)
        p = patches[0]
        area, pz, px = (w.patch_field(0, n) for n in ("area", "pz", "px"))
        assert area.shape == (p["field_ny"], p["field_nx"])
        assert (area * pz).sum() == pytest.approx(p["Fn"], rel=1e-12)
        assert (area * px).sum() == pytest.approx(p["Fx"], rel=1e-10)
        assert (w.patch_state(0) != 0).sum() == p["n_contact"]
        s = w.patch_field(0, "y")
        assert s[0, 0] == pytest.approx(p["field_s0"], abs=1e-15)
        rail = creepwork.WearProfile(np.linspace(-0.04, 0.04, 801))
        worn = w.add_wear(1e3, rail=rail, law="usfd")
        assert rail.totals()["volume"] == pytest.approx(1e3 * worn["volume_per_distance"], rel=1e-12)
        depth = rail.depth("height")
        centre = (depth * np.linspace(-0.04, 0.04, 801)).sum() / depth.sum()
        # the wear lies on the rail around the contact point (within the patch's half width)
        assert centre == pytest.approx(p["rail_profile_y"], abs=3e-3)
        with pytest.raises(creepwork.InvalidInputError, match="k = 1"):
            w.patch_field(1, "pz")
        with pytest.raises(creepwork.UnknownOptionError, match="'pressure'"):
            w.patch_field(0, "pressure")


def _patch_wear(w, k):
    """Patch k's own wear per pass (USFD, the defaults), through the C ABI:
    its solver view (cw_wheelrail_patch_solver) and cw_wear_compute."""
    view = lib.cw_wheelrail_patch_solver(w._live(), k)
    assert view
    wear = ctypes.c_void_p()
    assert lib.cw_wear_create(view, ctypes.byref(wear)) == 0
    out = np.zeros((), DTYPES["cw_wear_result"])
    lib.cw_wear_result_init(address(out))
    law = defaults("cw_wear_params").copy()
    assert lib.cw_wear_compute(wear, view, address(law), address(out)) == 0
    lib.cw_wear_destroy(wear)
    return out


def test_wear_of_two_patches():
    """Two patches (the reference case b11, tools/contact_reference/wheelrail:
    y = 5 mm, yaw 0.012, roll -0.00035, 10 kN, D_SEP = 2 mm and D_COMB = 1 mm
    keeping the two regions apart): add_wear's result sums the patches'
    mass, volume and work per pass, and its max_depth is the deeper patch's
    (header, cw_wheelrail_add_wear), each patch's wear its own."""
    motion = dict(y=5e-3, yaw=0.012, roll=-0.00035, vs=2.0, vpitch=-4.335)
    with creepwork.WheelRail(RAIL, WHEEL, d_sep=2e-3, d_comb=1e-3) as w, \
            creepwork.WearProfile(np.linspace(-0.04, 0.04, 801)) as rail:
        totals, _ = w.solve(Fz=1e4, **motion)
        assert totals["n_patches"] == 2
        worn = w.add_wear(1e3, rail=rail)
        each = [_patch_wear(w, k) for k in range(2)]
    depths = [float(e["max_depth"]) for e in each]
    assert min(depths) > 0 and worn["max_depth"] == max(depths)
    assert worn["max_depth"] < sum(depths)
    for name in ("mass_per_distance", "volume_per_distance", "work"):
        assert worn[name] == pytest.approx(sum(float(e[name]) for e in each), rel=1e-15), name


def test_fast_model_follows_exact():
    with creepwork.WheelRail(RAIL, WHEEL) as e, creepwork.WheelRail(
            RAIL, WHEEL, model=creepwork.CW_MODEL_FASTSIM,
            normal_method=creepwork.CW_NORMAL_SEMI_HERTZ) as f:
        pe = e.solve(Fz=1e4, **MOTION)[1][0]
        pf = f.solve(Fz=1e4, **MOTION)[1][0]
        for name in ("Fn", "Fx", "Fs"):
            assert pf[name] == pytest.approx(pe[name], abs=0.03 * 0.3 * pe["Fn"])


def test_profiles_meet_at_the_contact():
    """The contact point lies on the rail's profile and within the patch's
    approach of the wheel's, in track coordinates."""
    with creepwork.WheelRail(RAIL, WHEEL) as w:
        _, patches = w.solve(Fz=1e4, **MOTION)
        p = patches[0]
        for which, bound in (("rail", 1e-6), ("wheel", p["approach"] + 2e-6)):
            y, z = w.profile(which)
            ey, ez = np.diff(y), np.diff(z)
            t = ((p["y_contact"] - y[:-1]) * ey + (p["z_contact"] - z[:-1]) * ez) / (ey ** 2 + ez ** 2)
            t = np.clip(t, 0.0, 1.0)
            d = np.hypot(y[:-1] + t * ey - p["y_contact"], z[:-1] + t * ez - p["z_contact"]).min()
            assert d <= bound
        with pytest.raises(creepwork.UnknownOptionError, match="'axle'"):
            w.profile("axle")


def test_left_wheel_wears_the_same_profile_grid():
    """Mirror symmetry: the left wheel at the mirrored position (y, yaw and
    roll negated) wears the rail's and the wheel's grids (the profiles' y as
    their points are given) as the right wheel does, to 2e-6 of the peak: two
    force balances each meet Fz to 1e-6 and may accept heights that far
    apart (test_wheelrail_patch_capi's sides_mirror)."""
    mirrored = dict(MOTION, y=-MOTION["y"], yaw=-MOTION["yaw"], roll=-MOTION["roll"])
    depths = []
    for side, motion in ((creepwork.CW_WHEELRAIL_RIGHT, MOTION), (creepwork.CW_WHEELRAIL_LEFT, mirrored)):
        with creepwork.WheelRail(RAIL, WHEEL, side=side) as w:
            w.solve(Fz=1e4, **motion)
            rail = creepwork.WearProfile(np.linspace(-0.04, 0.04, 1601))
            wheel = creepwork.WearProfile(np.linspace(-0.04, 0.04, 1601))
            w.add_wear(1e3, rail=rail, wheel=wheel)
            depths.append((rail.depth("height"), wheel.depth("height")))
    for right, left in zip(depths[0], depths[1]):
        assert right.max() > 0
        np.testing.assert_allclose(left, right, rtol=0, atol=2e-6 * right.max())
