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
:func:`fit_wear_coefficient` calls); the m column is exact. Model runs are cached by K, so a
1-parameter fit takes 8–12 model runs.

Uncertainty (Gauss–Newton / delta method; e.g. Seber & Wild, *Nonlinear Regression*, 1989,
§2.1): with J the Jacobian of the residuals at the solution, p parameters and n points,

    cov(θ) = RSS/(n − p) · (JᵀJ)⁻¹,   σ_K = K · σ_lnK,   σ_scale = scale₀ · σ_m.

These are the standard errors of a correctly specified model with independent equal-variance
noise; they do not include the model's own (structural) uncertainty.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from types import ModuleType
from typing import Any, ClassVar, Protocol

import numpy as np
import xarray as xr
from numpy.typing import NDArray
from scipy.optimize import least_squares

from ballscrew.analyses.result import Presented
from ballscrew.calibration import report as calibration_report
from ballscrew.calibration.measured import MeasuredHistory
from ballscrew.case.inputs import resolved_inputs
from ballscrew.errors import BallscrewError, ConvergenceError, InputError

__all__ = [
    "CalibrationError",
    "CalibrationResult",
    "WearHistory",
    "fit_wear_coefficient",
    "model_values",
]

#: Attribute of the model history that each measured quantity is compared with.
HISTORY_FIELD: dict[str, str] = {
    "friction_torque": "friction_torque",
    "preload": "preload",
    "wear_depth": "max_wear_depth",
}

_LN10 = math.log(10.0)
_K_MIN, _K_MAX = 1.0e-16, 1.0  # K is a probability per asperity encounter
_DIFF_STEP = 1.0e-2
"""Default forward-difference step in the logarithm of a parameter, for the Jacobian."""
_SCAN_STEPS = 6
"""Default for the most decades the scan in K may extend beyond its first three points."""


class CalibrationError(BallscrewError, ValueError):
    """The measured data cannot determine the fitted parameters with this model."""


class WearHistory(Protocol):
    """What the calibration reads from a wear-model history (``ballscrew.wear_life``)."""

    revolutions: Any
    max_wear_depth: Any
    preload: Any
    friction_torque: Any


