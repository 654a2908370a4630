"""Least-squares calibration of any subset of the wear model's parameters, with held-out data.

Parameters (:data:`FIT_PARAMETERS`): the wear coefficient K, the drag-torque scale m (torque
data only), the film supply factor φ (``wear.film_factor``) and the running-in depth h_r
(``wear.running_in.depth``). K, φ and h_r are fitted as logarithms (positive, spanning decades);
m multiplies the model torque, which does not feed back into the wear, so its Jacobian column
is exact and no model run is spent on it. The residuals on the fitted points (revolutions ≤
``fit_until``) are

    r_i(θ) = (m · y_model(N_i; K, φ, h_r) − y_i) / s,

minimised with :func:`scipy.optimize.least_squares` (trust-region reflective) from a start that
a decade scan in K brackets (:func:`_start`). The columns of K, φ and h_r are forward differences
of 1 % (backward at an upper bound) at the first point and Broyden's (1965) rank-one secant
updates G += (Δy − G Δθ) Δθᵀ/|Δθ|² at later ones (one model run per iteration instead of one per
parameter); at the end the differences are taken afresh, and least squares restarts from there
while a Gauss–Newton step with them would still move a parameter by more than 0.1 σ (σ at least
10⁻⁶ max(|θ|, 1); a CalibrationWarning after three runs) (Broyden, *Math. Comp.* 19, 1965,
577–593). :func:`ballscrew.calibration.fit_wear_coefficient` is this
fitter on K (and m).

Uncertainty and prediction bands (Gauss–Newton / delta method; Seber & Wild 1989, §2.1, §5.1):

    cov(θ) = s_r² (JᵀJ)⁻¹,   s_r² = RSS/(n − p),
    σ_pred(N)² = g(N)ᵀ cov(θ) g(N) + s_r²,   g(N) = ∂ŷ(N)/∂θ,

g from the same difference runs as J on the model's own revolutions; the 95 % prediction band
is ŷ ± 1.96 σ_pred. The held-out error ``prediction_rmse`` is the RMS of the model minus the
measurements after ``fit_until``, not seen by the fit. Residual diagnostics:
:mod:`ballscrew.calibration.diagnostics`.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from ballscrew.calibration.diagnostics import residual_diagnostics
from ballscrew.calibration.measured import MeasuredHistory, check_values, measured_history
from ballscrew.calibration.result import CalibrationError, CalibrationResult, WearHistory
from ballscrew.calibration.search import (
    DIFF_STEP,
    LN10,
    SCAN_STEPS,
    KLine,
    ModelRuns,
    check_determined,
    covariance,
    line_minimum,
    refine,
    scan,
    solve_least_squares,
)
from ballscrew.errors import InputError

__all__ = ["FIT_PARAMETERS", "CalibrationWarning", "FitParameter", "fit_parameters"]


_K = "wear_coefficient"


class CalibrationWarning(UserWarning):
    """The fit is formally fine but its residuals or its use deserve a look."""


@dataclass(frozen=True)
class FitParameter:
    """A parameter the calibration can fit."""

    key: str | None
    """Dotted case key the value goes to (None: the torque multiplier, applied after the run)."""
    lower: float
    upper: float
    description: str
    short: str = ""
    """Its name in a message about its own value (default: the description)."""


FIT_PARAMETERS: dict[str, FitParameter] = {
    "wear_coefficient": FitParameter(
        "wear.coefficient", 1.0e-16, 1.0, "wear coefficient K", short="K"
    ),
    "torque_scale": FitParameter(
        None, 0.0, math.inf, "drag-torque scale on K_T", short="torque scale"
    ),
    "film_factor": FitParameter("wear.film_factor", 1.0e-3, 1.0, "film supply factor φ"),
    "running_in_depth": FitParameter(
        "wear.running_in.depth", 1.0e-9, 1.0e-4, "running-in depth h_r [m]"
    ),
}


def _split(data: MeasuredHistory, fit_until: float | None) -> tuple[MeasuredHistory, int]:
    if fit_until is None:
        return data, len(data)
    n = int(np.searchsorted(data.revolutions, fit_until, side="right"))
    if not (math.isfinite(fit_until) and 0 < n < len(data)):
        raise InputError(
            "--fit-until",
            fit_until,
            f"revolutions between the first and the last measured point "
            f"({data.revolutions[0]:g}–{data.revolutions[-1]:g}), leaving points to predict",
        )
    part = measured_history(
        data.revolutions[:n], data.values[:n], data.quantity, data.source, min_points=1
    )
    return part, n


_RESTARTS = 3
"""Most least-squares runs: a run whose end a Gauss–Newton step of the difference Jacobian
would still move by more than :data:`_MOVE` standard errors is restarted from there."""
_MOVE = 0.1
_SIGMA_FLOOR = 1e-6
"""Least standard error counted by :func:`_converged`, relative to max(|θ|, 1): on exact data
σ → 0 and no step would be small enough."""


class _SecantJacobian:
    """Jacobian of the scaled residuals: forward differences of the model columns at the first
    point, Broyden's (1965) rank-one secant update at every later one (one model run per
    iteration instead of one per parameter), the torque-multiplier column exact."""

    def __init__(
        self,
        model_at: Callable[[np.ndarray], np.ndarray],
        diff_step: float,
        upper: Sequence[float],
        fit_scale: bool,
        scale: float,
    ) -> None:
        self.model_at = model_at
        self.diff_step = diff_step
        self.upper = list(upper)
        self.fit_scale = fit_scale
        self.scale = scale
        self.x: np.ndarray | None = None
        self.values = np.zeros(0)
        self.columns = np.zeros((0, 0))

    def steps(self, x: np.ndarray) -> list[float]:
        """Difference steps in each model parameter (backward at an upper bound)."""
        h = self.diff_step
        return [-h if x[i] + h > top else h for i, top in enumerate(self.upper)]

    def difference(self, x: np.ndarray) -> np.ndarray:
        """The Jacobian at ``x`` by forward differences (p model runs, cached)."""
        x = np.array(x, dtype=float)
        here = self.model_at(x)
        columns = []
        for i, h in enumerate(self.steps(x)):
            shifted = x.copy()
            shifted[i] += h
            columns.append((self.model_at(shifted) - here) / h)
        self.x, self.values = x, here
        self.columns = np.column_stack(columns) if columns else np.zeros((here.size, 0))
        return self._full(x)

    def __call__(self, x: np.ndarray) -> np.ndarray:
        if self.x is None:
            return self.difference(x)
        x = np.array(x, dtype=float)
        here = self.model_at(x)
        dx = (x - self.x)[: len(self.upper)]
        norm = float(dx @ dx)
        if norm > 0.0:  # G += (Δy − G Δx) Δxᵀ / |Δx|²
            self.columns = self.columns + np.outer(
                here - self.values - self.columns @ dx, dx / norm
            )
        self.x, self.values = x, here
        return self._full(x)

    def _full(self, x: np.ndarray) -> np.ndarray:
        m = float(x[-1]) if self.fit_scale else 1.0
        jac = m * self.columns / self.scale
        return np.column_stack([jac, self.values / self.scale]) if self.fit_scale else jac


def _converged(
    jac: np.ndarray,
    residuals: np.ndarray,
    x: np.ndarray,
    bounds: tuple[Sequence[float], Sequence[float]],
    n: int,
) -> bool:
    """Would a Gauss–Newton step of ``jac`` (kept within the bounds) move every parameter by
    less than :data:`_MOVE` of its standard error (at least :data:`_SIGMA_FLOOR` max(|θ|, 1))?
    (True when ``jac`` is rank-deficient: the covariance reports that.)"""
    step, *_, singular = np.linalg.lstsq(jac, -residuals, rcond=None)
    if singular.size < x.size or singular[-1] <= 1e-10 * max(singular[0], 1e-300):
        return True
    moved = np.clip(x + step, bounds[0], bounds[1]) - x
    variance = float(residuals @ residuals) / max(n - x.size, 1)
    sigma = np.sqrt(variance * np.diag(np.linalg.pinv(jac.T @ jac)))
    sigma = np.maximum(sigma, _SIGMA_FLOOR * np.maximum(np.abs(x), 1.0))
    return bool(np.all(np.abs(moved) <= _MOVE * sigma))


def fit_parameters(
    simulate: Callable[[Mapping[str, float]], WearHistory],
    data: MeasuredHistory,
    fit: Sequence[str],
    start: Mapping[str, float],
    *,
    torque_scale: float = 1.0,
    fit_until: float | None = None,
    max_evaluations: int = 200,
    diff_step: float = DIFF_STEP,
    scan_steps: int = SCAN_STEPS,
    refine_steps: int = 6,
    label: str = "calibration (least squares)",
) -> CalibrationResult:
    """Fit the parameters ``fit`` (names of :data:`FIT_PARAMETERS`) to ``data``.

    Args:
        simulate: the wear model, {name: value} of the model parameters → history.
        data: the measured history.
        fit: the parameters to fit; ``torque_scale`` needs friction-torque data.
        start: the starting value of every model parameter (``wear_coefficient`` and any other
            the model takes); those not fitted stay at it.
        torque_scale: the torque scale the model torques were computed with.
        fit_until: fit the points up to these revolutions, predict the rest (None: fit all).
        max_evaluations: most model runs; more raises ConvergenceError.
        diff_step: forward-difference step in the logarithm of each model parameter.
        scan_steps: most decades the scan in K may extend beyond its first three points.
        refine_steps: most surrogate steps in K after the scan (one model run each).
        label: names the solver in a ConvergenceError.
    """
    names = _check_names(fit, data)
    check_values(data.source, data.quantity, np.asarray(data.values, dtype=np.float64))
    fitted_data, n_fit = _split(data, fit_until)
    p = len(names)
    if n_fit <= p:
        raise CalibrationError(
            f"{data.source}: {n_fit} points cannot determine {p} parameter(s); give at "
            f"least {p + 1}"
        )
    model_names = [n for n in names if n != "torque_scale"]
    fit_scale = "torque_scale" in names
    base = {k: float(v) for k, v in start.items()}
    for name in model_names:
        if name not in base:
            raise InputError("fit", name, f"a parameter of the model ({', '.join(base)})")
    model = ModelRuns(simulate, fitted_data, max_evaluations, label)
    y = fitted_data.values
    scale = float(np.max(np.abs(y))) or 1.0
    lower = [math.log(FIT_PARAMETERS[n].lower) for n in model_names]
    upper = [math.log(FIT_PARAMETERS[n].upper) for n in model_names]
    base, scanned, k_bracket = _start(model, base, model_names, fit_scale, scan_steps, refine_steps)
    x0 = [math.log(base[n]) for n in model_names]
    if k_bracket is not None:
        i = model_names.index("wear_coefficient")
        lower[i], upper[i] = k_bracket

    def values_of(x: np.ndarray) -> dict[str, float]:
        return {**base, **{n: math.exp(v) for n, v in zip(model_names, x, strict=False)}}

    def multiplier(x: np.ndarray) -> float:
        return float(x[-1]) if fit_scale else 1.0

    def residuals(x: np.ndarray) -> np.ndarray:
        return (multiplier(x) * model.at(values_of(x), fitted_data.revolutions) - y) / scale

    jacobian = _SecantJacobian(
        lambda x: model.at(values_of(x), fitted_data.revolutions),
        diff_step,
        upper,
        fit_scale,
        scale,
    )
    if fit_scale:
        here = model.at(values_of(np.array(x0)), fitted_data.revolutions)
        m0 = max(float(here @ y) / float(here @ here), 1e-12) if here @ here > 0 else 1.0
        x0, lower, upper = [*x0, m0], [*lower, 0.0], [*upper, np.inf]
    x = np.array([min(max(v, lo), hi) for v, lo, hi in zip(x0, lower, upper, strict=True)])
    message = ""
    for _ in range(_RESTARTS):
        solution = solve_least_squares(
            residuals, x, jacobian, (lower, upper), max_evaluations, label, lambda: model.best_rms
        )
        x, message = solution.x, str(solution.message)
        if _converged(jacobian.difference(x), residuals(x), x, (lower, upper), n_fit):
            break
    else:
        warnings.warn(
            f"{data.source}: after {_RESTARTS} least-squares runs a Gauss–Newton step would "
            f"still move the parameters by more than {_MOVE:g} standard error: the fit may "
            "not be at the minimum (check the data, or fit fewer parameters)",
            CalibrationWarning,
            stacklevel=2,
        )
    if "wear_coefficient" in model_names:
        i = model_names.index("wear_coefficient")
        if min(abs(x[i] - lower[i]), abs(x[i] - upper[i])) < 1e-9:
            raise CalibrationError(
                f"least squares stopped at the edge of the bracket K = "
                f"{math.exp(lower[i]):.3g}–{math.exp(upper[i]):.3g} found by the scan (the data "
                "do not constrain K)"
            )
    r = residuals(x)
    cov = _covariance(jacobian.difference(x), r, n_fit, names, data.source)
    values, errors = {}, {}
    for i, name in enumerate(names):
        if name == "torque_scale":
            values[name], errors[name] = torque_scale * x[i], torque_scale * math.sqrt(cov[i, i])
        else:
            values[name] = math.exp(x[i])
            errors[name] = values[name] * math.sqrt(cov[i, i])
        spec = FIT_PARAMETERS[name]
        check_determined(data.source, spec.short or spec.description, values[name], errors[name])
    m = multiplier(x)
    final = values_of(x)
    model_rev, model_val = model.run(final)
    fitted_all = m * np.interp(data.revolutions, model_rev, model_val)
    residual_fit = fitted_all[:n_fit] - y
    rss = float(residual_fit @ residual_fit)
    noise = math.sqrt(rss / (n_fit - p))
    gradient = []
    for i, h in enumerate(jacobian.steps(x)):  # the runs of the difference Jacobian
        shifted = np.array(x, dtype=float)
        shifted[i] += h
        gradient.append(m * (model.at(values_of(shifted), model_rev) - model_val) / h)
    if fit_scale:
        gradient.append(model_val)
    g = np.column_stack(gradient)
    sigma = np.sqrt(np.einsum("ij,jk,ik->i", g, cov, g) + noise**2)
    held = fitted_all[n_fit:] - data.values[n_fit:]
    diagnostics = residual_diagnostics(residual_fit)
    k = values.get("wear_coefficient", base.get("wear_coefficient", math.nan))
    curve = m * model_val
    for arr in (fitted_all, curve, sigma):
        arr.setflags(write=False)
    return CalibrationResult(
        quantity=data.quantity,
        unit=data.unit,
        source=data.source,
        wear_coefficient=k,
        standard_error=errors.get("wear_coefficient", 0.0),
        torque_scale=values.get("torque_scale", torque_scale),
        torque_scale_error=errors.get("torque_scale"),
        correlation=_correlation(cov, names),
        rms_residual=math.sqrt(rss / n_fit),
        n_points=n_fit,
        parameters=p,
        evaluations=model.evaluations,
        initial_coefficient=float(start.get("wear_coefficient", math.nan)),
        revolutions=data.revolutions,
        measured=data.values,
        fitted=fitted_all,
        model_revolutions=model_rev,
        model_values=curve,
        scan=scanned,
        message=message,
        values=values,
        errors=errors,
        n_fit=n_fit,
        fit_until=fit_until,
        prediction_rmse=float(np.sqrt(np.mean(held**2))) if held.size else None,
        prediction_sigma=sigma,
        diagnostics=diagnostics.as_dict(),
    )


def _grid(name: str, value: float, points: int = 3) -> list[float]:
    """Half-decade trial values of ``name`` around ``value`` (towards the interior of its
    bounds), the start first."""
    spec = FIT_PARAMETERS[name]
    step = math.sqrt(10.0)
    trials = [value * step**k for k in range(-(points // 2), points - points // 2)]
    if value * step > spec.upper:  # at the upper bound: go down only
        trials = [value / step**k for k in range(points)]
    inside = [v for v in trials if spec.lower <= v <= spec.upper]
    return sorted(inside, key=lambda v: abs(math.log(v / value)))


def _start(
    model: ModelRuns,
    base: dict[str, float],
    names: list[str],
    fit_scale: bool,
    scan_steps: int,
    refine_steps: int,
) -> tuple[dict[str, float], tuple[tuple[float, float], ...], tuple[float, float] | None]:
    """Starting values: K from a decade scan and surrogate steps (:func:`.search.scan`,
    :func:`.search.refine`); then for each other parameter in turn the best of half-decade
    trial values, K re-fitted at each by :func:`.search.line_minimum`; the decade scan; and the
    bracket of ln K (a decade either side of its best). Every run is one of ``model``'s."""
    fit_k = "wear_coefficient" in names
    first = KLine(model, base, fit_scale)
    ln_k = math.log(base["wear_coefficient"])
    scanned_rms: tuple[tuple[float, float], ...] = ()
    if fit_k:
        best, scanned = scan(first, ln_k, scan_steps)
        ln_k = refine(first, best, scanned, refine_steps)
        scanned_rms = tuple((math.exp(v), first.rms_at(v)[0]) for v in scanned)
    current, rms = {**base, "wear_coefficient": math.exp(ln_k)}, first.rms_at(ln_k)[0]
    for name in (n for n in names if n != "wear_coefficient"):
        for trial in _grid(name, current[name])[1:]:
            values = {**current, name: trial}
            try:
                if fit_k:
                    ln_t, rms_t = line_minimum(
                        KLine(model, values, fit_scale), math.log(current[_K])
                    )
                else:
                    ln_t, rms_t = ln_k, KLine(model, values, fit_scale).rms_at(ln_k)[0]
            except CalibrationError:  # K cannot reach the data at this trial value
                continue
            if rms_t < rms:
                current, rms = {**values, _K: math.exp(ln_t)}, rms_t
    bracket = None
    if fit_k:
        ln_k = math.log(current[_K])
        bracket = (ln_k - LN10, ln_k + LN10)
    return current, scanned_rms, bracket


