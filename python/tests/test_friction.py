"""A friction law of the slip speed through the Python package: keywords
(friction_law="exponential", mu_e1=..., s_h1=..., friction_speed="global",
k0=...) and polach=(mu0, A, B), against CONTACT's tractcurv example
(tests/data/contact_tractcurv.csv, series 4: FASTSIM with the exponential
law at the contact's slip speed and Spiryagin's reduction) and Polach's
full-sliding closed form; polach= gives the bits of the fields
cw_friction_polach writes; solve_many the bits of solve; bad inputs raise
naming them; a half speed in mm/s warns; the exact model with a law
against CONTACT's exact theory; the interface layer's keywords (layer_h,
layer_G, tau_c0, k_tau) against CONTACT's exact theory with the layer, named
when bad, warned about in mm."""

import csv
import math
import os
import warnings

import numpy as np
import pytest

import creepwork

GRID = {"kind": "uniform", "nx": 48, "ny": 44, "box_scale": 1.1}
N, V = 106.7e3, 10.0


def tractcurv(**keywords):
    """CONTACT's tractcurv contact (examples/tractcurv.inp): semi-axes as
    CONTACT prints them, the parabolic bound carrying N exactly."""
    out = dict(a=6.304e-3, b=12.61e-3, N=N, exact_load=1, V=V)
    out.update(keywords)
    return out


SERIES4 = dict(friction_law="exponential", mu=0.1368, mu_e1=0.2232, s_h1=0.990,
               friction_speed="global", k0=0.54, alpha_inf=0.02, beta=0.62)


def rows(test_data_dir, series):
    with open(os.path.join(test_data_dir, "contact_tractcurv.csv"), newline="") as f:
        return [r for r in csv.DictReader(f) if int(r["series"]) == series]


def half_unit(text):
    mant, _, exp = text.lower().partition("e")
    decimals = len(mant.partition(".")[2])
    return 0.5 * 10.0 ** (int(exp or 0) - decimals)


def test_series4_of_tractcurv(test_data_dir):
    """Every creepage of series 4: Fx/(mu_s N) within half CONTACT's last
    printed digit + 6e-5 (creepwork's FASTSIM and CONTACT's differ by up to
    5e-5 with Coulomb's law), the slip area element for element, mu(w)."""
    table = rows(test_data_dir, 4)
    assert len(table) == 30
    with creepwork.Solver(GRID) as s:
        for r in table:
            xi = float(r["CKSI"])
            res = s.solve(tractcurv(xi_x=xi, **SERIES4), fields=False)
            ref = r["FX_over_FSTAT_FN"]
            assert res.Fx / (0.36 * N) == pytest.approx(float(ref), abs=half_unit(ref) + 6e-5)
            assert res.n_slip == int(r["NSLIP"])
            assert res.mu_static == pytest.approx(0.36, abs=1e-15)
            mu_w = 0.1368 + 0.2232 * math.exp(-math.log(2) * V * xi / 0.990)
            assert res.mu_min == pytest.approx(mu_w, abs=1e-15) and res.mu_max == res.mu_min


def test_polach_gives_the_bits_of_its_fields(test_data_dir):
    """polach=(0.36, 0.38, 0.7) is the record cw_friction_polach writes
    (mu = A mu0, mu_e1 = (1 - A) mu0, s_h1 = ln2/B) and solves to its bits;
    in full sliding (series 4 from 12.5 %) the law at every element meets
    Polach's closed form A + (1 - A) exp(-B xi V) within 2e-4."""
    p = creepwork.params(polach=(0.36, 0.38, 0.7))
    assert p["friction_law"] == creepwork.CW_FRICTION_EXPONENTIAL
    assert p["mu"] == pytest.approx(0.38 * 0.36, rel=1e-15)
    assert p["mu_e1"] == pytest.approx(0.62 * 0.36, rel=1e-15)
    assert p["s_h1"] == pytest.approx(math.log(2) / 0.7, rel=1e-15)
    fields = {k: p[k].item() for k in ("mu", "mu_e1", "s_h1")}
    full = [r for r in rows(test_data_dir, 4) if int(r["NADH"]) == 0]
    assert len(full) == 6
    with creepwork.Solver(GRID) as s:
        for r in full:
            xi = float(r["CKSI"])
            a = s.solve(tractcurv(xi_x=xi, polach=(0.36, 0.38, 0.7)), fields=False)
            b = s.solve(tractcurv(xi_x=xi, friction_law="exponential", **fields), fields=False)
            assert (a.Fx, a.Fy, a.Mz, a.mu_min, a.mu_max) == (b.Fx, b.Fy, b.Mz, b.mu_min, b.mu_max)
            closed = 0.38 + 0.62 * math.exp(-0.7 * xi * V)
            assert -a.Fx / (0.36 * N) == pytest.approx(closed, abs=2e-4)


