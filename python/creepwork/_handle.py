"""The life cycle every class over a library handle shares: the handle is
made by the subclass's __init__ (self._handle), freed by close() --
idempotent, also at the end of a with block and when the object is
collected -- and refused once closed; errors carry the handle's detailed
message (cw_*_last_error)."""

import ctypes

from . import _errors
from ._library import lib


class Handle:
    #: The library's functions for this handle, by name: "cw_solver_destroy" ...
    _destroy = ""
    _last_error = ""

    def _close_parts(self) -> None:
        """Frees what the object holds besides its handle (subclasses)."""

    def close(self) -> None:
        """Frees the handle; idempotent; further calls raise ValueError."""
        self._close_parts()
        if getattr(self, "_handle", None):
            getattr(lib, self._destroy)(self._handle)
            self._handle = ctypes.c_void_p()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        if getattr(self, "_handle", None):
            self.close()

    def _live(self):
        if not getattr(self, "_handle", None):
            raise ValueError("creepwork.%s: closed" % type(self).__name__)
        return self._handle

    def _check(self, status):
        _errors.check(status, lambda: getattr(lib, self._last_error)(self._handle))
