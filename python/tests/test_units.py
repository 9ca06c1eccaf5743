"""Implausible units warn with creepwork.UnitWarning exactly where the CLI
warns (its plausibility_warnings, programs/cli/contact_inputs.cpp): each
rule is tried just beyond and just inside its threshold, through solve(),
solve_many() and the CLI, and all three must agree; a params array's values
warn as keywords do."""

import warnings

import numpy as np
import pytest

import creepwork
from conftest import run_cli

BASE = dict(a=7e-3, b=5e-3, N=100e3)
GIVEN = dict(flexibility="given", L1=5e-14, L2=5e-14, L3=5e-14)
# (keyword, CLI option, value beyond the threshold, value inside, extra keywords)
RULES = [
    ("a", "a", 0.11, 0.09, dict(b=0.08)),  # a/b stays within Kalker's range
    ("a", "a", 0.9e-4, 1.1e-4, {}),
    ("b", "b", 0.11, 0.09, dict(a=0.08)),
    ("b", "b", 0.9e-4, 1.1e-4, {}),
    ("N", "N", 1.1e7, 0.9e7, {}),
    ("N", "N", 999.0, 1001.0, {}),
    ("mu", "mu", 1.6, 1.4, {}),
    ("G", "G", 0.9e6, 1.1e6, {}),
    ("G", "G", 1.1e12, 0.9e12, {}),
    ("L1", "L1", 2e-10, 0.9e-10, GIVEN),
    ("L2", "L2", 0.9e-18, 1.1e-18, GIVEN),
    ("L3", "L3", 2e-10, 0.9e-10, GIVEN),
    ("xi_x", "xi-x", -0.6, -0.4, {}),
    ("xi_y", "xi-y", 0.6, 0.4, {}),
    ("phi", "spin", 51.0, 49.0, {}),
]


def python_warnings(keywords):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        creepwork.solve(**keywords, fields=False)
    return [str(w.message) for w in caught if issubclass(w.category, creepwork.UnitWarning)]


def cli_warnings(cli, keywords):
    names = {"N": "N", "xi_x": "xi-x", "xi_y": "xi-y", "phi": "spin", "mu": "mu", "G": "G",
             "a": "a", "b": "b", "L1": "L1", "L2": "L2", "L3": "L3"}
    args = ["solve"]
    for k, v in keywords.items():
        if k != "flexibility":
            args += ["--" + names[k], repr(v)]
    _, err = run_cli(cli, *args)
    return [line for line in err.splitlines() if "implausible" in line]


@pytest.mark.parametrize("keyword, option, beyond, inside, extra", RULES)
def test_same_warnings_as_the_cli(cli, keyword, option, beyond, inside, extra):
    for value, expected in ((beyond, 1), (inside, 0)):
        keywords = {**BASE, **extra, keyword: value}
        mine, theirs = python_warnings(keywords), cli_warnings(cli, keywords)
        assert len(mine) == len(theirs) == expected, (keywords, mine, theirs)
        if expected:
            assert mine[0].startswith("%s = " % keyword), mine
            assert ("--%s = " % option) in theirs[0], theirs


def test_solve_many_warns_once_per_rule_with_the_count():
    a = np.full(1000, 7e-3)
    a[[3, 500]] = 7.2e-3 * 1000  # two semi-axes typed in millimetres
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        out = creepwork.solve_many(a=a, b=a, N=100e3, xi_x=1e-3)
    messages = [str(w.message) for w in caught if w.category is creepwork.UnitWarning]
    assert len(messages) == 2  # a and b, once each
    assert "(2 of 1000 contacts)" in messages[0] and "millimetres" in messages[0]
    assert caught[0].filename == __file__  # points at the caller's line
    assert out.ok.all()


def test_params_array_warns_like_keywords():
    """Values inside a params array are checked as keywords are: records
    with the semi-axes in millimetres or the load in kN among plausible ones
    warn once per rule with the count, through solve_many and Batch.solve,
    with the keywords plausible; warn=False is silent."""
    p = np.empty(50, creepwork.DTYPES["cw_params"])
    p[...] = creepwork.params(**BASE)
    p["a"][[7, 31, 40]] = 7.0  # mm typed as m
    p["b"][[7, 31, 40]] = 5.0
    p["normal_force"][12] = 100.0  # kN typed as N
    for call in (lambda **k: creepwork.solve_many(p, xi_x=1e-3, **k),
                 lambda **k: creepwork.Batch(threads=1).solve(p, xi_x=1e-3, **k)):
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            out = call()
        messages = sorted(str(w.message) for w in caught if w.category is creepwork.UnitWarning)
        assert len(messages) == 3, messages
        assert messages[0].startswith("a = 7 m (3 of 50 contacts) is implausible"), messages
        assert messages[1].startswith("b = 5 m (3 of 50 contacts) is implausible"), messages
        # the record's field, as it was set (p["normal_force"])
        assert messages[2].startswith("normal_force = 100 N (1 of 50 contacts) is implausible"), \
            messages
        assert out.ok.all()
        with warnings.catch_warnings():
            warnings.simplefilter("error", creepwork.UnitWarning)
            call(warn=False)


def test_warn_false_and_the_warning_filter():
    with warnings.catch_warnings():
        warnings.simplefilter("error", creepwork.UnitWarning)
        creepwork.solve(**BASE, mu=2.0, warn=False, fields=False)
        with pytest.raises(creepwork.UnitWarning, match="mu = 2 is implausible"):
            creepwork.solve(**BASE, mu=2.0, fields=False)
    assert issubclass(creepwork.UnitWarning, UserWarning)
