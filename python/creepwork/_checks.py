"""The library's plausibility checks (cw_params_check, and the surface
post-processors' cw_temperature_params_check, cw_damage_params_check) as the messages of
creepwork.UnitWarning, naming each input as the user typed it; and the
library's canonical names of inputs and enumeration values (cw_input_name).

The rules live in the library, behind every door (the CLI, Octave and
Fortran print the same findings): values a solve accepts but no wheel-rail
contact has -- millimetres typed as metres, kN as N, MPa as Pa, a per cent
as a ratio, a gap grid in millimetres -- and a contact left at
cw_params_init's placeholder size and load. The library never warns by
itself: it works in any consistent units.
"""

import ctypes
import re

import numpy as np

from ._library import CONSTANTS, DTYPES, address, lib

_DEFAULT_GEOMETRY = CONSTANTS["CW_CHECK_DEFAULT_GEOMETRY"]


def text(chars):
    """A char array field of cw_check (input, unit, reason, message) as str."""
    return chars.split(b"\0", 1)[0].decode("utf-8", "replace")


def records(fill):
    """The cw_check records a check function gives: fill(out, len, found)
    calls it (a count query with out None, len 0, then the fill)."""
    found = ctypes.c_size_t(0)
    if fill(None, 0, ctypes.byref(found)) != 0 or found.value == 0:
        return []
    out = np.zeros(found.value, DTYPES["cw_check"])
    for k in range(found.value):
        lib.cw_check_init(address(out[k:k + 1]))
    if fill(address(out), found.value, ctypes.byref(found)) != 0:
        return []
    return list(out)


def findings(grid, recs):
    """The cw_check records cw_params_check gives for the cw_params record(s)
    recs (any shape) on grid (a cw_grid record)."""
    flat = recs if recs.flags.c_contiguous else np.ascontiguousarray(recs)
    where, count = address(flat), flat.size
    return records(lambda out, n, found: lib.cw_params_check(address(grid), where, count, out, n,
                                                             found))


def warnings_for(grid, recs, typed):
    """UnitWarning messages for the cw_params record(s) recs on grid; typed:
    the keywords the user gave, by field ({"normal_force": "N"}), which
    name the inputs in the messages. The placeholder size and load are
    reported only when a, b and N were not all given."""
    given = {"a", "b", "normal_force"} <= set(typed)
    out = []
    for c in findings(grid, recs):
        if int(c["rule"]) == _DEFAULT_GEOMETRY and given:
            continue
        field = text(c["input"])
        out.append(typed.get(field, field) + text(c["message"])[len(field):])
    return out


def params_warnings(struct, rec, typed):
    """UnitWarning messages for a cw_temperature_params or cw_damage_params
    record (struct "temperature" or "damage": cw_<struct>_params_check),
    each input named as typed ({field: keyword})."""
    check = getattr(lib, "cw_%s_params_check" % struct)
    return [as_typed(text(c["message"]), typed)
            for c in records(lambda out, n, found: check(address(rec), out, n, found))]


def as_typed(message, typed):
    """A library message with each field the user gave by another name
    named as typed ("normal_force = -1 is invalid" -> "N = -1 ...")."""
    for field, name in typed.items():
        if name != field:
            message = re.sub(r"\b%s\b" % re.escape(field), name, message)
    return message


def canonical(name):
    """The library's spelling of an input or enumeration value typed another
    way (cw_input_name): "N" -> "normal_force", "spin" -> "phi", "fast" ->
    "fastsim", "Semi-Hertz" -> "semi_hertz"; other names unchanged."""
    raw = name.encode()
    buf = ctypes.create_string_buffer(len(raw) + 32)
    if lib.cw_input_name(raw, buf, len(buf)) != 0:
        return name
    return buf.value.decode()
