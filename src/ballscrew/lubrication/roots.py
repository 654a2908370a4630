"""Bracketed root finding of many independent scalar equations at once.

SciPy's elementwise Chandrupatla solver (:func:`scipy.optimize.elementwise.find_root`;
Chandrupatla, T. R. (1997), "A new hybrid quadratic/bisection algorithm for finding the zero of a
nonlinear function without using derivatives", Adv. Eng. Softw. 28:145): inverse quadratic
interpolation where the last three points make it safe, bisection otherwise, every equation of a
batch advancing in the same array operations. This module adds the project's certificate and
its :class:`~ballscrew.errors.ConvergenceError`.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from numpy.typing import NDArray
from scipy.optimize import elementwise

from ballscrew.errors import ConvergenceError

__all__ = ["bracketed_roots"]

FloatArray = NDArray[np.float64]


def bracketed_roots(
    residual: Callable[[FloatArray, NDArray[np.intp]], FloatArray],
    low: FloatArray,
    high: FloatArray,
    xtol: float,
    rtol: float,
    solver: str,
    max_iterations: int = 200,
) -> FloatArray:
    """Roots x_i ∈ [low_i, high_i] of r_i(x) = 0, with r_i(low_i) and r_i(high_i) of opposite sign.

    ``residual(x, i)`` evaluates r at x[k] for the equations i[k]. Each root is certified: it
    lies in a bracket with a sign change of width < xtol + 2 rtol |x| (or r = 0 there). An
    equation still open after ``max_iterations`` raises :class:`ConvergenceError` with the
    largest |r| left.
    """
    index = np.arange(np.size(low), dtype=float)  # the solver passes each active equation's own

    def f(x: FloatArray, i: FloatArray) -> FloatArray:
        return residual(x, i.astype(np.intp))

    result = elementwise.find_root(
        f,
        (np.asarray(low, dtype=float), np.asarray(high, dtype=float)),
        args=(index,),
        tolerances={"xatol": xtol, "xrtol": 2.0 * rtol, "fatol": 0.0, "frtol": 0.0},
        maxiter=max_iterations,
    )
    if not np.all(result.success):
        open_ = ~result.success
        raise ConvergenceError(
            solver, max_iterations, float(np.max(np.abs(result.f_x[open_]))), xtol
        )
    return np.asarray(result.x, dtype=float)
