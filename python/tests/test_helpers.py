"""The linear-theory and Hertz helpers and Kalker's normalised FASTSIM
against published values: Kalker 1990 Table E.3, Kalker's 1982 check
values (tests/data), the header's Hertz example."""

import csv
import math
import os

import pytest

import creepwork


def read(test_data_dir, name):
    with open(os.path.join(test_data_dir, name), newline="") as f:
        return list(csv.DictReader(f))


def test_kalker_coefficients_reproduce_table_e3(test_data_dir):
    """Every entry of Kalker 1990, Table E.3 at its table point (the CSV's a/b
    is rounded; the exact point is its g column), to 1e-12."""
    rows = read(test_data_dir, "kalker_cij.csv")
    assert len(rows) == 57
    for row in rows:
        g, a_over_b = float(row["g"]), float(row["a_over_b"])
        c = creepwork.kalker_coefficients(g if a_over_b <= 1 else 1 / g, float(row["nu"]))
        for name in ("C11", "C22", "C23", "C33"):
            assert getattr(c, name) == pytest.approx(float(row[name]), rel=1e-12), (row, name)


def test_flexibilities_from_their_formulas():
    """Header: L1 = 8a/(3 C11 G), L2 = 8a/(3 C22 G), L3 = pi a sqrt(a/b)/(4 C23 G)."""
    a, b, G, nu = 7e-3, 5e-3, 82e9, 0.28
    c = creepwork.kalker_coefficients(a / b, nu)
    L = creepwork.kalker_flexibilities(a, b, G, nu)
    assert L.L1 == pytest.approx(8 * a / (3 * c.C11 * G), rel=1e-14)
    assert L.L2 == pytest.approx(8 * a / (3 * c.C22 * G), rel=1e-14)
    assert L.L3 == pytest.approx(math.pi * a * math.sqrt(a / b) / (4 * c.C23 * G), rel=1e-14)
    r = creepwork.solve(a=a, b=b, N=100e3, G=G, nu=nu, fields=False)
    assert (r.L1, r.L2, r.L3) == pytest.approx(tuple(L), rel=1e-15)


def test_hertz_example_of_the_header():
    """Wheel radius 0.457 m on a rail crown of 0.3 m, 100 kN, G = 82 GPa,
    nu = 0.28: a = 7.170 mm, b = 5.417 mm, p0 = 1229 MPa."""
    h = creepwork.hertz(1 / (2 * 0.457), 1 / (2 * 0.3), 100e3, 82e9 / (1 - 0.28))
    assert round(h.a * 1e3, 3) == 7.170 and round(h.b * 1e3, 3) == 5.417
    assert round(h.p0 / 1e6) == 1229
    # Hertz: N = (2/3) p0 pi a b
    assert 2 / 3 * h.p0 * math.pi * h.a * h.b == pytest.approx(100e3, rel=1e-12)
    with pytest.raises(creepwork.InvalidInputError, match="E_star|modulus"):
        creepwork.hertz(1.0, 1.0, 100e3, -1.0)


def test_fastsim_normalised_reproduces_kalker_1982(test_data_dir):
    """Kalker's published check values (Kalker 1982, 5 x 5), to their 4 decimals."""
    rows = read(test_data_dir, "kalker1982_checks.csv")
    assert len(rows) == 5
    for row in rows:
        tx, ty = creepwork.fastsim_normalised(*(float(row[k]) for k in ("ux", "uy", "fx", "fy")),
                                              int(row["mx"]), int(row["my"]), float(row["tol"]))
        assert abs(tx - float(row["Tx_published"])) <= 0.5e-4, row
        assert abs(ty - float(row["Ty_published"])) <= 0.5e-4, row


def test_versions():
    assert creepwork.version() == creepwork.__version__
    assert creepwork.version_number() == creepwork.CW_VERSION_NUMBER
