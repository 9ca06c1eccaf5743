#!/usr/bin/env python3
"""The one reader of creepwork's public C header: every generator and checker
that needs to know the C API (the Fortran module's constants, types and
interfaces, the Python package's and the MEX gateway's layouts, the C API
page of the manual, the export and binding checks) reads it through here.

  header = creepwork_header.load("capi/include/creepwork/creepwork.h")
  header.structs["cw_params"].fields     every field, in order, with its comment
  header.functions                       every CW_API prototype, with its comment
  header.macros, header.statuses, header.enums, header.handles, header.sections

The header's conventions it reads (anything else in their place is an
error naming it, so a header change the reader does not understand fails
the build instead of being read wrongly):
  typedef struct cw_x { <type> <name>[, <name>...][<n>]; /* doc */ ... } cw_x;
  typedef struct cw_x cw_x;                             an opaque handle
  #define CW_NAME <number or constant expression of CW_ macros> /* doc */
  X(CW_NAME, value, "message") entries of CW_STATUS_LIST
  CW_API <return type> cw_name(<named parameters>); /* doc */
  /* cw_struct.field ... */ right before a block of #defines (up to the next
      blank line): the values of that field (an enumeration)
  /* ------ heading */: a section of the header
A function's comment is the one on the line of its ';'; without one, the
nearest comment that stands on lines of its own above it, with no blank
line in between (one comment above a run of prototypes documents each).
The parts creepwork.h includes from beside it (creepwork_<part>.h) are
read in its place, as the compiler reads them.

Only the standard library (Python 3.7), so that the build needs nothing but
an interpreter.
"""

import ast
import os
import re
import sys
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Tuple, Union


class HeaderError(ValueError):
    """The header does not follow the conventions above."""


# ----------------------------------------------------------------- the text

def read_header(path):
    """The text of creepwork.h with each `#include "creepwork/creepwork_<part>.h"`
    of a part beside it replaced by that part's text: the whole C API as the
    compiler reads it. creepwork_export.h (CW_API's definition, generated
    into the build tree and installed beside the header) stays an include."""
    directory = os.path.dirname(path)
    with open(path, encoding="utf-8") as f:
        text = f.read()

    def part(match):
        name = os.path.join(directory, match.group(1))
        if match.group(1) == "creepwork_export.h" or not os.path.isfile(name):
            return match.group(0)
        with open(name, encoding="utf-8") as f:
            return f.read()
    return re.sub(r'#include "creepwork/(creepwork_\w+\.h)"', part, text)


def load(path):
    """The parsed header at path (with its parts)."""
    return parse(read_header(path), os.path.basename(path))


def write_if_changed(path, text, touch=False):
    """Writes a generated file unless it holds text already, so that an
    unchanged header rebuilds nothing; with touch, an unchanged file's time
    is still set to now (for a build that compares the output's time with
    the header's)."""
    try:
        with open(path, encoding="utf-8") as f:
            if f.read() == text:
                if touch:
                    os.utime(path)
                return
    except OSError:
        pass
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


def split_comments(text):
    """Yields ("code", str, start) and ("comment", str, start) in order; a
    comment's str is what lies between /* and */."""
    pos = 0
    while pos < len(text):
        start = text.find("/*", pos)
        if start < 0:
            yield ("code", text[pos:], pos)
            return
        if start > pos:
            yield ("code", text[pos:start], pos)
        end = text.find("*/", start + 2)
        if end < 0:
            raise HeaderError("unterminated comment at line %d" % (text.count("\n", 0, start) + 1))
        yield ("comment", text[start + 2:end], start)
        pos = end + 2


def clean_doc(comment):
    """A comment's words on one line."""
    return " ".join(comment.split())


def block_doc(comment):
    """A block comment's words on one line, without the '*' that starts
    its continuation lines."""
    return clean_doc(re.sub(r"\n[ \t]*\*(?!/)", "\n", comment))


def c_words(declaration):
    """The tokens of a C declaration that matter: identifiers, stars and
    array dimensions ([N])."""
    return re.findall(r"\[[^\]]*\]|\*|[A-Za-z_]\w*", declaration)