def test_solve_many_gives_solve_bits():
    """The batch with polach= arrays broadcast: each contact bitwise solve()'s."""
    xi = np.array([0.004, 0.02, 0.1])
    A = np.array([0.38, 0.5, 0.38])
    many = creepwork.solve_many(grid=GRID, xi_x=xi, polach=(0.36, A, 0.7), **tractcurv())
    assert list(many.status) == [0, 0, 0]
    for k in range(3):
        one = creepwork.solve(grid=GRID, xi_x=xi[k], polach=(0.36, A[k], 0.7), fields=False,
                              **tractcurv())
        assert (many.Fx[k], many.Fy[k], many.mu_min[k]) == (one.Fx, one.Fy, one.mu_min)


EXACT_LAW = dict(model="exact", pressure="elliptic", exact_load=0, friction_law="exponential",
                 mu=0.14, mu_e1=0.19, s_h1=1.25)


def test_exact_model_with_a_law(test_data_dir):
    """The exact model with the exponential law alone (CONTACT's FKIN 0.14,
    FEXP1 0.19, SABSH1 1250 mm/s; tests/data/contact_tractcurv_exponential.csv):
    every pure-creepage row within half CONTACT's last printed digit of
    Fx/(mu_s N) and its slip area; with fields the work map sums to W_macro
    (1e-9), mu_min and mu_max bound the law at the slip speeds |s| V; a
    Coulomb solve after it on the same Solver gives a new Solver's bits."""
    with open(os.path.join(test_data_dir, "contact_tractcurv_exponential.csv"), newline="") as f:
        table = [r for r in csv.DictReader(f)
                 if float(r["CETA"]) == 0.0 and float(r["CPHI_per_mm"]) == 0.0]
    assert len(table) >= 10
    with creepwork.Solver(GRID) as s:
        for r in table:
            res = s.solve(tractcurv(xi_x=float(r["CKSI"]), **EXACT_LAW), fields=False)
            ref = r["FX_over_FSTAT_FN"]
            assert res.Fx / (0.33 * N) == pytest.approx(float(ref), abs=half_unit(ref))
            assert res.n_slip == int(r["NSLIP"])
        res = s.solve(tractcurv(xi_x=3e-3, **EXACT_LAW))
        assert abs(res.work_consistent.sum() - res.W_macro) <= 1e-9 * res.W_macro
        slipping = res.state == 2  # CW_STATE_SLIP
        mu = 0.14 + 0.19 * np.exp(-math.log(2) * np.hypot(res.sx, res.sy)[slipping] * V / 1.25)
        # mu_min/mu_max come from the last local friction solve, the reported
        # slip from the final iterate: they agree to the solver's tolerance
        # (1e-8 of the slip), and |dmu/d|s|| |s| <= 0.19/e = 0.07 for this law,
        # so to 7e-10 (a warm solve's last Newton update need not end in a sweep).
        assert res.mu_min == pytest.approx(mu.min(), abs=1e-9)
        assert res.mu_max == pytest.approx(mu.max(), abs=1e-9)
        coulomb = tractcurv(xi_x=3e-3, **dict(EXACT_LAW, friction_law="coulomb", mu=0.33))
        after = s.solve(coulomb)
    with creepwork.Solver(GRID) as fresh:
        new = fresh.solve(coulomb)
    assert (after.Fx, after.Fy, after.Mz, after.W_macro) == (new.Fx, new.Fy, new.Mz, new.W_macro)
    assert after.px.tobytes() == new.px.tobytes()


def test_exact_model_with_memory(test_data_dir):
    """Friction memory reaches the exact model (CONTACT's MEMDST 3 um,
    MEM_S0 1 mm/s with the exponential law; tests/data/contact_tractcurv_memory.csv):
    every row within half CONTACT's last printed digit of Fx/(mu_s N); the
    Jacobian's dFx/dxi_x at 2 % against central differences (1e-4)."""
    with open(os.path.join(test_data_dir, "contact_tractcurv_memory.csv"), newline="") as f:
        table = list(csv.DictReader(f))
    assert len(table) == 6
    memory = dict(EXACT_LAW, memory_distance=3e-6, memory_s0=1e-3)
    with creepwork.Solver(GRID) as s:
        for r in table:
            res = s.solve(tractcurv(xi_x=float(r["CKSI"]), **memory), fields=False)
            ref = r["FX_over_FSTAT_FN"]
            assert res.Fx / (0.33 * N) == pytest.approx(float(ref), abs=half_unit(ref))
        cold = dict(memory, tolerance=1e-12, warm_start=0)
        J = s.jacobian(tractcurv(xi_x=0.02, **cold)).jacobian
        h = 1e-5 * 0.02
        up = s.solve(tractcurv(xi_x=0.02 + h, **cold), fields=False).Fx
        down = s.solve(tractcurv(xi_x=0.02 - h, **cold), fields=False).Fx
        assert J[0][0] > 0.0  # past the peak |Fx| falls (Fx < 0)
        assert J[0][0] == pytest.approx((up - down) / (2 * h), rel=1e-4)


