"""Wang–Komvopoulos domain-extension factor ψ(D) of the fractal spot-size distribution.

Source: Wang, S. & Komvopoulos, K. (1994), "A fractal theory of the interfacial temperature
distribution in the slow sliding regime: Part I", J. Tribol. 116:812–822. Theory manual:
``docs/theory/fractal-contact.md``, equation (F10).
"""

from __future__ import annotations

import math
from functools import lru_cache

from scipy.optimize import brentq

from ballscrew.errors import ConvergenceError, InputError
from ballscrew.validation import real_number

__all__ = ["domain_extension_factor", "size_distribution_constant", "validate_dimension"]

_PSI_BRACKET = (1.0, 1.0e6)
_PSI_XTOL = 1.0e-15
_PSI_RTOL = 1.0e-15
_PSI_MAXITER = 200


def validate_dimension(D: float) -> float:
    """Return the profile fractal dimension ``D`` as a float after checking 1 < D < 2.

    Raises:
        InputError: if ``D`` is not a finite number strictly between 1 and 2.
    """
    allowed = "profile fractal dimension with 1 < D < 2 (surface Ds = D + 1)"
    try:
        value = real_number("D", D)
    except InputError:
        value = math.nan
    if not 1.0 < value < 2.0:
        raise InputError("D", D, allowed)
    return value


def _f10_residual(psi: float, D: float) -> float:
    """Residual of (F10): [ψ^((2−D)/2) − (1 + ψ^(−D/2))^(−(2−D)/D)] / ((2−D)/D) − 1."""
    k = (2.0 - D) / D
    return (psi ** ((2.0 - D) / 2.0) - (1.0 + psi ** (-D / 2.0)) ** (-k)) / k - 1.0


@lru_cache(maxsize=256)
def _psi_cached(D: float) -> float:
    lo, hi = _PSI_BRACKET
    root, info = brentq(
        _f10_residual,
        lo,
        hi,
        args=(D,),
        xtol=_PSI_XTOL,
        rtol=_PSI_RTOL,
        maxiter=_PSI_MAXITER,
        full_output=True,
        disp=False,
    )
    if not info.converged:
        raise ConvergenceError(
            "domain_extension_factor (Brent, F10)",
            info.iterations,
            abs(_f10_residual(root, D)),
            _PSI_XTOL,
        )
    return float(root)


def domain_extension_factor(D: float) -> float:
    """Domain-extension factor ψ > 1 of Wang & Komvopoulos (1994), equation (F10).

    ψ is the root of

        [ψ^((2−D)/2) − (1 + ψ^(−D/2))^(−(2−D)/D)] / ((2−D)/D) = 1,

    found by Brent's method on the bracket (1, 10⁶). The residual is strictly negative at ψ = 1
    (because 1 − 2^(−k) < k for k > 0) and positive at 10⁶ for every 1 < D < 2, so the bracket
    always holds a root. Results are cached per D.

    Args:
        D: profile fractal dimension, 1 < D < 2 (dimensionless).

    Returns:
        ψ (dimensionless). Examples: D = 1.5 → 2.00071, D = 1.59 → 1.93509.

    Raises:
        InputError: if D is outside (1, 2).
        ConvergenceError: if Brent's method fails to converge (not expected).
    """
    return _psi_cached(validate_dimension(D))


def size_distribution_constant(D: float) -> float:
    """Constant c = ψ^((2−D)/2) of the spot-size distribution (F9); MB 1991 is ψ = 1 (c = 1).

    Args:
        D: profile fractal dimension, 1 < D < 2.

    Returns:
        c (dimensionless), e.g. 1.14492 for D = 1.59.
    """
    D = validate_dimension(D)
    return domain_extension_factor(D) ** ((2.0 - D) / 2.0)