def _check_names(fit: Sequence[str], data: MeasuredHistory) -> list[str]:
    names = list(dict.fromkeys(fit))
    allowed = ", ".join(FIT_PARAMETERS)
    if not names:
        raise InputError("--fit", "", f"one or more of {allowed}")
    for name in names:
        if name not in FIT_PARAMETERS:
            raise InputError("--fit", name, f"one or more of {allowed}")
    if "torque_scale" in names and data.quantity != "friction_torque":
        raise InputError(
            "--fit", "torque_scale", f"only with friction_torque data (got {data.quantity})"
        )
    # the torque multiplier is the last column
    return [n for n in names if n != "torque_scale"] + (
        ["torque_scale"] if "torque_scale" in names else []
    )


def _covariance(
    jac: np.ndarray, residuals: np.ndarray, n: int, names: list[str], source: str
) -> np.ndarray:
    """RSS/(n − p) · (JᵀJ)⁻¹; CalibrationError naming the parameters when J is rank-deficient."""
    what = " and ".join(FIT_PARAMETERS[n].description for n in names)
    return covariance(jac, residuals, n, len(names), source, what + " together")


def _correlation(cov: np.ndarray, names: list[str]) -> float | None:
    if "wear_coefficient" not in names or "torque_scale" not in names:
        return None
    i, j = names.index("wear_coefficient"), names.index("torque_scale")
    return float(cov[i, j] / math.sqrt(cov[i, i] * cov[j, j]))
