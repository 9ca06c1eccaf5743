"""Keyword arguments -> C struct records, for every struct of the header.

Each struct field (but struct_size) is a keyword of the same name, with the
default its C _init function sets; fields with an enumeration in the header
(a "/* cw_params.model ..." block of #defines) also take the value's name,
e.g. model="exact" for CW_MODEL_EXACT. Fields appended to the header become
keywords without an edit here.
"""

import ctypes
import difflib
import textwrap
import weakref

import numpy as np

from . import _checks, _errors
from ._layout import LAYOUT
from ._library import _NUMPY, DTYPES, address, defaults, lib

_ENUMS = {}
for _key, _members in LAYOUT["enums"].items():
    _struct, _field = _key.split(".")
    _ENUMS.setdefault(_struct, {})[_field] = _members

# The other name a keyword's documentation gives (the library resolves every
# alias: N, spin; strips, fast, any case and "-" for "_" of a value).
_DOC_ALIASES = {"cw_params": {"N": "normal_force", "spin": "phi"}}


class Keywords:
    """The keywords of one struct: names, defaults, enumerations, docs."""

    def __init__(self, struct):
        self.struct = struct
        self.dtype = DTYPES[struct]
        self.fields = {f["name"]: f for f in LAYOUT["structs"][struct] if f["name"] != "struct_size"}
        self.aliases = _DOC_ALIASES.get(struct, {})
        self.enums = _ENUMS.get(struct, {})

    def field(self, key, caller):
        """The field a keyword names (its own, or the library's alias: N for
        normal_force, spin for phi); TypeError (as Python's) for an unknown
        one, pointing at the other struct when the key is one of its fields."""
        if key in self.fields:
            return key
        name = _checks.canonical(key)
        if name in self.fields:
            return name
        names = list(self.fields) + list(self.aliases)
        close = difflib.get_close_matches(key, names, n=1)
        hint = " (did you mean %r?)" % close[0] if close else ""
        if self.struct == "cw_params" and key in GRID.fields:
            hint = " (%s is a field of the grid: grid={%r: ...})" % (key, key)
        elif self.struct == "cw_grid" and key in PARAMS.fields:
            hint = " (%s is a field of cw_params: a keyword of the call, not of grid)" % key
        raise TypeError("%s() got an unexpected keyword argument %r%s; the keywords are the "
                        "fields of %s: %s" % (caller, key, hint, self.struct, ", ".join(names)))

    def enum_value(self, field, name):
        """The number of an enumeration value: its name (the header's, or the
        library's other spellings: strips, fast, semi-hertz, any case)."""
        members = self.enums[field]
        if name not in members:
            canonical = _checks.canonical(name)
            if canonical not in members:
                raise _errors.BY_STATUS[_status("CW_ERR_UNKNOWN_OPTION")](
                    "%s = %r is not one of %s" % (field, name, ", ".join(members)))
            name = canonical
        return members[name]

    def convert(self, field, value):
        """value as the field's numbers: enumeration names mapped, integers
        checked (a scalar stays a scalar, an array an array)."""
        if field in self.enums:
            if isinstance(value, str):
                return self.enum_value(field, value)
            arr = np.asarray(value)
            if arr.dtype.kind in "US":
                out = np.empty(arr.shape, np.int64)
                for name in np.unique(arr):
                    out[arr == name] = self.enum_value(field, str(name))
                return out
        base = self.dtype.fields[field][0].base
        if base.kind in "iu":
            arr = np.asarray(value)
            if arr.dtype.kind not in "iub":
                if arr.dtype.kind != "f" or not np.all(np.isfinite(arr) & (arr == np.round(arr))):
                    raise TypeError("%s must be an integer, got %r" % (field, value))
            # numpy would wrap a value too large for the C type silently.
            limits = np.iinfo(base)
            if arr.size and (arr.min() < limits.min or arr.max() > limits.max):
                raise _errors.BY_STATUS[_status("CW_ERR_INVALID_INPUT")](
                    "%s = %s is outside the range of its C type %s" % (
                        field, value, LAYOUT["structs"][self.struct][self._index(field)]["ctype"]))
            return arr.astype(np.int64) if arr.ndim else int(arr)
        return value

    def _index(self, field):
        return [f["name"] for f in LAYOUT["structs"][self.struct]].index(field)

    def fill(self, record, keywords, caller, keep=None):
        """Sets record[field] = value for each keyword (record: a numpy record of
        this struct, any shape; values broadcast). Pointer fields take a numpy
        array, whose values the library reads in C order as the field's C
        type whatever the array's memory order and dtype (a C-ordered copy
        where they differ); the address is stored (and the size in the field
        <name>_len, unless that is given too). The array read is appended to
        keep, so that the caller holds it alive while the library may read
        it; without keep (a record that outlives the call) a copy lives as
        long as the array given."""
        for key, value in keywords.items():
            field = self.field(key, caller)
            spec = self.fields[field]
            if spec["pointer"]:
                if value is None:
                    record[field] = 0
                    continue
                arr = np.ascontiguousarray(value, dtype=_NUMPY[spec["ctype"]])
                if keep is not None:
                    keep.append(arr)
                elif not (isinstance(value, np.ndarray) and np.may_share_memory(arr, value)):
                    _outlive(value, arr, field, caller)
                record[field] = arr.__array_interface__["data"][0]
                # Its length field (gap -> gap_len) follows the array unless given.
                length = field + "_len"
                if length in self.fields and length not in keywords:
                    record[length] = arr.size
                continue
            record[field] = self.convert(field, value)

    def record(self, keywords, caller, keep=None):
        """A fresh record with the C defaults and the keywords set."""
        rec = defaults(self.struct).copy()
        self.fill(rec, keywords, caller, keep)
        return rec

    def doc(self, indent=4):
        """One entry per keyword: name, its default and the header's comment."""
        d = defaults(self.struct)
        lines = []
        alias_of = {v: k for k, v in self.aliases.items()}
        for name, f in self.fields.items():
            label = name if name not in alias_of else "%s (or %s)" % (alias_of[name], name)
            if f["pointer"]:
                default = "none"
            else:
                default = repr(d[name].tolist())
                for member, value in self.enums.get(name, {}).items():
                    if value == d[name]:
                        default = repr(member)
            names = ""
            if name in self.enums:
                names = "; names: " + ", ".join("%s = %r" % (k, v) for k, v in self.enums[name].items())
            lines.append(label + " (default %s)" % default)
            lines += textwrap.wrap(f["doc"] + names, 76 - indent, initial_indent="    ",
                                   subsequent_indent="    ")
        return textwrap.indent("\n".join(lines), " " * indent)


