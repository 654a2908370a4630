"""The worn groove seen by the next contact solution (E8.5).

The raceway normal-section profile after wear is the nominal arc pushed back along its local
normal by the wear depth h(y); since |y| ≪ r_s, y is the arc length across the groove and the
push-back adds h(y) to the ball–raceway gap (``docs/theory/wear.md`` (E8.5), (E4.8)).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ballscrew.errors import InputError
from ballscrew.validation import nonnegative_array, real_array

__all__ = ["worn_gap", "worn_gap_function"]

GapFunction = Callable[[Any, Any], Any]


def _profile(y: ArrayLike, depth: ArrayLike) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    yy = real_array("y", y, "m")
    hh = nonnegative_array("wear depth", depth, "m")
    if yy.ndim != 1 or yy.shape != hh.shape or yy.size < 2 or np.any(np.diff(yy) <= 0.0):
        raise InputError("wear profile", (yy.shape, hh.shape), "increasing y with one h per y")
    return yy, hh


def worn_gap_function(gap: GapFunction, y: ArrayLike, depth: ArrayLike) -> GapFunction:
    """Gap function of the worn groove: ``g(x, y) = g_0(x, y) + h(y)``, (E8.5), m.

    ``gap`` is a nominal gap function f(x, y) (e.g. :func:`ballscrew.geometry.gap_function`);
    h(y) is linear between the samples (y, depth) and 0 outside them (unworn raceway).
    """
    yy, hh = _profile(y, depth)

    def gap_worn(x: Any, y_points: Any) -> Any:
        base = np.asarray(gap(x, y_points), dtype=float)
        return base + np.interp(np.asarray(y_points, dtype=float), yy, hh, left=0.0, right=0.0)

    return gap_worn


def worn_gap(nominal: ArrayLike, depth: ArrayLike) -> NDArray[np.float64]:
    """Worn gap on a fixed grid: ``nominal[i, j] + depth[j]`` (axis 1 across the groove), m."""
    g = real_array("nominal", nominal, "m")
    h = nonnegative_array("wear depth", depth, "m")
    if g.ndim != 2:
        raise InputError("nominal", f"array of shape {g.shape}", "a 2-D gap grid in m")
    if h.shape != (g.shape[1],):
        raise InputError("wear depth", h.shape, f"one depth per grid column ({g.shape[1]})")
    return g + h[None, :]
