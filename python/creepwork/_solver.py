"""One contact: Solver (a cw_solver handle), Result, solve() and jacobian().

Array shapes: every per-element field is a C-ordered numpy array of shape
(ny, nx), element (i, j) at [j, i], i along x (the rolling direction), j
along y. That is the library's own layout ([i + j*nx], i fastest), so the
library writes straight into the array: no copy, no transpose.
"""

import ctypes
from collections import namedtuple
from typing import TYPE_CHECKING, Any, Dict, Optional, Tuple, Union

import numpy as np

from . import _checks, _errors
from ._handle import Handle
from ._layout import LAYOUT
from ._library import CONSTANTS, DTYPES, address, lib
from ._params import PARAMS, grid_record, model_default_grid, polach_keywords, require_geometry

if TYPE_CHECKING:
    from ._wear import WearResult
    from ._surface import DamageResult, TemperatureResult

_MESSAGE_LEN = 512
#: What params= takes: a dict of cw_params fields or a creepwork.params() record.
ParamsLike = Optional[Union[Dict[str, Any], np.ndarray]]
#: What grid= takes: a dict of cw_grid fields (or a cw_grid record); None for the default.
GridLike = Optional[Union[Dict[str, Any], np.ndarray]]

#: Field name -> CW_FIELD_* id, e.g. "pz" -> CW_FIELD_PZ, from the header.
FIELDS = {name[len("CW_FIELD_"):].lower(): value for name, value in CONSTANTS.items()
          if name.startswith("CW_FIELD_")}
#: Field name -> the header's description with its unit.
FIELD_DOCS = {name[len("CW_FIELD_"):].lower(): doc for name, doc in LAYOUT["constant_docs"].items()
              if name.startswith("CW_FIELD_")}
_RESULT_NAMES = DTYPES["cw_result"].names[1:]

_JAC_ROWS = {"Fx": "CW_JAC_FX", "Fy": "CW_JAC_FY", "Mz": "CW_JAC_MZ", "W_macro": "CW_JAC_W_MACRO"}
_JAC_COLS = {"xi_x": "CW_JAC_XI_X", "xi_y": "CW_JAC_XI_Y", "phi": "CW_JAC_PHI",
             "normal_force": "CW_JAC_N"}
#: Row names of Result.jacobian, in order: the totals differentiated.
JACOBIAN_ROWS = tuple(sorted(_JAC_ROWS, key=lambda k: CONSTANTS[_JAC_ROWS[k]]))
#: Column names of Result.jacobian, in order: the cw_params fields moved.
JACOBIAN_COLUMNS = tuple(sorted(_JAC_COLS, key=lambda k: CONSTANTS[_JAC_COLS[k]]))

Profile = namedtuple("Profile", "y w parabola")
Profile.__doc__ = """Lateral work profile, one value per strip j: strip centre y [m],
energy-consistent work per unit width w(y) [J/m per m] and the parabola over
[-b, b] with the same area [J/m per m]."""


class Result:
    """The outcome of one solve, in SI units.

    Totals: every field of the C struct cw_result as an attribute (float or
    int): Fx, Fy [N] and Mz [N m] on the wheel, W_macro [J/m], K, the
    element counts, the semi-axes and flexibilities used, ... (listed below
    with the header's comments). Those marked (FULL) are 0 after a solve
    with fields=False.

    Fields (fields=True): x, y, area, pz, px, py, sx, sy, mz, work_paper,
    work_consistent as numpy arrays of shape (ny, nx), element (i, j) at
    [j, i]; state, an int array (ny, nx) of CW_STATE_* (0 exterior, 1
    adhesion, 2 slip); profile, a Profile(y, w, parabola) per strip. The
    same arrays are in the dict fields, the totals in the dict totals.
    jacobian: a (4, 4) array after jacobian(), rows JACOBIAN_ROWS, columns
    JACOBIAN_COLUMNS. params: the cw_params record solved; grid: the grid
    (a dict of cw_grid fields).
    """

    def __init__(self, totals, fields=None, state=None, profile=None, jacobian=None,
                 params=None, grid=None):
        self.__dict__.update(totals)
        self.totals = totals
        self.fields = fields or {}
        self.__dict__.update(self.fields)
        self.state = state
        self.profile = profile
        self.jacobian = jacobian
        self.params = params
        self.grid = grid

    def __repr__(self):
        shape = ", fields %d x %d" % self.state.shape if self.state is not None else ""
        return ("<creepwork.Result Fx=%.6g N, Fy=%.6g N, Mz=%.6g N m, W_macro=%.6g J/m, "
                "adhesion %.0f %%%s>" % (self.Fx, self.Fy, self.Mz, self.W_macro,
                                         100 * self.adhesion_fraction, shape))


