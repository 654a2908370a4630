"""Argument checks shared by the physics modules; each failure names the argument.

Every check raises :class:`ballscrew.errors.InputError` with the argument's name, the offending
value and the allowed range, and returns the value converted (float or float64 array). Bools,
text and complex numbers are refused, never converted (a complex array would lose its imaginary
part silently).
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Mapping
from contextlib import contextmanager

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ballscrew.errors import InputError


def _suffix(unit: str) -> str:
    return f" {unit}" if unit else ""


def positive(name: str, value: float, unit: str = "") -> float:
    """``value`` as a float if it is a finite real number > 0."""
    allowed = f"a finite number > 0{_suffix(unit)}"
    number = _real(name, value, allowed)
    if not number > 0.0:
        raise InputError(name, value, allowed)
    return number


def nonnegative(name: str, value: float, unit: str = "") -> float:
    """``value`` as a float if it is a finite real number ≥ 0."""
    allowed = f"a finite number >= 0{_suffix(unit)}"
    number = _real(name, value, allowed)
    if not number >= 0.0:
        raise InputError(name, value, allowed)
    return number


def positive_array(name: str, value: ArrayLike, unit: str = "") -> NDArray[np.float64]:
    """``value`` as a float64 array if every entry is finite and > 0."""
    allowed = f"finite numbers > 0{_suffix(unit)}"
    arr = _real_array(name, value, allowed)
    bad = ~(np.isfinite(arr) & (arr > 0.0))
    if np.any(bad):
        raise InputError(name, arr[bad].flat[0], allowed)
    return arr


def nonnegative_array(name: str, value: ArrayLike, unit: str = "") -> NDArray[np.float64]:
    """``value`` as a float64 array if every entry is finite and ≥ 0."""
    allowed = f"finite values >= 0{_suffix(unit)}"
    arr = _real_array(name, value, allowed)
    bad = ~np.isfinite(arr) | (arr < 0.0)
    if np.any(bad):
        raise InputError(name, arr[bad].flat[0], allowed)
    return arr


def integer_at_least(name: str, value: int, minimum: int) -> int:
    """``value`` if it is an integer ≥ ``minimum`` (bools excluded)."""
    if isinstance(value, bool) or not isinstance(value, int | np.integer) or value < minimum:
        raise InputError(name, value, f"an integer ≥ {minimum}")
    return int(value)


def real_number(name: str, value: float, unit: str = "") -> float:
    """``value`` as a float if it is a finite real number (any sign)."""
    return _real(name, value, f"a finite real number{_suffix(unit)}")


def real_array(
    name: str, value: ArrayLike, unit: str = "", *, missing_ok: bool = False
) -> NDArray[np.float64]:
    """``value`` as a float64 array if every entry is a finite real number (or NaN, marking a
    missing value, when ``missing_ok``)."""
    allowed = f"finite real numbers{_suffix(unit)}" + (" or NaN (missing)" if missing_ok else "")
    arr = _real_array(name, value, allowed)
    bad = np.isinf(arr) if missing_ok else ~np.isfinite(arr)
    if np.any(bad):
        raise InputError(name, arr[bad].flat[0], allowed)
    return arr


def same_shape(names: str, *arrays: NDArray[np.float64]) -> tuple[int, ...]:
    """The common (broadcast) shape of ``arrays``; ``names`` lists them for the error."""
    try:
        return np.broadcast_shapes(*(np.shape(a) for a in arrays))
    except ValueError:
        shapes = " and ".join(str(np.shape(a)) for a in arrays)
        raise InputError(names, f"arrays of shapes {shapes}", "arrays of one shape") from None


def case_with(value: object, *sections: str) -> object:
    """``value`` if it looks like a :class:`ballscrew.case.Case` holding ``sections``."""
    if not all(hasattr(value, s) for s in sections):
        allowed = f"a case from ballscrew.load_case (with {', '.join(sections)})"
        raise InputError("case", _brief(value), allowed)
    return value


def _brief(value: object) -> object:
    """``value`` as shown in an error: itself if short, else its type."""
    text = repr(value)
    return value if len(text) <= 60 else f"a {type(value).__name__}"


def _real(name: str, value: object, allowed: str) -> float:
    """``value`` as a finite float; bools, text and complex numbers are refused."""
    if isinstance(value, bool | str | bytes) or np.iscomplexobj(value):
        raise InputError(name, _brief(value), allowed)
    try:
        number = float(value)  # type: ignore[arg-type]
    except (TypeError, ValueError, OverflowError):
        raise InputError(name, _brief(value), allowed) from None
    if not math.isfinite(number):
        raise InputError(name, value, allowed)
    return number


def _real_array(name: str, value: ArrayLike, allowed: str) -> NDArray[np.float64]:
    """``value`` as a float64 array; complex, text, object and ragged input is refused."""
    try:
        arr = np.asarray(value)
    except (TypeError, ValueError):  # ragged nesting
        raise InputError(name, _brief(value), allowed) from None
    if arr.dtype.kind not in "iuf":
        shown = arr.flat[0] if arr.size and arr.dtype.kind == "c" else _brief(value)
        raise InputError(name, shown, allowed)
    return arr.astype(np.float64, copy=False)


@contextmanager
def as_case_fields(fields: Mapping[str, str]) -> Iterator[None]:
    """Re-raise an :class:`InputError` on an internal argument as one on the case field it
    came from (``fields`` maps argument names such as ``lambda_2`` to dotted case keys)."""
    try:
        yield
    except InputError as exc:
        if exc.field not in fields:
            raise
        raise InputError(fields[exc.field], exc.value, exc.allowed) from None
