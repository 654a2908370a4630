"""Argument checks shared by the contact solvers; each failure names the argument."""

from __future__ import annotations

import math
from types import ModuleType
from typing import Any

import numpy as np

from ballscrew.errors import InputError


def positive(name: str, value: float) -> float:
    """``value`` as a float if it is finite and > 0, else :class:`InputError` naming ``name``."""
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise InputError(name, value, "a finite number > 0") from None
    if not (math.isfinite(number) and number > 0.0):
        raise InputError(name, value, "a finite number > 0")
    return number


def integer_at_least(name: str, value: int, minimum: int) -> int:
    """``value`` if it is an integer ≥ ``minimum`` (bools excluded), else :class:`InputError`."""
    if isinstance(value, bool) or not isinstance(value, int | np.integer) or value < minimum:
        raise InputError(name, value, f"an integer ≥ {minimum}")
    return int(value)


def finite_grid(name: str, array: Any, xp: ModuleType) -> Any:
    """``array`` as a 2-D float64 array of finite values, else :class:`InputError`."""
    grid = xp.asarray(array, dtype=xp.float64)
    if grid.ndim != 2 or grid.size == 0:
        raise InputError(name, f"array of shape {grid.shape}", "a non-empty 2-D array")
    if not bool(xp.isfinite(grid).all()):
        raise InputError(name, "array with non-finite values", "finite values only")
    return grid
