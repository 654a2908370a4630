"""Least-squares calibration of the wear coefficient K (and the drag-torque scale) to a test bench.

Method
------
The wear model is an injected callable ``simulate(K) -> history`` (by default
:func:`ballscrew.wear_life` on the case with ``wear.coefficient = K``). Its history is
interpolated linearly (``np.interp``) onto the measured revolutions, and the residuals

    r_i(θ) = (m · y_model(N_i; K) − y_i) / s,      θ = (ln K [, m])

are minimised with :func:`scipy.optimize.least_squares` (trust-region reflective). ``s`` is a
fixed scale of the data (conditioning only). ``m`` multiplies the model's friction torque and is
fitted only for torque data with ``fit_torque_scale``: the catalogue drag torque
T_p = K_T F_p L/(2π) (E9.1, theory manual *Wear*) is linear in K_T and the torque does not feed
back into the wear, so one model run per K serves every m, and the fitted torque scale is
``m`` times the case's ``wear.torque_scale``. This absorbs seal and lubricant drag (E9.3).

K is fitted as ln K: it is positive, spans decades, and the model responds to it roughly
multiplicatively (theory manual, *Wear*: K is confounded with the stroke and the revolutions,
so it is a calibration constant of the whole model).

Robust start: a coarse scan in ln K (one decade apart, starting at the case's K, extended
towards lower residuals until the minimum is bracketed) picks the best decade, with m from its
closed-form linear least-squares value at each K. Up to two surrogate steps follow (the model's
values at the data interpolated quadratically in ln K through the three nearest runs, the
surrogate's sum of squares minimised on a grid, one model run to check it), and least_squares
starts from the best run, bounded to the decade either side of the scan's best K.
The ln K column of the Jacobian is a forward difference with a fixed step (default 1e-2,
i.e. 1 % in K), large enough to step over the numerical noise of a wear model (explicit time
steps and iterative contact solves: about 3e-5 of the REF wear depth and preload), small enough
for a truncation error of about 0.5 % of the column, updated by secant steps between (the
general fitter :func:`ballscrew.calibration.multi.fit_parameters`, which
:func:`fit_wear_coefficient` calls); the m column is exact. Model runs are memoised by their
parameter values in one place (:class:`ballscrew.calibration.search.ModelRuns`), so a
1-parameter fit takes 8–12 model runs.

Uncertainty (Gauss–Newton / delta method; e.g. Seber & Wild, *Nonlinear Regression*, 1989,
§2.1): with J the Jacobian of the residuals at the solution, p parameters and n points,

    cov(θ) = RSS/(n − p) · (JᵀJ)⁻¹,   σ_K = K · σ_lnK,   σ_scale = scale₀ · σ_m.

These are the standard errors of a correctly specified model with independent equal-variance
noise; they do not include the model's own (structural) uncertainty.
"""

from __future__ import annotations

import math
from collections.abc import Callable

from ballscrew.calibration.measured import MeasuredHistory
from ballscrew.calibration.multi import fit_parameters
from ballscrew.calibration.result import (
    CalibrationError,
    CalibrationResult,
    WearHistory,
    model_values,
)
from ballscrew.calibration.search import DIFF_STEP, K_MAX, K_MIN, SCAN_STEPS
from ballscrew.errors import InputError

__all__ = [
    "CalibrationError",
    "CalibrationResult",
    "WearHistory",
    "fit_wear_coefficient",
    "model_values",
]


def fit_wear_coefficient(
    simulate: Callable[[float], WearHistory],
    data: MeasuredHistory,
    *,
    initial_coefficient: float = 1.0e-4,
    torque_scale: float = 1.0,
    fit_torque_scale: bool = False,
    max_evaluations: int = 40,
    diff_step: float = DIFF_STEP,
    scan_steps: int = SCAN_STEPS,
    refine_steps: int = 2,
) -> CalibrationResult:
    """Fit K (and the torque scale) so that ``simulate(K)`` matches the measured history.

    Args:
        simulate: the wear model, K → history with ``revolutions`` and the measured quantity
            (``friction_torque`` N·m, ``preload`` N or ``max_wear_depth`` m).
        data: the measured history (see :func:`ballscrew.calibration.read_measured`).
        initial_coefficient: K where the coarse scan starts (the case's value).
        torque_scale: the torque scale the model's torques were computed with (the case's
            ``wear.torque_scale``); the fitted scale is reported relative to 1.
        fit_torque_scale: fit the torque scale too (friction-torque data only).
        max_evaluations: most model runs allowed; more raises ConvergenceError.
        diff_step: forward-difference step in ln K for the Jacobian.
        scan_steps: most decades the scan may extend beyond its first three points.
        refine_steps: most surrogate steps (one model run each) between scan and least squares.

    Returns:
        The fit, its standard errors and the fitted curve (see :class:`CalibrationResult`).

    Raises:
        InputError: the scale is requested for other data than torque, bad arguments, or data
            beyond the simulated revolutions.
        CalibrationError: too few points, an unusable model history, a best fit at the end of
            the scan, or a Jacobian that does not determine the parameters.
        ConvergenceError: least squares did not converge within ``max_evaluations`` runs.
    """
    if fit_torque_scale and data.quantity != "friction_torque":
        raise InputError(
            "--fit-torque-scale", True, f"only with friction_torque data (got {data.quantity})"
        )
    if not (math.isfinite(initial_coefficient) and K_MIN < initial_coefficient < K_MAX):
        raise InputError("wear.coefficient", initial_coefficient, f"a number in ({K_MIN}, 1)")
    if not (math.isfinite(torque_scale) and torque_scale > 0.0):
        raise InputError("wear.torque_scale", torque_scale, "a number > 0")
    return fit_parameters(
        lambda values: simulate(values["wear_coefficient"]),
        data,
        ["wear_coefficient"] + (["torque_scale"] if fit_torque_scale else []),
        {"wear_coefficient": initial_coefficient},
        torque_scale=torque_scale,
        max_evaluations=max_evaluations,
        diff_step=diff_step,
        scan_steps=scan_steps,
        refine_steps=refine_steps,
        label="calibration (least squares on ln K)",
    )