Result.__doc__ += "\n    Totals (cw_result):\n" + "\n".join(
    "      %-18s %s" % (f["name"], f["doc"]) for f in LAYOUT["structs"]["cw_result"][1:]) + \
    "\n\n    Fields:\n" + "\n".join("      %-18s %s" % (k, v) for k, v in FIELD_DOCS.items()) + "\n"


def params(**keywords: Any) -> np.ndarray:
    """A cw_params record (a numpy structured scalar) with the C defaults
    (cw_params_init) and the keywords set, to reuse in loops:

        p = creepwork.params(a=7e-3, b=5e-3, N=100e3)
        p["xi_x"] = 2e-3
        solver.solve(p)

    The keywords are solve()'s (help(creepwork.solve)). A pointer field
    (gap=h) holds the address of h's values in C order as doubles (a copy
    where h is not that): the record reads them while h, or the array h
    views, lives."""
    return PARAMS.record(polach_keywords(keywords, "params"), "params")


def _params_record(params_in, keywords, caller, keep):
    if params_in is None:
        return PARAMS.record(keywords, caller, keep)
    if isinstance(params_in, np.ndarray) and params_in.dtype == DTYPES["cw_params"]:
        if params_in.shape != ():
            raise TypeError("%s(): params must be one cw_params record (shape ()), got shape %s; "
                            "use solve_many for many" % (caller, params_in.shape))
        if not keywords:
            return params_in
        rec = params_in.copy()
        PARAMS.fill(rec, keywords, caller, keep)
        return rec
    if isinstance(params_in, dict):
        return PARAMS.record({**params_in, **keywords}, caller, keep)
    raise TypeError("%s(): params must be a dict or a creepwork.params() record, got %r"
                    % (caller, type(params_in).__name__))


def _scalar_view(rec):
    return dict(zip(rec.dtype.names, rec.item()))


def typed_names(params_in, keywords, caller):
    """The fields the user named, each by the name typed ({"normal_force":
    "N"}): the keywords and the keys of a params dict."""
    typed = {}
    for source in (params_in if isinstance(params_in, dict) else {}, keywords):
        for key in source:
            typed[PARAMS.field(key, caller)] = key
    return typed


def check_gap_shape(gap, nx, ny):
    """InvalidInputError for a 2-D gap whose shape is not (ny, nx): the
    library's layout [i + j*nx], x along the second axis (a flat array is
    taken as it is; its length is the library's to check)."""
    shape = np.shape(gap)
    if len(shape) < 2 or shape == (ny, nx):
        return
    hint = " (transposed: gap.T has that shape)" if shape == (nx, ny) else ""
    raise _errors.BY_STATUS[CONSTANTS["CW_ERR_INVALID_INPUT"]](
        "gap has shape %s; the grid's nx = %d cells along x and ny = %d along y need shape "
        "(ny, nx) = (%d, %d): x along the second axis, gap[j, i] at x0 + i*dx, y0 + j*dy%s"
        % (shape, nx, ny, ny, nx, hint))


