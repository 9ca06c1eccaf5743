"""One wheel on one rail from the profiles to the forces (cw_wheelrail): the
contact patches of a wheelset position, the wheelset height for a vertical
force, every patch solved by Kalker's exact theory or the fast model, each
patch's fields and its wear on the profiles. CONTACT's module-1
conventions (track x along the track, y to the right, z down; creepages of
the rail relative to the wheel; forces on the rail), SI units."""

import ctypes
import os
from typing import Any, Dict, List, Optional

import numpy as np

from . import _checks, _errors
from ._handle import Handle
from ._library import CONSTANTS, DTYPES, address, defaults, lib
from ._params import WEAR_PARAMS
from ._solver import FIELDS
from ._wear import WearProfile, _totals

_MESSAGE_LEN = 1024


def _record(struct, keywords, where):
    rec = defaults(struct).copy()
    for name, value in keywords.items():
        if name == "struct_size" or name not in rec.dtype.names:
            known = ", ".join(n for n in rec.dtype.names if n != "struct_size")
            raise TypeError("%s: unknown keyword %r (known: %s)" % (where, name, known))
        rec[name] = value
    return rec


def _as_dict(rec):
    return {name: rec[name].item() for name in rec.dtype.names[1:]}


def _findings(handle):
    """cw_wheelrail_check of a handle: (rule, input, message) per finding."""
    found = _checks.records(lambda out, n, count: lib.cw_wheelrail_check(handle, out, n, count))
    return [(int(c["rule"]), _checks.text(c["input"]), _checks.text(c["message"])) for c in found]