# ------------------------------------------------------------------ the model

@dataclass
class Macro:
    name: str
    text: str           # the value as written, without its comment
    value: Union[int, float, None]  # evaluated; None if not a constant expression
    doc: str            # its comment on one line ("" if none)


@dataclass
class Field:
    name: str
    ctype: str          # the type's words without const and stars: "double", "unsigned int"
    const: bool
    pointer: int        # number of stars
    count: Optional[int]  # x[N]: N (a number or a CW_ constant); None for a scalar
    comment: str        # its trailing comment, raw ("" if none); shared by a declaration's names

    @property
    def doc(self):
        return clean_doc(self.comment)


@dataclass
class Declaration:
    """One declaration of a struct body: "double L1, L2, L3; /* doc */"."""
    fields: List[Field]


@dataclass
class Note:
    """A comment of its own line(s) in a struct body: "---- appended in 1.2 ----"."""
    comment: str


@dataclass
class Struct:
    name: str
    members: List[Union[Declaration, Note]]

    @property
    def fields(self):
        return [f for m in self.members if isinstance(m, Declaration) for f in m.fields]


@dataclass
class Param:
    name: str
    base: str           # the type's words without const and stars
    const: bool
    stars: int
    dim: Optional[str]  # "4" for double coefficients[4]


@dataclass
class Function:
    name: str
    return_type: str    # as written, blanks collapsed: "int", "const char*"
    params: List[Param]
    prototype: str      # "CW_API int cw_x(cw_grid* grid)": one line, blanks collapsed, no ';'
    comment: str        # raw; see the module's docstring for which comment
    section: str        # the heading of the header section it is in
    line: int

    @property
    def doc(self):
        return block_doc(self.comment)


@dataclass
class Header:
    name: str
    statuses: List[Tuple[str, int, str]]
    macros: List[Macro]
    enums: Dict[str, List[str]]        # "cw_struct.field" -> its CW_ macros, in order
    structs: Dict[str, Struct]
    handles: List[str]                 # opaque typedefs, in order
    handle_docs: Dict[str, str]        # the comment above an opaque typedef, raw
    functions: List[Function]
    sections: List[str] = field(default_factory=list)

    @property
    def constants(self):
        """Every status code and evaluated #define constant by name."""
        out = {n: v for n, v, _ in self.statuses}
        out.update((m.name, m.value) for m in self.macros if m.value is not None)
        return out

    def function(self, name):
        for f in self.functions:
            if f.name == name:
                return f
        raise KeyError(name)


# ------------------------------------------------------------------- parsing

def evaluate(expr, constants, where):
    """A numeric literal or a constant expression (+ - * and parentheses) of
    earlier CW_ macros."""
    expr = expr.strip()
    try:
        tree = ast.parse(expr, mode="eval")
    except SyntaxError:
        raise HeaderError("%s: cannot read the value %r" % (where, expr))

    def value(node):
        if isinstance(node, ast.Constant) and isinstance(node.value, (int, float)):
            return node.value
        if sys.version_info < (3, 8) and isinstance(node, ast.Num):
            return node.n
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


def parse_statuses(text):
    m = re.search(r"#define CW_STATUS_LIST\(X\)([^\n]*)", text)
    if not m:
        raise HeaderError("CW_STATUS_LIST not found")
    statuses = [(n, int(v), msg) for n, v, msg in
                re.findall(r'X\((CW_[A-Z0-9_]+),\s*(-?\d+),\s*"([^"]*)"\)', m.group(1))]
    if not statuses:
        raise HeaderError("CW_STATUS_LIST has no X(name, value, message) entries")
    return statuses


