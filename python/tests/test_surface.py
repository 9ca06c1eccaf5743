"""Temperature and Damage (surface temperature and damage indices) against
the relations the header states for them, so that a field read into the
wrong array, a default from the wrong slot or the solve's rolling direction
not passed on fails."""

import warnings

import numpy as np
import pytest

import creepwork

CONTACT = dict(a=7e-3, b=5e-3, N=100e3, xi_x=1.5e-3, xi_y=-5e-4, phi=0.5)
GRID = {"kind": "uniform", "nx": 24, "ny": 20, "box_scale": 1.2}


def steel_beta(conductivity=50.0):
    return np.sqrt(conductivity * 7850.0 * 450.0)


def test_temperature_of_dissimilar_bodies():
    with creepwork.Solver(GRID) as s:
        r = s.solve(rolling_direction=-1, **CONTACT)
        t = s.temperature(rolling_speed=30.0, T0_1=10.0, T0_2=70.0, conductivity_2=200.0)
        inside = r.state >= 1
        # "T_c = (b1 T0_1 + b2 T0_2)/(b1 + b2), b = sqrt(lambda rho c)", b2 = 2 b1 here
        b1, b2 = steel_beta(), steel_beta(200.0)
        assert t.contact_temperature == pytest.approx((b1 * 10 + b2 * 70) / (b1 + b2), rel=1e-14)
        # one surface temperature in contact; the maxima are the contact's largest values
        assert np.array_equal(t.rail[inside], t.wheel[inside])
        assert t.T_max_1 == t.rail[inside].max() and t.T_max_2 == t.wheel[inside].max()
        j, i = np.unravel_index(np.where(inside, t.rail, -np.inf).argmax(), t.rail.shape)
        assert (t.x_max_1, t.y_max_1) == (r.x[j, i], r.y[j, i])
        # "power: total frictional power, sum of q area": V times the work map's sum
        assert t.power == pytest.approx(30.0 * r.W_consistent, rel=1e-12)
        assert t.power == pytest.approx((t.heat * r.area).sum(), rel=1e-12)
        assert t.iterations == 1 and t.discretisation == creepwork.CW_TEMPERATURE_CONSISTENT
        # the solve's rolling direction is passed on: rolling towards -x the
        # material meets the low-x side first, so the hottest contact element
        # lies on the high-x half; the default is the solve's own direction,
        # 0 takes it too, and the other one is refused naming both
        assert t.x_max_1 > 0
        same = s.temperature(rolling_speed=30.0, T0_1=10.0, T0_2=70.0, conductivity_2=200.0,
                             rolling_direction=-1)
        solves = s.temperature(rolling_speed=30.0, T0_1=10.0, T0_2=70.0, conductivity_2=200.0,
                               rolling_direction=0)
        assert np.array_equal(same.rail, t.rail) and np.array_equal(solves.rail, t.rail)
        with pytest.raises(creepwork.InvalidInputError, match="cw_params.rolling_direction"):
            s.temperature(rolling_speed=30.0, T0_1=10.0, T0_2=70.0, conductivity_2=200.0,
                          rolling_direction=1)
        # CONTACT's discretisation: its body-1 flash is beta2/beta1 of body 2's
        c = s.temperature(rolling_speed=30.0, T0_1=0.0, T0_2=0.0, conductivity_2=200.0,
                          discretisation="contact")
        assert c.discretisation == creepwork.CW_TEMPERATURE_CONTACT
        np.testing.assert_allclose(c.rail[inside], b2 / b1 * c.wheel[inside], rtol=1e-12)


