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

The header's conventions it relies on (checked: anything else is an error,
so a header change that the parser does not understand fails the build):
  typedef struct cw_x { <type> <name>[, <name>...][<n>]; /* doc */ ... } cw_x;
  #define CW_NAME <number or constant expression of CW_ macros> /* doc */
  X(CW_NAME, value, "message") entries of CW_STATUS_LIST
  CW_API <return type> cw_name(<parameters>);
  a comment "/* cw_struct.field ..." right before a block of #defines (up to
  the next blank line) names the field those values are for.
Only the standard library is used (no numpy), so the build needs nothing but
a Python 3 interpreter.
"""

import argparse
import ast
import os
import re
import sys

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


class HeaderError(ValueError):
    """The header does not follow the conventions above."""


def split_comments(text):
    """Yields ("code", str) and ("comment", str) tokens, in order."""
    pos = 0
    while pos < len(text):
        start = text.find("/*", pos)
        if start < 0:
            yield ("code", text[pos:])
            return
        if start > pos:
            yield ("code", text[pos:start])
        end = text.find("*/", start + 2)
        if end < 0:
            raise HeaderError("unterminated comment")
        yield ("comment", text[start + 2:end])
        pos = end + 2


def clean_doc(comment):
    return " ".join(comment.split())


def strip_comments(text):
    return "".join(t[1] if t[0] == "code" else " " for t in split_comments(text))


def parse_declarator(words, constants, where):
    """words: tokens of one declarator, e.g. ['*', 'name'] or ['name', '[4]']."""
    stars = words.count("*")
    rest = [w for w in words if w != "*"]
    count = None
    if rest and rest[-1].startswith("["):
        dim = rest.pop()[1:-1].strip()
        if re.fullmatch(r"\d+", dim):
            count = int(dim)
        elif dim in constants and isinstance(constants[dim], int):
            count = constants[dim]
        else:
            raise HeaderError("%s: array length %r is not a number or CW_ constant" % (where, dim))
    if len(rest) != 1 or not re.fullmatch(r"[A-Za-z_]\w*", rest[0]):
        raise HeaderError("%s: cannot read the declarator %r" % (where, " ".join(words)))
    return rest[0], stars, count


def parse_declaration(decl, constants, where):
    """'double L1, L2, L3' -> [(name, ctype, pointer_depth, count), ...]."""
    decl = " ".join(decl.split())
    parts = [p.strip() for p in decl.split(",")]
    words = c_words(parts[0])
    # The name is the last identifier; everything before it (minus stars) is the type.
    ids = [k for k, w in enumerate(words) if re.fullmatch(r"[A-Za-z_]\w*", w)]
    if len(ids) < 2:
        raise HeaderError("%s: cannot read the declaration %r" % (where, decl))
    type_words = [w for w in words[:ids[-1]] if w != "*"]
    ctype = " ".join(type_words)
    out = []
    # First declarator: the stars between type and name, the name, a dimension.
    declarators = [words[len(type_words):]]
    declarators += [c_words(p) for p in parts[1:]]
    for d in declarators:
        name, stars, count = parse_declarator(d, constants, where)
        if stars == 0 and ctype not in SCALAR_KINDS:
            raise HeaderError("%s: field %s has type %r, not one of %s (teach generate_layout.py)"
                              % (where, name, ctype, ", ".join(sorted(SCALAR_KINDS))))
        out.append((name, ctype, stars, count))
    return out


def parse_struct(name, body, constants):
    fields = []
    pending = None  # fields of the last declaration, waiting for a trailing comment
    code = ""
    for token in split_comments(body):
        if token[0] == "code":
            chunk = token[1]
            while ";" in chunk:
                before, chunk = chunk.split(";", 1)
                decl = (code + before).strip()
                code = ""
                if not decl:
                    raise HeaderError("%s: empty declaration" % name)
                pending = []
                for fname, ctype, stars, count in parse_declaration(decl, constants, name):
                    kind = "pointer" if stars else SCALAR_KINDS[ctype]
                    field = {"name": fname, "ctype": ctype, "kind": kind, "pointer": stars,
                             "count": count, "doc": ""}
                    fields.append(field)
                    pending.append(field)
            code += chunk
            if "\n" in chunk:
                pending = None
        else:
            # A comment on the line of a declaration's ';' documents its fields.
            text = token[1]
            if pending is not None:
                for f in pending:
                    f["doc"] = clean_doc(text)
            pending = None
    if code.strip():
        raise HeaderError("%s: text after the last ';': %r" % (name, code.strip()))
    names = [f["name"] for f in fields]
    if len(set(names)) != len(names):
        raise HeaderError("%s: a field name repeats" % name)
    if not fields or fields[0]["name"] != "struct_size" or fields[0]["ctype"] != "size_t":
        raise HeaderError("%s: the first field must be size_t struct_size" % name)
    return fields


def evaluate(expr, constants, where):
    """A numeric literal or a constant expression of earlier CW_ macros."""
    expr = expr.strip()
    try:
        tree = ast.parse(expr, mode="eval")
    except SyntaxError:
        raise HeaderError("%s: cannot read the value %r" % (where, expr))

    def value(node):
        if isinstance(node, ast.Constant) and isinstance(node.value, (int, float)):
            return node.value
        if isinstance(node, ast.Name):
            if node.id not in constants:
                raise HeaderError("%s: %s is not defined before" % (where, node.id))
            return constants[node.id]
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
            v = value(node.operand)
            return -v if isinstance(node.op, ast.USub) else v
        if isinstance(node, ast.BinOp) and isinstance(node.op, (ast.Add, ast.Sub, ast.Mult)):
            a, b = value(node.left), value(node.right)
            return a + b if isinstance(node.op, ast.Add) else a - b if isinstance(node.op, ast.Sub) else a * b
        raise HeaderError("%s: unsupported expression %r" % (where, expr))

    return value(tree.body)


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


def parse_defines(text, constants, constant_docs, enums):
    """Object-like #defines (with their docs) and the enumeration groups."""
    lines = text.split("\n")
    group = None  # (struct, field, [macros])
    k = 0
    while k < len(lines):
        line = lines[k]
        stripped = line.strip()
        if not stripped:
            group = None
        m = re.match(r"/\*\s*(cw_\w+)\.(\w+)\b", stripped)
        if m:
            group = (m.group(1), m.group(2), [])
            enums.setdefault(m.group(1) + "." + m.group(2), {})
            enums[m.group(1) + "." + m.group(2)] = group[2]
        m = re.match(r"#define\s+(CW_\w+)(\(?)\s*(.*)$", stripped)
        if m and not m.group(2) and not m.group(1).endswith("_"):
            name, rest = m.group(1), m.group(3)
            doc = ""
            if "/*" in rest:
                rest, comment = rest.split("/*", 1)
                while "*/" not in comment:
                    k += 1
                    comment += " " + lines[k].strip()
                doc = clean_doc(comment.split("*/", 1)[0])
            rest = rest.split("//", 1)[0].strip()
            if rest:
                constants[name] = evaluate(rest, constants, name)
                if doc:
                    constant_docs[name] = doc
                if group is not None:
                    group[2].append(name)
        k += 1