class WheelRail(Handle):
    """A wheel and a rail profile with a track, a wheelset and a side, solved
    for any wheelset position:

        with creepwork.WheelRail("MBench_UIC60_v3.prr", "MBench_S1002_v3.prw") as w:
            totals, patches = w.solve(Fz=1e4, y=3e-3, yaw=0.0072, roll=-1.803e-4,
                                      vs=2.0, vpitch=-4.34515)

    The keywords are the fields of cw_wheelrail_params (side=creepwork.
    CW_WHEELRAIL_LEFT, dx, ds, mu, G, nu, gauge_width, nominal_radius,
    wheel_y_offset, rail_y_offset, mirror_wheel, profile_unit, ...) with
    cw_wheelrail_params_init's defaults (the Manchester benchmark's track
    and wheelset, 0.2 mm elements, steel). A wheel profile measured from its
    flange back (MiniProf) takes wheel_y_offset=-0.07, the flange back's
    place in this module's profile coordinates.

    The library's checks (cw_wheelrail_check) warn with creepwork.UnitWarning:
    inputs in a wrong unit, a wheel profile whose origin is off, and after
    each solve a patch on the wheel's flange tip or a wheelset height beyond
    5 mm on a tread contact, each with its likely cause."""

    _destroy = "cw_wheelrail_destroy"
    _last_error = "cw_wheelrail_last_error"

    def __init__(self, rail_profile: str, wheel_profile: str, **params: Any):
        rec = _record("cw_wheelrail_params", params, "WheelRail")
        self._handle = ctypes.c_void_p()
        message = ctypes.create_string_buffer(_MESSAGE_LEN)
        status = lib.cw_wheelrail_create(address(rec), os.fsencode(rail_profile),
                                         os.fsencode(wheel_profile), ctypes.byref(self._handle),
                                         message, _MESSAGE_LEN)
        _errors.check(status, lambda: message.value)
        # The parameters and the profiles: said once, here.
        first = _findings(self._handle)
        self._said = {(rule, name) for rule, name, _ in first}
        _errors.warn_units([m for _, _, m in first], 1)

    def solve(self, Fz: Optional[float] = None, **motion: float):
        """One wheelset position (the fields of cw_wheelrail_motion: y, z,
        roll, yaw, pitch, vs, vy, vz, vroll, vyaw, vpitch; default 0). With
        Fz [N] the height z is found for that vertical force on the rail
        (starting from z), otherwise z is the height. Returns (totals,
        patches): dicts of the fields of cw_wheelrail_totals and, per
        patch, cw_wheelrail_patch."""
        rec = _record("cw_wheelrail_motion", motion, "WheelRail.solve")
        totals = defaults("cw_wheelrail_totals").copy()
        if Fz is None:
            load, force = CONSTANTS["CW_WHEELRAIL_HEIGHT"], 0.0
        else:
            load, force = CONSTANTS["CW_WHEELRAIL_FORCE"], float(Fz)
        status = lib.cw_wheelrail_solve(self._live(), address(rec), load, force, address(totals))
        # What looks wrong is said also when the solve failed: it may be why.
        _errors.warn_units([m for rule, name, m in _findings(self._handle)
                            if (rule, name) not in self._said], 1)
        self._check(status)
        patches: List[Dict[str, Any]] = []
        for k in range(int(totals["n_patches"])):
            p = defaults("cw_wheelrail_patch").copy()
            self._check(lib.cw_wheelrail_get_patch(self._handle, k, address(p)))
            patches.append(_as_dict(p))
        return _as_dict(totals), patches

    def _patch(self, k: int):
        p = defaults("cw_wheelrail_patch").copy()
        self._check(lib.cw_wheelrail_get_patch(self._live(), k, address(p)))
        return p

    def patch_field(self, k: int, name: str) -> np.ndarray:
        """Field `name` (creepwork.FIELDS: pz, px, py, sx, sy, mz, x, y, area,
        work_paper, work_consistent) of patch k (from 0) of the last solve as
        a (field_ny, field_nx) array over the patch's s and x, in the
        wheel/rail conventions: x, y are the element's x and s from the
        reference point; px, py the traction on the rail along x and s; sx,
        sy the micro-slip of the rail relative to the wheel; mz the moment
        about n through the reference point."""
        if name not in FIELDS:
            raise _errors.BY_STATUS[CONSTANTS["CW_ERR_UNKNOWN_OPTION"]](
                "field %r is not one of %s" % (name, ", ".join(FIELDS)))
        p = self._patch(k)
        out = np.empty((int(p["field_ny"]), int(p["field_nx"])))
        self._check(lib.cw_wheelrail_get_patch_field(self._handle, k, FIELDS[name], address(out),
                                                     out.size))
        return out

    def patch_state(self, k: int) -> np.ndarray:
        """Element states of patch k, int (field_ny, field_nx): 0 exterior,
        1 adhesion, 2 slip."""
        p = self._patch(k)
        out = np.empty((int(p["field_ny"]), int(p["field_nx"])), np.intc)
        self._check(lib.cw_wheelrail_get_patch_state(self._handle, k, address(out), out.size))
        return out

    def add_wear(self, passes: float, rail: Optional[WearProfile] = None,
                 wheel: Optional[WearProfile] = None, **law: Any) -> Dict[str, Any]:
        """Adds the wear of every patch of the last solve, passes times, to
        the rail's and the wheel's WearProfile (nodes: the profile's y as
        its points are given, towards the field side on both sides), by the
        law the keywords give (the fields of cw_wear_params). Returns the
        patches' wear per pass summed (the fields of cw_wear_result)."""
        rec = WEAR_PARAMS.record(law, "add_wear")
        res = np.zeros((), DTYPES["cw_wear_result"])
        lib.cw_wear_result_init(address(res))
        handles = [None if p is None else p._live() for p in (rail, wheel)]
        self._check(lib.cw_wheelrail_add_wear(self._live(), address(rec), float(passes), handles[0],
                                              handles[1], address(res)))
        return _totals(res)

    def profile(self, which: str = "rail"):
        """The rail's ("rail") or the wheel's ("wheel") profile points in
        track coordinates at the last solve's position: (y, z) arrays [m], z
        down; the wheel in the wheelset's plane through the axle."""
        ids = {"rail": CONSTANTS["CW_WHEELRAIL_RAIL"], "wheel": CONSTANTS["CW_WHEELRAIL_WHEEL"]}
        if which not in ids:
            raise _errors.BY_STATUS[CONSTANTS["CW_ERR_UNKNOWN_OPTION"]](
                "which %r is not 'rail' or 'wheel'" % (which,))
        count = ctypes.c_size_t(0)
        status = lib.cw_wheelrail_get_profile(self._live(), ids[which], None, None, 0,
                                              ctypes.byref(count))
        if status != CONSTANTS["CW_ERR_BUFFER_TOO_SMALL"]:
            self._check(status)
        yz = np.empty((2, count.value))
        base = address(yz)
        self._check(lib.cw_wheelrail_get_profile(self._handle, ids[which], base, base + 8 * yz.shape[1],
                                                 yz.shape[1], ctypes.byref(count)))
        return yz[0], yz[1]
