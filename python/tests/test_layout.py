"""The package's generated layout against the C compiler's: every struct's
members (names, offsets, kinds, array lengths) and size, and every
function's parameter and return kinds, as read from the debug information
of layout_probe.o (dwarf.py), which includes creepwork.h; and the library's
exported cw_ symbols. These fail when the header changes and the package's
layout does not follow (test_stale_layout_is_caught shows it)."""

import os
import re
import subprocess

import numpy as np
import pytest

import creepwork
from creepwork import _library
from creepwork._layout import LAYOUT

import dwarf
from conftest import env_path


@pytest.fixture(scope="module")
def dies():
    return dwarf.read_dies(env_path("CREEPWORK_READELF"), env_path("CREEPWORK_LAYOUT_PROBE"))


@pytest.fixture(scope="module")
def c_structs(dies):
    found = dwarf.structs(dies)
    assert "cw_params" in found and "cw_result" in found, "the probe's debug information"
    return found


def differences(layout, c_structs):
    """What differs between a generated layout and the compiler's structs."""
    out = []
    for name in sorted(set(c_structs) | set(layout["structs"])):
        if name not in layout["structs"]:
            out.append("%s: in the header, not in the package's layout" % name)
            continue
        if name not in c_structs:
            out.append("%s: in the package's layout, not in the header" % name)
            continue
        fields = layout["structs"][name]
        dtype = _library._struct_dtype(fields)
        mine = [(f["name"], dtype.fields[f["name"]][1], f["kind"], f["count"])
                for f in fields]
        size, theirs = c_structs[name]
        for m in sorted(set(theirs) - set(mine), key=lambda t: t[1]):
            out.append("%s.%s (offset %d, %s) is in the header, not in the package's layout"
                       % (name, m[0], m[1], m[2]))
        for m in sorted(set(mine) - set(theirs), key=lambda t: t[1]):
            out.append("%s.%s (offset %d, %s) is in the package's layout, not in the header"
                       % (name, m[0], m[1], m[2]))
        if dtype.itemsize != size:
            out.append("sizeof(%s): %d in the header, %d in the package" % (name, size,
                                                                             dtype.itemsize))
    return out


def test_structs_match_the_compiler(generator, c_structs):
    assert differences(LAYOUT, c_structs) == []
    # And the dtypes the package uses are those of the layout.
    for name, (size, members) in c_structs.items():
        assert creepwork.DTYPES[name].itemsize == size
        assert [(m, creepwork.DTYPES[name].fields[m][1]) for m, *_ in members] == \
            [(m, off) for m, off, *_ in members]


def test_stale_layout_is_caught(generator, source_dir, c_structs):
    """A layout generated before cw_params gained its last field (an int after
    a double, so sizeof(cw_params) is the same with or without it: the
    padding hides it) is reported, naming the field."""
    with open(os.path.join(source_dir, "capi/include/creepwork/creepwork.h")) as f:
        header = f.read()
    last = LAYOUT["structs"]["cw_params"][-1]
    body = re.search(r"typedef struct cw_params \{.*?\} cw_params;", header, re.S).group(0)
    # The declaration's line and its comment, to the comment's end.
    decl = re.search(r"\n[^\n]*\b%s;.*?\*/" % last["name"], body, re.S).group(0)
    stale = generator.parse_header(header.replace(body, body.replace(decl, "")))
    assert last["name"] not in [f["name"] for f in stale["structs"]["cw_params"]]
    found = differences(stale, c_structs)
    assert any(("cw_params.%s " % last["name"]) in d and "not in the package" in d
               for d in found), found


def test_functions_match_the_compiler(dies):
    c_functions = dwarf.functions(dies)
    assert set(c_functions) == set(LAYOUT["functions"])
    for name, (ret, params) in c_functions.items():
        proto = LAYOUT["functions"][name]
        assert proto["restype"] == ret, name
        assert proto["argtypes"] == params, name


def test_every_exported_function_is_declared():
    """The library exports exactly the functions the package declares."""
    text = subprocess.run([env_path("CREEPWORK_READELF"), "--dyn-syms", "--wide",
                           env_path("CREEPWORK_LIBRARY_FILE")], check=True, capture_output=True,
                          text=True).stdout
    exported = {m.group(1) for m in re.finditer(r"\sFUNC\s+GLOBAL\s+DEFAULT\s+\d+\s+(cw_\w+)", text)}
    assert exported == set(LAYOUT["functions"])


def test_library_struct_sizes_are_the_headers(c_structs):
    """Each struct's _init function (the library) reports sizeof as the header has it."""
    for name, (size, _) in c_structs.items():
        init = getattr(_library.lib, name + "_init")
        buf = np.zeros(size + 256, np.uint8)
        assert init(buf.ctypes.data) == 0
        assert int(buf[:8].view(np.uintp)[0]) == size, name


def test_every_params_field_is_a_keyword(c_structs):
    """Each cw_params member the compiler knows is a keyword of params() and
    lands at the member's offset; every other member keeps cw_params_init's
    default. (Padding bytes are not compared: numpy copies a structured
    record field by field and leaves them as they come.)"""
    size, members = c_structs["cw_params"]
    width = {"double": 8, "int": 4, "size_t": 8, "pointer": 8}
    dtype = {"double": np.float64, "int": np.intc, "size_t": np.uintp, "pointer": np.uintp}
    defaults = _library.defaults("cw_params").tobytes()
    data = np.arange(3.0)  # a pointer field holds the address of its array
    for name, offset, kind, count in members:
        if name == "struct_size":
            continue
        value = {"double": 0.125, "int": 3, "size_t": 7, "pointer": data}.get(kind)
        assert value is not None, "teach this test the kind %s of %s" % (kind, name)
        raw = creepwork.params(**{name: value}).tobytes()
        stored = data.ctypes.data if kind == "pointer" else value
        expected = np.array(stored, dtype[kind]).tobytes()
        assert raw[offset:offset + width[kind]] == expected, name
        for other, o, k, _ in members:
            if kind == "pointer" and other == name + "_len":
                # The length field follows the array (gap -> gap_len).
                assert raw[o:o + width[k]] == np.array(data.size, np.uintp).tobytes()
            elif other != name:
                assert raw[o:o + width[k]] == defaults[o:o + width[k]], (name, other)