class Solver(Handle):
    """A solver for one grid, reused for many solves (cw_solver).

        with creepwork.Solver(grid={"kind": "uniform", "nx": 24, "ny": 24,
                                    "box_scale": 1.2}) as s:
            for xi in creepages:
                r = s.solve(a=7e-3, b=5e-3, N=100e3, xi_x=xi, model="exact",
                            fields=False)

    The grid (None: Kalker's strip grid, 20 x 20) is a dict of cw_grid
    fields: kind ("kalker_strips" or "strips", "uniform"), nx, ny,
    box_scale. All memory is made here. The exact model starts from the
    handle's last solution (warm_start = 1, the default), so a loop over
    nearby contacts converges in fewer iterations.

    Threads: one Solver must be used by one thread at a time; distinct
    Solvers run concurrently (the library releases the GIL in every call).
    close() (or the end of a with block) frees the handle; it is idempotent.
    """

    def __init__(self, grid: GridLike = None) -> None:
        self._handle = ctypes.c_void_p()
        rec = grid_record(grid, "Solver")
        message = ctypes.create_string_buffer(_MESSAGE_LEN)
        status = lib.cw_solver_create(address(rec), ctypes.byref(self._handle), message,
                                      _MESSAGE_LEN)
        _errors.check(status, lambda: message.value)
        nx, ny = ctypes.c_int(), ctypes.c_int()
        lib.cw_solver_grid_size(self._handle, ctypes.byref(nx), ctypes.byref(ny))
        #: Elements along x and strips along y.
        self.nx, self.ny = nx.value, ny.value
        #: The grid as solved on, a dict of cw_grid fields.
        self.grid = {k: v for k, v in _scalar_view(rec).items() if k != "struct_size"}
        self._grid_rec = rec
        self._result = np.zeros((), DTYPES["cw_result"])
        lib.cw_result_init(address(self._result))
        self._result_address = address(self._result)
        self._wear = None
        self._surface = {}
        self._rolling_direction = 1  # of the last solve: the temperature's default

    # -- life cycle (Handle): close() also frees the wear, temperature and damage workspaces
    _destroy = "cw_solver_destroy"
    _last_error = "cw_solver_last_error"

    def _close_parts(self) -> None:
        if getattr(self, "_wear", None) is not None:
            self._wear.close()
            self._wear = None
        for part in getattr(self, "_surface", {}).values():
            part.close()
        self._surface = {}

    @property
    def last_error(self) -> str:
        """The library's message about the last error on this handle ("" after success)."""
        return (lib.cw_solver_last_error(self._live()) or b"").decode("utf-8", "replace")

    # -- solving
    def solve(self, params: ParamsLike = None, *, fields: bool = True, warn: bool = True,
              **keywords: Any) -> "Result":
        """Solves one contact on this solver's grid: see creepwork.solve for
        the keywords. params: a dict or a creepwork.params() record; the
        keywords override it. fields=True (CW_SOLVE_FULL) also fills every
        field, the states and the lateral profile; fields=False
        (CW_SOLVE_FORCES) gives the totals only, fastest. warn=False skips
        the unit plausibility check (UnitWarning). Returns a Result."""
        return self._solve(params, keywords, fields, None, warn, "solve", 2)

    def jacobian(self, params: ParamsLike = None, *, fields: bool = False, warn: bool = True,
                 **keywords: Any) -> "Result":
        """As solve(), with result.jacobian the 4 x 4 derivatives of Fx, Fy, Mz,
        W_macro (rows, JACOBIAN_ROWS) with respect to xi_x, xi_y, phi,
        normal_force (columns, JACOBIAN_COLUMNS), SI: e.g. jacobian[0, 0] =
        dFx/dxi_x [N], jacobian[2, 2] = dMz/dphi [N m^2]
        (cw_solver_solve_jacobian; the totals are bitwise solve()'s)."""
        jac = np.empty((4, 4))
        return self._solve(params, keywords, fields, jac, warn, "jacobian", 2)

    def solve_mu_T(self, mu_T, params: ParamsLike = None, *, temperature: Optional[dict] = None,
                   tolerance: float = 1e-6, max_iterations: int = 100, warn: bool = True,
                   **keywords: Any) -> Tuple["Result", "TemperatureResult"]:
        """Solves one contact with friction that depends on the surface
        temperature (cw_temperature_solve, doc/theory/temperature.md): mu_T
        the points (T [deg C], mu) of mu piecewise linear in the rail's
        temperature, e.g. [(0, 0.33), (400, 0.14)] (CONTACT's L=6); params
        and keywords as solve() (model="exact", or "fastsim" on the
        ellipse's grids);
        temperature the keywords of Temperature.compute (rolling_speed
        defaults to V); tolerance and max_iterations those of the loop.
        Returns (Result with fields, TemperatureResult whose iterations are
        the loop's passes)."""
        from ._surface import Temperature
        if "temperature" not in self._surface:
            self._surface["temperature"] = Temperature(self)
        t = dict(temperature or {})
        t.setdefault("rolling_direction", 0)  # 0: the solve's
        call, read = self._surface["temperature"]._solve_call(mu_T, tolerance, max_iterations, t,
                                                              warn)
        result = self._solve(params, keywords, True, None, warn, "solve_mu_T", 2, call)
        return result, read()

    def _solve(self, params_in, keywords, fields, jacobian, warn, caller, stacklevel, call=None):
        handle = self._live()
        keywords = polach_keywords(keywords, caller)
        if isinstance(params_in, dict):
            params_in = polach_keywords(params_in, caller)
        typed = typed_names(params_in, keywords, caller)
        if params_in is None or isinstance(params_in, dict):
            require_geometry(typed, caller)
        gap = keywords.get("gap", params_in.get("gap") if isinstance(params_in, dict) else None)
        if gap is not None:
            check_gap_shape(gap, self.nx, self.ny)
        keep = []  # arrays whose addresses pointer fields hold, alive until the call returns
        rec = _params_record(params_in, keywords, caller, keep)
        if warn:
            _errors.warn_units(_checks.warnings_for(self._grid_rec, rec, typed), stacklevel)
        mode = CONSTANTS["CW_SOLVE_FULL"] if fields else CONSTANTS["CW_SOLVE_FORCES"]
        if call is not None:  # a solve by another call (cw_temperature_solve), then its result
            status = call(handle, address(rec))
            if status == 0:
                status = lib.cw_solver_get_result(handle, self._result_address)
        elif jacobian is None:
            status = lib.cw_solver_solve(handle, address(rec), mode, self._result_address)
        else:
            status = lib.cw_solver_solve_jacobian(handle, address(rec), mode,
                                                  self._result_address, address(jacobian),
                                                  jacobian.size)
        if status != 0:  # the library's message, naming the inputs as typed
            raise _errors.error_for(status, _checks.as_typed(self.last_error, typed))
        self._rolling_direction = int(rec["rolling_direction"])
        totals = dict(zip(_RESULT_NAMES, self._result.item()[1:]))
        solved = rec.copy() if rec is params_in else rec
        if not fields:
            return Result(totals, jacobian=jacobian, params=solved, grid=self.grid)
        # One block for every field: one address to look up, each field a view.
        block = np.empty((len(FIELDS), self.ny, self.nx))
        n = self.nx * self.ny
        base = address(block)
        out = {}
        for k, (name, field_id) in enumerate(FIELDS.items()):
            self._check(lib.cw_solver_get_field(handle, field_id, base + 8 * n * k, n))
            out[name] = block[k]
        return Result(totals, out, self.state(), self.profile(), jacobian, solved, self.grid)

    def result(self) -> "Result":
        """The totals of the last successful solve, as a Result without fields."""
        rec = np.zeros((), DTYPES["cw_result"])
        lib.cw_result_init(address(rec))
        self._check(lib.cw_solver_get_result(self._live(), address(rec)))
        return Result(dict(zip(_RESULT_NAMES, rec.item()[1:])))

    def field(self, name: str, out: Optional[np.ndarray] = None) -> np.ndarray:
        """One field of the last solve as a (ny, nx) array (FIELDS names them;
        sx, sy and the work maps need a solve with fields=True). out: a
        C-contiguous float64 array of nx*ny elements to fill instead."""
        if name not in FIELDS:
            raise _errors.BY_STATUS[CONSTANTS["CW_ERR_UNKNOWN_OPTION"]](
                "field %r is not one of %s" % (name, ", ".join(FIELDS)))
        out = self._out(out, np.float64)
        self._check(lib.cw_solver_get_field(self._live(), FIELDS[name], address(out), out.size))
        return out

    def state(self, out: Optional[np.ndarray] = None) -> np.ndarray:
        """Element states of the last solve, int (ny, nx): 0 exterior, 1 adhesion, 2 slip."""
        out = self._out(out, np.intc)
        self._check(lib.cw_solver_get_state(self._live(), address(out), out.size))
        return out

    def profile(self) -> Profile:
        """The lateral work profile of the last solve (fields=True): a Profile."""
        p = np.empty((3, self.ny))
        base, n = address(p), self.ny
        self._check(lib.cw_solver_get_profile(self._live(), base, base + 8 * n, base + 16 * n, n))
        return Profile(p[0], p[1], p[2])

    def patches(self) -> np.ndarray:
        """The separate contact patches of the last solve (cw_solver_get_patches):
        a structured array of cw_patch records (n_contact, n_adhesion, n_slip,
        x_centroid, y_centroid, Fx, Fy, Mz, Fn, p_max, W_macro), one per
        patch in the order of their first element (lowest y row first). On a
        gap grid (kind "gap") each 4-connected patch; otherwise the contact
        as one patch."""
        handle = self._live()
        count = ctypes.c_size_t()
        self._check(lib.cw_solver_get_patches(handle, None, 0, ctypes.byref(count)))
        out = np.zeros(count.value, DTYPES["cw_patch"])
        for k in range(count.value):
            lib.cw_patch_init(address(out[k:k + 1]))
        if count.value:
            self._check(lib.cw_solver_get_patches(handle, address(out), count.value,
                                                  ctypes.byref(count)))
        return out

    def _out(self, out, dtype):
        if out is None:
            return np.empty((self.ny, self.nx), dtype)
        if not (isinstance(out, np.ndarray) and out.dtype == dtype and out.flags.c_contiguous
                and out.flags.writeable):
            raise TypeError("out must be a writeable C-contiguous %s array" % np.dtype(dtype).name)
        return out

    def prepare(self, model: Union[str, int]) -> None:
        """Makes a model's memory now ("exact", "calibrated", "fastsim"), so its
        solves allocate nothing afterwards (cw_solver_prepare)."""
        value = PARAMS.convert("model", model)
        self._check(lib.cw_solver_prepare(self._live(), int(value)))

    def wear(self, **keywords: Any) -> "WearResult":
        """The wear of this solver's last solve (fields=True): see
        creepwork.Wear.compute for the keywords. Returns a WearResult."""
        from ._wear import Wear
        if self._wear is None:
            self._wear = Wear(self)
        return self._wear.compute(self, **keywords)


    def temperature(self, **keywords: Any) -> "TemperatureResult":
        """Both bodies' surface temperatures from this solver's last solve
        (fields=True): see creepwork.Temperature.compute for the keywords
        (rolling_speed: default the V of the last solve). Returns a
        TemperatureResult."""
        from ._surface import Temperature
        if "temperature" not in self._surface:
            self._surface["temperature"] = Temperature(self)
        return self._surface["temperature"].compute(self, **keywords)

    def damage(self, **keywords: Any) -> "DamageResult":
        """The damage indices of this solver's last solve (fields=True): see
        creepwork.Damage.compute for the keywords (k_yield is needed).
        Returns a DamageResult."""
        from ._surface import Damage
        if "damage" not in self._surface:
            self._surface["damage"] = Damage(self)
        return self._surface["damage"].compute(self, **keywords)


