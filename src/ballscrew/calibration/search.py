"""The steps the calibration fitters share: the one memo of model runs, the scan and surrogate
steps in ln K, and the least-squares solve with its covariance.

:class:`ModelRuns` is the only place that runs the wear model: each distinct set of parameter
values is simulated once, counted, and every later request is answered from the memo.
:class:`KLine` views those runs as a function of ln K at fixed other parameters (the torque
multiplier m in closed form), for the decade scan (:func:`scan`), the quadratic-surrogate steps
(:func:`refine`, :func:`line_minimum`) and the start of
:func:`ballscrew.calibration.multi.fit_parameters`. Method and sources:
:mod:`ballscrew.calibration.fit` and :mod:`ballscrew.calibration.multi`.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np
from scipy.optimize import least_squares

from ballscrew.calibration.measured import MeasuredHistory
from ballscrew.calibration.result import CalibrationError, WearHistory, covering_history
from ballscrew.errors import ConvergenceError

__all__ = [
    "DIFF_STEP",
    "K_MAX",
    "K_MIN",
    "LN10",
    "SCAN_STEPS",
    "KLine",
    "ModelRuns",
    "check_determined",
    "covariance",
    "downhill",
    "line_minimum",
    "linear_fit",
    "refine",
    "scan",
    "solve_least_squares",
    "surrogate_minimum",
]

LN10 = math.log(10.0)
K_MIN, K_MAX = 1.0e-16, 1.0  # K is a probability per asperity encounter
DIFF_STEP = 1.0e-2
"""Default forward-difference step in the logarithm of a parameter, for the Jacobian."""
SCAN_STEPS = 6
"""Default for the most decades the scan in K may extend beyond its first three points."""
_K = "wear_coefficient"


class ModelRuns:
    """The wear model's runs, memoised by the values of the model parameters and counted."""

    def __init__(
        self,
        simulate: Callable[[Mapping[str, float]], WearHistory],
        data: MeasuredHistory,
        max_evaluations: int,
        label: str,
    ) -> None:
        self.simulate = simulate
        self.data = data
        self.max_evaluations = max_evaluations
        self.label = label
        self.cache: dict[tuple[tuple[str, float], ...], tuple[np.ndarray, np.ndarray]] = {}
        self.best_rms = math.inf
        """Least RMS of a run minus the data so far (model unscaled) [SI]."""

    @property
    def evaluations(self) -> int:
        """Model runs so far (each distinct set of values once)."""
        return len(self.cache)

    def run(self, values: Mapping[str, float]) -> tuple[np.ndarray, np.ndarray]:
        """(model revolutions, model values) at ``values``; a ConvergenceError beyond
        ``max_evaluations`` runs."""
        key = tuple(sorted((k, float(v)) for k, v in values.items()))
        if key not in self.cache:
            if len(self.cache) >= self.max_evaluations:
                raise ConvergenceError(self.label, len(self.cache), self.best_rms, 0)
            rev, val = covering_history(self.simulate(dict(key)), self.data)
            error = np.interp(self.data.revolutions, rev, val) - self.data.values
            self.best_rms = min(self.best_rms, float(np.sqrt(np.mean(error**2))))
            self.cache[key] = rev, val
        return self.cache[key]

    def at(self, values: Mapping[str, float], revolutions: np.ndarray) -> np.ndarray:
        """The model at ``values``, interpolated linearly to ``revolutions``."""
        rev, val = self.run(values)
        return np.interp(revolutions, rev, val)


def linear_fit(
    model: np.ndarray, y: np.ndarray, fit_scale: bool, fit_offset: bool, offset: float = 0.0
) -> tuple[np.ndarray, np.ndarray]:
    """Closed-form (m, c) minimising |m·model + c − y|² along the last axis (ordinary least
    squares of a line; m = 1 and c = ``offset`` where not fitted; m ≥ 1e-12)."""
    model = np.asarray(model, dtype=float)
    ones = np.ones(model.shape[:-1])
    if fit_scale and fit_offset:
        centred = model - model.mean(axis=-1, keepdims=True)
        norm = np.einsum("...i,...i->...", centred, centred)
        ok = norm > 0.0
        m = np.where(ok, centred @ (y - y.mean()) / np.where(ok, norm, 1.0), 1.0)
        m = np.maximum(m, 1e-12)
        return m, y.mean() - m * model.mean(axis=-1)
    if fit_scale:
        norm = np.einsum("...i,...i->...", model, model)
        ok = norm > 0.0
        m = np.where(ok, model @ (y - offset) / np.where(ok, norm, 1.0), 1.0)
        return np.maximum(m, 1e-12), offset * ones
    if fit_offset:
        return ones, (y - model).mean(axis=-1)
    return ones, offset * ones


