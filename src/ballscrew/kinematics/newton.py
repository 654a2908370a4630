"""Damped Newton–Raphson with a finite-difference Jacobian, for the quasi-static ball balance.

``docs/theory/kinematics.md`` (E3.6): start from the static values, finite-difference Jacobian, stop
at |ΔX|/|X| < 1e-10 (here on scaled unknowns, together with a small scaled residual). A solve that
does not get there raises :class:`~ballscrew.errors.ConvergenceError` with the residual.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ballscrew.errors import ConvergenceError

__all__ = ["NewtonResult", "newton_solve"]

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class NewtonResult:
    """Converged root of a scaled residual."""

    x: FloatArray
    """Solution (unscaled)."""
    iterations: int
    residual: float
    """max |r_i| of the scaled residual at the solution."""


def _jacobian(
    func: Callable[[FloatArray], FloatArray], z: FloatArray, r0: FloatArray, step: float
) -> FloatArray:
    jac = np.empty((r0.size, z.size))
    for j in range(z.size):  # one column per unknown (≤ 7 unknowns)
        h = step * max(1.0, abs(z[j]))
        dz = z.copy()
        dz[j] += h
        jac[:, j] = (func(dz) - r0) / h
    return jac


def newton_solve(
    residual: Callable[[FloatArray], FloatArray],
    x0: FloatArray,
    scale: FloatArray,
    *,
    solver: str,
    step_tolerance: float = 1e-10,
    residual_tolerance: float = 1e-9,
    max_iterations: int = 60,
    fd_step: float = 1e-7,
) -> NewtonResult:
    """Solve residual(x) = 0 by damped Newton–Raphson on z = x/scale.

    ``residual`` must return a dimensionless (already scaled) vector. Each step solves J Δz = −r
    with a forward-difference Jacobian and halves Δz until max|r| decreases (at most 30 times).
    Converged when max|r| ≤ residual_tolerance and either max|Δz| ≤ step_tolerance · max(1, max|z|)
    or the last step no longer halved |r| (the rounding floor of the finite-difference Newton).
    Raises :class:`ConvergenceError` after ``max_iterations`` or when no step reduces |r|.
    """
    scale = np.asarray(scale, dtype=float)

    def func(z: FloatArray) -> FloatArray:
        return np.asarray(residual(z * scale), dtype=float)

    z = np.asarray(x0, dtype=float) / scale
    r = func(z)
    norm = float(np.max(np.abs(r)))
    for iteration in range(1, max_iterations + 1):
        jac = _jacobian(func, z, r, fd_step)
        try:
            dz = np.linalg.solve(jac, -r)
        except np.linalg.LinAlgError:
            dz = np.linalg.lstsq(jac, -r, rcond=None)[0]
        damping = 1.0
        for _ in range(30):
            trial = z + damping * dz
            r_trial = func(trial)
            n_trial = float(np.max(np.abs(r_trial)))
            if np.isfinite(n_trial) and (n_trial < norm or n_trial <= residual_tolerance):
                break
            damping *= 0.5
        else:
            if norm <= residual_tolerance:
                return NewtonResult(z * scale, iteration, norm)
            raise ConvergenceError(solver, iteration, norm, residual_tolerance)
        step = float(np.max(np.abs(damping * dz)))
        stalled = n_trial > 0.5 * norm  # no longer quadratic: at the rounding floor
        z, r, norm = trial, r_trial, n_trial
        small_step = step <= step_tolerance * max(1.0, float(np.max(np.abs(z))))
        if norm <= residual_tolerance and (small_step or stalled):
            return NewtonResult(z * scale, iteration, norm)
    raise ConvergenceError(solver, max_iterations, norm, residual_tolerance)