def test_temperature_against_a_direct_sum():
    """Every element against the moving-source sum written here with numpy
    from the solve's fields (Kalker's strip grid: each strip its own element
    length, taken from the centres): per row, in the order the material
    meets the elements, the heat V W/A of each upstream element integrated
    exactly, half the element itself; equal bodies at one bulk temperature."""
    with creepwork.Solver({"nx": 18, "ny": 12}) as s:
        r = s.solve(**CONTACT)
        t = s.temperature(rolling_speed=25.0, T0_1=20.0, T0_2=20.0)
        q = np.where(r.area > 0, 25.0 * np.maximum(r.work_consistent, 0) / np.where(
            r.area > 0, r.area, 1), 0.0)
        C = 1.0 / (2 * steel_beta() * np.sqrt(np.pi * 25.0))
        ref = np.empty_like(q)
        for j in range(r.x.shape[0]):
            x = r.x[j, ::-1]  # rolling towards +x: the material meets high x first
            h = 0.5 * abs(x[1] - x[0])
            qr = q[j, ::-1]
            d = np.abs(x[:, None] - x[None, :])  # [t, u]
            w = np.where(np.arange(len(x))[None, :] < np.arange(len(x))[:, None],
                         2 * (np.sqrt(d + h) - np.sqrt(np.maximum(d - h, 0))), 0.0)
            w[np.diag_indices(len(x))] = 2 * np.sqrt(h)
            ref[j, ::-1] = 20.0 + C * (w @ qr)
        np.testing.assert_allclose(t.rail, ref, rtol=1e-10, atol=0)
        assert np.array_equal(t.rail, t.wheel)


def test_damage_indices_in_full_sliding():
    with creepwork.Solver(GRID) as s:
        r = s.solve(a=7e-3, b=5e-3, N=100e3, mu=0.3, xi_x=0.05)
        assert r.n_adhesion == 0
        d = s.damage(k_yield=200e6)
        inside = (r.state >= 1) & (r.pz > 0)
        # "-0.5 outside the contact; in it max(-0.5, (|p_t| - k_yield)/p_n)"
        expect = np.full(r.pz.shape, -0.5)
        expect[inside] = np.maximum(-0.5, 0.3 - 200e6 / r.pz[inside])
        np.testing.assert_allclose(d.rcf_index, expect, rtol=0, atol=1e-12)
        assert d.rcf_index_max == pytest.approx(expect.max(), abs=1e-12)
        # "sums (x area) to W_macro"
        assert (d.t_gamma_density * r.area).sum() == pytest.approx(r.W_macro, rel=1e-12)
        assert d.T_gamma == r.W_macro
        # "FI_surf: mu_eff - 2 A k_yield / (3 N), A = pi a b"
        mu_eff = np.hypot(r.Fx, r.Fy) / 100e3
        assert d.FI_surf == pytest.approx(mu_eff - 2 * np.pi * 7e-3 * 5e-3 * 200e6 / 3e5,
                                          rel=1e-13)


def test_errors_name_the_input():
    with creepwork.Solver() as s:
        s.solve(**CONTACT)
        with pytest.raises(creepwork.InvalidInputError, match="rolling_speed"):
            s.temperature()  # no rolling speed: none given, the solve's V is 0
        with pytest.raises(creepwork.InvalidInputError, match="density_1"):
            s.temperature(rolling_speed=30.0, density_1=7.85e-6)
        with pytest.raises(creepwork.InvalidInputError, match="k_yield"):
            s.damage()
        with pytest.raises(creepwork.InvalidInputError, match="wlrm_zero"):
            s.damage(k_yield=3e8, wlrm_zero=50.0)
        s.solve(fields=False, **CONTACT)
        with pytest.raises(creepwork.NoWorkError):
            s.temperature(rolling_speed=30.0)


def _unit_warnings(call, **keywords):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        call(**keywords)
    return [str(w.message) for w in caught if issubclass(w.category, creepwork.UnitWarning)]


