"""Errors: one exception class per status code of the header, each raised
with the library's message naming the input; Python-side mistakes
(unknown keyword, non-integer count, unknown name of an enumeration value)
raise with the name too. Nothing is written on error."""

import os
import re

import numpy as np
import pytest

import creepwork

OK = dict(a=7e-3, b=5e-3, N=100e3, xi_x=1e-3)


def header_statuses(source_dir):
    """X(name, value, "message") of CW_STATUS_LIST, read here from the text."""
    with open(os.path.join(source_dir, "capi/include/creepwork/creepwork.h")) as f:
        text = f.read()
    return [(n, int(v), m) for n, v, m in re.findall(r'X\((CW_\w+), (\d+), "([^"]*)"\)', text)]


def test_one_class_per_status(source_dir):
    statuses = header_statuses(source_dir)
    assert len(statuses) >= 14
    for name, value, message in statuses:
        if value == 0:
            continue
        cls_name = "".join(w.capitalize() for w in name[len("CW_ERR_"):].split("_")) + "Error"
        cls = getattr(creepwork, cls_name)
        assert issubclass(cls, creepwork.Error)
        assert (cls.status, cls.name, cls.summary) == (value, name, message)
        assert creepwork.status_string(value) == message
        assert getattr(creepwork, name) == value


def test_nu_out_of_range_names_nu():
    with pytest.raises(creepwork.InvalidInputError) as e:
        creepwork.solve(**OK, nu=0.6)
    assert re.search(r"\bnu\b", str(e.value)), str(e.value)
    assert e.value.status == creepwork.CW_ERR_INVALID_INPUT
    assert isinstance(e.value, ValueError)


@pytest.mark.parametrize("keywords, cls, named", [
    (dict(a=-1e-3), creepwork.InvalidInputError, "a"),
    (dict(mu=float("nan")), creepwork.InvalidInputError, "mu"),
    (dict(G=0.0), creepwork.InvalidInputError, "G"),
    (dict(model="exact", grid={"kind": "strips"}), creepwork.InvalidInputError, "grid"),
    (dict(model="exact", tolerance=2.0), creepwork.InvalidInputError, "tolerance"),
    (dict(model=7), creepwork.UnknownOptionError, "model"),
    (dict(pressure="flat"), creepwork.UnknownOptionError, "pressure"),
    (dict(grid={"nx": 0}), creepwork.GridOutOfRangeError, "nx"),
    (dict(grid={"kind": "uniform", "box_scale": 0.5}), creepwork.GridOutOfRangeError, "box"),
])
def test_errors_name_the_input(keywords, cls, named):
    with pytest.raises(cls) as e:
        creepwork.solve(**{**OK, **keywords}, warn=False)
    assert named in str(e.value), str(e.value)


@pytest.mark.parametrize("left_out", ["a", "b", "N"])
def test_size_and_load_are_required(left_out):
    """No default for a contact's size and load (as creepwork solve)."""
    keywords = {k: v for k, v in OK.items() if k != left_out}
    with pytest.raises(TypeError, match=r"missing required keyword argument: '%s'" % left_out):
        creepwork.solve(**keywords)


def test_no_solution_and_no_work():
    with creepwork.Solver() as s:
        with pytest.raises(creepwork.NoSolutionError):
            s.field("pz")
        s.solve(**OK, fields=False)
        assert s.field("pz").max() > 0
        with pytest.raises(creepwork.NoWorkError):
            s.field("sx")
        # After an error the handle holds no solution, and stays usable.
        with pytest.raises(creepwork.InvalidInputError):
            s.solve(**OK, nu=0.6)
        assert "nu" in s.last_error
        with pytest.raises(creepwork.NoSolutionError):
            s.field("pz")
        assert s.solve(**OK).Fx < 0


def test_python_side_mistakes():
    with pytest.raises(TypeError, match="xi_x"):
        creepwork.solve(a=7e-3, b=5e-3, N=100e3, xi=1e-3)  # did you mean xi_x?
    with pytest.raises(TypeError, match="max_iterations"):
        creepwork.solve(**OK, model="exact", max_iterations=2.5)
    with pytest.raises(creepwork.InvalidInputError, match="max_iterations = 10000000000 is outside"):
        creepwork.solve(**OK, model="exact", max_iterations=10**10)  # would wrap in a C int
    with pytest.raises(creepwork.InvalidInputError, match="max_iterations"):
        creepwork.solve_many(**OK, model="exact", max_iterations=np.array([50, 2**31]))
    with pytest.raises(creepwork.UnknownOptionError, match="exakt"):
        creepwork.solve(**OK, model="exakt")
    with pytest.raises(TypeError, match="grid"):
        creepwork.solve(**OK, grid=(20, 20))
    with pytest.raises(creepwork.UnknownOptionError, match="'p'"):
        creepwork.Solver().field("p")


def test_out_buffers_are_checked_and_untouched_on_error():
    with creepwork.Solver() as s:
        s.solve(**OK)
        short = np.full(10, 7.0)
        with pytest.raises(creepwork.BufferTooSmallError):
            s.field("pz", out=short)
        assert np.all(short == 7.0)
        with pytest.raises(TypeError):
            s.field("pz", out=np.empty((20, 20), np.float32))
        buf = np.empty((20, 20))
        assert s.field("pz", out=buf) is buf and buf.max() > 0


def test_closed_handles_raise():
    s = creepwork.Solver()
    s.close()
    s.close()  # idempotent
    with pytest.raises(ValueError, match="closed"):
        s.solve(**OK)


def test_not_converged():
    with pytest.raises(creepwork.NotConvergedError, match="iteration"):
        creepwork.solve(**OK, xi_y=2e-3, phi=1.0, model="exact", tolerance=1e-13,
                        max_iterations=1)
