"""Pictures of one contact, as the creepwork CLI draws them
(programs/cli/patch_plots.cpp): maps over the patch of the slip/adhesion
states, the energy-consistent work per unit area, the tractions and
micro-slips along x and y, the moment per unit area and the traction-bound
utilisation |p|/(mu pz), each titled with its total; and the lateral work
profile against the parabola of equal area. Each element is drawn as its
own rectangle (Kalker's strip grid gives every strip its own element
length); lengths in mm, stresses in N/mm^2, forces in kN, as the CLI's SI
pictures.

Needs matplotlib (Debian: python3-matplotlib), imported when a function is
called: `import creepwork` never needs it.

    r = creepwork.solve(a=7e-3, b=5e-3, N=100e3, xi_x=1e-3, xi_y=5e-4, phi=0.5)
    fig = creepwork.plot.patch_maps(r)
    fig.savefig("patch.png")
"""

from typing import TYPE_CHECKING, Any

import numpy as np

from ._library import CONSTANTS

if TYPE_CHECKING:
    from ._solver import Result

# The CLI's palettes (programs/cli/gnuplot.cpp): white to brown for values
# of one sign, blue-white-red for signed ones, blue adhesion / red slip.
_SEQUENTIAL = [(0.0, "white"), (0.2, "#fee391"), (0.55, "#fe9929"), (1.0, "#8c2d04")]
_DIVERGING = [(0.0, "#2166ac"), (0.3, "#92c5de"), (0.5, "white"), (0.7, "#f4a582"),
              (1.0, "#b2182b")]
_STATES = ["#c6dbef", "#f4a582"]


def _pyplot():
    try:
        import matplotlib
        from matplotlib import pyplot
        from matplotlib.collections import PolyCollection
        from matplotlib.colors import LinearSegmentedColormap, ListedColormap
    except ImportError as e:
        raise ImportError("creepwork.plot needs matplotlib, which is not installed (Debian: "
                          "apt-get install python3-matplotlib); the rest of creepwork works "
                          "without it") from e
    return matplotlib, pyplot, PolyCollection, LinearSegmentedColormap, ListedColormap


def _rectangles(result):
    """Corners (n, 4, 2) in mm of the contact elements, and their mask."""
    grid = getattr(result, "grid", None) or {}
    ny, nx = result.state.shape
    uniform = grid.get("kind") == CONSTANTS["CW_GRID_UNIFORM"]
    scale = grid.get("box_scale", 1.0) if uniform else 1.0
    dy = 2.0 * scale * result.b / ny
    inside = (result.area > 0) & (result.state != 0)
    dx = result.area / dy
    x, y = result.x[inside], result.y[inside]
    hx, hy = dx[inside] / 2, np.full(x.shape, dy / 2)
    corners = np.stack([np.stack([x - hx, y - hy], -1), np.stack([x + hx, y - hy], -1),
                        np.stack([x + hx, y + hy], -1), np.stack([x - hx, y + hy], -1)], 1)
    return 1e3 * corners, inside


def _panels(result):
    area = np.where(result.area > 0, result.area, 1.0)
    mu = float(result.params["mu"]) if getattr(result, "params", None) is not None else None
    panels = [
        ("Work per unit area (energy-consistent), W = %.6g J/m" % result.W_consistent,
         result.work_consistent / area * 1e-6, "J/m per mm$^2$"),
        ("Longitudinal traction on the wheel, Fx = %.6g kN" % (result.Fx / 1e3),
         result.px * 1e-6, "N/mm$^2$"),
        ("Longitudinal micro-slip W_x/V (0 in adhesion)", result.sx, "-"),
        ("Lateral traction on the wheel, Fy = %.6g kN" % (result.Fy / 1e3),
         result.py * 1e-6, "N/mm$^2$"),
        ("Lateral micro-slip W_y/V (0 in adhesion)", result.sy, "-"),
        ("Creep moment per unit area on the wheel, Mz = %.6g N m" % result.Mz,
         result.mz / area * 1e-3, "N mm per mm$^2$"),
    ]
    if mu:
        bound = mu * result.pz
        util = np.where(bound > 0, np.hypot(result.px, result.py) / np.where(bound > 0, bound, 1),
                        0.0)
        panels.append(("Traction-bound utilisation |p|/(mu p_z): 1 in slip", util, "-"))
    return panels