def _grid_for(grid, params_in, keywords):
    """The grid solve() and solve_many() use: as given, else the exact
    model's default (as the CLI's) when every contact is exact, else the
    library's."""
    if grid is not None:
        return grid
    model = keywords.get("model")
    if model is None and isinstance(params_in, dict):
        model = params_in.get("model")
    if model is None and isinstance(params_in, np.ndarray) and \
            params_in.dtype == DTYPES["cw_params"]:
        model = params_in["model"]
    if model is None:
        return None
    values = np.asarray(PARAMS.convert("model", model))
    if values.size and np.all(values == CONSTANTS["CW_MODEL_EXACT"]):
        return model_default_grid(CONSTANTS["CW_MODEL_EXACT"])
    return None


def solve(params: ParamsLike = None, *, grid: GridLike = None, fields: bool = True,
          warn: bool = True, **keywords: Any) -> Result:
    """Solves one wheel-rail contact and returns a creepwork.Result.

        r = creepwork.solve(a=7e-3, b=5e-3, N=100e3, xi_x=1e-3, xi_y=5e-4, phi=0.5)
        r.Fx, r.Fy, r.Mz, r.W_macro     # totals (floats, SI, on the wheel)
        r.pz, r.work_consistent         # fields, numpy (ny, nx): [j, i]
        r.state, r.profile              # slip/adhesion map, lateral profile

    grid: a dict of cw_grid fields, e.g. {"kind": "uniform", "nx": 24,
    "ny": 24, "box_scale": 1.2}; None gives Kalker's strip grid 20 x 20, or
    for model="exact" the CLI's uniform 24 x 24 grid over 1.2 times the
    semi-axes. fields=False skips the fields (CW_SOLVE_FORCES, fastest).
    warn=False silences creepwork.UnitWarning (issued for implausible
    values such as a = 7.2 m, with the CLI's thresholds). params: a dict or
    creepwork.params() record the keywords override. Errors raise a
    subclass of creepwork.Error naming the input (e.g. nu = 0.6:
    creepwork.InvalidInputError).

    A friction law of the slip speed (doc/theory/friction.md): e.g.
    friction_law="exponential", mu=0.1368 (the kinetic coefficient),
    mu_e1=0.2232, s_h1=0.99 [m/s], V=10 [m/s]; or Polach's law as
    polach=(mu0, A, B) with B in s/m (written by cw_friction_polach). The
    exact model takes it at every element's slip speed on the uniform and
    gap grids; FASTSIM at every element (on the ellipse's and gap grids),
    or with friction_speed="global" at the contact's slip speed (the
    ellipse's grids); every one in either mode. The calibrated model
    refuses it naming friction_law.

    For many contacts use solve_many (one call, threads); for loops, a
    Solver. Keywords: every field of the C struct cw_params, in SI units,
    with cw_params_init's defaults (steel on steel, mu = 0.3, parabolic
    pressure, FASTSIM):
    """
    keywords = polach_keywords(keywords, "solve")
    grid = _grid_for(grid, params, keywords)
    with Solver(grid) as s:
        return s._solve(params, keywords, fields, None, warn, "solve", 2)


def jacobian(params: ParamsLike = None, *, grid: GridLike = None, fields: bool = False,
             warn: bool = True, **keywords: Any) -> Result:
    """solve() with the 4 x 4 Jacobian: returns a Result whose jacobian holds
    d(Fx, Fy, Mz, W_macro)/d(xi_x, xi_y, phi, normal_force), SI, rows
    creepwork.JACOBIAN_ROWS, columns creepwork.JACOBIAN_COLUMNS
    (cw_solver_solve_jacobian). Keywords as solve()."""
    keywords = polach_keywords(keywords, "jacobian")
    grid = _grid_for(grid, params, keywords)
    with Solver(grid) as s:
        return s._solve(params, keywords, fields, np.empty((4, 4)), warn, "jacobian", 2)


solve.__doc__ += "\n" + PARAMS.doc()
