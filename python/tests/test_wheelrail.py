"""creepwork.WheelRail against CONTACT's module 1 on the Manchester benchmark
(case A-2.2, right wheel at y_ws = 3 mm, 10 kN: FN 9774 N, FX -417.5 N,
FS -2902 N, p_max 713.2 N/mm^2, z_ws 0.1143 mm; CONTACT's
examples/mbench_a22_right.ref_out): forces within 1 % of the load, p_max
within 3 %; the height prescribed gives the same forces; errors name the
input; implausible units warn."""

import os
import warnings

import pytest

import creepwork

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


def test_implausible_units_warn():
    with creepwork.WheelRail(RAIL, WHEEL) as w:
        with pytest.warns(creepwork.UnitWarning, match="Fz = 10 N"):
            w.solve(Fz=10.0, **MOTION)
    with pytest.warns(creepwork.UnitWarning, match="G = 82000 Pa"):
        creepwork.WheelRail(RAIL, WHEEL, G=82000.0).close()