def parse_functions(code):
    functions = {}
    for m in re.finditer(r"CW_API\s+([^;()]*?)\b(cw_\w+)\s*\(([^)]*)\)\s*;", code):
        ret, name, params = m.group(1), m.group(2), m.group(3).strip()
        args = []
        if params and params != "void":
            for p in params.split(","):
                words = c_words(p)
                # Drop the parameter's name (every prototype names them).
                if len(words) > 1 and re.fullmatch(r"[A-Za-z_]\w*", words[-1]):
                    words = words[:-1]
                elif len(words) > 2 and words[-1].startswith("["):
                    words = words[:-2] + ["*"]
                args.append(type_kind(words, name))
        functions[name] = {"restype": type_kind(c_words(ret), name), "argtypes": args}
    if not functions:
        raise HeaderError("no CW_API prototypes found")
    return functions


def c_words(declaration):
    """The tokens of a C declaration that matter here: identifiers, stars,
    array dimensions; without const and volatile."""
    return [w for w in re.findall(r"\[[^\]]*\]|\*|[A-Za-z_]\w*", declaration)
            if w not in ("const", "volatile")]


def type_kind(words, where):
    """Kind of a type without a name: a scalar kind, "pointer", "char_p" or "void"."""
    if "*" in words:
        return "char_p" if words == ["char", "*"] else "pointer"
    ctype = " ".join(words)
    if ctype == "void":
        return "void"
    if ctype not in SCALAR_KINDS:
        raise HeaderError("%s: type %r (teach generate_layout.py)" % (where, ctype))
    return SCALAR_KINDS[ctype]


