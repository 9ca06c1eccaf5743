#!/usr/bin/env python3
"""Prints the repository map of CONTRIBUTING.md from map.txt (beside this
file) and checks it against the tree: a path of map.txt that does not
exist, a top-level folder without an entry, or a folder with entries for
some of its subfolders but not for another fails (exit 1, naming them),
so that the map cannot drift from the tree. The tree is git's list of
files when the source is a git checkout, else the files on disk (without
build*/, out/ and hidden folders).

CONTRIBUTING.md holds the map between "<!-- generated: COMMAND -->"
markers: scripts/doc-tables.sh pastes it, doc_pages_current and
doc_tables_current check it.

usage: repository_map.py [--source DIR]
"""

import argparse
import fnmatch
import os
import subprocess
import sys
import textwrap

HERE = os.path.dirname(os.path.abspath(__file__))
WIDTH = 92   # characters per line of the map
COLUMN = 14  # the widest name column of a group, from its indent


def entries(path):
    """[(path, description)] of map.txt, in order."""
    out = []
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            line = line.rstrip("\n")
            if not line.strip() or line.startswith("#"):
                continue
            if line[0] in " \t":
                if not out:
                    raise SystemExit("%s:%d: a continuation line before any entry" % (path, number))
                out[-1] = (out[-1][0], out[-1][1] + " " + line.strip())
                continue
            name, _, description = line.partition(" ")
            if not description.strip():
                raise SystemExit("%s:%d: %s has no description" % (path, number, name))
            out.append((name, description.strip()))
    return out


def tracked_files(source):
    try:
        listed = subprocess.run(["git", "-C", source, "ls-files", "-z"], capture_output=True, check=True)
        if listed.stdout:
            return [f for f in listed.stdout.decode().split("\0") if f]
    except (OSError, subprocess.CalledProcessError):
        pass
    files = []
    for root, dirs, names in os.walk(source):
        rel = os.path.relpath(root, source)
        dirs[:] = sorted(d for d in dirs if not d.startswith(".") and d != "__pycache__" and
                         not (rel == "." and (d.startswith("build") or d == "out")))
        files += [os.path.normpath(os.path.join(rel, n)) for n in names]
    return files


def problems(described, files):
    folders = {os.path.dirname(f) for f in files}
    folders |= {"/".join(f.split("/")[:k]) for f in folders for k in range(1, f.count("/") + 1)}
    folders.discard("")
    out = []
    for name in described:
        if name.endswith("/"):
            if name[:-1] not in folders:
                out.append("%s: no such folder" % name)
        elif not fnmatch.filter(files, name):
            out.append("%s: no such file" % name)
    dirs = {name[:-1] for name in described if name.endswith("/")}
    for folder in sorted(folders):
        parent = os.path.dirname(folder)
        if folder.split("/")[0].startswith(".") or folder in dirs:
            continue
        if parent == "":
            out.append("%s/: a top-level folder without an entry" % folder)
        elif any(d.startswith(parent + "/") and d.count("/") == folder.count("/") for d in dirs):
            out.append("%s/: its siblings have entries, it has none" % folder)
    return out


def render(items):
    """The map as text: each entry under its parent entry, indented two
    blanks per level, its description in a column."""
    lines = []
    names = [name for name, _ in items]
    for name, description in items:
        parent = ""
        for other in names:
            if other.endswith("/") and name != other and name.startswith(other) and len(other) > len(parent):
                parent = other
        depth = parent.count("/")
        label = "  " * depth + name[len(parent):]
        siblings = [n for n in names if n != parent and n.startswith(parent) and
                    not any(o.endswith("/") and o != n and n.startswith(o) and len(o) > len(parent)
                            for o in names)]
        column = min(max(len(n) - len(parent) for n in siblings) + 2, COLUMN) + 2 * depth
        first = label + " " * max(column - len(label), 2)
        wrapped = textwrap.wrap(description, WIDTH - column, break_on_hyphens=False)
        lines.append(first + wrapped[0])
        lines += [" " * column + w for w in wrapped[1:]]
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--source", default=os.path.join(HERE, "..", ".."))
    args = ap.parse_args()
    items = entries(os.path.join(HERE, "map.txt"))
    found = problems([name for name, _ in items], tracked_files(os.path.abspath(args.source)))
    if found:
        sys.exit("the repository map (tools/repository_map/map.txt) and the tree differ:\n  " +
                 "\n  ".join(found))
    print("```\n%s\n```" % render(items))


if __name__ == "__main__":
    main()
