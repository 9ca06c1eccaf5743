"""Wear of a solved contact (cw_wear), its accumulation on a profile grid
(cw_wear_profile), the profile update helper, and the work accumulator of
simulation loops (cw_accumulator). Units SI; depths per pass (one axle
passage for a rail, one wheel revolution for a wheel)."""

import ctypes
from typing import TYPE_CHECKING, Any, Dict, Sequence, Union
from collections import namedtuple

import numpy as np

from . import _errors
from ._handle import Handle
from ._library import CONSTANTS, DTYPES, address, lib
from ._params import WEAR_PARAMS

if TYPE_CHECKING:
    from ._solver import Solver

_MESSAGE_LEN = 512
ArrayLike = Union[np.ndarray, Sequence[float]]


def _named(prefix):
    return {n[len(prefix):].lower(): v for n, v in CONSTANTS.items() if n.startswith(prefix)}


#: Wear field name -> CW_WEAR_FIELD_* id: rate, depth, mass, work_density, sliding.
WEAR_FIELDS = _named("CW_WEAR_FIELD_")
#: Depth kinds of WearProfile.depth: normal, height.
DEPTH_KINDS = _named("CW_WEAR_DEPTH_")
#: Accumulated work maps of Accumulator.field.
WORK_FIELDS = {"work_paper": CONSTANTS["CW_FIELD_WORK_PAPER"],
               "work_consistent": CONSTANTS["CW_FIELD_WORK_CONSISTENT"]}

Strips = namedtuple("Strips", "y width depth parabola")
Strips.__doc__ = """The lateral wear profile per strip j: centre y [m], width [m], depth per
pass [m], and the paper's parabola with the same worn cross-section [m]."""


def _totals(rec):
    return {name: (rec[name].copy() if rec.dtype.fields[name][0].shape else rec[name].item())
            for name in rec.dtype.names[1:]}


def _unknown(what, name, known):
    return _errors.BY_STATUS[CONSTANTS["CW_ERR_UNKNOWN_OPTION"]](
        "%s %r is not one of %s" % (what, name, ", ".join(known)))


class WearResult:
    """The wear of one contact: every cw_wear_result field as an attribute
    (mass_per_distance [kg/m], mass_per_pass [kg], volume_per_distance
    [m^3/m], max_depth [m], work [J/m], regime_area [m^2] (4,), law,
    source); the fields rate [kg/m^3], depth [m per pass], mass [kg per
    pass], work_density [Pa], sliding [-] as (ny, nx) arrays; regimes, an
    int (ny, nx) array (0 none, then the law's regimes 1..4); strips, a
    Strips(y, width, depth, parabola)."""

    def __init__(self, totals, fields, regimes, strips):
        self.__dict__.update(totals)
        self.totals = totals
        self.fields = fields
        self.__dict__.update(fields)
        self.regimes = regimes
        self.strips = strips

    def __repr__(self):
        return "<creepwork.WearResult mass_per_distance=%.6g kg/m, max_depth=%.6g m>" % (
            self.mass_per_distance, self.max_depth)


class Wear(Handle):
    """The wear workspace of one solver's grid (cw_wear). Usually reached
    through Solver.wear(**keywords); made directly for several laws on the
    same solve:

        with creepwork.Solver() as s, creepwork.Wear(s) as w:
            s.solve(a=7e-3, b=5e-3, N=100e3, xi_y=2e-3)
            usfd = w.compute(s, law="usfd")
            kth = w.compute(s, law="archard_kth", rolling_speed=20.0)
    """

    _destroy = "cw_wear_destroy"
    _last_error = "cw_wear_last_error"

    def __init__(self, solver):
        self._handle = ctypes.c_void_p()
        self.nx, self.ny = solver.nx, solver.ny
        status = lib.cw_wear_create(solver._live(), ctypes.byref(self._handle))
        _errors.check(status)

    def compute(self, solver: "Solver", **keywords: Any) -> WearResult:
        """The wear of solver's last solve (which needs fields=True), by the
        law and parameters the keywords give (the fields of cw_wear_params,
        with cw_wear_params_init's defaults):
        """
        rec = WEAR_PARAMS.record(keywords, "compute")
        res = np.zeros((), DTYPES["cw_wear_result"])
        lib.cw_wear_result_init(address(res))
        self._check(lib.cw_wear_compute(self._live(), solver._live(), address(rec), address(res)))
        block = np.empty((len(WEAR_FIELDS), self.ny, self.nx))
        n, base = self.nx * self.ny, address(block)
        fields = {}
        for k, (name, field_id) in enumerate(WEAR_FIELDS.items()):
            self._check(lib.cw_wear_get_field(self._handle, field_id, base + 8 * n * k, n))
            fields[name] = block[k]
        regimes = np.empty((self.ny, self.nx), np.intc)
        self._check(lib.cw_wear_get_regimes(self._handle, address(regimes), n))
        strips = np.empty((4, self.ny))
        b, m = address(strips), self.ny
        self._check(lib.cw_wear_get_strips(self._handle, b, b + 8 * m, b + 16 * m, b + 24 * m, m))
        return WearResult(_totals(res), fields, regimes, Strips(*strips))