def test_implausible_units_warn():
    # The library's rules (header, cw_temperature_params_check and
    # cw_damage_params_check): a value just beyond a threshold warns with
    # the library's message, just inside is silent.
    implausible = " is implausible for a wheel-rail contact: "
    with creepwork.Solver() as s:
        s.solve(**CONTACT)
        assert _unit_warnings(s.temperature, rolling_speed=30.0, conductivity_1=1.01) == []
        (w,) = _unit_warnings(s.temperature, rolling_speed=30.0, conductivity_1=0.05)
        assert w.startswith("conductivity_1 = 0.05 W/(m K)" + implausible)
        assert "W/(mm K) typed as W/(m K)?" in w
        (w,) = _unit_warnings(s.temperature, rolling_speed=30.0, heat_capacity_2=99.0)
        assert w.startswith("heat_capacity_2 = 99 J/kg/K" + implausible)
        (w,) = _unit_warnings(s.temperature, rolling_speed=30.0, density_1=7.85)
        assert w.startswith("density_1 = 7.85 kg/m^3" + implausible)
        assert _unit_warnings(s.temperature, rolling_speed=149.5) == []
        (w,) = _unit_warnings(s.temperature, rolling_speed=150.5)
        assert w.startswith("rolling_speed = 150.5 m/s" + implausible)
        assert "km/h typed as m/s?" in w
        assert _unit_warnings(s.temperature, warn=False, rolling_speed=300.0) == []
        assert _unit_warnings(s.damage, k_yield=1.01e6) == []
        (w,) = _unit_warnings(s.damage, k_yield=300.0)
        assert w.startswith("k_yield = 300 Pa" + implausible)
        assert "MPa or N/mm^2 typed as Pa?" in w
        (w,) = _unit_warnings(s.damage, k_yield=3e8, wlrm_onset=0.0, wlrm_peak=0.065,
                              wlrm_zero=175.0)
        assert w.startswith("wlrm_peak = 0.065 N" + implausible)


EURO = dict(a=6.304e-3, b=12.61e-3, N=106.7e3, V=10.0, xi_x=0.25, model="exact")
EURO_GRID = {"kind": "uniform", "nx": 44, "ny": 44, "box_scale": 1.1}
EURO_TEMPERATURE = dict(T0_1=0.0, T0_2=0.0, discretisation="contact")


def test_mu_of_temperature_as_the_c_abi():
    """solve_mu_T: CONTACT's euro_tractcurv at 25 % creepage (L=6, -0.19 over
    400 deg C; Fx/(0.33 N) = -0.6108, T_max 364.7 deg C printed, within the
    C test's tolerances), the fields those of the last solve, and the same
    bits as the CLI's JSON (cw_temperature_solve behind both)."""
    import json
    import os
    import subprocess
    with creepwork.Solver(EURO_GRID) as s:
        r, t = s.solve_mu_T([(0.0, 0.33), (400.0, 0.14)], temperature=EURO_TEMPERATURE, **EURO)
        assert abs(r.Fx / (0.33 * 106.7e3) + 0.6108) <= 5.5e-4
        assert abs(max(t.T_max_1, t.T_max_2) - 364.7) <= 2e-3 * 364.7
        assert t.iterations > 2
        assert t.T_max_1 == t.rail.max()
        assert r.Fx == s.result().Fx
        cli = os.environ.get("CREEPWORK_CLI")
        if cli:
            out = subprocess.run(
                [cli, "solve", "--model", "exact", "--a", "6.304e-3", "--b", "12.61e-3", "--N",
                 "106.7e3", "--V", "10", "--xi-x", "0.25", "--nx", "44", "--ny", "44",
                 "--box-scale", "1.1", "--temperature", "--T0-1", "0", "--T0-2", "0",
                 "--temperature-discretisation", "contact", "--mu-T", "0:0.33,400:0.14",
                 "--format", "json"], check=True, capture_output=True, text=True).stdout
            j = json.loads(out)
            assert j["Fx"] == r.Fx and j["T_max_1"] == t.T_max_1
            assert j["temperature_iterations"] == t.iterations


def test_mu_of_temperature_errors_name_the_entry():
    with creepwork.Solver(EURO_GRID) as s:
        with pytest.raises(creepwork.InvalidInputError, match=r"temperature\[1\]"):
            s.solve_mu_T([(400.0, 0.33), (0.0, 0.14)], temperature=EURO_TEMPERATURE, **EURO)
        with pytest.raises(creepwork.InvalidInputError, match="count"):
            s.solve_mu_T([(0.0, 0.33)], temperature=EURO_TEMPERATURE, **EURO)
        with pytest.raises(creepwork.InvalidInputError, match=r"mu\[1\]"):
            s.solve_mu_T([(0.0, 0.33), (400.0, float("nan"))], temperature=EURO_TEMPERATURE,
                         **EURO)
        with pytest.raises(creepwork.InvalidInputError, match="mu_T"):
            s.solve_mu_T([(0.0, 0.33), (400.0, 0.14)], temperature=EURO_TEMPERATURE,
                         **dict(EURO, model="calibrated"))
        with pytest.raises(creepwork.NoSolutionError):
            s.result()