def patch_maps(result: "Result", fig: Any = None) -> Any:
    """The eight-panel overview of a Result solved with fields=True:
    slip/adhesion map and seven heat maps. Returns the matplotlib Figure
    (fig: one to draw into, else a new one)."""
    if result.state is None:
        raise ValueError("patch_maps needs a Result with fields (solve with fields=True)")
    _, pyplot, PolyCollection, Segmented, Listed = _pyplot()
    if fig is None:
        fig = pyplot.figure(figsize=(11, 15))
    corners, inside = _rectangles(result)
    axes = fig.subplots(4, 2).ravel()
    states = result.state[inside]
    a_mm, b_mm = 1e3 * result.a, 1e3 * result.b
    _draw(axes[0], corners, states, Listed(_STATES), (0.5, 2.5), PolyCollection, a_mm, b_mm)
    axes[0].set_title("Slip/adhesion: %d adhesion, %d slip elements (adhesion %.3g %%)"
                      % (result.n_adhesion, result.n_slip, 100 * result.adhesion_fraction),
                      fontsize=9)
    for ax, (title, values, unit) in zip(axes[1:], _panels(result)):
        v = values[inside]
        lo, hi = float(v.min(initial=0.0)), float(v.max(initial=0.0))
        if lo >= 0:
            cmap, limits = Segmented.from_list("cw_sequential", _SEQUENTIAL), (0, hi or 1.0)
        else:
            m = max(-lo, hi)
            cmap, limits = Segmented.from_list("cw_diverging", _DIVERGING), (-m, m)
        coll = _draw(ax, corners, v, cmap, limits, PolyCollection, a_mm, b_mm)
        fig.colorbar(coll, ax=ax, label=unit if unit != "-" else None)
        ax.set_title(title, fontsize=9)
    for ax in axes[len(_panels(result)) + 1:]:
        ax.set_visible(False)
    towards = "+x" if result.params is None or result.params["rolling_direction"] >= 0 else "-x"
    fig.suptitle("a = %.4g mm, b = %.4g mm; rolling towards %s (leading edge at x = %sa); "
                 "tractions, forces and moment on the wheel" % (a_mm, b_mm, towards, towards[0]))
    fig.tight_layout()
    return fig


def _draw(ax, corners, values, cmap, limits, PolyCollection, a_mm, b_mm):
    coll = PolyCollection(corners, array=np.asarray(values, float), cmap=cmap, edgecolors="none")
    coll.set_clim(*limits)
    ax.add_collection(coll)
    t = np.linspace(0, 2 * np.pi, 181)
    ax.plot(a_mm * np.cos(t), b_mm * np.sin(t), color="black", lw=0.6)  # the Hertz ellipse
    ax.set_xlim(corners[..., 0].min() * 1.05, corners[..., 0].max() * 1.05)
    ax.set_ylim(corners[..., 1].min() * 1.05, corners[..., 1].max() * 1.05)
    ax.set_aspect("equal")
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    return coll


def profile(result: "Result", ax: Any = None) -> Any:
    """The lateral work profile w(y) per strip against the parabola of equal
    area (the paper's Figs. 8-9). Returns the matplotlib Axes."""
    if result.profile is None:
        raise ValueError("profile needs a Result with fields (solve with fields=True)")
    _, pyplot, *_ = _pyplot()
    if ax is None:
        ax = pyplot.figure(figsize=(7, 4)).add_subplot()
    y = 1e3 * result.profile.y
    ax.step(y, 1e-3 * result.profile.w, where="mid", color="#b2182b", lw=2,
            label="energy-consistent work per strip")
    yy = np.linspace(-result.b, result.b, 201)
    ax.plot(1e3 * yy, 1e-3 * 0.75 * result.W_consistent / result.b * (1 - (yy / result.b) ** 2),
            "--", color="#2166ac", lw=2, label="parabola of equal area")
    ax.set_xlabel("y [mm]")
    ax.set_ylabel("w(y) [J/m per mm]")
    ax.set_title("Lateral work profile, W = %.6g J/m" % result.W_consistent)
    ax.legend()
    return ax