def read_header(path):
    """The text of creepwork.h with each `#include "creepwork/creepwork_<part>.h"`
    of a part beside it (creepwork_wear.h, creepwork_wheelrail.h) replaced by
    that part's text: the whole C API as the compiler reads it."""
    directory = os.path.dirname(path)
    with open(path, encoding="utf-8") as f:
        text = f.read()

    def part(match):
        name = os.path.join(directory, match.group(1))
        if not os.path.isfile(name):
            return match.group(0)  # creepwork_export.h: generated, not a part
        with open(name, encoding="utf-8") as f:
            return f.read()
    return re.sub(r'#include "creepwork/(creepwork_\w+\.h)"', part, text)


def parse_header(text, header_name="creepwork.h"):
    joined = re.sub(r"\\\r?\n", " ", text)  # continued macro lines
    constants, constant_docs, enums = {}, {}, {}
    m = re.search(r"#define CW_STATUS_LIST\(X\)([^\n]*)", joined)
    if not m:
        raise HeaderError("CW_STATUS_LIST not found")
    statuses = [(n, int(v), msg) for n, v, msg in
                re.findall(r'X\((CW_[A-Z0-9_]+),\s*(-?\d+),\s*"([^"]*)"\)', m.group(1))]
    if not statuses:
        raise HeaderError("CW_STATUS_LIST has no X(name, value, message) entries")
    for n, v, _ in statuses:
        constants[n] = v
    parse_defines(joined, constants, constant_docs, enums)
    enum_values = {}
    for key, macros in enums.items():
        if macros:
            struct, field = key.split(".")
            enum_values[key] = {enum_member_name(mac, macros, field): constants[mac]
                                for mac in macros}
    structs = {}
    for sm in re.finditer(r"typedef\s+struct\s+(cw_\w+)\s*\{(.*?)\}\s*(cw_\w+)\s*;", joined, re.S):
        if sm.group(1) != sm.group(3):
            raise HeaderError("typedef struct %s ... %s: names differ" % (sm.group(1), sm.group(3)))
        structs[sm.group(1)] = parse_struct(sm.group(1), sm.group(2), constants)
    if not structs:
        raise HeaderError("no typedef struct cw_... { ... } found")
    for key in enum_values:
        struct, field = key.split(".")
        if struct not in structs or field not in [f["name"] for f in structs[struct]]:
            raise HeaderError("enumeration comment names %s, which is not a struct field" % key)
    return {
        "header": header_name,
        "structs": structs,
        "constants": constants,
        "constant_docs": constant_docs,
        "enums": enum_values,
        "statuses": statuses,
        "functions": parse_functions(strip_comments(joined)),
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
    try:
        with open(path, encoding="utf-8") as f:
            if f.read() == text:
                os.utime(path)
                return
    except OSError:
        pass
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


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
