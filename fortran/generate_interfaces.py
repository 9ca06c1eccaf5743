#!/usr/bin/env python3
"""Generates the C side of module creepwork from the C header, so that the
two cannot drift (STYLE.md, Fortran). The header is read by
tools/header/creepwork_header.py, the reader every generator shares.

  --constants FILE  every X(CW_NAME, value, "message") of CW_STATUS_LIST as
                    integer(c_int), parameter :: CW_NAME = value, the arrays
                    CW_STATUS_CODES and CW_STATUS_MESSAGES (list order), and
                    every #define CW_NAME <number or constant expression of
                    other CW_ macros> as an integer(c_int) or real(c_double)
                    parameter
  --types FILE      every struct as a bind(C) derived type cw_x: the same
                    fields in the same order, each zero-initialised
                    (struct_size 0 means "not initialised"); a "const T* x;"
                    field as type(c_ptr) (c_null_ptr; set with c_loc)
  --bindings FILE   every CW_API function cw_x as a bind(C) interface capi_x
                    (private to the library's Fortran modules), by the rules:
     int, double, size_t, int64_t by value     -> value dummies of c_int ...
     char* message                             -> character(kind=c_char) :: message(*)
     T* x, T a primitive type                  -> x(*) when x, or a run of T*
                                                  pointers ending at x, is followed
                                                  by its size_t length; x(N) for
                                                  T x[N]; else a scalar
     cw_s* x, cw_s a struct of the header      -> type(cw_s) :: x
     cw_h* x / cw_h** x, cw_h an opaque handle -> type(c_ptr), value / intent(out)
     const                                     -> intent(in), else intent(inout)
     returned int / const char* / const cw_h*  -> integer(c_int) / type(c_ptr)
                    and two lists below for what a prototype alone does not
                    say. Anything else stops the build with the prototype
                    named, so a new kind of argument is a decision, not a
                    silent mis-binding.
Each file is written only when it changes, so an unchanged header rebuilds
nothing.

usage: generate_interfaces.py --header creepwork.h [--constants F] [--types F] [--bindings F]
"""

import argparse
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools", "header"))
import creepwork_header  # noqa: E402  (tools/header)

GENERATOR = "generate_interfaces.py"

# Pointers the header lets the caller pass as NULL and the module passes as
# NULL (its optional arguments): bound as type(c_ptr), value.
NULLABLE = [
    "cw_solver_solve.result", "cw_solver_solve_jacobian.result",
    "cw_solver_get_profile.y", "cw_solver_get_profile.w", "cw_solver_get_profile.parabola",
    "cw_batch_solve.statuses", "cw_wear_compute.result",
    "cw_wear_get_strips.y", "cw_wear_get_strips.width", "cw_wear_get_strips.depth",
    "cw_wear_get_strips.parabola", "cw_wheelrail_add_wear.result",
    "cw_temperature_compute.result", "cw_damage_compute.result",
    "cw_temperature_solve.result", "cw_temperature_solve.temperature_result",
    "cw_transient_get_wear.mass_map"]
# Struct pointers that are arrays (count elements): bound as type(cw_s) :: x(*).
STRUCT_ARRAYS = ["cw_batch_solve.params", "cw_batch_solve.results", "cw_solver_get_patches.out",
                 "cw_params_check.params", "cw_params_check.out", "cw_wheelrail_check.out",
                 "cw_temperature_params_check.out", "cw_damage_params_check.out"]

SCALARS = {"int": "integer(c_int)", "double": "real(c_double)", "size_t": "integer(c_size_t)",
           "int64_t": "integer(c_int64_t)",
           "uint64_t": "integer(c_int64_t)"}  # no unsigned kinds in Fortran: the bits pass unchanged


class GeneratorError(Exception):
    pass


def check_case_clash(names, where):
    """Fortran names are case-insensitive: two names differing only in case clash."""
    seen = set()
    for n in names:
        if n.lower() in seen:
            raise GeneratorError("%s: '%s' clashes with another name in Fortran (case)" % (where, n))
        seen.add(n.lower())


def wrap_list(items, indent):
    """'a, b, c' joined onto lines of at most 80 characters after indent."""
    result, line = "", ""
    for item in items:
        if line == "":
            line = item
        elif len(("%s, %s" % (line, item)).encode()) > 80:
            result += "%s, &\n%s" % (line, indent)
            line = item
        else:
            line = "%s, %s" % (line, item)
    return result + line


# ---------------------------------------------------------------- constants

