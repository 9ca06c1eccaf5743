"""creepwork.plot: a clear ImportError without matplotlib (the package
itself never needs it); with matplotlib, the overview holds one rectangle
per contact element, the totals in its titles, and a utilisation map that
is 1 exactly where elements slip (|p| = mu pz there, by the friction law)."""

import importlib
import sys

import numpy as np
import pytest

import creepwork

CONTACT = dict(a=7e-3, b=5e-3, N=100e3, xi_x=1e-3, xi_y=5e-4, phi=0.5)


def test_clear_import_error_without_matplotlib(monkeypatch):
    r = creepwork.solve(**CONTACT)
    for name in [m for m in sys.modules if m == "matplotlib" or m.startswith("matplotlib.")]:
        monkeypatch.delitem(sys.modules, name)
    monkeypatch.setitem(sys.modules, "matplotlib", None)  # import matplotlib -> ImportError
    importlib.reload(creepwork.plot)  # importing the module itself needs nothing
    with pytest.raises(ImportError, match="python3-matplotlib"):
        creepwork.plot.patch_maps(r)
    with pytest.raises(ImportError, match="needs matplotlib"):
        creepwork.plot.profile(r)


def test_patch_maps_with_matplotlib():
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    r = creepwork.solve(**CONTACT)
    fig = creepwork.plot.patch_maps(r)
    axes = [ax for ax in fig.axes if ax.get_visible() and ax.get_xlabel() == "x [mm]"]
    assert len(axes) == 8
    for ax in axes:
        assert len(ax.collections[0].get_paths()) == r.n_contact
    titles = " ".join(ax.get_title() for ax in axes)
    assert "Fx = -8.36421 kN" in titles and "Mz = -23.0706 N m" in titles
    assert "%d adhesion, %d slip" % (r.n_adhesion, r.n_slip) in titles
    utilisation = np.asarray(axes[-1].collections[0].get_array())
    slip = r.state[(r.area > 0) & (r.state != 0)] == creepwork.CW_STATE_SLIP
    assert np.allclose(utilisation[slip], 1.0, rtol=1e-9)
    assert utilisation[~slip].max() < 1.0
    ax = creepwork.plot.profile(r)
    assert len(ax.lines) == 2
