"""Transient rolling (cw_transient): Kalker's exact theory with memory on a
gap grid, stepped, committed, rewound, saved and restored
(doc/theory/transient.md). Units SI."""

import ctypes
from typing import Any, Dict, Optional

import numpy as np

from . import _errors
from ._handle import Handle
from ._library import CONSTANTS, DTYPES, address, lib
from ._params import WEAR_PARAMS, grid_record
from ._solver import _params_record

_MESSAGE_LEN = 512

#: Field name -> CW_FIELD_* id of Transient.field (sx, sy: the slip of the step [m];
#: work: the frictional work of each element over the step [J], summing to W_step).
TRANSIENT_FIELDS = {name: CONSTANTS["CW_FIELD_" + name.upper()]
                    for name in ("x", "y", "pz", "px", "py", "sx", "sy")}
TRANSIENT_FIELDS["work"] = CONSTANTS["CW_FIELD_WORK_CONSISTENT"]


#: Transient(coordinates=...) -> CW_COORDINATES_* id.
_COORDINATES = {"contact": CONSTANTS["CW_COORDINATES_CONTACT"],
                "world": CONSTANTS["CW_COORDINATES_WORLD"]}


class Transient(Handle):
    """The transient contact of a gap grid (cw_transient): the normal problem
    is solved here, the state starts from zero tractions.

        with creepwork.Transient(grid={"kind": "gap", "nx": 34, "ny": 33, "x0": -4e-3,
                                       "y0": -4e-3, "dx": 2.5e-4, "dy": 2.5e-4},
                                 gap=h, N=0.4705, G=1e6, nu=0.28, mu=0.4013) as t:
            t.step(dq=0.0, Fx=-0.124)          # a Cattaneo shift, found for Fx
            t.commit()
            for k in range(56):
                r = t.step(dq=2.5e-4, Fx=-0.124)  # a trial: xi_x found
                t.commit()

    grid: a dict of cw_grid fields with kind "gap"; the keywords are
    solve()'s (gap, N or approach, normal_method, G, nu, mu, tolerance,
    max_iterations, spin_offset); model="fastsim" takes FASTSIM's transient
    form instead of the exact theory (the default). coordinates:
    "contact" (contact-fixed, CONTACT's T = 2) or "world" (world-fixed, T =
    1, the exact model's: the grid stays with the material, the geometry
    moves over it by dq towards +x per step and the normal problem is solved
    per step). step() is a
    trial: repeated after rewind() it gives the same bits; commit() makes
    it the state; save() and restore() give and take the state."""

    _destroy = "cw_transient_destroy"
    _last_error = "cw_transient_last_error"

    def __init__(self, grid: Any, params: Any = None, coordinates: str = "contact",
                 **keywords: Any) -> None:
        self._handle = ctypes.c_void_p()
        if coordinates not in _COORDINATES:
            raise _errors.BY_STATUS[CONSTANTS["CW_ERR_UNKNOWN_OPTION"]](
                "Transient(): coordinates = %r is not one of %s"
                % (coordinates, ", ".join(_COORDINATES)))
        keywords.setdefault("model", "exact")
        rec_grid = grid_record(grid, "Transient")
        keep = []  # arrays whose addresses the record holds, alive until create returns
        rec = _params_record(params, keywords, "Transient", keep)
        message = ctypes.create_string_buffer(_MESSAGE_LEN)
        status = lib.cw_transient_create(address(rec_grid), address(rec),
                                         ctypes.byref(self._handle), message, _MESSAGE_LEN)
        _errors.check(status, lambda: message.value)
        #: Cells along x and y.
        self.nx, self.ny = int(rec_grid["nx"]), int(rec_grid["ny"])
        if coordinates != "contact":
            self._check(lib.cw_transient_set_coordinates(self._live(), _COORDINATES[coordinates]))
        self._result = np.zeros((), DTYPES["cw_transient_result"])
        lib.cw_transient_result_init(address(self._result))

    def _input(self, dq, xi_x, xi_y, phi, Fx, Fy):
        rec = np.zeros((), DTYPES["cw_transient_input"])
        lib.cw_transient_input_init(address(rec))
        rec["dq"], rec["xi_x"], rec["xi_y"], rec["phi"] = dq, xi_x, xi_y, phi
        if Fy is not None and Fx is None:
            raise TypeError("Transient.step(): Fy needs Fx (both forces are prescribed together)")
        if Fx is not None:
            rec["Fx"] = Fx
            rec["prescribe"] = CONSTANTS["CW_PRESCRIBE_FX"]
        if Fy is not None:
            rec["Fy"] = Fy
            rec["prescribe"] = CONSTANTS["CW_PRESCRIBE_FORCES"]
        return rec

    def _totals(self) -> Dict[str, Any]:
        return {name: self._result[name].item() for name in self._result.dtype.names[1:]}

    def step(self, dq: float = 0.0, xi_x: float = 0.0, xi_y: float = 0.0, phi: float = 0.0,
             Fx: Optional[float] = None, Fy: Optional[float] = None) -> Dict[str, Any]:
        """One step from the committed state (a trial): dq [m] rolled (0 <= dq
        <= dx; 0: a shift, xi_x, xi_y, phi then the rigid shift [m] and
        rotation [rad]); Fx (and Fy) [N] prescribed find xi_x (xi_y). Returns
        the cw_transient_result fields as a dict."""
        rec = self._input(dq, xi_x, xi_y, phi, Fx, Fy)
        self._check(lib.cw_transient_step(self._live(), address(rec), address(self._result)))
        return self._totals()

    def start_steady(self, xi_x: float = 0.0, xi_y: float = 0.0, phi: float = 0.0,
                     Fx: Optional[float] = None, Fy: Optional[float] = None) -> Dict[str, Any]:
        """Starts from the steady-rolling solution of the creepages (or forces)."""
        rec = self._input(0.0, xi_x, xi_y, phi, Fx, Fy)
        self._check(lib.cw_transient_start_steady(self._live(), address(rec),
                                                  address(self._result)))
        return self._totals()

    def start_zero(self) -> None:
        """Starts from zero tractions."""
        self._check(lib.cw_transient_start_zero(self._live()))

    def commit(self) -> None:
        """Makes the last trial the committed state."""
        self._check(lib.cw_transient_commit(self._live()))

    def rewind(self) -> None:
        """Drops the last trial."""
        self._check(lib.cw_transient_rewind(self._live()))

    def save(self) -> np.ndarray:
        """The committed state as an array of uint64 words."""
        words = ctypes.c_size_t()
        self._check(lib.cw_transient_state_size(self._live(), ctypes.byref(words)))
        out = np.zeros(words.value, np.uint64)
        self._check(lib.cw_transient_save(self._live(), address(out), out.size))
        return out

    def restore(self, state: np.ndarray) -> None:
        """Makes a saved state (save()'s array) the committed state."""
        words = np.ascontiguousarray(state, dtype=np.uint64)
        self._check(lib.cw_transient_restore(self._live(), address(words), words.size))

    def field(self, name: str) -> np.ndarray:
        """A field of the last step as an (ny, nx) array: x, y [m], pz, px, py
        [Pa], sx, sy (the slip of the step [m]), work (each element's
        frictional work over the step [J]; the sum is W_step)."""
        if name not in TRANSIENT_FIELDS:
            raise _errors.BY_STATUS[CONSTANTS["CW_ERR_UNKNOWN_OPTION"]](
                "Transient.field(): %r is not one of %s" % (name, ", ".join(TRANSIENT_FIELDS)))
        out = np.empty((self.ny, self.nx))
        self._check(lib.cw_transient_get_field(self._live(), TRANSIENT_FIELDS[name],
                                               address(out), out.size))
        return out

    def jacobian(self) -> np.ndarray:
        """The derivative of the last step by its inputs, a (3, 3) array
        J[r, c] = d(output r)/d(input c): rows Fx, Fy, Mz, columns xi_x,
        xi_y, phi (a shift: the shift [m] and rotation [rad]); a prescribed
        force and its found creepage trade places (Fx given: row 0 is xi_x,
        column 0 Fx; Fy given too: row 1 is xi_y, column 1 Fy)."""
        out = np.empty((3, 3))
        self._check(lib.cw_transient_jacobian(self._live(), address(out), out.size))
        return out

    def add_wear(self, **law: Any) -> float:
        """Adds the wear of the last step to the accumulated wear, by the law
        the keywords give (the fields of cw_wear_params; pass_length is not
        read): the step's work map per rolled distance dq through the law,
        the mass of an element its rate times its area times dq (a shift
        adds none). Returns the step's mass [kg]. Add each step once."""
        rec = WEAR_PARAMS.record(law, "add_wear")
        mass = ctypes.c_double()
        self._check(lib.cw_transient_add_wear(self._live(), address(rec), ctypes.byref(mass)))
        return mass.value

    def wear(self) -> Dict[str, Any]:
        """The accumulated wear: {"mass": total [kg], "mass_map": (ny, nx)
        array [kg]}."""
        out = np.empty((self.ny, self.nx))
        mass = ctypes.c_double()
        self._check(lib.cw_transient_get_wear(self._live(), address(out), out.size,
                                              ctypes.byref(mass)))
        return {"mass": mass.value, "mass_map": out}

    def reset_wear(self) -> None:
        """Sets the accumulated wear to zero."""
        self._check(lib.cw_transient_reset_wear(self._live()))

    def state(self) -> np.ndarray:
        """The element states of the last step, an int (ny, nx) array (0
        exterior, 1 adhesion, 2 slip)."""
        out = np.empty((self.ny, self.nx), np.intc)
        self._check(lib.cw_transient_get_state(self._live(), address(out), out.size))
        return out
