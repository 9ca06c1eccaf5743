#!/usr/bin/env python3
"""The header reader and the C API page on small headers written here (the
expected values read off the text by hand) and on the real header (every
prototype found, by an independent count of its 'CW_API' lines). Standard
library only: python3 test_header_reader.py [REAL_HEADER]."""

import os
import re
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import c_api_page  # noqa: E402
import creepwork_header as ch  # noqa: E402

REAL_HEADER = os.path.join(HERE, "..", "..", "capi", "include", "creepwork", "creepwork.h")

HEADER = r'''
#define CW_STATUS_LIST(X)                            \
    X(CW_OK, 0, "success")                           \
    X(CW_ERR_THING, 7, "a thing; with a semicolon")
#define CW_BASE 3
#define CW_DERIVED (CW_BASE * 100 + 2) /* an expression */

/* ---------------------------------------------------------------- boxes */

/* cw_box.shape: how the box looks */
#define CW_SHAPE_ROUND 0   /* round */
#define CW_SHAPE_SQUARE 1  /* square */

typedef struct cw_box {
    size_t struct_size; /* set by cw_box_init */
    double L1, L2;      /* two at once
                           over two lines */
    int shape;
    /* ---- appended in 1.1 ---- */
    const double* gap;  /* caller's array [m] */
    double corners[CW_BASE];
} cw_box;

/* Fills the box. Errors: CW_ERR_THING (box). */
CW_API int cw_box_init(cw_box* box);

/* A crate of boxes (e.g. many). Owned by the caller. */
typedef struct cw_crate cw_crate;

/* Makes a crate from a box (Figs. 8-9). Errors: CW_ERR_THING. */
CW_API int cw_crate_create(const cw_box* box, cw_crate** crate);
CW_API int cw_crate_destroy(cw_crate* crate); /* NULL: no-op */
/* Counts the boxes: *n receives their number. Errors: CW_ERR_THING. After
 * an error nothing is written. */
CW_API int cw_crate_count(const cw_crate* crate,
                          size_t* n);

CW_API const char* cw_crate_last_error(const cw_crate* crate);

/* ------------------------------------------------------------- helpers */

/* Sums values[4]. */
CW_API int cw_sum(double values[4], char* message, size_t message_len);
'''


class Reader(unittest.TestCase):
    def setUp(self):
        self.h = ch.parse(HEADER, "box.h")

    def test_macros_statuses_enums(self):
        self.assertEqual(self.h.statuses, [("CW_OK", 0, "success"),
                                           ("CW_ERR_THING", 7, "a thing; with a semicolon")])
        self.assertEqual(self.h.constants["CW_DERIVED"], 302)
        self.assertEqual([(m.name, m.text, m.doc) for m in self.h.macros][:2],
                         [("CW_BASE", "3", ""), ("CW_DERIVED", "(CW_BASE * 100 + 2)", "an expression")])
        self.assertEqual(self.h.enums, {"cw_box.shape": ["CW_SHAPE_ROUND", "CW_SHAPE_SQUARE"]})

    def test_struct_members(self):
        box = self.h.structs["cw_box"]
        self.assertEqual([(f.name, f.ctype, f.const, f.pointer, f.count) for f in box.fields],
                         [("struct_size", "size_t", False, 0, None), ("L1", "double", False, 0, None),
                          ("L2", "double", False, 0, None), ("shape", "int", False, 0, None),
                          ("gap", "double", True, 1, None),
                          ("corners", "double", False, 0, 3)])
        self.assertEqual(box.fields[1].doc, "two at once over two lines")
        self.assertEqual(box.fields[1].comment, box.fields[2].comment)
        notes = [m.comment for m in box.members if isinstance(m, ch.Note)]
        self.assertEqual(notes, [" ---- appended in 1.1 ---- "])

    def test_functions_and_their_comments(self):
        f = {g.name: g for g in self.h.functions}
        self.assertEqual(list(f), ["cw_box_init", "cw_crate_create", "cw_crate_destroy", "cw_crate_count",
                                   "cw_crate_last_error", "cw_sum"])
        self.assertEqual(f["cw_box_init"].doc, "Fills the box. Errors: CW_ERR_THING (box).")
        # The comment above a run documents it; a comment on the line wins.
        self.assertEqual(f["cw_crate_create"].doc, "Makes a crate from a box (Figs. 8-9). Errors: CW_ERR_THING.")
        self.assertEqual(f["cw_crate_destroy"].doc, "NULL: no-op")
        self.assertEqual(f["cw_crate_count"].doc, "Counts the boxes: *n receives their number. Errors: "
                         "CW_ERR_THING. After an error nothing is written.")
        # A blank line ends what a comment documents.
        self.assertEqual(f["cw_crate_last_error"].doc, "")
        self.assertEqual(f["cw_crate_count"].prototype,
                         "CW_API int cw_crate_count(const cw_crate* crate, size_t* n)")
        self.assertEqual(f["cw_crate_last_error"].return_type, "const char*")
        self.assertEqual([(p.name, p.base, p.const, p.stars, p.dim) for p in f["cw_crate_create"].params],
                         [("box", "cw_box", True, 1, None), ("crate", "cw_crate", False, 2, None)])
        self.assertEqual([(p.name, p.dim) for p in f["cw_sum"].params],
                         [("values", "4"), ("message", None), ("message_len", None)])
        self.assertEqual([g.section for g in self.h.functions], ["boxes"] * 5 + ["helpers"])
        self.assertEqual(self.h.handles, ["cw_crate"])
        self.assertEqual(ch.block_doc(self.h.handle_docs["cw_crate"]), "A crate of boxes (e.g. many). Owned by the caller.")

    def test_refuses_what_it_cannot_read(self):
        for bad, why in [("CW_API int cw_other(double, int n);", "every parameter is named"),
                         ("CW_API int (*cw_ptr)(void);", "CW_API declarations"),
                         ("int a[CW_UNKNOWN];", "CW_UNKNOWN"),
                         ("CW_API int cw_box_init(cw_box* box);", "declared twice")]:
            with self.subTest(bad=bad):
                if bad.startswith("int a"):
                    text = HEADER.replace("    double corners[CW_BASE];", "    " + bad)
                else:
                    text = HEADER + bad + "\n"
                with self.assertRaisesRegex(ch.HeaderError, re.escape(why)):
                    ch.parse(text)


