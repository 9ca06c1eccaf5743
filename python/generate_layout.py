#!/usr/bin/env python3
"""Reads creepwork.h and writes what the Python package and the MEX gateway
need to know about it, so that neither holds a hand-copied layout:

  --python FILE   creepwork/_layout.py: the structs (field names, C types,
                  array lengths, the header's comment of each field), every
                  #define constant, the enumerations named after the struct
                  field they belong to, the status list and the prototypes
  --c-fields FILE an X-macro table of every struct field and enumeration for
                  C code (the MEX gateway: offsetof() by the C compiler)
  --probe FILE    a C file that uses every struct, compiled with -g by the
                  layout test: the compiler's debug information is the
                  independent truth the generated layout is checked against

The header is read by tools/header/creepwork_header.py, the one reader of
every generator and checker (its docstring lists the conventions it
accepts); this file turns what it reads into the layouts above. Only the
standard library is used (no numpy), so the build needs nothing but a
Python 3 interpreter.
"""

import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tools", "header"))
import creepwork_header  # noqa: E402  (tools/header)

HeaderError = creepwork_header.HeaderError
read_header = creepwork_header.read_header

# C scalar types the structs and prototypes may use, by their kind; the
# package maps kinds to numpy and ctypes types.
SCALAR_KINDS = {
    "double": "double",
    "float": "float",
    "int": "int",
    "unsigned": "unsigned",
    "unsigned int": "unsigned",
    "size_t": "size_t",
    "int32_t": "int32_t",
    "uint32_t": "uint32_t",
    "int64_t": "int64_t",
    "uint64_t": "uint64_t",
    "char": "char",
}


def layout_field(f, struct):
    if not f.pointer and f.ctype not in SCALAR_KINDS:
        raise HeaderError("%s: field %s has type %r, not one of %s (teach generate_layout.py)"
                          % (struct, f.name, f.ctype, ", ".join(sorted(SCALAR_KINDS))))
    return {"name": f.name, "ctype": f.ctype, "kind": "pointer" if f.pointer else SCALAR_KINDS[f.ctype],
            "pointer": f.pointer, "count": f.count, "doc": f.doc}


def type_kind(base, stars, where):
    """Kind of a type: a scalar kind, "pointer", "char_p" or "void"."""
    if stars:
        return "char_p" if (base, stars) == ("char", 1) else "pointer"
    if base == "void":
        return "void"
    if base not in SCALAR_KINDS:
        raise HeaderError("%s: type %r (teach generate_layout.py)" % (where, base))
    return SCALAR_KINDS[base]


def layout_function(f):
    ret = [w for w in creepwork_header.c_words(f.return_type) if w not in ("const", "volatile")]
    base = " ".join(w for w in ret if w != "*")
    # An array parameter (double coefficients[4]) is a pointer.
    args = [type_kind(p.base, p.stars + (p.dim is not None), f.name) for p in f.params]
    return {"restype": type_kind(base, ret.count("*"), f.name), "argtypes": args}


def enum_member_name(macro, group, field):
    if len(group) > 1:
        prefix = os.path.commonprefix(group)
        prefix = prefix[: prefix.rfind("_") + 1]
        name = macro[len(prefix):]
    else:
        name = macro[3:]
        if name.startswith(field.upper() + "_"):
            name = name[len(field) + 1:]
    return name.lower()


def parse_header(text, header_name="creepwork.h"):
    header = creepwork_header.parse(text, header_name)
    constants = header.constants
    enums = {}
    for key, macros in header.enums.items():
        field = key.split(".")[1]
        enums[key] = {enum_member_name(mac, macros, field): constants[mac] for mac in macros}
    return {
        "header": header_name,
        "structs": {name: [layout_field(f, name) for f in s.fields]
                    for name, s in header.structs.items()},
        "constants": constants,
        "constant_docs": {m.name: m.doc for m in header.macros if m.doc},
        "enums": enums,
        "statuses": header.statuses,
        "functions": {f.name: layout_function(f) for f in header.functions},
    }