def constants_source(header):
    out = ["! Generated from %s by %s: do not edit." % (header.name, GENERATOR),
           "! Included in the specification part of module creepwork.", ""]
    codes, messages = [], []
    for name, value, msg in header.statuses:
        out.append("integer(c_int), parameter, public :: %s = %d_c_int" % (name, value))
        codes.append("%d_c_int" % value)
        messages.append("'%s'" % msg.replace("'", "''"))
    width = max([1] + [len(msg.encode()) for _, _, msg in header.statuses])
    n = len(header.statuses)
    out += ["", "! Every status code of CW_STATUS_LIST and its message, in list order.",
            "integer, parameter, public :: CW_STATUS_COUNT = %d" % n,
            "integer(c_int), parameter, public :: CW_STATUS_CODES(%d) = [ &" % n,
            "    " + ", &\n    ".join(codes) + "]",
            "character(len=%d), parameter, public :: CW_STATUS_MESSAGES(%d) = &" % (width, n),
            "  [character(len=%d) :: &" % width,
            "    " + ", &\n    ".join(messages) + "]", ""]
    for m in header.macros:
        if re.fullmatch(r"-?[0-9]+", m.text):
            out.append("integer(c_int), parameter, public :: %s = %s_c_int" % (m.name, m.text))
        elif (re.fullmatch(r"-?[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?", m.text)
              or re.fullmatch(r"-?[0-9]+\.[0-9]*", m.text)):
            out.append("real(c_double), parameter, public :: %s = %s_c_double" % (m.name, m.text))
        elif re.fullmatch(r"[-+*/() 0-9A-Z_]+", m.text) and "CW_" in m.text:
            # A constant expression of integer macros, e.g. CW_VERSION_NUMBER: valid Fortran as written.
            out.append("integer(c_int), parameter, public :: %s = %s" % (m.name, m.text))
    return "\n".join(out) + "\n"


# -------------------------------------------------------------------- types

def first_line(comment):
    return comment.split("\n")[0].rstrip()


def types_source(header):
    out = ["! Generated from %s by %s: do not edit." % (header.name, GENERATOR),
           "! The structs of the header as bind(C) derived types: the same fields in the",
           "! same order, each zero-initialised (struct_size 0: call the _init first)."]
    for struct in header.structs.values():
        out += ["", "   type, bind(c), public :: %s" % struct.name]
        for member in struct.members:
            if isinstance(member, creepwork_header.Note):
                # A comment of its own (e.g. "---- appended in 1.1 ----"): its first line kept.
                out.append("      ! " + re.sub(r"[ -]+$", "", re.sub(r"^[ -]*", "", first_line(member.comment))))
                continue
            fields = member.fields
            f0 = fields[0]
            where = "%s: the field '%s'" % (struct.name, ", ".join(f.name for f in fields))
            if f0.ctype == "char":
                # char x[N]: N characters of NUL-terminated text (cw_check's input, message).
                if len(fields) > 1 or f0.pointer or f0.count is None:
                    raise GeneratorError("%s: only 'char x[N];' text fields are bound" % where)
                ftype, zero = "character(kind=c_char)", "c_null_char"
            elif f0.ctype not in SCALARS:
                raise GeneratorError("%s: no Fortran type for field type '%s'" % (where, f0.ctype))
            elif any(f.pointer for f in fields):
                if len(fields) > 1 or not f0.const or f0.pointer != 1 or f0.count is not None:
                    raise GeneratorError("%s: only 'const T* x;' pointer fields are bound" % where)
                ftype, zero = "type(c_ptr)", "c_null_ptr"
            else:
                if any(f.count is not None for f in fields) and len(fields) > 1:
                    raise GeneratorError("%s: one array field per declaration" % where)
                ftype, zero = SCALARS[f0.ctype], "0"
            inits = ", ".join("%s%s = %s" % (f.name, "" if f.count is None else "(%d)" % f.count, zero)
                              for f in fields)
            line = "      %s :: %s" % (ftype, inits)
            if f0.comment:
                comment = first_line(f0.comment).lstrip(" ")
                if "\n" in f0.comment:
                    comment += " ..."
                else:
                    comment = comment.rstrip(" ")
                room = 130 - len(line.encode()) - 3
                if room > 10:
                    line += " ! " + comment.encode()[:room].decode(errors="ignore")
            out.append(line)
        check_case_clash([f.name for f in struct.fields], struct.name)
        out.append("   end type %s" % struct.name)
    return "\n".join(out) + "\n"


# ----------------------------------------------------------------- bindings

