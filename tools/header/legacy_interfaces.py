#!/usr/bin/env python3
"""The legacy layer's interfaces, read from where they are written: the CW*
subroutines of the Fortran sources (fortran/creepwork_legacy*.f90), the
installed include files (creepwork_legacy.inc: a "! CALL NAME(...)" comment
and an "EXTERNAL NAME" line per routine; creepwork_legacy.fi: an interface
body per routine) and the manual (a "`CALL NAME(...)`" line, then a table
row per argument). The C header's reader is creepwork_header.py beside this
file; these are the legacy layer's headers. A signature is "NAME|A,B,C":
upper case, blanks dropped.
"""

import re


def joined(text):
    """Fortran continuation lines ('&' at the end, an optional '&' or '!' at
    the start of the next) joined into one line each."""
    return re.sub(r"&[ \t]*\n[ \t]*!?[ \t]*&?", " ", text)


def signatures(text, regex):
    """The signature of every "<prefix>NAME(args)" match of regex, NAME CW[A-Z]+."""
    out = []
    for hit in re.findall(regex, text):
        m = re.search(r"(CW[A-Z]+)[ \t]*\(([^)]*)\)", hit)
        out.append(re.sub(r"[ \t\n]+", "", "%s|%s" % (m.group(1), m.group(2))))
    return out


def source_signatures(text):
    """Every CW* subroutine defined in a Fortran source."""
    return signatures(joined(text).upper(), r"\nSUBROUTINE CW[A-Z]+[ \t]*\([^)]*\)")


def interface_signatures(fi_text):
    """Every interface body of creepwork_legacy.fi."""
    return signatures(joined(fi_text).upper(), r"SUBROUTINE CW[A-Z]+[ \t]*\([^)]*\)")


def include_signatures(inc_text):
    """The "! CALL NAME(a, b," / "!             c, d)" comments of
    creepwork_legacy.inc, and its EXTERNAL names."""
    calls = signatures(re.sub(r",[ \t]*\n![ \t]*", ", ", inc_text), r"! CALL CW[A-Z]+\([^)]*\)")
    externals = re.findall(r"\n      EXTERNAL (CW[A-Z]+)\b", inc_text)
    return calls, externals


def documented_signatures(docs_text):
    """Every "`CALL NAME(...)`" line of the manual."""
    return signatures(docs_text, r"`CALL CW[A-Z]+\([^)]*\)`")


def documented_section(docs_text, name):
    """The manual's text from "`CALL NAME(" to the next "`CALL CW" (None if absent)."""
    start = docs_text.find("`CALL %s(" % name)
    if start < 0:
        return None
    nxt = docs_text.find("`CALL CW", start + 1)
    return docs_text[start:nxt if nxt >= 0 else len(docs_text)]