def parse_defines(text, constants):
    """Object-like CW_ #defines with their comments, and the enumeration
    groups (a "/* cw_struct.field" comment names the field of the #defines
    after it, up to the next blank line)."""
    macros, enums = [], {}
    lines = text.split("\n")
    group = None
    k = 0
    while k < len(lines):
        stripped = lines[k].strip()
        if not stripped:
            group = None
        m = re.match(r"/\*\s*(cw_\w+)\.(\w+)\b", stripped)
        if m:
            group = enums.setdefault(m.group(1) + "." + m.group(2), [])
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
                value = evaluate(rest, constants, name)
                constants[name] = value
                macros.append(Macro(name, rest, value, doc))
                if group is not None:
                    group.append(name)
        k += 1
    return macros, {key: names for key, names in enums.items() if names}


def parse_declaration(decl, constants, where):
    """'double L1, L2, L3' -> [Field, ...] (comments filled in later)."""
    decl = " ".join(decl.split())
    parts = [p.strip() for p in decl.split(",")]
    words = c_words(parts[0])
    const = "const" in words
    words = [w for w in words if w not in ("const", "volatile")]
    ids = [k for k, w in enumerate(words) if re.fullmatch(r"[A-Za-z_]\w*", w)]
    if len(ids) < 2:
        raise HeaderError("%s: cannot read the declaration %r" % (where, decl))
    type_words = [w for w in words[:ids[-1]] if w != "*"]
    ctype = " ".join(type_words)
    declarators = [words[len(type_words):]] + [c_words(p) for p in parts[1:]]
    out = []
    for d in declarators:
        stars = d.count("*")
        rest = [w for w in d if w != "*"]
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
            raise HeaderError("%s: cannot read the declarator %r" % (where, " ".join(d)))
        out.append(Field(rest[0], ctype, const, stars, count, ""))
    return out


def parse_struct(name, body, constants):
    members = []
    pending = None  # the last declaration, waiting for a comment on its line
    code = ""
    for kind, chunk, _ in split_comments(body):
        if kind == "code":
            while ";" in chunk:
                before, chunk = chunk.split(";", 1)
                decl = (code + before).strip()
                code = ""
                if not decl:
                    raise HeaderError("%s: empty declaration" % name)
                pending = Declaration(parse_declaration(decl, constants, name))
                members.append(pending)
            code += chunk
            if "\n" in chunk:
                pending = None
        else:
            if code.strip():
                raise HeaderError("%s: a comment inside the declaration %r" % (name, code.strip()))
            if pending is not None:
                for f in pending.fields:
                    f.comment = chunk
            else:
                members.append(Note(chunk))
            pending = None
    if code.strip():
        raise HeaderError("%s: text after the last ';': %r" % (name, code.strip()))
    struct = Struct(name, members)
    names = [f.name for f in struct.fields]
    if len(set(names)) != len(names):
        raise HeaderError("%s: a field name repeats" % name)
    if not names or names[0] != "struct_size" or struct.fields[0].ctype != "size_t":
        raise HeaderError("%s: the first field must be size_t struct_size" % name)
    return struct


def parse_params(arglist, where):
    arglist = " ".join(arglist.split())
    if arglist in ("", "void"):
        return []
    params = []
    for p in arglist.split(","):
        words = c_words(p)
        const = "const" in words
        words = [w for w in words if w not in ("const", "volatile")]
        dim = None
        if words and words[-1].startswith("["):
            dim = words.pop()[1:-1].strip()
        ids = [w for w in words if w != "*"]
        if len(ids) < 2 or words[-1] == "*":
            raise HeaderError("%s: cannot read the parameter %r (every parameter is named)"
                              % (where, p.strip()))
        params.append(Param(ids[-1], " ".join(ids[:-1]), const, words.count("*"), dim))
    return params


def blank_comments(text):
    """text with every comment's characters but its newlines made blanks:
    the same offsets, the same lines."""
    return "".join(chunk if kind == "code" else re.sub(r"[^\n]", " ", "/*" + chunk + "*/")
                   for kind, chunk, _ in split_comments(text))


def own_line_comments(text):
    """The comments that stand on lines of their own: (start, end, raw)."""
    out = []
    for kind, chunk, start in split_comments(text):
        if kind != "comment":
            continue
        line_start = text.rfind("\n", 0, start) + 1
        if text[line_start:start].strip() == "":
            out.append((start, start + len(chunk) + 4, chunk))
    return out