def binding(f, header):
    structs, opaque = set(header.structs), set(header.handles)
    decls = []
    for i, p in enumerate(f.params):
        intent = "in" if p.const else "inout"
        ftype = SCALARS.get(p.base) if " " not in p.base else None
        where = "%s.%s" % (f.name, p.name)
        if where in NULLABLE:
            if p.stars != 1:
                raise GeneratorError("%s is listed as nullable but is not a pointer" % where)
            d = "type(c_ptr), value :: %s ! %s*, may be NULL" % (p.name, p.base)
        elif p.base == "char" and p.stars == 1:
            d = "character(kind=c_char), intent(%s) :: %s(*)" % (intent, p.name)
        elif ftype and p.stars == 0 and p.dim is not None:
            d = "%s, intent(%s) :: %s(%s)" % (ftype, intent, p.name, p.dim)
        elif ftype and p.stars == 0:
            d = "%s, value :: %s" % (ftype, p.name)
        elif ftype and p.stars == 1:
            # An array when it, or the run of such pointers it ends, is followed by a size_t length.
            is_array = False
            for q in f.params[i + 1:]:
                if q.base == "size_t" and q.stars == 0:
                    is_array = True
                    break
                if not (q.base == p.base and q.stars == 1):
                    break
            d = "%s, intent(%s) :: %s%s" % (ftype, intent, p.name, "(*)" if is_array else "")
        elif p.base in structs and p.stars == 1:
            d = "type(%s), intent(%s) :: %s%s" % (p.base, intent, p.name,
                                                  "(*)" if where in STRUCT_ARRAYS else "")
        elif p.base in opaque and p.stars == 1:
            d = "type(c_ptr), value :: %s ! %s*" % (p.name, p.base)
        elif p.base in opaque and p.stars == 2 and intent == "inout":
            d = "type(c_ptr), intent(out) :: %s ! %s*, set on success" % (p.name, p.base)
        else:
            raise GeneratorError("%s: no Fortran binding rule for argument %s (%s %s, %d stars): "
                                 "add one to %s" % (f.name, p.name, "const" if p.const else "var",
                                                    p.base, p.stars, GENERATOR))
        decls.append("         " + d)

    rtype = f.return_type
    m = re.fullmatch(r"const (cw_[a-z_]+) ?\*", rtype)
    if rtype == "int":
        rdecl = "integer(c_int) :: return_value"
    elif re.fullmatch(r"const char ?\*", rtype):
        rdecl = "type(c_ptr) :: return_value ! const char*: static or owned by the handle"
    elif m and m.group(1) in opaque:
        rdecl = "type(c_ptr) :: return_value ! %s*: owned by the handle" % m.group(1)
    else:
        raise GeneratorError("%s: no Fortran binding rule for the return type '%s'" % (f.name, rtype))

    names = [p.name for p in f.params]
    iname = re.sub(r"^cw_", "capi_", f.name)
    # The prototype as a comment, cut at its commas onto short lines.
    proto = wrap_list(f.prototype.split(", "), "      !    ").replace(", &\n", ",\n")
    return ["", "      ! %s;" % proto,
            "      function %s(%s) &" % (iname, wrap_list(names, "            ")),
            "         bind(c, name='%s') result(return_value)" % f.name,
            "         import"] + decls + ["         " + rdecl, "      end function %s" % iname]


def bindings_source(header):
    out = ["! Generated from %s by %s: do not edit." % (header.name, GENERATOR),
           "! One bind(C) interface capi_<x> per CW_API function cw_<x> of the header.",
           "   interface"]
    for f in header.functions:
        check_case_clash([p.name for p in f.params], f.name)
        out += binding(f, header)
    out.append("   end interface")
    # The override lists name only what exists.
    bound = {f.name for f in header.functions}
    for entry in NULLABLE + STRUCT_ARRAYS:
        if entry.split(".")[0] not in bound:
            raise GeneratorError("%s: no such function in %s (update %s)" % (entry, header.name, GENERATOR))
    return "\n".join(out) + "\n"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--header", required=True)
    ap.add_argument("--constants")
    ap.add_argument("--types")
    ap.add_argument("--bindings")
    args = ap.parse_args(argv)
    try:
        header = creepwork_header.load(args.header)
        outputs = [(args.constants, constants_source), (args.types, types_source),
                   (args.bindings, bindings_source)]
        texts = [(path, make(header)) for path, make in outputs if path]
    except (creepwork_header.HeaderError, GeneratorError) as e:
        sys.exit("%s: %s: %s" % (GENERATOR, args.header, e))
    for path, text in texts:
        creepwork_header.write_if_changed(path, text)


if __name__ == "__main__":
    main()
