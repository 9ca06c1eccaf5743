"""Warnings for inputs that are valid but implausible for a wheel-rail
contact: millimetres typed as metres, kN as N, MPa as Pa, per cent as a ratio.

The rules and thresholds are the creepwork CLI's, plausibility_warnings() in
programs/cli/contact_inputs.cpp, so every door warns about the same inputs
(tests/test_units.py runs both on values either side of each threshold).
The library itself never warns: it works in any consistent units.
"""

import numpy as np

# (field, unit, condition, what is plausible); conditions take a number or a
# numpy array (SI) and the flexibility mode (CW_FLEX_FROM_MATERIAL = 0 or
# CW_FLEX_GIVEN = 1), so only operators both understand (& | abs).
_SEMI_AXIS_HIGH = "semi-axes are 1-20 mm (were millimetres typed as metres?)"
_SEMI_AXIS_LOW = "semi-axes are 1-20 mm, not below 0.1 mm"
_FLEX = "Kalker's flexibilities of steel contacts are ~5e-14 m/Pa (mm^3/N are 1e-9 m^3/N)"
_CREEPAGE = "creepages are ratios, usually below 0.02 (a per cent typed as a ratio?)"

_RULES = [
    ("a", "m", lambda v, flex: v > 0.1, _SEMI_AXIS_HIGH),
    ("a", "m", lambda v, flex: v < 1e-4, _SEMI_AXIS_LOW),
    ("b", "m", lambda v, flex: v > 0.1, _SEMI_AXIS_HIGH),
    ("b", "m", lambda v, flex: v < 1e-4, _SEMI_AXIS_LOW),
    ("normal_force", "N", lambda v, flex: v > 1e7, "wheel loads are below 1 MN (kN typed as N?)"),
    ("normal_force", "N", lambda v, flex: (v > 0.0) & (v < 1000.0),
     "wheel loads are 1-500 kN, not below 1 kN (kN typed where N are read?)"),
    ("mu", "", lambda v, flex: v > 1.5, "dry steel on steel is 0.1-0.6"),
    ("G", "Pa", lambda v, flex: (flex == 0) & (v < 1e6),
     "steel is 8.2e10 Pa (a modulus in MPa or N/mm^2 typed as Pa?)"),
    ("G", "Pa", lambda v, flex: (flex == 0) & (v > 1e12),
     "steel is 8.2e10 Pa, no solid exceeds 1e12 Pa"),
    ("L1", "m/Pa", lambda v, flex: (flex != 0) & ((v > 1e-10) | (v < 1e-18)), _FLEX),
    ("L2", "m/Pa", lambda v, flex: (flex != 0) & ((v > 1e-10) | (v < 1e-18)), _FLEX),
    ("L3", "m/Pa", lambda v, flex: (flex != 0) & ((v > 1e-10) | (v < 1e-18)), _FLEX),
    ("xi_x", "", lambda v, flex: abs(v) > 0.5, _CREEPAGE),
    ("xi_y", "", lambda v, flex: abs(v) > 0.5, _CREEPAGE),
    ("phi", "1/m", lambda v, flex: abs(v) > 50.0,
     "spin of wheel-rail contacts stays below ~20 1/m (1/mm typed as 1/m?)"),
]

# The keyword a user types for a cw_params field, where it differs.
_KEYWORD = {"normal_force": "N"}

#: The fields the rules read.
FIELDS = frozenset(rule[0] for rule in _RULES) | {"flexibility"}


def warnings_for(values):
    """Messages for the implausible values among values: a dict field ->
    number (one contact) or numpy array (many), or a cw_params record or
    structured array. Fields absent from a dict are not checked (the
    library's defaults are plausible); "flexibility" decides which of G and
    L1..L3 is read (absent: from material). One message per rule, with how
    many values of an array break it."""
    flex = values["flexibility"] if _has(values, "flexibility") else 0
    scalar_flex = isinstance(flex, (int, float)) or np.ndim(flex) == 0
    out = []
    for field, unit, bad, why in _RULES:
        if not _has(values, field):
            continue
        v = values[field]
        if scalar_flex and (isinstance(v, (int, float)) or np.ndim(v) == 0):
            # One value: plain Python numbers, fifty times faster than numpy's
            # (isinstance first: np.ndim of a float costs as much as the rule).
            v = float(v)
            if bad(v, int(flex)):
                out.append(_message(field, unit, v, "", why))
            continue
        v = np.asarray(v)
        mask = np.asarray(bad(v, np.asarray(flex)))
        if mask.any():
            first = np.broadcast_to(v, mask.shape)[mask].flat[0]
            where = " (%d of %d values)" % (np.count_nonzero(mask), mask.size) \
                if mask.size > 1 else ""
            out.append(_message(field, unit, first, where, why))
    return out


def _has(values, field):
    if isinstance(values, dict):
        return field in values
    return field in values.dtype.names


def _message(field, unit, value, where, why):
    return "%s = %.10g%s%s is implausible for a wheel-rail contact: %s" % (
        _KEYWORD.get(field, field), value, " " + unit if unit else "", where, why)
