"""Exceptions: one class per status code of the header's CW_STATUS_LIST.

CW_ERR_INVALID_INPUT becomes InvalidInputError, CW_ERR_NOT_CONVERGED
NotConvergedError, and so on, all derived from Error; a code appended to the
list gets its class without an edit here. Each carries the status (int), the
code's name, the list's static message and the library's detailed message
naming the offending input (cw_solver_last_error and its siblings).
"""

import warnings

from ._layout import LAYOUT


class Error(Exception):
    """A creepwork call failed.

    Attributes: status (the CW_* code, int), name ("CW_ERR_..."), summary (the
    code's static message) and message (the library's detailed message,
    naming the input)."""

    status = None
    name = None
    summary = None

    def __init__(self, message, status=None):
        super().__init__(message)
        self.message = message
        if status is not None:
            self.status = status


class UnitWarning(UserWarning):
    """An input is valid but implausible for a wheel-rail contact (a length in
    millimetres typed as metres, kN as N, a gap grid in millimetres, a wheel
    profile whose origin is off, ...): the library's checks
    (cw_params_check, cw_wheelrail_check), the same at every door. The
    library itself never warns; the package does."""


# Python's own exception a status also is, so that `except ValueError` works.
_ALSO = {
    "CW_ERR_INVALID_INPUT": ValueError,
    "CW_ERR_GRID_OUT_OF_RANGE": ValueError,
    "CW_ERR_UNKNOWN_OPTION": ValueError,
    "CW_ERR_BUFFER_TOO_SMALL": ValueError,
    "CW_ERR_OUT_OF_MEMORY": MemoryError,
    "CW_ERR_NUMERIC": ArithmeticError,
}


def _class_name(code_name):
    words = code_name[len("CW_ERR_"):].split("_")
    return "".join(w.capitalize() for w in words) + "Error"


#: status code -> exception class, for every error status of the header.
BY_STATUS = {}
#: status code -> its name in the header, e.g. 2 -> "CW_ERR_INVALID_INPUT".
STATUS_NAMES = {}
SUMMARIES = {}
for _name, _value, _summary in LAYOUT["statuses"]:
    STATUS_NAMES[_value] = _name
    SUMMARIES[_value] = _summary
    if _value == 0:
        continue
    _bases = (Error,) + ((_ALSO[_name],) if _name in _ALSO else ())
    _cls = type(_class_name(_name), _bases, {
        "__doc__": "%s (%d): %s." % (_name, _value, _summary),
        "__module__": "creepwork",
        "status": _value,
        "name": _name,
        "summary": _summary,
    })
    BY_STATUS[_value] = _cls
    globals()[_cls.__name__] = _cls

Error.__module__ = "creepwork"
UnitWarning.__module__ = "creepwork"

#: Names of the generated exception classes, for `from creepwork import *`.
EXCEPTION_NAMES = [cls.__name__ for cls in BY_STATUS.values()]


def error_for(status, detail=""):
    """The exception for a status, with the detailed message (or the summary)."""
    cls = BY_STATUS.get(status)
    summary = SUMMARIES.get(status, "unknown status code")
    text = detail or summary
    if cls is None:
        return Error("status %d: %s" % (status, text), status)
    return cls(text, status)


def check(status, detail_fn=None):
    """Raises the status's exception unless status is CW_OK (0). detail_fn()
    gives the library's detailed message; it is only called on error."""
    if status != 0:
        detail = detail_fn() if detail_fn is not None else ""
        if isinstance(detail, bytes):
            detail = detail.decode("utf-8", "replace")
        raise error_for(status, detail)


def warn_units(messages, stacklevel):
    """Issues a UnitWarning per message; stacklevel counts the frames from the
    caller of warn_units up to the user's call."""
    for m in messages:
        warnings.warn(m, UnitWarning, stacklevel=stacklevel + 2)
