"""Argument checks shared by the contact solvers; each failure names the argument."""

from __future__ import annotations

import warnings
from types import ModuleType
from typing import Any

import numpy as np

from ballscrew.budget import check_memory, contact_batch_bytes
from ballscrew.errors import ImplausibleValueWarning, InputError
from ballscrew.validation import integer_at_least, positive

__all__ = [
    "PLAUSIBLE_E_STAR",
    "composite_modulus_checked",
    "finite_grid",
    "gap_grid",
    "integer_at_least",
    "positive",
]

PLAUSIBLE_E_STAR = (5e8, 1.2e12)
"""Composite moduli E* of two engineering solids [Pa]: from two polymers (E ≈ 1 GPa, ν ≈ 0.4:
E* ≈ 0.6 GPa) to diamond on diamond (E = 1050 GPa, ν = 0.1: E* ≈ 530 GPa) or on a rigid body
(1.06 TPa); steel on steel is 113 GPa. Outside it a unit is likely missing (206 for 206 GPa)."""


def composite_modulus_checked(name: str, value: Any, stacklevel: int = 3) -> float:
    """``value`` as a float if finite and > 0 (else :class:`InputError`); an
    :class:`~ballscrew.errors.ImplausibleValueWarning` outside :data:`PLAUSIBLE_E_STAR`.
    ``stacklevel`` points the warning at the caller of the public function."""
    e_star = positive(name, value, "Pa")
    low, high = PLAUSIBLE_E_STAR
    if not low <= e_star <= high:
        warnings.warn(
            f"{name} = {e_star:.4g} Pa is outside the composite moduli of engineering solids "
            f"({low:.1e} to {high:.1e} Pa); is it in GPa or MPa?",
            ImplausibleValueWarning,
            stacklevel=stacklevel,
        )
    return e_star


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


def gap_grid(name: str, array: Any, xp: ModuleType, ndim: int = 2) -> Any:
    """The gaps of a normal contact solve (``ndim`` 3: a stack of them) as :func:`finite_grid`,
    after two checks that allocate nothing for an array (a list is converted to read its dtype
    and shape): an integer or boolean array is refused (a gap in metres is a fraction of a
    millimetre; integers mean another unit or a mistake), and the solve's memory
    (:func:`~ballscrew.budget.contact_batch_bytes`) must fit the budget
    (:class:`~ballscrew.budget.BudgetError` naming ``name`` and its shape)."""
    dtype = array.dtype if hasattr(array, "dtype") else np.asarray(array).dtype
    if dtype.kind in "biu":
        raise InputError(
            name, f"an array of {dtype}", "a float array of gaps in metres (integers hold no µm)"
        )
    shape = tuple(array.shape) if hasattr(array, "shape") else np.shape(array)
    if len(shape) == ndim and all(shape):  # else finite_grid refuses it
        count = shape[0] if ndim == 3 else 1
        nx, ny = shape[-2:]
        what = f"{count} normal contact solve{'s' * (count > 1)} on {nx} × {ny} cells"
        check_memory(name, f"array of shape {shape}", contact_batch_bytes(count, nx, ny), what)
    return finite_grid(name, array, xp, ndim)
