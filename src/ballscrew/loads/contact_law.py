"""Load–approach law Q(δ) of a ball's two contacts, tabulated at a few loads.

The per-ball distribution needs, for every ball, the normal load Q that a contact approach δ
makes (and its slope dQ/dδ for Newton). Hertz gives δ = K Q^(2/3) in closed form; a conforming
groove (non-Hertzian gap) gives it only through a numerical contact solve. All balls of a nut
share the groove geometry, so the law is tabulated once at loads Q_1 < … < Q_m (one batched
contact solve per raceway) and interpolated monotonically: a PCHIP (Fritsch & Carlson 1980)
of ln Q against ln δ, so a power law δ = c Q^n is reproduced exactly and the interpolant keeps
the table's monotony. Beyond the table the end tangents in log-log continue it (a power law with
the end exponent; below the smallest load the contact is small and nearly Hertzian, n → 2/3).
The error of that continuation grows with the change of the log-slope n(Q) = d ln δ / d ln Q
beyond the table: ln(δ/δ_ext) = ∫ (n − n_end) d ln Q, at most |n(Q) − n_end| · |ln(Q/Q_end)|
where n varies monotonically (a conforming groove or a compliant layer stiffens or softens the
law gradually); a caller whose loads leave the table should say so (:attr:`TabulatedContact.top`).
A ball without approach carries nothing: Q = 0 for δ ≤ 0.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.interpolate import PchipInterpolator
from scipy.optimize import brentq

from ballscrew.errors import InputError

__all__ = ["TabulatedContact"]


@dataclass(frozen=True)
class TabulatedContact:
    """Q(δ) through the points (δ_k, Q_k) of a ball's two contacts in series (SI)."""

    loads: NDArray[np.float64]
    """Tabulation loads Q_k [N], strictly increasing, > 0."""
    approaches: NDArray[np.float64]
    """Approach δ_k = δ_A(Q_k) + δ_B(Q_k) of the ball's two contacts [m], strictly increasing."""
    _curve: PchipInterpolator = field(init=False, repr=False, compare=False)
    _ends: tuple[float, float, float, float, float, float] = field(
        init=False, repr=False, compare=False
    )

    def __post_init__(self) -> None:
        q = np.asarray(self.loads, dtype=float)
        d = np.asarray(self.approaches, dtype=float)
        if q.ndim != 1 or q.shape != d.shape or q.size < 2:
            raise InputError("loads", f"{q.size} points", "two or more (load, approach) pairs")
        for name, v in (("loads", q), ("approaches", d)):
            if not (np.all(np.isfinite(v)) and np.all(v > 0.0) and np.all(np.diff(v) > 0.0)):
                raise InputError(name, v.tolist(), "finite values > 0, strictly increasing")
        object.__setattr__(self, "loads", q)
        object.__setattr__(self, "approaches", d)
        u, w = np.log(d), np.log(q)
        curve = PchipInterpolator(u, w, extrapolate=False)
        slope = curve.derivative()
        ends = (u[0], w[0], float(slope(u[0])), u[-1], w[-1], float(slope(u[-1])))
        object.__setattr__(self, "_curve", curve)
        object.__setattr__(self, "_ends", ends)

    @property
    def top(self) -> float:
        """The largest tabulated load [N]; above it the law is extrapolated."""
        return float(self.loads[-1])

    @property
    def exponents(self) -> tuple[float, float]:
        """(n_low, n_high): the exponents n of δ ∝ Q^n that continue the law below and above the
        table (the PCHIP's end log-slopes, 1/(d ln Q / d ln δ)) [-]."""
        _, _, s0, _, _, s1 = self._ends
        return 1.0 / s0, 1.0 / s1

    @classmethod
    def hertz(cls, hertz_constant: float, loads: ArrayLike) -> TabulatedContact:
        """The table of δ = K Q^(2/3) at ``loads`` (a Hertz contact pair, K = K_A + K_B)."""
        q = np.asarray(loads, dtype=float)
        return cls(q, hertz_constant * q ** (2.0 / 3.0))

    def approach(self, load: float) -> float:
        """δ at the load Q > 0 [m]: the inverse of :meth:`load` (root of the monotone PCHIP in
        ln δ; the end power laws beyond the table)."""
        u0, w0, s0, u1, w1, s1 = self._ends
        w = math.log(load)
        if w <= w0:
            return math.exp(u0 + (w - w0) / s0)
        if w >= w1:
            return math.exp(u1 + (w - w1) / s1)
        return math.exp(brentq(lambda u: float(self._curve(u)) - w, u0, u1, xtol=1e-15))

    def load(self, approach: ArrayLike) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """(Q, dQ/dδ) at the approaches δ [m]: 0 where δ ≤ 0."""
        d = np.asarray(approach, dtype=float)
        u0, w0, s0, u1, w1, s1 = self._ends
        positive = d > 0.0
        u = np.log(np.where(positive, d, 1.0))
        w = self._curve(u)
        dw = self._curve(u, 1)
        low, high = u < u0, u > u1
        w = np.where(low, w0 + s0 * (u - u0), np.where(high, w1 + s1 * (u - u1), w))
        dw = np.where(low, s0, np.where(high, s1, dw))
        q = np.where(positive, np.exp(w), 0.0)
        return q, np.where(positive, q * dw / np.where(positive, d, 1.0), 0.0)
