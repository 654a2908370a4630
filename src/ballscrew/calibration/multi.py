"""Least-squares calibration of any subset of the wear model's parameters, with held-out data.

Parameters (:data:`FIT_PARAMETERS`): the wear coefficient K, the drag-torque scale m (torque
data only), the film supply factor φ (``wear.film_factor``) and the running-in depth h_r
(``wear.running_in.depth``). K, φ and h_r are fitted as logarithms (positive, spanning decades);
m multiplies the model torque, which does not feed back into the wear, so its Jacobian column
is exact and no model run is spent on it. The residuals on the fitted points (revolutions ≤
``fit_until``) are

    r_i(θ) = (m · y_model(N_i; K, φ, h_r) − y_i) / s,

minimised with :func:`scipy.optimize.least_squares` (trust-region reflective) from a start that
a decade scan in K brackets (as :func:`ballscrew.calibration.fit_wear_coefficient`); the
columns of K, φ and h_r are forward differences of 1 % (backward at an upper bound).

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
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np
from scipy.optimize import minimize_scalar

from ballscrew.calibration.diagnostics import residual_diagnostics
from ballscrew.calibration.fit import (
    _LN10,
    CalibrationError,
    CalibrationResult,
    WearHistory,
    _check_determined,
    _Objective,
    _refine,
    _scan,
    covering_history,
    solve_least_squares,
)
from ballscrew.calibration.fit import _covariance as _fit_covariance
from ballscrew.calibration.measured import MeasuredHistory, check_values, measured_history
from ballscrew.errors import ConvergenceError, InputError

__all__ = ["FIT_PARAMETERS", "CalibrationWarning", "FitParameter", "fit_parameters"]


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


FIT_PARAMETERS: dict[str, FitParameter] = {
    "wear_coefficient": FitParameter("wear.coefficient", 1.0e-16, 1.0, "wear coefficient K"),
    "torque_scale": FitParameter(None, 0.0, math.inf, "drag-torque scale on K_T"),
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


class _Model:
    """Model runs cached by the values of the model parameters."""

    def __init__(
        self,
        simulate: Callable[[Mapping[str, float]], WearHistory],
        data: MeasuredHistory,
        max_evaluations: int,
    ) -> None:
        self.simulate = simulate
        self.data = data
        self.max_evaluations = max_evaluations
        self.cache: dict[tuple[tuple[str, float], ...], tuple[np.ndarray, np.ndarray]] = {}

    def run(self, values: Mapping[str, float]) -> tuple[np.ndarray, np.ndarray]:
        """(model revolutions, model values) at ``values``."""
        key = tuple(sorted((k, float(v)) for k, v in values.items()))
        if key not in self.cache:
            if len(self.cache) >= self.max_evaluations:
                raise ConvergenceError("calibration (least squares)", len(self.cache), math.nan, 0)
            self.cache[key] = covering_history(self.simulate(dict(key)), self.data)
        return self.cache[key]

    def at(self, values: Mapping[str, float], revolutions: np.ndarray) -> np.ndarray:
        rev, val = self.run(values)
        return np.interp(revolutions, rev, val)


def fit_parameters(
    simulate: Callable[[Mapping[str, float]], WearHistory],
    data: MeasuredHistory,
    fit: Sequence[str],
    start: Mapping[str, float],
    *,
    torque_scale: float = 1.0,
    fit_until: float | None = None,
    max_evaluations: int = 200,
    diff_step: float = 1.0e-2,
    scan_steps: int = 6,
    refine_steps: int = 6,
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
        max_evaluations: most model runs.
    """
    names = _check_names(fit, data)
    check_values(data.source, data.quantity, np.asarray(data.values, dtype=np.float64))
    fitted_data, n_fit = _split(data, fit_until)
    p = len(names)
    if n_fit <= p:
        raise CalibrationError(
            f"{data.source}: {n_fit} fitted points cannot determine {p} parameter(s); give at "
            f"least {p + 1}"
        )
    model_names = [n for n in names if n != "torque_scale"]
    fit_scale = "torque_scale" in names
    base = {k: float(v) for k, v in start.items()}
    for name in model_names:
        if name not in base:
            raise InputError("fit", name, f"a parameter of the model ({', '.join(base)})")
    model = _Model(simulate, fitted_data, max_evaluations)
    y = fitted_data.values
    scale = float(np.max(np.abs(y))) or 1.0
    lower = [math.log(FIT_PARAMETERS[n].lower) for n in model_names]
    upper = [math.log(FIT_PARAMETERS[n].upper) for n in model_names]
    x0 = [math.log(base[n]) for n in model_names]
    base, scan, k_bracket = _start(
        model, fitted_data, base, model_names, fit_scale, scan_steps, refine_steps
    )
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

    def steps(x: np.ndarray) -> list[float]:
        return [
            -diff_step if x[i] + diff_step > upper[i] else diff_step
            for i in range(len(model_names))
        ]

    def jacobian(x: np.ndarray) -> np.ndarray:
        here = model.at(values_of(x), fitted_data.revolutions)
        columns = []
        for i, h in enumerate(steps(x)):
            shifted = np.array(x, dtype=float)
            shifted[i] += h
            moved = model.at(values_of(shifted), fitted_data.revolutions)
            columns.append(multiplier(x) * (moved - here) / h / scale)
        if fit_scale:
            columns.append(here / scale)
        return np.column_stack(columns)

    if fit_scale:
        here = model.at(values_of(np.array(x0)), fitted_data.revolutions)
        m0 = max(float(here @ y) / float(here @ here), 1e-12) if here @ here > 0 else 1.0
        x0, lower, upper = [*x0, m0], [*lower, 0.0], [*upper, np.inf]
    x0 = [min(max(v, lo), hi) for v, lo, hi in zip(x0, lower, upper, strict=True)]
    solution = solve_least_squares(
        residuals,
        x0,
        jacobian,
        (lower, upper),
        max_evaluations,
        "calibration (least squares)",
        lambda: math.nan,
    )
    x = solution.x
    if "wear_coefficient" in model_names:
        i = model_names.index("wear_coefficient")
        if min(abs(x[i] - lower[i]), abs(x[i] - upper[i])) < 1e-9:
            raise CalibrationError(
                f"least squares stopped at the edge of the bracket K = "
                f"{math.exp(lower[i]):.3g}–{math.exp(upper[i]):.3g} found by the scan (the data "
                "do not constrain K)"
            )
    r = residuals(x)
    jac = jacobian(x)
    cov = _covariance(jac, r, n_fit, names, data.source)
    values, errors = {}, {}
    for i, name in enumerate(names):
        if name == "torque_scale":
            values[name], errors[name] = torque_scale * x[i], torque_scale * math.sqrt(cov[i, i])
        else:
            values[name] = math.exp(x[i])
            errors[name] = values[name] * math.sqrt(cov[i, i])
        _check_determined(data.source, FIT_PARAMETERS[name].description, values[name], errors[name])
    m = multiplier(x)
    final = values_of(x)
    model_rev, model_val = model.run(final)
    fitted_all = m * np.interp(data.revolutions, model_rev, model_val)
    residual_fit = fitted_all[:n_fit] - y
    rss = float(residual_fit @ residual_fit)
    noise = math.sqrt(rss / (n_fit - p))
    gradient = []
    for i, h in enumerate(steps(x)):
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
        evaluations=len(model.cache),
        initial_coefficient=float(start.get("wear_coefficient", math.nan)),
        revolutions=data.revolutions,
        measured=data.values,
        fitted=fitted_all,
        model_revolutions=model_rev,
        model_values=curve,
        scan=scan,
        message=str(solution.message),
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
    model: _Model,
    data: MeasuredHistory,
    base: dict[str, float],
    names: list[str],
    fit_scale: bool,
    scan_steps: int,
    refine_steps: int,
) -> tuple[dict[str, float], tuple[tuple[float, float], ...], tuple[float, float] | None]:
    """Starting values: for each parameter other than K in turn, the best of half-decade trial
    values, K re-fitted at each (first a decade scan and surrogate steps, then, with other
    parameters, a bounded Brent search in ln K to 0.05, at most 8 runs); the decade scan; and
    the bracket of ln K (a decade either side of its best)."""
    fit_k = "wear_coefficient" in names

    def best_k(
        values: dict[str, float], around: float | None = None
    ) -> tuple[float, float, tuple[tuple[float, float], ...]]:
        """Best K at ``values`` (m closed-form): from the decade scan, or, ``around`` a known
        ln K, by a bounded Brent search a decade either side; its RMS; the scan."""
        objective = _Objective(
            lambda k: _History(*model.run({**values, "wear_coefficient": k}), data.quantity),
            data,
            fit_scale,
            model.max_evaluations,
        )
        if not fit_k:
            ln_k = math.log(values["wear_coefficient"])
            return values["wear_coefficient"], objective.rms_at(ln_k)[0], ()
        scan: tuple[tuple[float, float], ...] = ()
        if around is None:
            ln_k, scanned = _scan(objective, math.log(values["wear_coefficient"]), scan_steps)
            best = _refine(objective, ln_k, scanned, refine_steps)
            scan = tuple((math.exp(v), objective.rms_at(v)[0]) for v in scanned)
            if len(names) == 1:
                return math.exp(best), objective.rms_at(best)[0], scan
        else:
            ln_k = best = around
        line = minimize_scalar(  # other parameters make the valley in ln K sharper
            lambda v: objective.rms_at(v)[0],
            bounds=(ln_k - _LN10, ln_k + _LN10),
            method="bounded",
            options={"xatol": 0.05, "maxiter": 8},
        )
        if line.fun < objective.rms_at(best)[0]:
            best = float(line.x)
        return math.exp(best), objective.rms_at(best)[0], scan

    k, rms, scan = best_k(base)
    current = {**base, "wear_coefficient": k}
    for name in (n for n in names if n != "wear_coefficient"):
        for trial in _grid(name, current[name])[1:]:
            try:
                k_t, rms_t, _ = best_k(
                    {**current, name: trial}, math.log(current["wear_coefficient"])
                )
            except CalibrationError:  # K cannot reach the data at this trial value
                continue
            if rms_t < rms:
                current, rms = {**current, name: trial, "wear_coefficient": k_t}, rms_t
    bracket = None
    if fit_k:
        ln_k = math.log(current["wear_coefficient"])
        bracket = (ln_k - _LN10, ln_k + _LN10)
    return current, scan, bracket


@dataclass(frozen=True)
class _History:
    """A model history reduced to the measured quantity (for the scan in K)."""

    revolutions: np.ndarray
    values: np.ndarray
    quantity: str

    def __getattr__(self, name: str) -> np.ndarray:
        if name in ("friction_torque", "preload", "max_wear_depth"):
            return vars(self)["values"]
        raise AttributeError(name)


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
    return _fit_covariance(jac, residuals, n, len(names), source, what + " together")


def _correlation(cov: np.ndarray, names: list[str]) -> float | None:
    if "wear_coefficient" not in names or "torque_scale" not in names:
        return None
    i, j = names.index("wear_coefficient"), names.index("torque_scale")
    return float(cov[i, j] / math.sqrt(cov[i, i] * cov[j, j]))