@pytest.mark.parametrize("keywords, name", [
    (dict(friction_law="exponential", mu_e1=0.2, s_h1=1.0, V=0.0), "V"),
    (dict(friction_law="exponential", mu_e1=-0.2, s_h1=1.0), "mu_e1"),
    (dict(friction_law="rational", mu_e1=0.2, s_h1=0.0), "s_h1"),
    (dict(polach=(0.36, 1.5, 0.7)), "polach_A"),
    (dict(polach=(0.36, 0.38, -1.0)), "polach_B"),
    (dict(friction_law="linear", mu_e1=0.2, s_h1=1.0, model="calibrated"), "friction_law"),
    (dict(friction_speed="global", k0=0.0, friction_law="exponential", mu_e1=0.2, s_h1=1.0),
     "k0"),
    (dict(friction_law="exponential", mu_e1=0.2, s_h1=1.0, memory_distance=-1.0),
     "memory_distance"),
])
def test_bad_inputs_are_named(keywords, name):
    with pytest.raises(creepwork.InvalidInputError, match=r"\b%s\b" % name):
        creepwork.solve(fields=False, **tractcurv(xi_x=0.01, **keywords))


def test_unknown_law_is_named():
    with pytest.raises(creepwork.UnknownOptionError, match="friction_law"):
        creepwork.solve(fields=False, **tractcurv(xi_x=0.01, friction_law="stribeck"))
    with pytest.raises(TypeError, match="polach"):
        creepwork.solve(fields=False, **tractcurv(xi_x=0.01, polach=(0.36, 0.38, 0.7), mu_e1=0.1))


def test_local_law_gives_the_work_map():
    """FASTSIM with Polach's law at every element, with fields: the
    energy-consistent map sums to W_macro (1e-12), is >= 0 and 0 outside
    slip (the march's energy identity); the forces are forces mode's."""
    case = tractcurv(xi_x=0.004, polach=(0.36, 0.38, 0.7))
    res = creepwork.solve(fields=True, **case)
    forces = creepwork.solve(fields=False, **case)
    assert res.Fx == forces.Fx and res.W_macro == forces.W_macro
    assert abs(res.work_consistent.sum() - res.W_macro) <= 1e-12 * res.W_macro
    assert (res.work_consistent >= 0.0).all()
    assert (res.work_consistent[res.state != 2] == 0.0).all()


def test_half_speed_in_mm_per_s_warns():
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        creepwork.solve(fields=False, **tractcurv(xi_x=0.01, friction_law="exponential",
                                                  mu=0.1368, mu_e1=0.2232, s_h1=990.0))
    messages = [str(w.message) for w in caught if issubclass(w.category, creepwork.UnitWarning)]
    assert len(messages) == 1 and messages[0].startswith("s_h1 = 990 m/s")


LAYER = dict(model="exact", pressure="elliptic", exact_load=0, mu=0.33,
             layer_h=1.25e-3, layer_G=8.2e9)


def test_interface_layer_against_contact(test_data_dir):
    """The exact model with tractcurv's elastic layer (layer_h, layer_G as
    keywords) meets CONTACT's printed Fx/(mu N) of the layer alone
    (tests/data/contact_tractcurv_layer.csv) to half a unit of its last
    digit, and its adhesion count."""
    with open(os.path.join(test_data_dir, "contact_tractcurv_layer.csv"), newline="") as f:
        table = [r for r in csv.DictReader(f) if r["CETA"] == "0.000" and r["CPHI_per_mm"] == "0.000"]
    assert len(table) == 30
    for r in table[::5]:
        res = creepwork.solve(fields=False, grid=GRID, **tractcurv(xi_x=float(r["CKSI"]), **LAYER))
        printed = r["FX_over_FSTAT_FN"]
        assert res.Fx / (0.33 * N) == pytest.approx(float(printed), abs=half_unit(printed))
        assert res.n_adhesion == int(r["NADH"])


@pytest.mark.parametrize("keywords, name", [
    (dict(LAYER, layer_G=0.0), "layer_G"),
    (dict(LAYER, tau_c0=-1.0), "tau_c0"),
    (dict(LAYER, k_tau=1e9), "k_tau"),  # needs tau_c0
    (dict(layer_h=1.25e-3, layer_G=8.2e9), "layer_h"),  # FASTSIM has no layer
])
def test_bad_layer_inputs_are_named(keywords, name):
    with pytest.raises(creepwork.InvalidInputError, match=r"\b%s\b" % name):
        creepwork.solve(fields=False, **tractcurv(xi_x=0.01, **keywords))


def test_layer_in_mm_warns():
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        creepwork.solve(fields=False, grid=GRID, **tractcurv(xi_x=0.002, **dict(LAYER, layer_h=1.25)))
    messages = [str(w.message) for w in caught if issubclass(w.category, creepwork.UnitWarning)]
    assert len(messages) == 1 and messages[0].startswith("layer_h = 1.25 m")