# The fields cw_friction_polach writes: Polach's law as the exponential law.
_POLACH_FIELDS = ("friction_law", "mu", "mu_e1", "s_h1", "mu_e2", "s_h2")


def polach_keywords(keywords, caller):
    """keywords with polach=(mu0, A, B) (B in s/m; scalars or arrays that
    broadcast) replaced by the fields the library's cw_friction_polach
    writes for them (the exponential law: mu = A mu0, mu_e1 = (1 - A) mu0,
    s_h1 = ln2/B). TypeError when one of those fields is given too."""
    if "polach" not in keywords:
        return keywords
    out = dict(keywords)
    value = out.pop("polach")
    for key in list(out):
        if PARAMS.field(key, caller) in _POLACH_FIELDS:
            raise TypeError("%s(): polach=(mu0, A, B) sets the friction law and mu; %r cannot "
                            "be given with it" % (caller, key))
    try:
        mu0, A, B = (np.asarray(v, dtype=float) for v in value)
    except (TypeError, ValueError):
        raise TypeError("%s(): polach must be (mu0, A, B), got %r" % (caller, value)) from None
    shape = np.broadcast_shapes(mu0.shape, A.shape, B.shape)
    fields = {name: np.empty(shape, PARAMS.dtype.fields[name][0]) for name in _POLACH_FIELDS}
    rec = defaults("cw_params").copy()
    message = ctypes.create_string_buffer(512)
    for index in np.ndindex(shape):
        status = lib.cw_friction_polach(float(np.broadcast_to(mu0, shape)[index]),
                                        float(np.broadcast_to(A, shape)[index]),
                                        float(np.broadcast_to(B, shape)[index]), address(rec),
                                        message, len(message))
        _errors.check(status, lambda: message.value)
        for name in _POLACH_FIELDS:
            fields[name][index] = rec[name]
    out.update({name: (v[()] if v.ndim == 0 else v) for name, v in fields.items()})
    return out


