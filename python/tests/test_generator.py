"""generate_layout.py on small headers written here (expected values read
off the text by hand), on the real header with a field appended as the
header's growth rule allows, and on constructs it must refuse."""

import os
import re

import pytest

from creepwork import _library

HEADER = r'''
#define CW_STATUS_LIST(X)                            \
    X(CW_OK, 0, "success")                           \
    X(CW_ERR_THING, 7, "a thing; with a semicolon")
#define CW_STATUS_ENUMERATOR_(name, value, message) name = value,
#define CW_BASE 3
#define CW_DERIVED (CW_BASE * 100 + 2) /* an expression */
#define CW_RATIO 1e-3       /* a double */

/* cw_box.shape: how the box looks */
#define CW_SHAPE_ROUND 0   /* round */
#define CW_SHAPE_SQUARE 1  /* square, with a comment
                              over two lines */

/* cw_box.level */
#define CW_LEVEL_DEFAULT -1.0

typedef struct cw_box {
    size_t struct_size; /* set by cw_box_init */
    double L1, L2;      /* two at once [m/Pa] */
    int shape;
    /* ---- appended in 1.1 ---- */
    unsigned int flags; /* bits; "quoted" */
    const double* gap;  /* caller's array [m] */
    double corners[CW_BASE]; /* three */
    int64_t count;      /* a multi-line
                           comment; with a semicolon */
    double level;
} cw_box;

CW_API int cw_box_init(cw_box* box);
CW_API const char* cw_box_name(const cw_box* box, int which);
CW_API int cw_box_fill(double values[4], char* message, size_t message_len);
CW_API int cw_version_number(void);
'''


@pytest.fixture(scope="module")
def box(generator):
    return generator.parse_header(HEADER, "box.h")


def test_struct_fields(box):
    fields = [(f["name"], f["ctype"], f["pointer"], f["count"]) for f in box["structs"]["cw_box"]]
    assert fields == [("struct_size", "size_t", 0, None), ("L1", "double", 0, None),
                      ("L2", "double", 0, None), ("shape", "int", 0, None),
                      ("flags", "unsigned int", 0, None), ("gap", "double", 1, None),
                      ("corners", "double", 0, 3), ("count", "int64_t", 0, None),
                      ("level", "double", 0, None)]


def test_field_docs(box):
    docs = {f["name"]: f["doc"] for f in box["structs"]["cw_box"]}
    assert docs["L1"] == docs["L2"] == "two at once [m/Pa]"
    assert docs["shape"] == ""  # the standalone comment on the next line is not its doc
    assert docs["flags"] == 'bits; "quoted"'
    assert docs["count"] == "a multi-line comment; with a semicolon"
    assert docs["level"] == ""


def test_constants_and_enumerations(box):
    c = box["constants"]
    assert (c["CW_OK"], c["CW_ERR_THING"], c["CW_DERIVED"], c["CW_RATIO"]) == (0, 7, 302, 1e-3)
    assert "CW_STATUS_LIST" not in c and "CW_STATUS_ENUMERATOR_" not in c
    assert box["enums"] == {"cw_box.shape": {"round": 0, "square": 1},
                            "cw_box.level": {"default": -1.0}}
    assert box["constant_docs"]["CW_SHAPE_SQUARE"] == "square, with a comment over two lines"
    assert box["statuses"] == [("CW_OK", 0, "success"),
                               ("CW_ERR_THING", 7, "a thing; with a semicolon")]


def test_prototypes(box):
    f = box["functions"]
    assert f["cw_box_init"] == {"restype": "int", "argtypes": ["pointer"]}
    assert f["cw_box_name"] == {"restype": "char_p", "argtypes": ["pointer", "int"]}
    assert f["cw_box_fill"] == {"restype": "int", "argtypes": ["pointer", "char_p", "size_t"]}
    assert f["cw_version_number"] == {"restype": "int", "argtypes": []}


def test_dtype_offsets(box):
    """The C layout of cw_box on x86-64 / AArch64 (LP64), by hand: size_t 0,
    L1 8, L2 16, shape 24, flags 28, gap 32, corners 40..64, count 64,
    level 72, size 80."""
    dtype = _library._struct_dtype(box["structs"]["cw_box"])
    offsets = [dtype.fields[n][1] for n in dtype.names]
    assert offsets == [0, 8, 16, 24, 28, 32, 40, 64, 72]
    assert dtype.itemsize == 80


@pytest.mark.parametrize("bad, why", [
    ("long double x;", "long double"),
    ("struct cw_other inner;", "struct cw_other"),
    ("int a[CW_UNKNOWN];", "CW_UNKNOWN"),
])
def test_refuses_what_it_cannot_read(generator, bad, why):
    header = HEADER.replace("    double level;\n", "    double level;\n    %s\n" % bad)
    with pytest.raises(generator.HeaderError, match=re.escape(why)):
        generator.parse_header(header)


def test_first_field_must_be_struct_size(generator):
    with pytest.raises(generator.HeaderError, match="struct_size"):
        generator.parse_header(HEADER.replace("size_t struct_size;", "size_t size;"))


def test_appended_field_of_the_real_header(generator, source_dir):
    """The header's growth rule: fields are appended after a comment. An int
    appended to cw_params becomes the last field, with its doc and an
    offset after every old one; the old offsets do not move. (A name no
    header will use: the real header grows too.)"""
    with open(os.path.join(source_dir, "capi/include/creepwork/creepwork.h")) as f:
        header = f.read()
    grown = re.sub(r"(\n\} cw_params;)",
                   "\n    /* ---- appended in 9.9 ---- */\n    int test_appended; /* 1: on [-] */\\1",
                   header, count=1)
    old = generator.parse_header(header)["structs"]["cw_params"]
    new = generator.parse_header(grown)["structs"]["cw_params"]
    assert new[:-1] == old
    assert new[-1] == {"name": "test_appended", "ctype": "int", "kind": "int", "pointer": 0,
                       "count": None, "doc": "1: on [-]"}
    d_old, d_new = _library._struct_dtype(old), _library._struct_dtype(new)
    assert all(d_new.fields[n][1] == d_old.fields[n][1] for n in d_old.names)
    assert d_new.fields["test_appended"][1] >= d_old.fields[d_old.names[-1]][1] + 4


def test_generated_files_are_deterministic(generator, source_dir, tmp_path):
    """Generating twice gives the same files (the build writes only on change)."""
    header = os.path.join(source_dir, "capi/include/creepwork/creepwork.h")
    for run in ("a", "b"):
        generator.main(["--header", header, "--python", str(tmp_path / run / "_layout.py"),
                        "--c-fields", str(tmp_path / run / "fields.h"),
                        "--probe", str(tmp_path / run / "probe.c")])
    for name in ("_layout.py", "fields.h", "probe.c"):
        assert (tmp_path / "a" / name).read_text() == (tmp_path / "b" / name).read_text()