class Page(unittest.TestCase):
    def setUp(self):
        self.h = ch.parse(HEADER.replace("CW_API const char* cw_crate_last_error",
                                         "/* The message. */\nCW_API const char* cw_crate_last_error"), "box.h")

    def test_groups_by_object(self):
        groups = [(title, [f.name for f in fs]) for title, _, fs in c_api_page.groups(self.h)]
        self.assertEqual(groups, [("`cw_crate`", ["cw_box_init", "cw_crate_create", "cw_crate_destroy",
                                                  "cw_crate_count", "cw_crate_last_error"]),
                                  ("Helpers", ["cw_sum"])])

    def test_groups_do_not_depend_on_header_order(self):
        """The header reordered (the helpers' section first, the crate's
        functions reversed) gives the same groups."""
        boxes = HEADER.index("/* ------------------------------------------------------------" + "---- boxes */")
        helpers = HEADER.index("/* ------------------------------------------------------------- helpers */")
        crate = HEADER.index("/* Makes a crate")
        runs = HEADER[crate:helpers].strip().split("\n\n")
        moved = (HEADER[:boxes] + HEADER[helpers:] + "\n" + HEADER[boxes:crate] +
                 "\n\n".join(reversed(runs)) + "\n")
        h = ch.parse(moved.replace("CW_API const char* cw_crate_last_error",
                                   "/* The message. */\nCW_API const char* cw_crate_last_error"))
        self.assertEqual([f.name for f in h.functions][:3], ["cw_sum", "cw_box_init", "cw_crate_last_error"])
        before = {title: sorted(f.name for f in fs) for title, _, fs in c_api_page.groups(self.h)}
        after = {title: sorted(f.name for f in fs) for title, _, fs in c_api_page.groups(h)}
        self.assertEqual(after, before)

    def test_description_and_errors(self):
        d, e = c_api_page.description_and_errors(self.h.function("cw_crate_count"))
        self.assertEqual((d, e), ("Counts the boxes: *n receives their number.", "CW_ERR_THING"))
        d, e = c_api_page.description_and_errors(self.h.function("cw_crate_create"))
        self.assertEqual((d, e), ("Makes a crate from a box (Figs. 8-9).", "CW_ERR_THING"))
        self.assertEqual(c_api_page.sentences("Sums (e.g. 4 values). mode: any, e.g. Two. Done"),
                         ["Sums (e.g. 4 values).", "mode: any, e.g. Two.", "Done"])
        long = "The state (as words: 64 bits), to move it" + " far" * 40 + ": the rest."
        self.assertEqual(c_api_page.short(long), long[:long.index(": the rest")] + ".")
        self.assertEqual(c_api_page.cell("out[i + j*nx] | CW_STATE_* of cw_x"),
                         "out[i + j\\*nx] \\| `CW_STATE_*` of `cw_x`")

    def test_a_function_without_description_fails(self):
        with self.assertRaisesRegex(ch.HeaderError, "cw_crate_last_error"):
            c_api_page.functions_table(ch.parse(HEADER))

    def test_every_function_is_on_the_page(self):
        table = c_api_page.functions_table(self.h)
        for f in self.h.functions:
            self.assertEqual(table.count("| `%s(" % f.name), 1, f.name)


class InstalledHeader(unittest.TestCase):
    def test_the_export_header_beside_it_stays_an_include(self):
        """Installed, creepwork_export.h (CW_API's definition) sits beside the
        header: its preprocessor lines are not prototypes."""
        import shutil
        import tempfile
        with tempfile.TemporaryDirectory() as d:
            for name in os.listdir(os.path.dirname(REAL_HEADER)):
                shutil.copy(os.path.join(os.path.dirname(REAL_HEADER), name), d)
            with open(os.path.join(d, "creepwork_export.h"), "w") as f:
                f.write("#ifndef CW_API\n#  ifdef CW_BUILDING\n#    define CW_API __attribute__((visibility(\"default\")))\n"
                        "#  else\n#    define CW_API\n#  endif\n#endif\n")
            installed = ch.load(os.path.join(d, "creepwork.h"))
        self.assertEqual([f.name for f in installed.functions], [f.name for f in ch.load(REAL_HEADER).functions])


class RealHeader(unittest.TestCase):
    def test_every_prototype_is_read(self):
        text = ch.read_header(REAL_HEADER)
        # An independent count: lines that start a CW_API declaration.
        names = re.findall(r"^CW_API [^(]*?\b(cw_\w+)\(", text, re.M)
        header = ch.parse(text)
        self.assertEqual([f.name for f in header.functions], names)
        self.assertGreater(len(names), 70)
        page = c_api_page.functions_table(header)
        self.assertEqual(sorted(re.findall(r"^\| `(cw_\w+)\(", page, re.M)), sorted(names))


if __name__ == "__main__":
    if len(sys.argv) > 1 and not sys.argv[1].startswith("-"):
        REAL_HEADER = sys.argv.pop(1)
    unittest.main()
