"""Figures of the analyses (matplotlib, non-interactive): shared drawing helpers."""

from __future__ import annotations

from functools import cache
from pathlib import Path
from types import ModuleType
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

DPI = 110
"""Resolution of the report figures [dots per inch]."""


@cache
def pyplot() -> ModuleType:
    """:mod:`matplotlib.pyplot` on the non-interactive Agg backend, imported at the first figure
    (not at the import of ``ballscrew``: it takes ~0.4 s that a command without figures would
    pay)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def save_figure(fig: Figure, path: str | Path, dpi: float = DPI) -> Path:
    """Write ``fig`` to ``path`` as a PNG in one drawing pass, close it and return the path.

    ``Figure.savefig`` draws a figure that has a layout engine twice (once without rendering,
    to place the axes, then to render); the Agg canvas's ``print_png`` draws once, the
    constrained layout running inside that draw, and gives the same image in about 20 % less
    time per figure.
    """
    fig.set_dpi(dpi)
    fig.canvas.print_png(path)
    pyplot().close(fig)
    return Path(path)


def plain(text: object) -> str:
    """``text`` shown literally in a figure: every ``$`` escaped, so mathtext never starts.

    Outside ``$…$`` matplotlib draws ``^``, ``_`` and ``\\`` as they are, so user text (case,
    sensor, profile and file names) can neither break the figure nor change its look.
    """
    return str(text).replace("$", r"\$")


def pressure_map(
    x: np.ndarray,
    y: np.ndarray,
    pressure: np.ndarray,
    hertz_semi_axes: tuple[float, float],
    title: str,
    path: str | Path,
) -> Path:
    """Contact pressure over the tangent-plane grid, Hertz ellipse drawn over it.

    ``x`` (rolling direction) and ``y`` (across the groove) in m, ``pressure`` in Pa with
    ``pressure[i, j]`` at ``(x[i], y[j])``, ``hertz_semi_axes`` = (semi-axis along x, along y).
    Axes are drawn in µm and pressure in GPa.
    """
    from matplotlib.patches import Ellipse

    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6.4, 4.2), layout="constrained")
    extent = (y[0] * 1e6, y[-1] * 1e6, x[0] * 1e6, x[-1] * 1e6)
    image = ax.imshow(pressure * 1e-9, origin="lower", extent=extent, aspect="auto", cmap="inferno")
    fig.colorbar(image, ax=ax, label="contact pressure [GPa]")
    ax.add_patch(
        Ellipse(
            (0.0, 0.0),
            width=2e6 * hertz_semi_axes[1],
            height=2e6 * hertz_semi_axes[0],
            fill=False,
            color="cyan",
            linestyle="--",
            linewidth=1.2,
            label="Hertz ellipse",
        )
    )
    ax.set_xlabel("y, across the groove [µm] (axes not to scale)")
    ax.set_ylabel("x, rolling direction [µm]")
    ax.set_title(plain(title))
    ax.legend(loc="upper right", fontsize=8)
    return save_figure(fig, path)


def pressure_profiles(
    x: np.ndarray,
    y: np.ndarray,
    pressure: np.ndarray,
    hertz_p0: float,
    hertz_semi_axes: tuple[float, float],
    title: str,
    path: str | Path,
) -> Path:
    """Centre-line pressure profiles along x and y against the Hertz ellipsoidal profile."""
    plt = pyplot()
    i0, j0 = np.unravel_index(np.argmax(pressure), pressure.shape)
    fig, axes = plt.subplots(1, 2, figsize=(8.0, 3.2), layout="constrained")
    for ax, coord, profile, semi, label in (
        (axes[0], x, pressure[:, j0], hertz_semi_axes[0], "x, rolling direction [µm]"),
        (axes[1], y, pressure[i0, :], hertz_semi_axes[1], "y, across the groove [µm]"),
    ):
        fine = np.linspace(coord[0], coord[-1], 400)
        hertz = hertz_p0 * np.sqrt(np.clip(1.0 - (fine / semi) ** 2, 0.0, None))
        ax.plot(fine * 1e6, hertz * 1e-9, "k--", linewidth=1, label="Hertz")
        ax.plot(coord * 1e6, profile * 1e-9, ".", markersize=3, label="numerical")
        ax.set_xlabel(label)
        ax.set_ylabel("pressure [GPa]")
        ax.legend(fontsize=8)
    fig.suptitle(plain(title), fontsize=10)
    return save_figure(fig, path)


def resistance_map(
    x: np.ndarray,
    y: np.ndarray,
    resistance: np.ndarray,
    cell: tuple[float, float],
    title: str,
    path: str | Path,
) -> Path:
    """Element thermal contact resistance R_ij on the fractal cells (log colour scale, K/W).

    ``x``, ``y``: the cells' centres [m]; ``cell``: their sides along x and y [m], so the map
    covers the cells' edges (one cell, e.g. a whole patch, is drawn over its own extent).
    """
    plt = pyplot()
    from matplotlib.colors import LogNorm

    finite = np.where(np.isfinite(resistance), resistance, np.nan)
    fig, ax = plt.subplots(figsize=(6.4, 4.2), layout="constrained")
    hx, hy = 0.5 * cell[0], 0.5 * cell[1]
    extent = ((y[0] - hy) * 1e6, (y[-1] + hy) * 1e6, (x[0] - hx) * 1e6, (x[-1] + hx) * 1e6)
    low, high = np.nanmin(finite), np.nanmax(finite)
    if not high > low:  # one value (one element): a decade around it
        low, high = low / np.sqrt(10.0), high * np.sqrt(10.0)
    image = ax.imshow(
        finite,
        origin="lower",
        extent=extent,
        aspect="auto",
        cmap="viridis_r",
        norm=LogNorm(low, high),
    )
    fig.colorbar(image, ax=ax, label="element resistance R_ij [K/W]")
    ax.set_xlabel("y, across the groove [µm] (axes not to scale)")
    ax.set_ylabel("x, rolling direction [µm]")
    ax.set_title(plain(title))
    return save_figure(fig, path)


_LINESTYLES = ("-", "--", "-.", ":")
_MARKERS = ("o", "s", "^", "v", "D", "P", "X", "*")


def line_styles(n: int) -> list[dict[str, object]]:
    """``n`` distinguishable line styles: colours of a perceptually ordered map, and for more
    than ten curves also line styles and markers, so no two curves look alike."""
    plt = pyplot()
    colours = (
        plt.get_cmap("tab10").colors
        if n <= 10
        else plt.get_cmap("viridis")(np.linspace(0.0, 0.9, n))
    )
    return [
        {
            "color": colours[k % len(colours)],
            "linestyle": _LINESTYLES[k % len(_LINESTYLES)] if n > 10 else "-",
            "marker": _MARKERS[k % len(_MARKERS)],
        }
        for k in range(n)
    ]


def legend_outside(ax: Axes, **kwargs: object) -> None:
    """A legend to the right of the axes, never over the data."""
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0, **kwargs)


def revolutions_axis(revolutions: np.ndarray) -> tuple[float, str]:
    """(divisor, label) of a revolution count for a plot axis: a power of 10³ of the largest,
    ``screw revolutions [10⁶ rev]``, so that matplotlib puts no bare ``1e6`` beside the axis."""
    revolutions = np.asarray(revolutions, dtype=float)
    top = float(np.nanmax(np.abs(revolutions))) if revolutions.size else 0.0
    power = 3 * int(np.floor(np.log10(top) / 3)) if top >= 1e4 else 0
    if power == 0:
        return 1.0, "screw revolutions"
    exponent = str(power).translate(str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹"))
    return 10.0**power, f"screw revolutions [10{exponent} rev]"


def zero_noise(values: np.ndarray, tolerance: float) -> np.ndarray:
    """``values`` with every entry smaller in magnitude than ``tolerance`` set to 0.

    A solver returns such values as round-off (a spin of 1e-15 rad/s); plotted, they would look
    like data.
    """
    values = np.asarray(values, dtype=float)
    return np.where(np.abs(values) < tolerance, 0.0, values)


def label_box() -> dict[str, object]:
    """A white, slightly transparent box behind a label drawn over a colour map (readable on
    any colour)."""
    return {"boxstyle": "round,pad=0.15", "facecolor": "white", "alpha": 0.8, "linewidth": 0}
