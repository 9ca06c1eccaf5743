#!/usr/bin/env python3
"""Fails unless the dynamic symbols the library defines are exactly the
functions the header declares with CW_API (read by tools/header): nothing
outside the cw_ prefix leaks (no C++ core, no Eigen, no STL), and nothing
declared is missing.

usage: check_exports.py --library libcreepwork.so --header creepwork.h --nm nm
"""

import argparse
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "header"))
import creepwork_header  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--library", required=True)
    ap.add_argument("--header", required=True)
    ap.add_argument("--nm", required=True)
    args = ap.parse_args()
    nm = subprocess.run([args.nm, "-D", "--defined-only", args.library], capture_output=True, text=True)
    if nm.returncode != 0:
        sys.exit("nm failed (%d): %s" % (nm.returncode, nm.stderr))
    # "<address> <type> <name>[@version]" per line.
    exported = [m.group(1) for m in re.finditer(r"^[0-9a-fA-F]* *[A-Za-z] ([^@ \n]+)", nm.stdout, re.M)]
    declared = [f.name for f in creepwork_header.load(args.header).functions]
    foreign = [s for s in exported if not s.startswith("cw_")]
    missing = [f for f in declared if f not in exported]
    undeclared = [s for s in exported if s.startswith("cw_") and s not in declared]
    if foreign or missing or undeclared:
        sys.exit("libcreepwork exports: not cw_: %s; declared but not exported: %s; exported but not "
                 "declared: %s" % (foreign, missing, undeclared))
    print("%d exported symbols, all cw_, all %d declared functions present" % (len(exported), len(declared)))


if __name__ == "__main__":
    main()
