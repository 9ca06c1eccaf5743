#!/usr/bin/env python3
"""Layer check: no include in core/ goes against the documented layer order.

The core's folders stand in layers (CONTRIBUTING.md, "Repository map"); a file
may include files of its own folder and of lower layers only, never of a
higher layer nor of another folder of its own layer (two models, say). So no
two folders include each other, and a new arrow upwards fails this check
(CTest: core_layers; core_layers_self_test plants one and expects it found).

    scripts/check-layers.py [--root DIR] [--self-test]

Prints every include against the order (file:line, the two folders) and
exits 1 if there is one, or if a folder of core/ has no layer here.
"""
import argparse
import os
import re
import sys
import tempfile

# Lowest first. A folder of core/ is named by its path; the files at the top
# of core/ (solver.*) are the unit "solver".
LAYERS = [
    ["simd"],                  # the ISA dispatch and vector types of every SIMD kernel
    ["contact"],               # grids, inputs, totals, the ContactModel interface
    ["friction"],              # friction laws of the slip speed, Polach's model: pure functions
    ["halfspace"],             # Kalker's half-space: influence coefficients, FFT products
    ["normal", "march"],       # the normal problem on any gap; the strip march
    ["exact", "fastsim", "calibrated"],  # the tangential models on the ellipse's grids
    ["gap", "transient"],      # the tangential models on a gap grid; transient rolling
    ["solver"],                # the solver: makes the models, runs them, exports fields
    ["wear", "thermal", "damage"],  # post-processors of the fields
    ["wheelrail"],             # wheel/rail geometry: a solver per contact patch
]
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')
SOURCES = (".hpp", ".cpp", ".h")


def unit_of(relpath):
    """The unit of a path relative to core/: its first folder, or "solver"."""
    parts = relpath.replace(os.sep, "/").split("/")
    return parts[0] if len(parts) > 1 else "solver"


def check(core):
    """Returns the list of messages for includes against the order."""
    layer = {u: n for n, units in enumerate(LAYERS) for u in units}
    problems = []
    for top, dirs, files in os.walk(core):
        dirs.sort()
        for name in sorted(files):
            if not name.endswith(SOURCES):
                continue
            path = os.path.join(top, name)
            rel = os.path.relpath(path, core)
            src = unit_of(rel)
            if src not in layer:
                problems.append(f"{rel}: folder {src}/ has no layer in scripts/check-layers.py")
                continue
            with open(path, encoding="utf-8") as f:
                for number, line in enumerate(f, 1):
                    m = INCLUDE.match(line)
                    if not m:
                        continue
                    target = m.group(1)
                    if not os.path.exists(os.path.join(core, target)):
                        problems.append(f"{rel}:{number}: includes \"{target}\", which is not "
                                        "a path below core/ (the core includes only itself)")
                        continue
                    dst = unit_of(target)
                    if dst == src:
                        continue
                    if dst not in layer:
                        problems.append(f"{rel}:{number}: folder {dst}/ has no layer")
                    elif layer[dst] >= layer[src]:
                        how = "a higher layer" if layer[dst] > layer[src] else "the same layer"
                        problems.append(f"{rel}:{number}: {src} includes {dst} ({how}): "
                                        f"\"{target}\"")
    return problems


def self_test():
    """A tree with one upward include must fail, the same tree without it pass."""
    with tempfile.TemporaryDirectory() as tmp:
        def write(rel, text):
            path = os.path.join(tmp, rel)
            os.makedirs(os.path.dirname(path), exist_ok=True)
            with open(path, "w", encoding="utf-8") as f:
                f.write(text)
        write("contact/params.hpp", "#pragma once\n")
        write("normal/method.hpp", '#include "contact/params.hpp"\n')
        write("solver.hpp", '#include "normal/method.hpp"\n')
        clean = check(tmp)
        write("contact/grid.cpp", '#include "contact/params.hpp"\n#include "normal/method.hpp"\n')
        planted = check(tmp)
        write("fastsim/model.cpp", '#include "exact/model.hpp"\n')
        write("exact/model.hpp", '#include "contact/params.hpp"\n')
        sideways = check(tmp)
    ok = (clean == [] and len(planted) == 1 and "contact/grid.cpp:2" in planted[0]
          and any("fastsim includes exact (the same layer)" in p for p in sideways))
    print("self-test: " + ("an upward and a sideways include are found, a clean tree passes"
                           if ok else f"FAILED: clean {clean}, planted {planted}, {sideways}"))
    return 0 if ok else 1


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--root", default=os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                    "..", "core"),
                    help="the core's folder (default: core/ of this tree)")
    ap.add_argument("--self-test", action="store_true",
                    help="check the checker on a planted upward include")
    args = ap.parse_args()
    if args.self_test:
        return self_test()
    problems = check(os.path.normpath(args.root))
    for p in problems:
        print(p)
    if not problems:
        print("every include of core/ follows the layer order: " +
              " < ".join("{" + ", ".join(u) + "}" if len(u) > 1 else u[0] for u in LAYERS))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