@dataclass(frozen=True)
class CalibrationResult(Presented):
    """A fitted wear coefficient (and torque scale) with its uncertainty.

    Attributes:
        quantity: the measured quantity (``friction_torque``, ``preload`` or ``wear_depth``).
        unit: its SI unit.
        source: where the measured data came from.
        wear_coefficient: fitted K.
        standard_error: standard error of K (delta method from ln K).
        torque_scale: fitted torque scale (multiplies the catalogue K_T) or the case's value
            when it was not fitted.
        torque_scale_error: its standard error, None when not fitted.
        correlation: correlation of ln K and the torque scale, None when not fitted.
        rms_residual: root-mean-square of (model − measured), SI unit of the quantity.
        n_points: number of measured points.
        parameters: number of fitted parameters (1 or 2).
        evaluations: number of wear-model runs.
        initial_coefficient: the K the scan started from.
        revolutions: measured revolutions.
        measured: measured values (SI).
        fitted: the fitted model at the measured revolutions.
        model_revolutions: revolutions of the fitted model's own history.
        model_values: the fitted model's history of the quantity (SI).
        scan: (K, RMS residual) of the coarse scan, in the order evaluated.
        message: the least-squares solver's termination message.
        case: the calibrated case (None for :func:`fit_wear_coefficient` on its own).
        options: the options of the run, as ``summary.json`` states them.
        warnings: warnings of the model run nearest the fitted K (one line each).
    """

    quantity: str
    unit: str
    source: str
    wear_coefficient: float
    standard_error: float
    torque_scale: float
    torque_scale_error: float | None
    correlation: float | None
    rms_residual: float
    n_points: int
    parameters: int
    evaluations: int
    initial_coefficient: float
    revolutions: NDArray[np.float64]
    measured: NDArray[np.float64]
    fitted: NDArray[np.float64]
    model_revolutions: NDArray[np.float64]
    model_values: NDArray[np.float64]
    scan: tuple[tuple[float, float], ...]
    message: str
    case: Any = None
    options: Mapping[str, Any] = field(default_factory=dict)
    warnings: tuple[str, ...] = ()
    values: Mapping[str, float] = field(default_factory=dict)
    """Every fitted parameter by name (``wear_coefficient``, ``torque_scale``, …)."""
    errors: Mapping[str, float] = field(default_factory=dict)
    """Their standard errors (delta method)."""
    n_fit: int | None = None
    """Points the fit used (the first ``n_fit``; None: all)."""
    fit_until: float | None = None
    """Revolutions up to which the data were fitted (None: all)."""
    prediction_rmse: float | None = None
    """RMS of (model − measured) on the held-out points after ``fit_until`` (None: none)."""
    prediction_sigma: NDArray[np.float64] | None = None
    """σ of a new measurement at :attr:`model_revolutions`: √(gᵀ cov g + s²) (delta method)."""
    diagnostics: Mapping[str, Any] = field(default_factory=dict)
    """Runs test and lag-1 autocorrelation of the fitted residuals."""
    calibrated_range: Mapping[str, float] | None = None
    """Speeds [rad/s] and axial loads [N] of the calibrated programme."""

    analysis: ClassVar[str] = "calibrate"
    presentation: ClassVar[ModuleType] = calibration_report

    @property
    def title(self) -> str:
        return f"Wear calibration: {self.case_name}"

    @property
    def case_name(self) -> str:
        """Name of the calibrated case (the measured file's when there is no case)."""
        return self.case.name if self.case is not None else self.source

    @property
    def inputs(self) -> dict[str, Any]:
        return resolved_inputs(self.case) if self.case is not None else {}

    def to_xarray(self) -> dict[str, xr.Dataset]:
        from ballscrew.calibration import report

        return {"fit": report.fit_dataset(self)}

    @property
    def relative_error(self) -> float:
        """σ_K / K."""
        return self.standard_error / self.wear_coefficient

    @property
    def residuals(self) -> NDArray[np.float64]:
        """Model minus measured at the measured revolutions, SI unit."""
        return self.fitted - self.measured


def model_values(history: WearHistory, quantity: str) -> tuple[np.ndarray, np.ndarray]:
    """(revolutions, values) of ``quantity`` in a model history, checked and as float arrays."""
    field = HISTORY_FIELD[quantity]
    rev = np.asarray(history.revolutions, dtype=np.float64).reshape(-1)
    val = np.asarray(getattr(history, field), dtype=np.float64).reshape(-1)
    if rev.size < 2 or rev.shape != val.shape or not np.all(np.isfinite(val)):
        raise CalibrationError(
            f"the wear model returned an unusable {field} history "
            f"({rev.size} revolutions, {val.size} values, finite: {bool(np.all(np.isfinite(val)))})"
        )
    if np.any(np.diff(rev) < 0.0):
        raise CalibrationError("the wear model returned revolutions that decrease")
    return rev, val


def covering_history(history: WearHistory, data: MeasuredHistory) -> tuple[np.ndarray, ...]:
    """:func:`model_values` of ``data``'s quantity; InputError unless they span the data."""
    rev, val = model_values(history, data.quantity)
    first, last = data.revolutions[0], data.revolutions[-1]
    if last > rev[-1] * (1.0 + 1e-9) or first < rev[0]:
        raise InputError(
            f"{data.source}: revolutions",
            float(last if last > rev[-1] else first),
            f"within the simulated test, {rev[0]:g} to {rev[-1]:g} rev "
            "(lengthen the case's load programme)",
        )
    return rev, val