Wear.compute.__doc__ += "\n" + WEAR_PARAMS.doc(8)


class WearProfile(Handle):
    """Wear depth accumulated over many passes on a host's profile grid
    (cw_wear_profile): nodes s [m], strictly increasing, any spacing. Sums
    are exact: the depths do not depend on the order or grouping of the
    passes added, nor on merging.

        with creepwork.WearProfile(np.linspace(-0.05, 0.05, 201)) as rail:
            s.solve(...); w = s.wear()
            rail.add(s, s0=0.0, passes=1000)
            depth = rail.depth()          # [m] per node
    """

    _destroy = "cw_wear_profile_destroy"
    _last_error = "cw_wear_profile_last_error"

    def __init__(self, s):
        self._handle = ctypes.c_void_p()
        self.s = np.ascontiguousarray(s, dtype=np.float64).copy()
        message = ctypes.create_string_buffer(_MESSAGE_LEN)
        status = lib.cw_wear_profile_create(address(self.s), self.s.size,
                                            ctypes.byref(self._handle), message, _MESSAGE_LEN)
        _errors.check(status, lambda: message.value)

    def add(self, wear: Union[Wear, "Solver"], s0: float = 0.0, orientation: int = 1,
            contact_angle: float = 0.0, passes: float = 1.0) -> None:
        """Adds passes times the lateral profile of wear's last compute (a Wear,
        or a Solver whose wear() was called): s0 [m] the patch centre's
        profile coordinate; orientation +1 when s grows with the contact's y,
        -1 when it falls; contact_angle [rad] between contact plane and s
        axis; passes axle passages (rail) or wheel revolutions (wheel)."""
        wear = getattr(wear, "_wear", wear)
        if wear is None:
            raise _errors.BY_STATUS[CONSTANTS["CW_ERR_NO_SOLUTION"]](
                "the solver has no wear: call its wear() first")
        self._check(lib.cw_wear_profile_add(self._live(), wear._live(), float(s0),
                                            int(orientation), float(contact_angle),
                                            float(passes)))

    def add_strips(self, y: ArrayLike, width: ArrayLike, depth: ArrayLike, s0: float = 0.0,
                   orientation: int = 1, contact_angle: float = 0.0,
                   passes: float = 1.0) -> None:
        """Adds the caller's strips (centres y [m], widths [m], depths per pass
        [m], arrays of one length), as add() does a wear's."""
        arrays = [np.ascontiguousarray(v, dtype=np.float64) for v in (y, width, depth)]
        if not arrays[0].shape == arrays[1].shape == arrays[2].shape or arrays[0].ndim != 1:
            raise ValueError("y, width and depth must be 1-D arrays of one length")
        self._check(lib.cw_wear_profile_add_strips(
            self._live(), *(address(a) for a in arrays), arrays[0].size, float(s0),
            int(orientation), float(contact_angle), float(passes)))

    def depth(self, kind: str = "normal") -> np.ndarray:
        """Accumulated depth per node [m]: "normal" to the surface, or "height"
        along the profile's height axis."""
        if kind not in DEPTH_KINDS:
            raise _unknown("depth kind", kind, DEPTH_KINDS)
        out = np.empty(self.s.size)
        self._check(lib.cw_wear_profile_get_depth(self._live(), DEPTH_KINDS[kind], address(out),
                                                  out.size))
        return out

    def totals(self) -> Dict[str, Any]:
        """dict of cw_wear_profile_totals: passes, volume [m^2], volume_lost [m^2], adds."""
        rec = np.zeros((), DTYPES["cw_wear_profile_totals"])
        lib.cw_wear_profile_totals_init(address(rec))
        self._check(lib.cw_wear_profile_get_totals(self._live(), address(rec)))
        return _totals(rec)

    def reset(self):
        """Back to zero."""
        self._check(lib.cw_wear_profile_reset(self._live()))

    def merge(self, other: "WearProfile") -> None:
        """self += other (same nodes), exactly."""
        self._check(lib.cw_wear_profile_merge(self._live(), other._live()))

    def state(self) -> np.ndarray:
        """The exact state as a uint64 array, to move between processes."""
        words = ctypes.c_size_t()
        self._check(lib.cw_wear_profile_state_size(self._live(), ctypes.byref(words)))
        out = np.empty(words.value, np.uint64)
        self._check(lib.cw_wear_profile_get_state(self._handle, address(out), out.size))
        return out

    def add_state(self, state: ArrayLike) -> None:
        """Adds a state() saved from an accumulator on the same nodes."""
        state = np.ascontiguousarray(state, dtype=np.uint64)
        self._check(lib.cw_wear_profile_add_state(self._live(), address(state), state.size))