def _status(name):
    return LAYOUT["constants"][name]


def _outlive(source, copy, field, caller):
    """Keeps copy, the C-ordered values of source that a record's pointer
    field holds, alive as long as the array source views (or source itself):
    the record then reads them while the caller's array lives, as it reads
    a C-ordered array in place."""
    owner = source
    while isinstance(owner, np.ndarray) and isinstance(owner.base, np.ndarray):
        owner = owner.base
    if not isinstance(owner, np.ndarray):
        raise TypeError("%s(): %s must be a numpy array, got %s: the record keeps the address "
                        "of its values" % (caller, field, type(source).__name__))
    weakref.finalize(owner, _release, copy)


def _release(copy):
    """The finalizer's callback: the copy goes with its last reference."""


PARAMS = Keywords("cw_params")
GRID = Keywords("cw_grid")
WEAR_PARAMS = Keywords("cw_wear_params")
TEMPERATURE_PARAMS = Keywords("cw_temperature_params")
DAMAGE_PARAMS = Keywords("cw_damage_params")


def model_default_grid(model):
    """The grid a model gets when none is given (cw_grid_init_model): for
    the exact model CONTACT's layout, the uniform grid over 1.2 times the
    semi-axes with 24 x 24 elements; for the others cw_grid_init's."""
    rec = np.zeros((), DTYPES["cw_grid"])
    _errors.check(lib.cw_grid_init_model(address(rec), int(model)))
    return rec


def require_geometry(keys, caller):
    """TypeError unless the keywords keys (fields, aliases resolved) give a
    contact's size and load: a, b and N -- or, with a gap, N or
    normal_load="approach". None of them has a sensible default; the
    CLI refuses the same omission."""
    keys = set(keys)
    if "gap" in keys:
        missing = [] if keys & {"normal_force", "normal_load"} else ["N"]
        why = "a gap's load: N, or normal_load='approach' with approach"
    else:
        missing = [name for name, field in (("a", "a"), ("b", "b"), ("N", "normal_force"))
                   if field not in keys]
        why = ("the contact's semi-axes and load have no sensible default (e.g. a=6e-3, "
               "b=6e-3, N=80e3: a 6 mm circle under 80 kN; a and b from the radii: "
               "creepwork.hertz)")
    if missing:
        raise TypeError("%s() missing required keyword argument%s: %s: %s" % (
            caller, "s" if len(missing) > 1 else "", ", ".join(repr(m) for m in missing), why))


def grid_record(grid, caller):
    """A cw_grid record from None (the C default), a dict of cw_grid fields
    ({"kind": "uniform", "nx": 24, "ny": 24, "box_scale": 1.2}), a record,
    or a model's default grid (model_default_grid)."""
    if grid is None:
        return defaults("cw_grid").copy()
    if isinstance(grid, np.ndarray) and grid.dtype == DTYPES["cw_grid"]:
        return grid.copy()
    if not isinstance(grid, dict):
        raise TypeError("%s(): grid must be a dict of cw_grid fields such as {'kind': 'uniform', "
                        "'nx': 24, 'ny': 24}, got %r" % (caller, grid))
    return GRID.record(grid, caller)
