"""Residual diagnostics of a fit: are the residuals noise, or does the model miss a shape?

* Wald–Wolfowitz runs test on the signs of the residuals in revolution order (Wald &
  Wolfowitz 1940): with n₊, n₋ residuals of each sign and R runs,

      μ_R = 2 n₊ n₋ / n + 1,   σ_R² = 2 n₊ n₋ (2 n₊ n₋ − n) / (n² (n − 1)),   z = (R − μ_R)/σ_R,

  and the one-sided p = Φ(z) of too few runs (a systematic misfit gives long runs).
* Lag-1 autocorrelation r₁ = Σ e_t e_(t+1) / Σ e_t²; for independent noise r₁ ≈ N(−1/n, 1/n)
  (Box & Jenkins 1976), so z₁ = (r₁ + 1/n) √n.

Residuals are called systematic when p < :data:`ALPHA` or z₁ > the one-sided normal quantile of
:data:`ALPHA`.

The least-squares standard errors come from the residual scatter alone, s² = RSS/(n − p), as if
the residuals were independent. Positively correlated residuals carry less information than n
independent ones: with lag-1 autocorrelation r₁ > 0 (an AR(1) process) the effective number of
points is

    n_eff = n (1 − r₁)/(1 + r₁)                       (Bayley & Hammersley 1946)

and the residual variance over n_eff − p degrees of freedom, s_eff² = RSS/(n_eff − p), inflates
every standard error by √((n − p)/(n_eff − p)) (the rule for trend errors of Santer et al. 2000;
Zięba 2010 for the standard uncertainty of correlated measurements). Neither error covers the
model-form error: a model whose shape misses the data's is not made right by wider errors.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike
from scipy.special import ndtr, ndtri

__all__ = [
    "ALPHA",
    "ResidualDiagnostics",
    "effective_points",
    "error_inflation",
    "residual_diagnostics",
]

ALPHA = 0.01
"""Significance level of both tests (one-sided)."""


@dataclass(frozen=True)
class ResidualDiagnostics:
    """Runs test and lag-1 autocorrelation of a residual series."""

    runs: int
    expected_runs: float
    runs_p_value: float
    """One-sided p of so few runs under independent noise (1 when undefined)."""
    lag1_autocorrelation: float
    lag1_z: float

    @property
    def systematic(self) -> bool:
        """True when either test rejects independent noise at :data:`ALPHA`."""
        return self.runs_p_value < ALPHA or self.lag1_z > float(ndtri(1.0 - ALPHA))

    def message(self) -> str:
        """One line describing the evidence."""
        return (
            f"the residuals are systematic ({self.runs} runs of equal sign where "
            f"{self.expected_runs:.1f} are expected, runs-test p = {self.runs_p_value:.2g}; "
            f"lag-1 autocorrelation {self.lag1_autocorrelation:.2f}): the model misses the shape "
            "of the data and the standard errors understate the uncertainty"
        )

    def as_dict(self) -> dict[str, float | int | bool]:
        return {
            "runs": self.runs,
            "expected_runs": self.expected_runs,
            "runs_test_p_value": self.runs_p_value,
            "lag1_autocorrelation": self.lag1_autocorrelation,
            "systematic": self.systematic,
        }


def residual_diagnostics(residuals: ArrayLike) -> ResidualDiagnostics:
    """Runs test and lag-1 autocorrelation of ``residuals`` (in revolution order)."""
    e = np.asarray(residuals, dtype=float).reshape(-1)
    signs = np.sign(e[e != 0.0])
    n = signs.size
    runs = int(1 + np.count_nonzero(np.diff(signs))) if n else 0
    pos = int(np.count_nonzero(signs > 0))
    neg = n - pos
    expected = 2.0 * pos * neg / n + 1.0 if n else 0.0
    variance = 2.0 * pos * neg * (2.0 * pos * neg - n) / (n * n * (n - 1.0)) if n > 1 else 0.0
    p = float(ndtr((runs - expected) / math.sqrt(variance))) if variance > 0.0 else 1.0
    m = e.size
    total = float(e @ e)
    r1 = float(e[:-1] @ e[1:]) / total if m > 1 and total > 0.0 else 0.0
    z1 = (r1 + 1.0 / m) * math.sqrt(m) if m > 1 else 0.0
    return ResidualDiagnostics(runs, expected, p, r1, z1)


def effective_points(n: int, r1: float) -> float:
    """n_eff = n (1 − r₁)/(1 + r₁) for r₁ > 0, else n (Bayley & Hammersley 1946)."""
    return n * (1.0 - r1) / (1.0 + r1) if r1 > 0.0 else float(n)


def error_inflation(n: int, p: int, r1: float) -> float | None:
    """√((n − p)/(n_eff − p)), the factor on a standard error of p parameters fitted to n
    residuals of lag-1 autocorrelation r₁ (1 for r₁ ≤ 0); None when n_eff ≤ p: the residuals
    are too correlated to determine any error."""
    n_eff = effective_points(n, r1)
    return math.sqrt((n - p) / (n_eff - p)) if n_eff > p else None
