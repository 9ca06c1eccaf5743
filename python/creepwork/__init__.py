"""creepwork: creep forces, creep moment and frictional-work distributions of
a wheel rolling on a rail (FASTSIM, Kalker's exact theory, a calibrated
simplified model), over the C library libcreepwork.

    import creepwork
    r = creepwork.solve(a=7e-3, b=5e-3, N=100e3, xi_x=1e-3, xi_y=5e-4, phi=0.5)
    r.Fx, r.Fy, r.Mz, r.W_macro          # totals on the wheel [N, N, N m, J/m]
    r.work_consistent                    # numpy (ny, nx): element (i, j) at [j, i]

    out = creepwork.solve_many(a=7e-3, b=5e-3, N=100e3,
                               xi_x=numpy.linspace(0, 3e-3, 10000))
    out.Fx, out.status                   # arrays, one C call, threads

Units are SI throughout (m, N, Pa, 1/m, J/m). Forces act on the wheel,
opposite in sign to the creepages (Kalker's and CONTACT's convention).
Arrays of per-element fields have shape (ny, nx), C order: the library's own
layout, filled in place. Errors raise subclasses of creepwork.Error, one per
status code of the C header (e.g. InvalidInputError), with the library's
message naming the input; implausible units (a = 7.2 m) warn with
creepwork.UnitWarning.

Contents: solve, jacobian, params, Solver, Result; solve_many, Batch,
ManyResult; Wear, WearResult, WearProfile, wear_profile_update,
Accumulator; Temperature, TemperatureResult, Damage, DamageResult (surface
temperature and damage indices); WheelRail (profiles to forces); kalker_coefficients, kalker_flexibilities, hertz,
fastsim_normalised; version, version_number, status_string; Error and its
subclasses, UnitWarning; the header's constants (CW_*); creepwork.plot
(needs matplotlib).
"""

try:
    import numpy as _numpy  # noqa: F401  the one run-time dependency: say how to get it
except ImportError as _missing:
    import sys as _sys
    raise ImportError(
        "creepwork needs numpy, which this Python (%s, %s) does not have. On Debian, "
        "/usr/bin/python3 has it with the package python3-numpy (apt-get install "
        "python3-numpy): run your script with /usr/bin/python3. Or install numpy into this "
        "Python: %s -m pip install numpy"
        % (_sys.executable, _sys.version.split()[0], _sys.executable)) from _missing

from ._errors import Error, UnitWarning, EXCEPTION_NAMES, BY_STATUS as _BY_STATUS
from ._library import CONSTANTS as _CONSTANTS, DTYPES, LIBRARY_PATH
from ._solver import (FIELDS, JACOBIAN_COLUMNS, JACOBIAN_ROWS, Profile, Result, Solver,
                      jacobian, params, solve)
from ._batch import Batch, ManyResult, solve_many
from ._wear import (DEPTH_KINDS, WEAR_FIELDS, Accumulator, Strips, Wear, WearProfile,
                    WearResult, wear_profile_update)
from ._surface import (DAMAGE_FIELDS, TEMPERATURE_FIELDS, Damage, DamageResult, Temperature,
                       TemperatureResult)
from ._wheelrail import WheelRail
from ._transient import TRANSIENT_FIELDS, Transient
from . import plot
from ._helpers import (Flexibilities, Hertz, KalkerCoefficients, fastsim_normalised, hertz,
                       kalker_coefficients, kalker_flexibilities, status_string, version,
                       version_number)

# Every exception class and #define constant of the header, by name.
for _cls in _BY_STATUS.values():
    globals()[_cls.__name__] = _cls
globals().update(_CONSTANTS)

__version__ = "%d.%d.%d" % (_CONSTANTS["CW_VERSION_MAJOR"], _CONSTANTS["CW_VERSION_MINOR"],
                            _CONSTANTS["CW_VERSION_PATCH"])

__all__ = (["solve", "jacobian", "params", "Solver", "Result", "Profile", "FIELDS",
            "JACOBIAN_ROWS", "JACOBIAN_COLUMNS", "solve_many", "Batch", "ManyResult", "Wear",
            "WearResult", "WearProfile", "Strips", "WEAR_FIELDS", "DEPTH_KINDS",
            "wear_profile_update", "Accumulator", "WheelRail", "Transient", "TRANSIENT_FIELDS",
            "kalker_coefficients",
            "kalker_flexibilities", "hertz", "fastsim_normalised", "KalkerCoefficients",
            "Flexibilities", "Hertz", "version", "version_number", "status_string", "Error",
            "UnitWarning", "DTYPES", "LIBRARY_PATH"] + EXCEPTION_NAMES + list(_CONSTANTS))
