"""Argument checks shared by the contact solvers; each failure names the argument."""

from __future__ import annotations

from types import ModuleType
from typing import Any

from ballscrew.errors import InputError
from ballscrew.validation import integer_at_least, positive

__all__ = ["finite_grid", "integer_at_least", "positive"]


def finite_grid(name: str, array: Any, xp: ModuleType) -> Any:
    """``array`` as a 2-D float64 array of finite values, else :class:`InputError`."""
    if xp.iscomplexobj(array):
        raise InputError(name, "a complex array", "a real 2-D array (complex values are refused)")
    try:
        grid = xp.asarray(array, dtype=xp.float64)
    except (TypeError, ValueError):
        raise InputError(name, f"a {type(array).__name__}", "a real 2-D array") from None
    if grid.ndim != 2 or grid.size == 0:
        raise InputError(name, f"array of shape {grid.shape}", "a non-empty 2-D array")
    if not bool(xp.isfinite(grid).all()):
        raise InputError(name, "array with non-finite values", "finite values only")
    return grid
