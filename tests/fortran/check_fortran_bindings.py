#!/usr/bin/env python3
"""Module creepwork cannot drift from the C header:
  1. the generated bind(C) interfaces (BINDINGS, from
     fortran/generate_interfaces.py) are exactly the CW_API functions of the
     header (read by tools/header), each once, with the same number of
     arguments (a check on the generator);
  2. every generated interface capi_x is used by a hand-written source of
     the module (SOURCES), i.e. wrapped by a public procedure, or is listed
     below as deliberately not wrapped, with the reason.
A function added to the header is bound automatically and fails 2 until a
wrapper calls it: --self-test shows that on a copy of the header with one
more prototype (the real header passes, the grown one is bound by the
generator and fails the check, naming the function).

usage: check_fortran_bindings.py --header creepwork.h --sources a.f90 b.f90 ...
           (--bindings creepwork_bindings.inc | --self-test WORK_DIR)
"""

import argparse
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools", "header"))
sys.path.insert(0, os.path.join(HERE, "..", "..", "fortran"))
import creepwork_header  # noqa: E402
import generate_interfaces  # noqa: E402

# "cw_name: reason" for each C function module creepwork does not wrap.
NOT_WRAPPED = {
    "cw_wheelrail_patch_solver": "the patch's fields come through get_patch_field and its wear through "
                                 "add_wear, and a borrowed solver would need a handle type that is never "
                                 "destroyed",
}


def count_args(args):
    args = args.strip()
    return 0 if args in ("", "void") else args.count(",") + 1


def check(header, bindings, sources):
    """(problems, summary) of the two checks above."""
    problems = []
    c_args = {f.name: len(f.params) for f in header.functions}
    # Fortran: "function capi_x(<args>) bind(c, name='cw_x')", continuation lines joined.
    joined = re.sub(r"&[ ]*\r?\n[ ]*&?", "", bindings)
    f_args, interface = {}, {}
    for m in re.finditer(r"function[ ]+([a-z0-9_]+)\(([^)]*)\)[ ]*bind\(c, name='(cw_[a-z0-9_]+)'\)", joined):
        name = m.group(3)
        if name in f_args:
            problems.append("%s is bound twice" % name)
        f_args[name], interface[name] = count_args(m.group(2)), m.group(1)
    for name, n in c_args.items():
        if name not in f_args:
            problems.append("%s (%s) has no bind(C) interface" % (name, header.name))
        elif n != f_args[name]:
            problems.append("%s: %d arguments in C, %d in Fortran" % (name, n, f_args[name]))
    problems += ["%s is bound but not declared in %s" % (n, header.name) for n in f_args if n not in c_args]

    # Wrapped: the interface is called ("capi_x(...)", or passed on as
    # "capi_x": a handle's destroy and last_error) in a hand-written source.
    code = "\n".join(sources)
    code = re.sub(r"![^\n]*", "", code).lower()  # comments do not wrap anything
    problems += ["NOT_WRAPPED names %s, which %s does not declare" % (n, header.name)
                 for n in NOT_WRAPPED if n not in c_args]
    wrapped = 0
    for name, iname in interface.items():
        if name in NOT_WRAPPED:
            continue
        if re.search(r"[^a-z0-9_]%s[ ]*[(,)]" % re.escape(iname), code):
            wrapped += 1
        else:
            problems.append("%s: its interface %s has no wrapper in module creepwork (call it from a "
                            "public procedure, or list it in NOT_WRAPPED of %s with the reason)"
                            % (name, iname, os.path.basename(__file__)))
    summary = ("all %d functions of %s are bound with matching argument counts; %d are wrapped, "
               "%d deliberately not" % (len(c_args), header.name, wrapped, len(NOT_WRAPPED)))
    return problems, summary


def self_test(header_path, sources, work_dir):
    """The real header passes; a copy with one more prototype is bound by the
    generator but fails the check, naming the function."""
    os.makedirs(work_dir, exist_ok=True)
    text = creepwork_header.read_header(header_path)
    extra = "CW_API int cw_solver_new_feature(cw_solver* solver, const double* x, size_t x_len);\n"
    anchor = '#ifdef __cplusplus\n} /* extern "C" */'
    if anchor not in text:
        sys.exit("self-test: could not add a prototype to the copy of %s" % header_path)
    grown_path = os.path.join(work_dir, "creepwork.h")
    with open(grown_path, "w", encoding="utf-8") as f:
        f.write(text.replace(anchor, extra + anchor))
    for case, path in (("real", header_path), ("grown", grown_path)):
        header = creepwork_header.load(path)
        bindings = generate_interfaces.bindings_source(header)
        problems, _ = check(header, bindings, sources)
        if case == "real" and problems:
            sys.exit("self-test: the check fails on the real header:\n  " + "\n  ".join(problems))
    if "function capi_solver_new_feature(solver, x, x_len)" not in bindings:
        sys.exit("self-test: the generator did not bind the added function")
    if not any(p.startswith("cw_solver_new_feature: its interface") for p in problems):
        sys.exit("self-test: the check did not catch the unwrapped function: %s" % problems)
    print("an unwrapped function added to the header fails check_fortran_bindings")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--header", required=True)
    ap.add_argument("--sources", nargs="+", required=True)
    group = ap.add_mutually_exclusive_group(required=True)
    group.add_argument("--bindings")
    group.add_argument("--self-test", metavar="WORK_DIR")
    args = ap.parse_args()
    sources = []
    for path in args.sources:
        with open(path, encoding="utf-8") as f:
            sources.append(f.read())
    if args.self_test:
        return self_test(args.header, sources, args.self_test)
    with open(args.bindings, encoding="utf-8") as f:
        bindings = f.read()
    problems, summary = check(creepwork_header.load(args.header), bindings, sources)
    if problems:
        sys.exit("module creepwork and the header differ:\n  " + "\n  ".join(problems))
    print(summary)


if __name__ == "__main__":
    main()
