"""Surface temperature (cw_temperature) and damage indices (cw_damage) of a
solved contact. Body 1 is the rail, body 2 the wheel. Units SI, temperatures
in deg C (doc/theory/temperature.md, doc/theory/damage.md)."""

import ctypes
from typing import TYPE_CHECKING, Any

import numpy as np

from . import _checks, _errors
from ._handle import Handle
from ._library import CONSTANTS, DTYPES, address, lib
from ._params import DAMAGE_PARAMS, TEMPERATURE_PARAMS

if TYPE_CHECKING:
    from ._solver import Solver


def _named(prefix):
    return {n[len(prefix):].lower(): v for n, v in CONSTANTS.items() if n.startswith(prefix)}


#: Temperature field name -> CW_TEMPERATURE_FIELD_* id: rail, wheel, heat.
TEMPERATURE_FIELDS = _named("CW_TEMPERATURE_FIELD_")
#: Damage field name -> CW_DAMAGE_FIELD_* id: rcf_index, t_gamma_density.
DAMAGE_FIELDS = _named("CW_DAMAGE_FIELD_")


class SurfaceResult:
    """The result of a compute: every field of its C result struct as an
    attribute, and its fields as (ny, nx) arrays (attributes too)."""

    def __init__(self, rec, fields):
        self.totals = {name: rec[name].item() for name in rec.dtype.names[1:]}
        self.__dict__.update(self.totals)
        self.fields = fields
        self.__dict__.update(fields)

    def __repr__(self):
        shown = ", ".join("%s=%.6g" % kv for kv in list(self.totals.items())[:3])
        return "<creepwork.%s %s>" % (type(self).__name__, shown)


class TemperatureResult(SurfaceResult):
    """Both bodies' temperatures: T_max_1, x_max_1, y_max_1 (the rail's
    hottest contact element [deg C, m]), T_max_2, x_max_2, y_max_2 (the
    wheel's), contact_temperature [deg C], power [W], iterations,
    discretisation; fields rail and wheel [deg C], heat [W/m^2]."""


class DamageResult(SurfaceResult):
    """The damage indices: rcf_index_max, x_rcf_max, y_rcf_max, mu_eff,
    FI_surf, contact_area [m^2], T_gamma [N], wlrm_damage [per pass];
    fields rcf_index [-] and t_gamma_density [Pa]."""


class _Surface(Handle):
    _noun = ""
    _params = None
    _fields = {}
    _result_class = SurfaceResult

    def __init__(self, solver: "Solver") -> None:
        self._handle = ctypes.c_void_p()
        self.nx, self.ny = solver.nx, solver.ny
        _errors.check(getattr(lib, "cw_%s_create" % self._noun)(solver._live(),
                                                                  ctypes.byref(self._handle)))

    def _record(self, keywords, warn):
        rec = self._params.record(keywords, "compute")
        if warn:
            typed = {self._params.field(k, "compute"): k for k in keywords}
            _errors.warn_units(_checks.params_warnings(self._noun, rec, typed), 4)
        res = np.zeros((), DTYPES["cw_%s_result" % self._noun])
        getattr(lib, "cw_%s_result_init" % self._noun)(address(res))
        return rec, res

    def _compute(self, solver, keywords, warn):
        rec, res = self._record(keywords, warn)
        self._check(getattr(lib, "cw_%s_compute" % self._noun)(
            self._live(), solver._live(), address(rec), address(res)))
        return self._read(res)

    def _read(self, res):
        block = np.empty((len(self._fields), self.ny, self.nx))
        n, base = self.nx * self.ny, address(block)
        get = getattr(lib, "cw_%s_get_field" % self._noun)
        fields = {}
        for k, (name, field_id) in enumerate(self._fields.items()):
            self._check(get(self._handle, field_id, base + 8 * n * k, n))
            fields[name] = block[k]
        return self._result_class(res, fields)


class Temperature(_Surface):
    """The temperature workspace of one solver's grid (cw_temperature).
    Usually reached through Solver.temperature(**keywords):

        with creepwork.Solver() as s:
            s.solve(a=7e-3, b=5e-3, N=100e3, xi_x=2e-3)
            t = s.temperature(rolling_speed=30.0)
            t.T_max_1, t.rail            # deg C; (ny, nx) array
    """

    _destroy = "cw_temperature_destroy"
    _last_error = "cw_temperature_last_error"
    _noun = "temperature"
    _params = TEMPERATURE_PARAMS
    _fields = TEMPERATURE_FIELDS
    _result_class = TemperatureResult

    def compute(self, solver: "Solver", warn: bool = True, **keywords: Any) -> TemperatureResult:
        """The temperatures of solver's last solve (which needs fields=True)
        from the keywords (the fields of cw_temperature_params, with
        cw_temperature_params_init's defaults; rolling_direction defaults to
        that of solver's last solve). warn=False skips the plausibility check
        for steel (UnitWarning):
        """
        keywords.setdefault("rolling_direction", getattr(solver, "_rolling_direction", 1))
        return self._compute(solver, keywords, warn)

    def _solve_call(self, mu_T, tolerance, max_iterations, keywords, warn):
        """What Solver.solve_mu_T calls: a function of the solver's handle and
        the params' address that runs cw_temperature_solve and returns its
        status, and a function that reads the TemperatureResult after it."""
        table = np.ascontiguousarray(np.asarray(mu_T, dtype=np.float64).reshape(-1, 2).T)
        rec, res = self._record(keywords, warn)
        m = np.zeros((), DTYPES["cw_mu_temperature"])
        lib.cw_mu_temperature_init(address(m))
        m["count"] = table.shape[1]
        m["temperature"] = address(table[0]) if table.size else 0
        m["mu"] = address(table[1]) if table.size else 0
        m["tolerance"] = tolerance
        m["max_iterations"] = max_iterations

        def call(handle, params_address):
            keep = (table, rec, m)  # alive until the call returns
            return lib.cw_temperature_solve(self._live(), handle, params_address,
                                            address(keep[1]), address(keep[2]), None,
                                            address(res))

        return call, lambda: self._read(res)


class Damage(_Surface):
    """The damage-index workspace of one solver's grid (cw_damage). Usually
    reached through Solver.damage(k_yield=...)."""

    _destroy = "cw_damage_destroy"
    _last_error = "cw_damage_last_error"
    _noun = "damage"
    _params = DAMAGE_PARAMS
    _fields = DAMAGE_FIELDS
    _result_class = DamageResult

    def compute(self, solver: "Solver", warn: bool = True, **keywords: Any) -> DamageResult:
        """The damage indices of solver's last solve (fields=True) from the
        keywords (the fields of cw_damage_params; k_yield has no default).
        warn=False skips the plausibility check (UnitWarning):
        """
        return self._compute(solver, keywords, warn)


Temperature.compute.__doc__ += "\n" + TEMPERATURE_PARAMS.doc(8)
Damage.compute.__doc__ += "\n" + DAMAGE_PARAMS.doc(8)