def wear_profile_update(s: ArrayLike, old_profile: ArrayLike, depth: ArrayLike,
                        smoothing: float = 0.0) -> np.ndarray:
    """new_profile = old_profile - smooth(depth) on the nodes s [m]; smooth is
    a volume-conserving Gaussian filter of standard deviation smoothing [m]
    (0: none) (cw_wear_profile_update). Returns the new profile."""
    arrays = [np.ascontiguousarray(v, dtype=np.float64) for v in (s, old_profile, depth)]
    n = arrays[0].size
    if any(a.ndim != 1 or a.size != n for a in arrays):
        raise ValueError("s, old_profile and depth must be 1-D arrays of one length")
    out = np.empty(n)
    message = ctypes.create_string_buffer(_MESSAGE_LEN)
    status = lib.cw_wear_profile_update(*(address(a) for a in arrays), n, float(smoothing),
                                        address(out), n, message, _MESSAGE_LEN)
    _errors.check(status, lambda: message.value)
    return out


class Accumulator(Handle):
    """Running work totals of a simulation loop on one solver's grid
    (cw_accumulator, paper eqs. 35 and 37): add(solver, distance) after each
    solve with fields=True, distance = V dt [m]."""

    _destroy = "cw_accumulator_destroy"
    _last_error = "cw_accumulator_last_error"

    def __init__(self, solver):
        self._handle = ctypes.c_void_p()
        self.nx, self.ny = solver.nx, solver.ny
        _errors.check(lib.cw_accumulator_create(solver._live(), ctypes.byref(self._handle)))

    def add(self, solver: "Solver", distance: float) -> None:
        """Adds the solver's last solve for a step of distance = V dt [m]."""
        self._check(lib.cw_accumulator_add(self._live(), solver._live(), float(distance)))

    def totals(self) -> Dict[str, Any]:
        """dict of cw_accumulation: distance [m], W_macro [J], W_micro_paper [J], K,
        W_consistent [J], steps."""
        rec = np.zeros((), DTYPES["cw_accumulation"])
        lib.cw_accumulation_init(address(rec))
        self._check(lib.cw_accumulator_get_totals(self._live(), address(rec)))
        return _totals(rec)

    def field(self, name: str = "work_consistent") -> np.ndarray:
        """Accumulated work per element [J], (ny, nx): work_paper or work_consistent."""
        if name not in WORK_FIELDS:
            raise _unknown("field", name, WORK_FIELDS)
        out = np.empty((self.ny, self.nx))
        self._check(lib.cw_accumulator_get_field(self._live(), WORK_FIELDS[name], address(out),
                                                 out.size))
        return out

    def strip_work(self) -> np.ndarray:
        """Accumulated energy-consistent work per strip [J], (ny,)."""
        out = np.empty(self.ny)
        self._check(lib.cw_accumulator_get_strip_work(self._live(), address(out), out.size))
        return out

    def reset(self):
        """Back to zero totals and maps."""
        self._check(lib.cw_accumulator_reset(self._live()))
