"""Argument checks shared by the contact solvers; each failure names the argument."""

from __future__ import annotations

from types import ModuleType
from typing import Any

from ballscrew.errors import InputError
from ballscrew.validation import integer_at_least, positive

__all__ = ["finite_grid", "integer_at_least", "positive"]


def finite_grid(name: str, array: Any, xp: ModuleType) -> Any:
    """``array`` as a 2-D float64 array of finite values, else :class:`InputError`."""
    grid = xp.asarray(array, dtype=xp.float64)
    if grid.ndim != 2 or grid.size == 0:
        raise InputError(name, f"array of shape {grid.shape}", "a non-empty 2-D array")
    if not bool(xp.isfinite(grid).all()):
        raise InputError(name, "array with non-finite values", "finite values only")
    return grid
