"""The C compiler's view of creepwork.h, read from the debug information of
layout_probe.o (readelf --debug-dump=info): every struct's members with
their offsets, kinds and array lengths, the struct sizes, and every
function's parameter and return kinds. The layout test compares the
package's generated layout with it; nothing here comes from the package's
own parser."""

import re
import subprocess

_ENTRY = re.compile(r"^\s*<(\d+)><([0-9a-f]+)>: Abbrev Number: (\d+)(?: \((DW_TAG_\w+)\))?")
_ATTR = re.compile(r"^\s*<[0-9a-f]+>\s+(DW_AT_\w+)\s*:\s?(.*)$")

# Typedef names that are kinds of their own (stop resolving there).
_TYPEDEF_KINDS = {"size_t", "int32_t", "uint32_t", "int64_t", "uint64_t"}
_BASE_KINDS = {"double": "double", "float": "float", "int": "int", "unsigned int": "unsigned",
               "char": "char"}


def _value(text):
    """An attribute's value without readelf's decorations: the form
    ("(strp) ", "(data1) "), and the string offset ("(offset: 0x40): ",
    "(indirect string, offset: 0x5a): ")."""
    text = re.sub(r"^\((?:strp|line_strp|string|data\d|sdata|udata|ref\d|ref_udata|flag\w*|"
                  r"implicit_const|exprloc|sec_offset|addr\w*|strx\d?)\)\s*", "", text)
    text = re.sub(r"^\((?:indirect (?:line )?string, )?offset: (?:0x)?[0-9a-f]+\):\s*", "", text)
    return text.strip()


def read_dies(readelf, obj):
    """Every debugging information entry: {offset: (tag, attrs, children)}."""
    text = subprocess.run([readelf, "--debug-dump=info", "--wide", obj], check=True,
                          capture_output=True, text=True).stdout
    dies, stack = {}, []
    current = None
    for line in text.splitlines():
        m = _ENTRY.match(line)
        if m:
            depth, offset, tag = int(m.group(1)), int(m.group(2), 16), m.group(4)
            del stack[depth:]
            if tag is None:  # a null entry closes a list of children
                current = None
                continue
            current = (tag, {}, [])
            dies[offset] = current
            if stack:
                stack[-1][2].append(offset)
            stack.append(current)
            continue
        m = _ATTR.match(line)
        if m and current is not None:
            current[1][m.group(1)] = _value(m.group(2))
    return dies


def _ref(text):
    return int(re.search(r"<0x([0-9a-f]+)>", text).group(1), 16)


def kind(dies, offset):
    """(kind, count) of a type: a scalar kind, "pointer", "char_p" or "void";
    count the array length (None for scalars)."""
    tag, attrs, children = dies[offset]
    if tag == "DW_TAG_typedef":
        name = attrs["DW_AT_name"]
        return (name, None) if name in _TYPEDEF_KINDS else kind(dies, _ref(attrs["DW_AT_type"]))
    if tag in ("DW_TAG_const_type", "DW_TAG_volatile_type"):
        return kind(dies, _ref(attrs["DW_AT_type"])) if "DW_AT_type" in attrs else ("void", None)
    if tag == "DW_TAG_pointer_type":
        if "DW_AT_type" in attrs and kind(dies, _ref(attrs["DW_AT_type"]))[0] == "char":
            return ("char_p", None)
        return ("pointer", None)
    if tag == "DW_TAG_base_type":
        return (_BASE_KINDS.get(attrs["DW_AT_name"], attrs["DW_AT_name"]), None)
    if tag == "DW_TAG_array_type":
        element = kind(dies, _ref(attrs["DW_AT_type"]))[0]
        bounds = [dies[c][1] for c in children if dies[c][0] == "DW_TAG_subrange_type"]
        if len(bounds) != 1:
            raise ValueError("multi-dimensional array")
        count = bounds[0].get("DW_AT_count") or str(int(bounds[0]["DW_AT_upper_bound"], 0) + 1)
        return (element, int(count, 0))
    if tag == "DW_TAG_structure_type":
        return ("struct " + attrs.get("DW_AT_name", "?"), None)
    raise ValueError("unexpected type entry %s" % tag)


def structs(dies):
    """{name: (byte_size, [(member, offset, kind, count), ...])} of the cw_ structs."""
    out = {}
    for tag, attrs, children in dies.values():
        name = attrs.get("DW_AT_name", "")
        if tag != "DW_TAG_structure_type" or not name.startswith("cw_") or \
                "DW_AT_declaration" in attrs:
            continue
        members = []
        for c in children:
            ctag, cattrs, _ = dies[c]
            if ctag != "DW_TAG_member":
                continue
            k, count = kind(dies, _ref(cattrs["DW_AT_type"]))
            members.append((cattrs["DW_AT_name"], int(cattrs["DW_AT_data_member_location"], 0),
                            k, count))
        out[name] = (int(attrs["DW_AT_byte_size"], 0), members)
    return out


def functions(dies):
    """{name: (return kind, [parameter kinds])} of the cw_ functions declared."""
    out = {}
    for tag, attrs, children in dies.values():
        name = attrs.get("DW_AT_name", "")
        if tag != "DW_TAG_subprogram" or not name.startswith("cw_"):
            continue
        ret = kind(dies, _ref(attrs["DW_AT_type"]))[0] if "DW_AT_type" in attrs else "void"
        params = [kind(dies, _ref(dies[c][1]["DW_AT_type"]))[0] for c in children
                  if dies[c][0] == "DW_TAG_formal_parameter"]
        out[name] = (ret, params)
    return out
