"""Loads libcreepwork and declares its functions from the generated layout.

Every prototype of the header becomes a ctypes function with argtypes and
restype (pointers as c_void_p), and every struct a numpy dtype with C
alignment. At import the loaded library is checked against the header the
package was generated from: the ABI version, and each struct's size as the
library's own _init function reports it in struct_size. A mismatch (a
package generated from another version of the header than the library's)
is an ImportError, never silently wrong results.

The library is looked for, in this order: the file named by the
environment variable CREEPWORK_LIBRARY; the one the package was built or
installed with (_config.LIBRARY, relative to this folder when installed
beside it); libcreepwork.so.1 on the system loader's path.
"""

import ctypes
import os

import numpy as np

from . import _config
from ._layout import LAYOUT

_CTYPES = {
    "double": ctypes.c_double,
    "float": ctypes.c_float,
    "int": ctypes.c_int,
    "unsigned": ctypes.c_uint,
    "size_t": ctypes.c_size_t,
    "int32_t": ctypes.c_int32,
    "uint32_t": ctypes.c_uint32,
    "int64_t": ctypes.c_int64,
    "uint64_t": ctypes.c_uint64,
    "char": ctypes.c_char,
    "pointer": ctypes.c_void_p,
    "char_p": ctypes.c_char_p,
    "void": None,
}

_NUMPY = {
    "double": np.float64,
    "float": np.float32,
    "int": np.intc,
    "unsigned": np.uintc,
    "size_t": np.uintp,
    "int32_t": np.int32,
    "uint32_t": np.uint32,
    "int64_t": np.int64,
    "uint64_t": np.uint64,
}

CONSTANTS = LAYOUT["constants"]


def _field_format(field):
    if field["kind"] == "pointer":
        base = np.dtype(np.uintp)
    elif field["kind"] == "char":
        return "S%d" % (field["count"] or 1)
    else:
        base = np.dtype(_NUMPY[field["kind"]])
    return (base, (field["count"],)) if field["count"] else base


def _struct_dtype(fields):
    return np.dtype({"names": [f["name"] for f in fields],
                     "formats": [_field_format(f) for f in fields]}, align=True)


#: numpy dtype of every struct of the header, laid out as the C compiler does.
DTYPES = {name: _struct_dtype(fields) for name, fields in LAYOUT["structs"].items()}


def _candidates():
    env = os.environ.get("CREEPWORK_LIBRARY")
    if env:
        return [env]
    found = []
    if getattr(_config, "LIBRARY", None):
        found.append(os.path.join(os.path.dirname(os.path.abspath(__file__)), _config.LIBRARY))
    found.append("libcreepwork.so.%d" % CONSTANTS["CW_VERSION_MAJOR"])
    return found


def _load():
    errors = []
    for path in _candidates():
        try:
            # CDLL (not PyDLL) releases the GIL during every call.
            return ctypes.CDLL(path), path
        except OSError as e:
            errors.append("%s: %s" % (path, e))
    raise ImportError("creepwork: cannot load the creepwork library (set CREEPWORK_LIBRARY to "
                      "the path of libcreepwork.so):\n  " + "\n  ".join(errors))


lib, LIBRARY_PATH = _load()

for _name, _proto in LAYOUT["functions"].items():
    _f = getattr(lib, _name, None)
    if _f is None:
        continue  # an older library: calling it raises AttributeError
    _f.restype = _CTYPES[_proto["restype"]]
    _f.argtypes = [_CTYPES[k] for k in _proto["argtypes"]]


def _check_library():
    abi = lib.cw_abi_version()
    if abi != CONSTANTS["CW_ABI_VERSION"]:
        raise ImportError("creepwork: %s has ABI version %d, the package was generated for %d"
                          % (LIBRARY_PATH, abi, CONSTANTS["CW_ABI_VERSION"]))
    for struct, dtype in DTYPES.items():
        init = getattr(lib, struct + "_init", None)
        if init is None:
            continue
        buf = np.zeros(dtype.itemsize + 1024, np.uint8)  # room for a larger library struct
        init(buf.ctypes.data)
        size = int(buf[:np.dtype(np.uintp).itemsize].view(np.uintp)[0])
        if size != dtype.itemsize:
            raise ImportError(
                "creepwork: %s says sizeof(%s) = %d bytes, the package's layout (generated from "
                "%s) has %d: the package and the library come from different versions; "
                "reinstall both from one source tree" % (LIBRARY_PATH, struct, size,
                                                         LAYOUT["header"], dtype.itemsize))


_check_library()


def new_record(struct, count=None):
    """A zeroed numpy record (count None: shape (), else (count,)) of struct."""
    return np.zeros(() if count is None else count, DTYPES[struct])


_DEFAULTS = {}


def defaults(struct):
    """The record the C _init function fills (cached; a read-only copy)."""
    if struct not in _DEFAULTS:
        rec = new_record(struct)
        getattr(lib, struct + "_init")(rec.ctypes.data)
        rec.flags.writeable = False
        _DEFAULTS[struct] = rec
    return _DEFAULTS[struct]


def filled(struct, shape):
    """An array of shape whose every element is the _init function's record
    (copied as bytes: ten times faster than a structured assignment)."""
    out = np.empty(shape, DTYPES[struct])
    raw = np.frombuffer(defaults(struct).tobytes(), np.uint8)
    out.reshape(-1).view(np.uint8).reshape(-1, raw.size)[...] = raw
    return out


def address(array):
    """Address of a numpy array's first element (ndarray.ctypes.data: fast;
    __array_interface__ builds a structured dtype's description first)."""
    return array.ctypes.data
