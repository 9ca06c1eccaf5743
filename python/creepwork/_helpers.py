"""Linear theory and Hertz helpers, Kalker's normalised FASTSIM, versions."""

import ctypes
from typing import Tuple
from collections import namedtuple

import numpy as np

from . import _errors
from ._library import CONSTANTS, address, lib

_MESSAGE_LEN = 512

KalkerCoefficients = namedtuple("KalkerCoefficients", "C11 C22 C23 C33")
Flexibilities = namedtuple("Flexibilities", "L1 L2 L3")
Hertz = namedtuple("Hertz", "a b p0 approach")
Hertz.__doc__ = "Hertz contact: semi-axes a (along x), b [m], maximum pressure p0 [Pa], approach [m]."


def _call(function, *args):
    """Calls a helper whose last two arguments are a message buffer and its length."""
    message = ctypes.create_string_buffer(_MESSAGE_LEN)
    _errors.check(function(*args, message, _MESSAGE_LEN), lambda: message.value)


def kalker_coefficients(a_over_b: float, nu: float) -> "KalkerCoefficients":
    """Kalker's creepage coefficients C11, C22, C23, C33 [-] for the semi-axis
    ratio a/b in [1e-3, 1e3] and Poisson's ratio nu in [0, 0.5] (Kalker 1990,
    Table E.3, interpolated as CONTACT does; cw_kalker_coefficients)."""
    out = np.empty(4)
    _call(lib.cw_kalker_coefficients, float(a_over_b), float(nu), address(out))
    return KalkerCoefficients(*out.tolist())


def kalker_flexibilities(a: float, b: float, G: float, nu: float) -> "Flexibilities":
    """The simplified theory's flexibilities L1, L2, L3 [m/Pa] of an a x b [m]
    ellipse, G [Pa], nu [-]: L1 = 8a/(3 C11 G), L2 = 8a/(3 C22 G),
    L3 = pi a sqrt(a/b)/(4 C23 G) (cw_kalker_flexibilities)."""
    out = np.empty(3)
    _call(lib.cw_kalker_flexibilities, float(a), float(b), float(G), float(nu), address(out))
    return Flexibilities(*out.tolist())


def hertz(A: float, B: float, N: float, E_star: float) -> "Hertz":
    """Hertz contact of elastically similar bodies (cw_hertz_solve): A, B > 0
    [1/m] the coefficients of the gap z = A x^2 + B y^2, i.e. HALF the
    relative curvatures, A = (1/R1x + 1/R2x)/2 along x (rolling), B across;
    N >= 0 [N]; E_star > 0 [Pa] (G/(1 - nu) for identical materials).
    Returns Hertz(a, b, p0, approach). Example: a 0.457 m wheel on a 0.3 m
    rail crown, hertz(1/(2*0.457), 1/(2*0.3), 100e3, 82e9/(1 - 0.28)) gives
    a = 7.170 mm, b = 5.417 mm, p0 = 1229 MPa."""
    out = np.empty(4)
    _call(lib.cw_hertz_solve, float(A), float(B), float(N), float(E_star), address(out))
    return Hertz(*out.tolist())


def fastsim_normalised(ux: float, uy: float, fx: float, fy: float, mx: int = 20, my: int = 20,
                       tol: float = 0.0) -> Tuple[float, float]:
    """Kalker's original normalised FASTSIM (1982, his SIM routine;
    cw_fastsim_normalised): normalised creepages ux, uy and spin terms fx, fy
    on the unit disk, mx elements per strip, my strips cut at the spin pole
    (tol as Kalker's). Returns (tx, ty) with Kalker's published signs:
    tx = -Fx/(mu N), ty = +Fy/(mu N) in solve()'s convention."""
    tx, ty = ctypes.c_double(), ctypes.c_double()
    _call(lib.cw_fastsim_normalised, float(ux), float(uy), float(fx), float(fy), int(mx), int(my),
          float(tol), ctypes.byref(tx), ctypes.byref(ty))
    return tx.value, ty.value


def version() -> str:
    """The loaded library's version string, e.g. "1.1.0"."""
    return lib.cw_version_string().decode()


def version_number() -> int:
    """The loaded library's 10000*major + 100*minor + patch."""
    return lib.cw_version_number()


def status_string(status: int) -> str:
    """The static message of a status code (cw_status_string)."""
    return lib.cw_status_string(int(status)).decode()


#: The version of the header the package was generated from.
HEADER_VERSION_NUMBER = CONSTANTS["CW_VERSION_NUMBER"]