def trailing_comment(text, end):
    """The comment that starts on the line of position end (after it), raw."""
    line_end = text.find("\n", end)
    line = text[end:line_end if line_end >= 0 else len(text)]
    m = re.match(r"\s*/\*", line)
    if not m:
        return None
    close = text.find("*/", end)
    return text[end + m.end():close]


def comment_above(text, start, comments):
    """The nearest own-line comment ending before start with no blank line
    between them, raw (None if there is none)."""
    best = None
    for c_start, c_end, raw in comments:
        if c_end <= start:
            best = (c_end, raw)
        else:
            break
    if best is None or re.search(r"\n[ \t]*\n", text[best[0]:start]):
        return None
    return best[1]


# "/* ------------------------------------------------------------- grid */"
SECTION = re.compile(r"/\*[ ]*-{3,}[ ]+([^*\n]*[^-*\s])[ ]*\*/")


def parse(text, header_name="creepwork.h"):
    """The Header of text (creepwork.h with its parts, read_header)."""
    text = re.sub(r"\\\r?\n", " ", text)  # continued macro lines: one line each
    statuses = parse_statuses(text)
    constants = {n: v for n, v, _ in statuses}
    macros, enums = parse_defines(text, constants)
    code = blank_comments(text)
    comments = own_line_comments(text)

    structs = {}
    for m in re.finditer(r"typedef\s+struct\s+(cw_\w+)\s*\{", code):
        close = re.compile(r"\}\s*(cw_\w+)\s*;").search(code, m.end())
        if not close:
            raise HeaderError("typedef struct %s: no closing '} %s;'" % (m.group(1), m.group(1)))
        if close.group(1) != m.group(1):
            raise HeaderError("typedef struct %s ... %s: names differ" % (m.group(1), close.group(1)))
        structs[m.group(1)] = parse_struct(m.group(1), text[m.end():close.start()], constants)
    if not structs:
        raise HeaderError("no typedef struct cw_... { ... } found")
    for key in enums:
        struct, fname = key.split(".")
        if struct not in structs or fname not in [f.name for f in structs[struct].fields]:
            raise HeaderError("enumeration comment names %s, which is not a struct field" % key)

    handles, handle_docs = [], {}
    for m in re.finditer(r"typedef\s+struct\s+(cw_\w+)\s+(cw_\w+)\s*;", code):
        if m.group(1) != m.group(2):
            raise HeaderError("typedef struct %s %s: names differ" % (m.group(1), m.group(2)))
        handles.append(m.group(1))
        doc = comment_above(text, m.start(), comments)
        if doc is not None:
            handle_docs[m.group(1)] = doc

    sections = [(m.start(), m.group(1)) for m in SECTION.finditer(text)]
    functions = []
    for m in re.finditer(r"CW_API\s+([^;()]*?)\b(cw_\w+)\s*\(([^)]*)\)\s*;", code):
        name = m.group(2)
        if any(f.name == name for f in functions):
            raise HeaderError("%s is declared twice" % name)
        comment = trailing_comment(text, m.end())
        if comment is None:
            comment = comment_above(text, m.start(), comments)
        section = ""
        for s_start, heading in sections:
            if s_start < m.start():
                section = heading
        prototype = " ".join(m.group(0).split())[:-1].rstrip()
        functions.append(Function(name, " ".join(m.group(1).split()),
                                  parse_params(m.group(3), name), prototype,
                                  comment or "", section, text.count("\n", 0, m.start()) + 1))
    if not functions:
        raise HeaderError("no CW_API prototypes found")
    # Every CW_API outside preprocessor lines must have been read as a prototype.
    declared = sum(len(re.findall(r"\bCW_API\b", line)) for line in code.split("\n")
                   if not line.lstrip().startswith("#"))
    if declared != len(functions):
        raise HeaderError("%d CW_API declarations, %d of them read as 'CW_API <type> cw_x(...);'"
                          % (declared, len(functions)))
    return Header(header_name, statuses, macros, enums, structs, handles, handle_docs, functions,
                  [heading for _, heading in sections])
