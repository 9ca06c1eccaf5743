#!/usr/bin/env python3
"""The legacy layer's documentation cannot drift from its code: every CW*
subroutine of the legacy sources must appear with the same argument list in
the installed include files (creepwork_legacy.inc, as a "! CALL NAME(...)"
comment and an EXTERNAL line; creepwork_legacy.fi, as an interface body) and
in the user documentation (a "`CALL NAME(...)`" line followed by a table row
for every argument, in any one of the pages; pages that do not exist are
skipped), and nothing else may be documented there. The files are read by
tools/header/legacy_interfaces.py.

usage: check_legacy_docs.py --sources a.f90 ... --inc creepwork_legacy.inc
                            --fi creepwork_legacy.fi --docs x.md ...
"""

import argparse
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "header"))
import legacy_interfaces as li  # noqa: E402


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--sources", nargs="+", required=True)
    ap.add_argument("--inc", required=True)
    ap.add_argument("--fi", required=True)
    ap.add_argument("--docs", nargs="+", required=True)
    args = ap.parse_args()
    source = [s for path in args.sources for s in li.source_signatures(read(path))]
    if not source:
        sys.exit("no CW* subroutine found in %s" % args.sources)
    found = {"fi": li.interface_signatures(read(args.fi))}
    found["inc"], externals = li.include_signatures(read(args.inc))
    doc_files = [d for d in args.docs if os.path.isfile(d)]
    if not doc_files:
        sys.exit("none of the documentation files exists: %s" % args.docs)
    docs_text = "".join(read(d) + "\n" for d in doc_files)
    found["docs"] = li.documented_signatures(docs_text)

    problems = []
    for where in ("fi", "inc", "docs"):
        problems += ["%s: %s matches no subroutine of the source" % (where, s)
                     for s in found[where] if s not in source]
    for sig in source:
        name, arglist = sig.split("|")
        problems += ["%s: %s missing or with other arguments than %s" % (where, name, sig)
                     for where in ("fi", "inc", "docs") if sig not in found[where]]
        if name not in externals:
            problems.append("inc: no EXTERNAL %s" % name)
        section = li.documented_section(docs_text, name)
        if section is not None:
            problems += ["docs: no table row for %s argument %s" % (name, arg)
                         for arg in arglist.split(",") if arg
                         if not re.search(r"\n\|[^\n]*`%s`" % re.escape(arg), section)]
    if problems:
        sys.exit("legacy layer documentation drifted:\n  " + "\n  ".join(problems))
    print("%d legacy routines documented alike in source, .inc, .fi and %s"
          % (len(source), " ".join(doc_files)))


if __name__ == "__main__":
    main()