class KLine:
    """The residual of the fit along ln K, the other model parameters fixed at ``values``, the
    torque multiplier m and offset c (where fitted) in closed form (:func:`linear_fit`; its
    runs are those of ``runs``)."""

    def __init__(
        self,
        runs: ModelRuns,
        values: Mapping[str, float],
        fit_scale: bool,
        fit_offset: bool = False,
        offset: float = 0.0,
    ) -> None:
        self.runs = runs
        self.values = dict(values)
        self.fit_scale = fit_scale
        self.fit_offset = fit_offset
        self.offset = offset
        self.data = runs.data

    def at_data(self, ln_k: float) -> np.ndarray:
        """The model at the data's revolutions for K = exp(ln_k)."""
        values = {**self.values, _K: math.exp(float(ln_k))}
        return self.runs.at(values, self.data.revolutions)

    def best_linear(self, model: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(m, c) minimising |m·model + c − data|² (:func:`linear_fit`)."""
        return linear_fit(model, self.data.values, self.fit_scale, self.fit_offset, self.offset)

    def rms_at(self, ln_k: float) -> tuple[float, float]:
        """(RMS residual in SI units, best m) at K = exp(ln_k)."""
        model = self.at_data(ln_k)
        m, c = self.best_linear(model)
        return float(np.sqrt(np.mean((m * model + c - self.data.values) ** 2))), float(m)


def downhill(points: Mapping[float, float], step: float) -> float | None:
    """The next ln K of a bracketing search: ``step`` beyond the point of least RMS when it is
    an end of ``points`` (ln K → RMS); None once the least RMS is bracketed."""
    best = min(points, key=points.__getitem__)
    if best == min(points):
        return best - step
    if best == max(points):
        return best + step
    return None


def scan(line: KLine, ln_k0: float, max_steps: int) -> tuple[float, list[float]]:
    """Coarse scan one decade apart until the smallest RMS is bracketed; best ln K and log."""
    lo, hi = math.log(K_MIN), math.log(K_MAX)
    start = min(max(ln_k0, lo + LN10), hi - LN10)
    points = {x: line.rms_at(x)[0] for x in (start - LN10, start, start + LN10)}
    for _ in range(max_steps):
        nxt = downhill(points, LN10)
        if nxt is None or not lo <= nxt <= hi:
            break
        points[nxt] = line.rms_at(nxt)[0]
    best = min(points, key=points.__getitem__)
    if best in (min(points), max(points)):
        raise CalibrationError(
            f"the best fit lies at K = {math.exp(best):.3g}, the end of the scanned range "
            f"{math.exp(min(points)):.3g}–{math.exp(max(points)):.3g}: the model cannot reach "
            f"the measured {line.data.quantity} (check the case, the units and the data)"
        )
    return best, sorted(points)


def surrogate_minimum(line: KLine, points: list[float]) -> float:
    """ln K minimising the residual of a quadratic surrogate through three model runs.

    The model's values at the data are interpolated, as vectors, quadratically in ln K
    (Lagrange) through the three runs ``points``; the sum of squares of this surrogate (with
    the best torque multiplier and offset at each ln K) is minimised on a dense grid between
    the outer points. No model run is spent; the model history is smooth in ln K even where the
    sum of squares is far from a parabola (the preload saturating at 0 for large K).
    """
    x = np.asarray(sorted(points))
    runs = np.stack([line.at_data(v) for v in x])
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
    m, c = line.best_linear(surrogate)
    sse = np.sum((surrogate * m[:, None] + c[:, None] - line.data.values) ** 2, axis=1)
    return float(grid[int(np.argmin(sse))])


def refine(line: KLine, best: float, evaluated: list[float], steps: int) -> float:
    """Up to ``steps`` surrogate steps from the scan; returns the best ln K evaluated."""
    tried = list(evaluated)
    for _ in range(steps):
        nearest = sorted(tried, key=lambda v: abs(v - best))[:3]
        candidate = surrogate_minimum(line, nearest)
        if any(abs(candidate - v) < 0.01 for v in tried):
            break
        tried.append(candidate)
        if line.rms_at(candidate)[0] < line.rms_at(best)[0]:
            best = candidate
        else:
            break
    return best


def line_minimum(
    line: KLine, centre: float, step: float = 0.5, max_runs: int = 5
) -> tuple[float, float]:
    """(ln K, RMS) of the least residual in ln K near ``centre``: three runs ``step`` apart,
    extended :func:`downhill` until the least is bracketed, then quadratic-surrogate steps
    (:func:`surrogate_minimum`) to 0.02; at most ``max_runs`` runs after the first three."""
    rms = {x: line.rms_at(x)[0] for x in (centre - step, centre, centre + step)}
    for _ in range(max_runs):
        nxt = downhill(rms, step)
        if nxt is None:
            best = min(rms, key=rms.__getitem__)
            nearest = sorted(rms, key=lambda v: abs(v - best))[:3]
            nxt = surrogate_minimum(line, nearest)
            if any(abs(nxt - v) < 0.02 for v in rms):
                break
        if not math.log(K_MIN) <= nxt <= math.log(K_MAX):
            raise CalibrationError(f"the best K lies beyond {math.exp(nxt):.3g}")
        rms[nxt] = line.rms_at(nxt)[0]
    best = min(rms, key=rms.__getitem__)
    return best, rms[best]


def check_determined(source: str, name: str, value: float, error: float) -> None:
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


def covariance(
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
