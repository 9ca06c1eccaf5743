#!/usr/bin/env python3
"""The tables of doc/reference/c-api.md, printed from the header (through
creepwork_header.py), so that the page names every function, struct and
status code the header declares and says what the header says:

  c_api_page.py functions   every CW_API function, grouped by the object it
                            belongs to, with its one-line description and
                            its errors
  c_api_page.py structs     every struct with its fields and _init function
  c_api_page.py statuses    CW_STATUS_LIST: code, value, message

The page holds each table between "<!-- generated: COMMAND -->" markers;
scripts/doc-tables.sh pastes them and the CTest tests doc_tables_current
and doc_pages_current fail when the page and the header disagree.

Grouping, whatever the order of the header: a function whose name starts
with a handle's name (cw_solver_..., cw_wear_profile_...: the longest
wins) belongs to that handle; a struct's _init (cw_params_init) to the
handle that takes the struct in the most functions (the first declared on
a tie), unless the functions of a header section take it as often (then
it stays in its section: cw_check_init); every other function to its header section (version, status codes,
helpers). Groups appear in the order of their first function in the
header, functions in header order within a group. A function's
description is the first sentence of its comment (a long one up to its
first colon); its errors are the
sentence of its comment that starts with "Errors:". A function whose
comment gives no description fails the page.

usage: c_api_page.py functions|structs|statuses [--header creepwork.h]
"""

import argparse
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import creepwork_header  # noqa: E402

DEFAULT_HEADER = os.path.join(HERE, "..", "..", "capi", "include", "creepwork", "creepwork.h")


# Words a period ends without ending the sentence ("e.g. many", "eqs. 35").
ABBREVIATIONS = {"e.g", "i.e", "cf", "eq", "eqs", "fig", "figs", "al", "vs", "approx", "resp", "no"}


def sentences(text):
    """text cut after each '. ' followed by a letter or a quote, outside
    parentheses and brackets and not after an abbreviation."""
    out, depth, start = [], 0, 0
    for k, ch in enumerate(text):
        if ch in "([":
            depth += 1
        elif ch in ")]":
            depth = max(0, depth - 1)
        elif (ch == "." and depth == 0 and text[k + 1:k + 2] == " "
              and re.match(r"[A-Za-z\"']", text[k + 2:k + 3] or "")):
            word = re.search(r"[\w.]*$", text[start:k]).group(0).lower()
            if word in ABBREVIATIONS:
                continue
            out.append(text[start:k + 1].strip())
            start = k + 2
    if text[start:].strip():
        out.append(text[start:].strip())
    return out


def short(sentence, longest=160):
    """A sentence longer than longest cut at its first ':' outside
    parentheses, where the header's sentences turn to details."""
    if len(sentence) <= longest:
        return sentence
    depth = 0
    for k, ch in enumerate(sentence):
        depth += ch in "([" and 1 or ch in ")]" and -1 or 0
        if ch == ":" and depth == 0 and sentence[k + 1:k + 2] == " ":
            return sentence[:k] + "."
    return sentence


def description_and_errors(f):
    parts = sentences(f.doc)
    errors = [s for s in parts if s.startswith("Errors:")]
    description = [s for s in parts if not s.startswith("Errors:")]
    if not description:
        raise creepwork_header.HeaderError(
            "%s (line %d): its comment says nothing but its errors, or it has none: the C API page "
            "needs a description" % (f.name, f.line))
    return short(description[0]), errors[0][len("Errors:"):].strip().rstrip(".") if errors else ""


def cell(text):
    """Markdown for a table cell: identifiers of the API as code, '*', '|'
    and a '<' that could open a tag escaped elsewhere."""
    out = []
    for k, part in enumerate(re.split(r"((?<!\w)(?:cw|CW)_\w*(?:\.\w+)?(?:\*|\b))", text)):
        if k % 2:
            out.append("`%s`" % part.replace("|", "\\|"))
        else:
            part = part.replace("\\", "\\\\").replace("*", "\\*").replace("|", "\\|")
            out.append(re.sub(r"<(?=[A-Za-z/!?])", "&lt;", part))
    return "".join(out)


def groups(header):
    """[(title, intro, [Function])] in the order of their first function."""
    handles = sorted(header.handles, key=len, reverse=True)
    owner = {}
    for f in header.functions:
        for h in handles:
            if f.name.startswith(h + "_"):
                owner[f.name] = h
                break
    for f in header.functions:
        if f.name in owner or not f.name.endswith("_init") or len(f.params) != 1:
            continue
        struct = f.params[0].base
        if struct not in header.structs:
            continue
        uses, first = {}, {}
        for k, g in enumerate(header.functions):
            if g is not f and any(p.base == struct for p in g.params):
                key = owner.get(g.name) or "section:" + g.section
                uses[key] = uses.get(key, 0) + 1
                first.setdefault(key, k)
        if uses:
            best = max(uses, key=lambda key: (uses[key], -first[key]))
            if not best.startswith("section:"):
                owner[f.name] = best
    ordered, members = [], {}
    for f in header.functions:
        key = owner.get(f.name) or "section:" + f.section
        if key not in members:
            ordered.append(key)
            members[key] = []
        members[key].append(f)
    out = []
    for key in ordered:
        if key.startswith("section:"):
            title = key[len("section:"):] or "other functions"
            out.append((title[0].upper() + title[1:], "", members[key]))
        else:
            intro = header.handle_docs.get(key, "")
            intro = short(sentences(creepwork_header.block_doc(intro))[0]) if intro else ""
            out.append(("`%s`" % key, intro, members[key]))
    return out


def functions_table(header):
    lines = []
    for title, intro, functions in groups(header):
        lines += ["### %s" % title, ""]
        if intro:
            lines += [cell(intro), ""]
        lines += ["| function | returns | what it does | errors |", "|---|---|---|---|"]
        for f in functions:
            description, errors = description_and_errors(f)
            call = "`%s(%s)`" % (f.name, ", ".join(p.name for p in f.params))
            lines.append("| %s | `%s` | %s | %s |" % (call, f.return_type, cell(description),
                                                      cell(errors) if errors else "–"))
        lines.append("")
    n = len(header.functions)
    lines.append("%d functions." % n)
    return "\n".join(lines)


def structs_table(header):
    inits = {f.params[0].base: f.name for f in header.functions
             if f.name.endswith("_init") and len(f.params) == 1}
    lines = ["| struct | set by | fields after `struct_size`, in order |", "|---|---|---|"]
    for name, struct in header.structs.items():
        fields = [", ".join("`%s`" % fl.name + ("[%d]" % fl.count if fl.count else "") for fl in m.fields)
                  for m in struct.members if isinstance(m, creepwork_header.Declaration)]
        init = "`%s`" % inits[name] if name in inits else "–"
        lines.append("| `%s` | %s | %s |" % (name, init, "; ".join(fields[1:])))
    return "\n".join(lines)


def statuses_table(header):
    lines = ["| code | value | message |", "|---|---:|---|"]
    lines += ["| `%s` | %d | %s |" % (name, value, cell(msg)) for name, value, msg in header.statuses]
    return "\n".join(lines)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("table", choices=["functions", "structs", "statuses"])
    ap.add_argument("--header", default=DEFAULT_HEADER)
    args = ap.parse_args(argv)
    try:
        header = creepwork_header.load(args.header)
        text = {"functions": functions_table, "structs": structs_table,
                "statuses": statuses_table}[args.table](header)
    except creepwork_header.HeaderError as e:
        sys.exit("c_api_page.py: %s: %s" % (args.header, e))
    print(text)


if __name__ == "__main__":
    main()
