"""Argument checks shared by the contact solvers; each failure names the argument."""

from __future__ import annotations

from types import ModuleType
from typing import Any

from ballscrew.errors import InputError
from ballscrew.validation import integer_at_least, positive

__all__ = ["finite_grid", "integer_at_least", "positive"]


def finite_grid(name: str, array: Any, xp: ModuleType, ndim: int = 2) -> Any:
    """``array`` as an ``ndim``-D float64 array of finite values, else :class:`InputError`."""
    kind = f"{ndim}-D array"
    if xp.iscomplexobj(array):
        raise InputError(name, "a complex array", f"a real {kind} (complex values are refused)")
    try:
        grid = xp.asarray(array, dtype=xp.float64)
    except (TypeError, ValueError):
        raise InputError(name, f"a {type(array).__name__}", f"a real {kind}") from None
    if grid.ndim != ndim or grid.size == 0:
        raise InputError(name, f"array of shape {grid.shape}", f"a non-empty {kind}")
    if not bool(xp.isfinite(grid).all()):
        raise InputError(name, "array with non-finite values", "finite values only")
    return grid