class _Objective:
    """Residuals of the fit with a per-K cache of model runs."""

    def __init__(
        self,
        simulate: Callable[[float], WearHistory],
        data: MeasuredHistory,
        fit_scale: bool,
        max_evaluations: int,
    ) -> None:
        self.simulate = simulate
        self.data = data
        self.fit_scale = fit_scale
        self.max_evaluations = max_evaluations
        self.cache: dict[float, tuple[np.ndarray, np.ndarray, np.ndarray]] = {}
        values = np.abs(data.values)
        self.scale = float(np.max(values)) if np.max(values) > 0.0 else 1.0
        self.best_rms = math.inf

    @property
    def evaluations(self) -> int:
        return len(self.cache)

    def run(self, ln_k: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(model at the data, model revolutions, model values) for K = exp(ln_k), cached."""
        key = float(ln_k)
        if key not in self.cache:
            if len(self.cache) >= self.max_evaluations:
                raise ConvergenceError(
                    "calibration (least squares on ln K)", len(self.cache), self.best_rms, 0.0
                )
            rev, val = covering_history(self.simulate(math.exp(key)), self.data)
            at_data = np.interp(self.data.revolutions, rev, val)
            self.cache[key] = (at_data, rev, val)
            rms = float(np.sqrt(np.mean((at_data - self.data.values) ** 2)))
            self.best_rms = min(self.best_rms, rms)
        return self.cache[key]

    def best_multiplier(self, model: np.ndarray) -> float:
        """Closed-form m minimising |m·model − data|² (1 when the scale is not fitted)."""
        if not self.fit_scale:
            return 1.0
        denominator = float(model @ model)
        if denominator <= 0.0:
            return 1.0
        return max(float(model @ self.data.values) / denominator, 1e-12)

    def rms_at(self, ln_k: float) -> tuple[float, float]:
        """(RMS residual in SI units, best m) at K = exp(ln_k)."""
        model = self.run(ln_k)[0]
        m = self.best_multiplier(model)
        return float(np.sqrt(np.mean((m * model - self.data.values) ** 2))), m


def _downhill(points: Mapping[float, float], step: float) -> float | None:
    """The next ln K of a bracketing search: ``step`` beyond the point of least RMS when it is
    an end of ``points`` (ln K → RMS); None once the least RMS is bracketed."""
    best = min(points, key=points.__getitem__)
    if best == min(points):
        return best - step
    if best == max(points):
        return best + step
    return None


def _scan(objective: _Objective, ln_k0: float, max_steps: int) -> tuple[float, list[float]]:
    """Coarse scan one decade apart until the smallest RMS is bracketed; best ln K and log."""
    lo, hi = math.log(_K_MIN), math.log(_K_MAX)
    start = min(max(ln_k0, lo + _LN10), hi - _LN10)
    points = {x: objective.rms_at(x)[0] for x in (start - _LN10, start, start + _LN10)}
    for _ in range(max_steps):
        nxt = _downhill(points, _LN10)
        if nxt is None or not lo <= nxt <= hi:
            break
        points[nxt] = objective.rms_at(nxt)[0]
    best = min(points, key=points.__getitem__)
    if best in (min(points), max(points)):
        raise CalibrationError(
            f"the best fit lies at K = {math.exp(best):.3g}, the end of the scanned range "
            f"{math.exp(min(points)):.3g}–{math.exp(max(points)):.3g}: the model cannot reach "
            f"the measured {objective.data.quantity} (check the case, the units and the data)"
        )
    return best, sorted(points)


def _surrogate_minimum(objective: _Objective, points: list[float]) -> float:
    """ln K minimising the residual of a quadratic surrogate through three model runs.

    The model's values at the data are interpolated, as vectors, quadratically in ln K
    (Lagrange) through the three runs ``points``; the sum of squares of this surrogate (with
    the best torque multiplier at each ln K) is minimised on a dense grid between the outer
    points. No model run is spent; the model history is smooth in ln K even where the sum of
    squares is far from a parabola (the preload saturating at 0 for large K).
    """
    x = np.asarray(sorted(points))
    runs = np.stack([objective.run(v)[0] for v in x])
    grid = np.linspace(x[0], x[-1], 801)
    basis = np.stack(
        [
            (grid - x[(i + 1) % 3])
            * (grid - x[(i + 2) % 3])
            / ((x[i] - x[(i + 1) % 3]) * (x[i] - x[(i + 2) % 3]))
            for i in range(3)
        ],
        axis=1,
    )
    surrogate = basis @ runs  # (grid, data)
    y = objective.data.values
    if objective.fit_scale:
        norm = np.einsum("ij,ij->i", surrogate, surrogate)
        m = np.where(norm > 0.0, surrogate @ y / np.where(norm > 0.0, norm, 1.0), 1.0)
        surrogate = surrogate * np.maximum(m, 1e-12)[:, None]
    sse = np.sum((surrogate - y) ** 2, axis=1)
    return float(grid[int(np.argmin(sse))])


def _refine(objective: _Objective, best: float, evaluated: list[float], steps: int) -> float:
    """Up to ``steps`` surrogate steps from the scan; returns the best ln K evaluated."""
    tried = list(evaluated)
    for _ in range(steps):
        nearest = sorted(tried, key=lambda v: abs(v - best))[:3]
        candidate = _surrogate_minimum(objective, nearest)
        if any(abs(candidate - v) < 0.01 for v in tried):
            break
        tried.append(candidate)
        if objective.rms_at(candidate)[0] < objective.rms_at(best)[0]:
            best = candidate
        else:
            break
    return best


def fit_wear_coefficient(
    simulate: Callable[[float], WearHistory],
    data: MeasuredHistory,
    *,
    initial_coefficient: float = 1.0e-4,
    torque_scale: float = 1.0,
    fit_torque_scale: bool = False,
    max_evaluations: int = 40,
    diff_step: float = _DIFF_STEP,
    scan_steps: int = _SCAN_STEPS,
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
    from ballscrew.calibration.multi import fit_parameters  # the general fitter (uses this module)

    if fit_torque_scale and data.quantity != "friction_torque":
        raise InputError(
            "--fit-torque-scale", True, f"only with friction_torque data (got {data.quantity})"
        )
    if not (math.isfinite(initial_coefficient) and _K_MIN < initial_coefficient < _K_MAX):
        raise InputError("wear.coefficient", initial_coefficient, f"a number in ({_K_MIN}, 1)")
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


def _check_determined(source: str, name: str, value: float, error: float) -> None:
    """CalibrationError when a fitted parameter's standard error is not below its value."""
    if not (math.isfinite(error) and error < abs(value)):
        raise CalibrationError(
            f"{source}: the data do not determine the {name}: the fit gives {value:.3g} ± "
            f"{error:.2g} (a standard error as large as the value; check the data and units)"
        )


def solve_least_squares(
    residuals: Callable[[np.ndarray], np.ndarray],
    x0: Any,
    jacobian: Callable[[np.ndarray], np.ndarray],
    bounds: tuple[Any, Any],
    max_evaluations: int,
    label: str,
    best_rms: Callable[[], float],
) -> Any:
    """Trust-region reflective least squares with the calibration's tolerances; a
    ConvergenceError (with the best RMS so far) when it does not converge."""
    x0 = np.asarray(x0, dtype=float)
    try:
        solution = least_squares(
            residuals,
            x0,
            jac=jacobian,
            bounds=bounds,
            method="trf",
            x_scale=np.ones(x0.size),
            xtol=1e-4,
            ftol=1e-6,
            gtol=1e-8,
            max_nfev=max_evaluations,
        )
    except ConvergenceError as exc:
        raise ConvergenceError(label, exc.iterations, best_rms(), 0.0) from None
    if solution.status <= 0:
        raise ConvergenceError(label, int(solution.nfev), best_rms(), 0.0)
    return solution


def _covariance(
    jac: np.ndarray, residuals: np.ndarray, n: int, p: int, source: str, what: str
) -> np.ndarray:
    """RSS/(n − p) · (JᵀJ)⁻¹ via the SVD of J; CalibrationError naming ``what`` (the fitted
    parameters) when J is rank-deficient."""
    _, singular, vt = np.linalg.svd(jac, full_matrices=False)
    if (
        singular.size < p
        or not np.all(np.isfinite(singular))
        or singular[-1] <= (1e-10 * max(singular[0], 1e-300))
    ):
        raise CalibrationError(
            f"{source}: the measured history does not determine "
            + what
            + " (the model is insensitive to them over the measured revolutions; singular values "
            + ", ".join(f"{s:.2e}" for s in singular)
            + ")"
        )
    variance = float(residuals @ residuals) / (n - p)
    return variance * (vt.T / singular**2) @ vt
