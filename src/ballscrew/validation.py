"""Argument checks shared by the physics modules; each failure names the argument.

Every check raises :class:`ballscrew.errors.InputError` with the argument's name, the offending
value and the allowed range, and returns the value converted (float or float64 array).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ballscrew.errors import InputError


def _suffix(unit: str) -> str:
    return f" {unit}" if unit else ""


def positive(name: str, value: float, unit: str = "") -> float:
    """``value`` as a float if it is finite and > 0."""
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise InputError(name, value, f"a finite number > 0{_suffix(unit)}") from None
    if not (math.isfinite(number) and number > 0.0):
        raise InputError(name, value, f"a finite number > 0{_suffix(unit)}")
    return number


def nonnegative(name: str, value: float, unit: str = "") -> float:
    """``value`` as a float if it is finite and ≥ 0."""
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise InputError(name, value, f"a finite number >= 0{_suffix(unit)}") from None
    if not (math.isfinite(number) and number >= 0.0):
        raise InputError(name, value, f"a finite number >= 0{_suffix(unit)}")
    return number


def positive_array(name: str, value: ArrayLike, unit: str = "") -> NDArray[np.float64]:
    """``value`` as a float64 array if every entry is finite and > 0."""
    arr = np.asarray(value, dtype=np.float64)
    bad = ~(np.isfinite(arr) & (arr > 0.0))
    if np.any(bad):
        raise InputError(name, arr[bad].flat[0], f"finite numbers > 0{_suffix(unit)}")
    return arr


def nonnegative_array(name: str, value: ArrayLike, unit: str = "") -> NDArray[np.float64]:
    """``value`` as a float64 array if every entry is finite and ≥ 0."""
    arr = np.asarray(value, dtype=np.float64)
    bad = ~np.isfinite(arr) | (arr < 0.0)
    if np.any(bad):
        raise InputError(name, arr[bad].flat[0], f"finite values >= 0{_suffix(unit)}")
    return arr


def integer_at_least(name: str, value: int, minimum: int) -> int:
    """``value`` if it is an integer ≥ ``minimum`` (bools excluded)."""
    if isinstance(value, bool) or not isinstance(value, int | np.integer) or value < minimum:
        raise InputError(name, value, f"an integer ≥ {minimum}")
    return int(value)
