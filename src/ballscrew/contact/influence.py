"""Influence coefficients of the elastic half-space for uniform pressure on rectangular cells.

Love (1929), Phil. Trans. R. Soc. A 228:377; Johnson (1985), Contact Mechanics, §3.2. The sum of the
normal displacements of both surfaces is taken, so the composite modulus E* (K1) is the only
elastic constant: 1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ballscrew.validation import integer_at_least, positive, real_array, same_shape

__all__ = ["love_coefficient", "love_coefficients"]


def _asinh_term(x: NDArray[np.float64], y: NDArray[np.float64]) -> NDArray[np.float64]:
    """x·asinh(y/|x|), taken as 0 where x = 0 (its limit)."""
    ratio = np.divide(y, np.abs(x), out=np.zeros_like(x), where=x != 0)
    return x * np.arcsinh(ratio)


def _love_primitive(x: NDArray[np.float64], y: NDArray[np.float64]) -> NDArray[np.float64]:
    """F(X, Y) = X·asinh(Y/|X|) + Y·asinh(X/|Y|) of (K4)."""
    return _asinh_term(x, y) + _asinh_term(y, x)


def love_coefficient(
    x: ArrayLike, y: ArrayLike, dx: float, dy: float, e_star: float
) -> NDArray[np.float64]:
    """Displacement at (x, y) per unit pressure on the cell [−dx/2, dx/2] × [−dy/2, dy/2], in m/Pa.

    (K4), Love (1929):
    K = (1/(π E*)) [F(x+a, y+b) − F(x+a, y−b) − F(x−a, y+b) + F(x−a, y−b)], a = dx/2, b = dy/2,
    F(X, Y) = X·asinh(Y/|X|) + Y·asinh(X/|Y|).

    ``x``, ``y`` [m] broadcast against each other; ``e_star`` [Pa] is the composite modulus (K1).
    A square cell of side Δ has K(0, 0) = 4 ln(1 + √2)/π · Δ/E* = 1.122200 Δ/E*; far away K tends to
    the point load Δ²/(π E* r) of Boussinesq (K2).
    """
    x, y = real_array("x", x, "m"), real_array("y", y, "m")
    same_shape("x, y", x, y)
    x, y = np.broadcast_arrays(x, y)
    dx, dy, e_star = _checked_cell(dx, dy, e_star)
    a, b = 0.5 * dx, 0.5 * dy
    total = (
        _love_primitive(x + a, y + b)
        - _love_primitive(x + a, y - b)
        - _love_primitive(x - a, y + b)
        + _love_primitive(x - a, y - b)
    )
    return total / (np.pi * e_star)


def love_coefficients(nx: int, ny: int, dx: float, dy: float, e_star: float) -> NDArray[np.float64]:
    """Table K[i, j] = K(i·dx, j·dy) of (K4) for 0 ≤ i < nx, 0 ≤ j < ny [m/Pa].

    K is even in x and in y, so this quadrant holds every coefficient of an nx × ny grid:
    u[i, j] = Σ_kl K[|i − k|, |j − l|] p[k, l]   (K5).
    The cell corners x_i ± dx/2 lie on one lattice, so F of (K4) is evaluated once per corner and
    K is its second mixed difference (4x fewer evaluations than :func:`love_coefficient`).
    """
    nx, ny = integer_at_least("nx", nx, 1), integer_at_least("ny", ny, 1)
    dx, dy, e_star = _checked_cell(dx, dy, e_star)
    x = dx * (np.arange(nx + 1, dtype=np.float64) - 0.5)[:, None]
    y = dy * (np.arange(ny + 1, dtype=np.float64) - 0.5)[None, :]
    f = _love_primitive(*np.broadcast_arrays(x, y))
    return (f[1:, 1:] - f[1:, :-1] - f[:-1, 1:] + f[:-1, :-1]) / (np.pi * e_star)


def _checked_cell(dx: float, dy: float, e_star: float) -> tuple[float, float, float]:
    """Cell sides [m] and composite modulus [Pa], each a finite number > 0."""
    return positive("dx", dx, "m"), positive("dy", dy, "m"), positive("e_star", e_star, "Pa")