def python_source(layout):
    """The layout as a Python literal, one struct field or prototype per line."""
    out = ["# Generated from %s by python/generate_layout.py: do not edit." % layout["header"],
           "# The package builds its numpy dtypes, ctypes prototypes, exceptions and",
           "# keyword documentation from this description of the header.", "",
           "LAYOUT = {", "    'header': %r," % layout["header"], "    'structs': {"]
    for struct, fields in layout["structs"].items():
        out.append("        %r: [" % struct)
        out += ["            %r," % (f,) for f in fields]
        out.append("        ],")
    out.append("    },")
    for key in ("constants", "constant_docs", "enums", "functions"):
        out.append("    %r: {" % key)
        out += ["        %r: %r," % item for item in layout[key].items()]
        out.append("    },")
    out.append("    'statuses': [")
    out += ["        %r," % (entry,) for entry in layout["statuses"]]
    out += ["    ],", "}", ""]
    return "\n".join(out)


C_KIND = {"double": "DOUBLE", "float": "FLOAT", "int": "INT", "unsigned": "UNSIGNED",
          "size_t": "SIZE_T", "int32_t": "INT32", "uint32_t": "UINT32", "int64_t": "INT64",
          "uint64_t": "UINT64", "char": "CHAR"}


def c_fields_source(layout):
    """X(struct, field, kind, count) per field; E(struct, field, "name", value) per
    enumeration member; C(name) per constant. kind is CW_KIND_<C type> or
    CW_KIND_POINTER."""
    out = ["/* Generated from %s by python/generate_layout.py: do not edit. */" % layout["header"],
           "#ifndef CREEPWORK_FIELDS_H", "#define CREEPWORK_FIELDS_H", ""]
    for struct, fields in layout["structs"].items():
        out.append("#define CW_FIELDS_%s(X) \\" % struct)
        for f in fields:
            kind = "POINTER" if f["pointer"] else C_KIND[f["kind"]]
            out.append("    X(%s, %s, CW_KIND_%s, %d) \\" % (struct, f["name"], kind, f["count"] or 1))
        out.append("")
    out.append("#define CW_ENUMS(E) \\")
    for key, members in layout["enums"].items():
        struct, field = key.split(".")
        for name, value in members.items():
            out.append("    E(%s, %s, \"%s\", %r) \\" % (struct, field, name, value))
    out += ["", "/* C(CW_NAME) per #define constant and status code. */", "#define CW_CONSTANTS(C) \\"]
    out += ["    C(%s) \\" % name for name in layout["constants"]]
    out += ["", "#endif", ""]
    return "\n".join(out)


def probe_source(layout):
    out = ["/* Generated from %s by python/generate_layout.py: do not edit. Compiled with" % layout["header"],
           " * -g, so that the layout test can read every struct's members and every",
           " * function's parameters from the compiler's debug information. */",
           "#include <creepwork/creepwork.h>", ""]
    for struct in layout["structs"]:
        out.append("%s cw_probe_%s;" % (struct, struct))
    out += ["", "void* cw_probe_functions[] = {"]
    out += ["    (void*)%s," % name for name in layout["functions"]]
    out += ["};", ""]
    return "\n".join(out)


def write_if_changed(path, text):
    """Writes text to path unless it holds it already; then only touches it
    (the build compares times: the output must be newer than the header)."""
    creepwork_header.write_if_changed(path, text, touch=True)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--header", required=True)
    ap.add_argument("--python")
    ap.add_argument("--c-fields")
    ap.add_argument("--probe")
    args = ap.parse_args(argv)
    try:
        layout = parse_header(read_header(args.header), os.path.basename(args.header))
    except HeaderError as e:
        sys.exit("generate_layout.py: %s: %s" % (args.header, e))
    if args.python:
        write_if_changed(args.python, python_source(layout))
    if args.c_fields:
        write_if_changed(args.c_fields, c_fields_source(layout))
    if args.probe:
        write_if_changed(args.probe, probe_source(layout))


if __name__ == "__main__":
    main()
