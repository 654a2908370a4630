"""Least-squares calibration of any subset of the wear model's parameters, with held-out data.

Parameters (:data:`FIT_PARAMETERS`): the wear coefficient K, the drag-torque scale m (torque
data only), the film supply factor φ (``wear.film_factor``), the running-in depth h_r
(``wear.running_in.depth``) and the preload F_p (``operating.preload``; with m it is only as good
as the K assumed, :func:`warn_scale_and_preload`). K, φ, h_r and F_p are fitted as logarithms
(positive, spanning decades); m multiplies the model torque, which does not feed back into the
wear, so its Jacobian column is exact and no model run is spent on it. The residuals on the
fitted points (revolutions ≤ ``fit_until``) are

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
    linear_fit,
    refine,
    scan,
    solve_least_squares,
)
from ballscrew.errors import InputError
from ballscrew.units import split_list

__all__ = [
    "CORRELATION_LIMIT",
    "FIT_PARAMETERS",
    "LINEAR",
    "PLAUSIBLE_TORQUE_SCALE",
    "CalibrationWarning",
    "FitParameter",
    "HistoryFit",
    "check_names",
    "correlations",
    "fit_parameters",
    "solve",
    "start_values",
    "warn_correlated",
    "warn_implausible_scale",
    "warn_scale_and_preload",
]


_K = "wear_coefficient"


class CalibrationWarning(UserWarning):
    """The fit is formally fine but its residuals or its use deserve a look."""


@dataclass(frozen=True)
class FitParameter:
    """A parameter the calibration can fit."""

    key: str
    """Dotted case key the value goes to."""
    lower: float
    upper: float
    description: str
    short: str = ""
    """Its name in a message about its own value (default: the description)."""
    kind: str = "model"
    """``model``: a wear-model input, fitted as its logarithm, each trial one model run;
    ``scale`` / ``offset``: m and T_0 of T = m·T_model + T_0, applied after the run (exact
    Jacobian columns, no model run)."""
    unit: str = ""
    """SI unit of the value (``summary.json``)."""


FIT_PARAMETERS: dict[str, FitParameter] = {
    "wear_coefficient": FitParameter(
        "wear.coefficient", 1.0e-16, 1.0, "wear coefficient K", short="K"
    ),
    "torque_scale": FitParameter(
        "wear.torque_scale",
        0.0,
        math.inf,
        "drag-torque scale on K_T",
        short="torque scale",
        kind="scale",
    ),
    "torque_offset": FitParameter(
        "wear.torque_offset",
        -math.inf,
        math.inf,
        "preload-independent torque T_0 [N·m]",
        short="torque offset",
        kind="offset",
        unit="N*m",
    ),
    "film_factor": FitParameter("wear.film_factor", 1.0e-3, 1.0, "film supply factor φ"),
    "running_in_depth": FitParameter(
        "wear.running_in.depth", 1.0e-9, 1.0e-4, "running-in depth h_r [m]", unit="m"
    ),
    "preload": FitParameter(
        "operating.preload", 1.0, 1.0e7, "preload F_p [N]", short="preload", unit="N"
    ),
}
LINEAR = ("torque_scale", "torque_offset")
"""The parameters applied after the model run, in their column order (last)."""
CORRELATION_LIMIT = 0.995
"""|correlation| of two fitted parameters above which a CalibrationWarning says the data hardly
separate them (GUESS: each one's standard error is then 1/√(1 − r²) = 10× what it would be
with the other known)."""


PLAUSIBLE_TORQUE_SCALE = (0.2, 5.0)
"""Band of the fitted torque scale m outside which a CalibrationWarning suspects the torque's
unit (GUESS: seals, lubricant and running-in move a nut's drag torque by a few times the
catalogue value, not by a factor of 1000 as N·mm read as N·m does)."""


def too_few_points(source: str, n: int, p: int, fit_until: float | None) -> CalibrationError:
    """The error for ``n`` fitted points and ``p`` parameters, naming ``--fit-until`` if set."""
    points = f"{source}: {n} points"
    if fit_until is not None:
        points = f"--fit-until = {fit_until!r} is not allowed: the {n} points of {source} it keeps"
    return CalibrationError(f"{points} cannot determine {p} parameter(s); give at least {p + 1}")


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
    iteration instead of one per parameter), the columns of the torque multiplier m (the
    model's values) and of the offset (ones, as it is fitted in units of the data scale)
    exact."""

    def __init__(
        self,
        model_at: Callable[[np.ndarray], np.ndarray],
        diff_step: float,
        bounds: tuple[Sequence[float], Sequence[float]],
        fit_scale: bool,
        scale: float,
        fit_offset: bool = False,
    ) -> None:
        self.model_at = model_at
        self.diff_step = diff_step
        self.lower, self.upper = list(bounds[0]), list(bounds[1])
        self.fit_scale = fit_scale
        self.fit_offset = fit_offset
        self.scale = scale
        self.x: np.ndarray | None = None
        self.values = np.zeros(0)
        self.columns = np.zeros((0, 0))

    def steps(self, x: np.ndarray) -> list[float]:
        """Difference steps in each model parameter (backward at an upper bound)."""
        h = self.diff_step
        return [-h if x[i] + h > top else h for i, top in enumerate(self.upper)]

    def difference(self, x: np.ndarray, central: bool = False) -> np.ndarray:
        """The Jacobian at ``x`` by forward differences (p model runs, cached), or by central
        ones (2p runs; one-sided within h of a bound) for the covariance: a forward column's
        O(h) error e biases the standard errors by about e/(1 − ρ²) where parameters correlate
        by ρ (2 % at h = 0.01 and ρ ≈ 0.99), a central column's error is O(h²)."""
        x = np.array(x, dtype=float)
        here = self.model_at(x)
        columns = []
        for i, h in enumerate(self.steps(x)):
            ahead, behind = x.copy(), x.copy()
            ahead[i] += h
            if central and h > 0.0 and x[i] - h >= self.lower[i]:
                behind[i] -= h
                columns.append((self.model_at(ahead) - self.model_at(behind)) / (2.0 * h))
            else:
                columns.append((self.model_at(ahead) - here) / h)
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
        m = float(x[len(self.upper)]) if self.fit_scale else 1.0
        columns = [m * self.columns / self.scale]
        if self.fit_scale:
            columns.append(self.values[:, None] / self.scale)
        if self.fit_offset:
            columns.append(np.ones((self.values.size, 1)))
        return np.hstack(columns)


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


class HistoryFit:
    """One measured history's part of a fit: its model runs (:class:`ModelRuns`), its fitted
    parameters and their local vector x = (ln θ_model…, m, c/s) (m and c where fitted), the
    scaled residuals and the Jacobian; :meth:`result` turns a solution into a
    :class:`CalibrationResult`."""

    def __init__(
        self,
        simulate: Callable[[Mapping[str, float]], WearHistory],
        data: MeasuredHistory,
        fit: Sequence[str],
        start: Mapping[str, float],
        *,
        torque_scale: float,
        torque_offset: float,
        fit_until: float | None,
        max_evaluations: int,
        diff_step: float,
        label: str,
    ) -> None:
        self.names = check_names(fit, data)
        warn_scale_and_preload(self.names, data.source)
        check_values(data.source, data.quantity, np.asarray(data.values, dtype=np.float64))
        if not math.isfinite(torque_offset):
            raise InputError("wear.torque_offset", torque_offset, "a finite torque in N·m")
        self.data = data
        self.fitted_data, self.n_fit = _split(data, fit_until)
        self.fit_until = fit_until
        self.model_names = [n for n in self.names if FIT_PARAMETERS[n].kind == "model"]
        self.fit_scale = "torque_scale" in self.names
        self.fit_offset = "torque_offset" in self.names
        self.base = {k: float(v) for k, v in start.items()}
        for name in self.model_names:
            if name not in self.base:
                raise InputError("fit", name, f"a parameter of the model ({', '.join(self.base)})")
            spec = FIT_PARAMETERS[name]  # fitted as its logarithm: its start within the bounds
            if not spec.lower <= self.base[name] <= spec.upper:
                raise InputError(
                    f"start[{name!r}]", self.base[name], f"{spec.lower:g} to {spec.upper:g}"
                )
        self.start = dict(self.base)
        self.runs = ModelRuns(simulate, self.fitted_data, max_evaluations, label)
        self.y = self.fitted_data.values
        self.scale = float(np.max(np.abs(self.y))) or 1.0
        self.torque_scale = torque_scale
        self.torque_offset = torque_offset
        self.lower = [math.log(FIT_PARAMETERS[n].lower) for n in self.model_names]
        self.upper = [math.log(FIT_PARAMETERS[n].upper) for n in self.model_names]
        self.jacobian = _SecantJacobian(
            self.model_at,
            diff_step,
            (self.lower, self.upper),
            self.fit_scale,
            self.scale,
            self.fit_offset,
        )

    def values_of(self, x: np.ndarray) -> dict[str, float]:
        """The model parameters at ``x``."""
        fitted = zip(self.model_names, x, strict=False)
        return {**self.base, **{n: math.exp(v) for n, v in fitted}}

    def linear(self, x: np.ndarray) -> tuple[float, float]:
        """(m, T_0) at ``x`` (1 and the case's offset where not fitted)."""
        i = len(self.model_names)
        m = float(x[i]) if self.fit_scale else 1.0
        c = float(x[i + self.fit_scale]) * self.scale if self.fit_offset else self.torque_offset
        return m, c

    def model_at(self, x: np.ndarray) -> np.ndarray:
        """The unscaled model at the fitted revolutions."""
        return self.runs.at(self.values_of(x), self.fitted_data.revolutions)

    def residuals(self, x: np.ndarray) -> np.ndarray:
        """(m·y_model + T_0 − y)/s at the fitted points."""
        m, c = self.linear(x)
        return (m * self.model_at(x) + c - self.y) / self.scale

    def begin(self, k_bracket: tuple[float, float] | None) -> tuple[np.ndarray, list, list]:
        """(x₀, lower, upper) from :attr:`base` (after :func:`_start`), m and T_0 in closed form;
        ln K bounded to ``k_bracket``."""
        x0 = [math.log(self.base[n]) for n in self.model_names]
        lower, upper = list(self.lower), list(self.upper)
        if k_bracket is not None and _K in self.model_names:
            i = self.model_names.index(_K)
            lower[i], upper[i] = k_bracket
        m, c = linear_fit(
            self.model_at(np.array(x0)), self.y, self.fit_scale, self.fit_offset, self.torque_offset
        )
        if self.fit_scale:
            x0, lower, upper = [*x0, float(m)], [*lower, 0.0], [*upper, np.inf]
        if self.fit_offset:
            x0, lower, upper = [*x0, float(c) / self.scale], [*lower, -np.inf], [*upper, np.inf]
        x = np.array([min(max(v, lo), hi) for v, lo, hi in zip(x0, lower, upper, strict=True)])
        return x, lower, upper

    def check_bracket(self, x: np.ndarray, lower: Sequence[float], upper: Sequence[float]) -> None:
        """CalibrationError when ln K stopped at the edge of the scan's bracket."""
        if _K in self.model_names:
            i = self.model_names.index(_K)
            if min(abs(x[i] - lower[i]), abs(x[i] - upper[i])) < 1e-9:
                raise CalibrationError(
                    f"least squares stopped at the edge of the bracket K = "
                    f"{math.exp(lower[i]):.3g}–{math.exp(upper[i]):.3g} found by the scan (the "
                    "data do not constrain K)"
                )

    def result(
        self, x: np.ndarray, cov: np.ndarray, noise: float, message: str, scanned: tuple
    ) -> CalibrationResult:
        """The fit at ``x`` with covariance ``cov`` (of x) and noise σ ``noise`` [SI]."""
        data, names, n_fit = self.data, self.names, self.n_fit
        values, errors = {}, {}
        for i, name in enumerate(names):
            kind = FIT_PARAMETERS[name].kind
            if kind == "scale":
                values[name] = float(self.torque_scale * x[i])
                errors[name] = self.torque_scale * math.sqrt(cov[i, i])
            elif kind == "offset":
                values[name] = float(self.scale * x[i])
                errors[name] = self.scale * math.sqrt(cov[i, i])
                continue  # an offset may be 0: its error is not checked against its value
            else:
                values[name] = math.exp(x[i])
                errors[name] = values[name] * math.sqrt(cov[i, i])
            spec = FIT_PARAMETERS[name]
            label = spec.short or spec.description
            check_determined(data.source, label, values[name], errors[name])
        m, c = self.linear(x)
        final = self.values_of(x)
        model_rev, model_val = self.runs.run(final)
        fitted_all = m * np.interp(data.revolutions, model_rev, model_val) + c
        residual_fit = fitted_all[:n_fit] - self.y
        rss = float(residual_fit @ residual_fit)
        gradient = []
        for i, h in enumerate(self.jacobian.steps(x)):  # the runs of the difference Jacobian
            shifted = np.array(x, dtype=float)
            shifted[i] += h
            gradient.append(m * (self.runs.at(self.values_of(shifted), model_rev) - model_val) / h)
        if self.fit_scale:
            gradient.append(model_val)
        if self.fit_offset:
            gradient.append(np.full(model_val.size, self.scale))
        g = np.column_stack(gradient)
        sigma = np.sqrt(np.einsum("ij,jk,ik->i", g, cov, g) + noise**2)
        held = fitted_all[n_fit:] - data.values[n_fit:]
        diagnostics = residual_diagnostics(residual_fit)
        curve = m * model_val + c
        pairs = correlations(cov, names)
        for arr in (fitted_all, curve, sigma):
            arr.setflags(write=False)
        return CalibrationResult(
            quantity=data.quantity,
            unit=data.unit,
            source=data.source,
            wear_coefficient=values.get(_K, self.base.get(_K, math.nan)),
            standard_error=errors.get(_K, 0.0),
            torque_scale=values.get("torque_scale", self.torque_scale),
            torque_scale_error=errors.get("torque_scale"),
            correlation=pairs.get(f"{_K},torque_scale", pairs.get(f"torque_scale,{_K}")),
            rms_residual=math.sqrt(rss / n_fit),
            n_points=n_fit,
            parameters=len(names),
            evaluations=self.runs.evaluations,
            initial_coefficient=float(self.start.get(_K, math.nan)),
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
            fit_until=self.fit_until,
            prediction_rmse=float(np.sqrt(np.mean(held**2))) if held.size else None,
            prediction_sigma=sigma,
            diagnostics=diagnostics.as_dict(),
            torque_offset=values.get("torque_offset", self.torque_offset),
            correlations=pairs,
            data_notes=data.notes,
        )


def solve(
    residuals: Callable[[np.ndarray], np.ndarray],
    jacobian: Callable[[np.ndarray], np.ndarray],
    difference: Callable[[np.ndarray], np.ndarray],
    x: np.ndarray,
    bounds: tuple[Sequence[float], Sequence[float]],
    n: int,
    max_evaluations: int,
    label: str,
    best_rms: Callable[[], float],
    source: str,
) -> tuple[np.ndarray, str]:
    """Least squares from ``x``, restarted (at most :data:`_RESTARTS` runs) from fresh
    differences ``difference`` while a Gauss–Newton step would still move the solution
    (:func:`_converged`); (solution, solver message)."""
    message = ""
    for _ in range(_RESTARTS):
        solution = solve_least_squares(
            residuals, x, jacobian, bounds, max_evaluations, label, best_rms
        )
        x, message = solution.x, str(solution.message)
        if _converged(difference(x), residuals(x), x, bounds, n):
            break
    else:
        warnings.warn(
            f"{source}: after {_RESTARTS} least-squares runs a Gauss–Newton step would "
            f"still move the parameters by more than {_MOVE:g} standard error: the fit may "
            "not be at the minimum (check the data, or fit fewer parameters)",
            CalibrationWarning,
            stacklevel=3,
        )
    return x, message


def described(name: str) -> str:
    """A fit name in words; ``name[j]`` (a per-history parameter) as "… of history j"."""
    base, _, index = name.partition("[")
    words = FIT_PARAMETERS[base].description
    return f"{words} of history {index.rstrip(']')}" if index else words


def warn_if_systematic(result: CalibrationResult) -> None:
    """CalibrationWarning naming the history when the residuals of its fitted points are
    systematic (:func:`~ballscrew.calibration.diagnostics.residual_diagnostics`)."""
    if result.diagnostics.get("systematic"):
        fitted = slice(0, result.n_fit)
        text = residual_diagnostics(result.fitted[fitted] - result.measured[fitted]).message()
        warnings.warn(f"{result.source}: {text}", CalibrationWarning, stacklevel=3)


def warn_correlated(cov: np.ndarray, names: Sequence[str], source: str) -> None:
    """CalibrationWarning for each pair of fitted parameters whose correlation exceeds
    :data:`CORRELATION_LIMIT` in magnitude (the data hardly separate them)."""
    for pair, r in correlations(cov, names).items():
        if abs(r) > CORRELATION_LIMIT:
            a, b = (described(n) for n in split_list(pair))
            warnings.warn(
                f"{source}: the data hardly separate the {a} and the {b} ({pair}: correlation "
                f"{r:+.3f} from the covariance): one trades off against the other, so each "
                "alone is poorly identified; quote them together, or fix one",
                CalibrationWarning,
                stacklevel=3,
            )


def warn_scale_and_preload(names: Sequence[str], source: str) -> None:
    """CalibrationWarning when the torque scale m and the preload F_p are both fitted.

    T = m K_T F_p(N) L/(2π) (E9.1): the as-new torque fixes only m·F_p. With the Hertz preload
    law (E1.13), F_p(N)/F_p = (1 − h/(sinβ cosλ C_a F_p^(2/3)))^(3/2), and a wear depth
    h ∝ K F_p^a, the shape of the loss fixes only K·F_p^(a − 2/3): F_p is then as good as the K
    assumed, and with K fitted too the three are not identifiable (the Jacobian has rank 2).
    """
    if "torque_scale" in names and "preload" in names:
        warnings.warn(
            f"{source}: the torque scale and the preload are fitted together "
            "(torque_scale,preload): the as-new torque fixes only their product m·F_p, and the "
            "torque's loss only K·F_p^(a−2/3) (wear depth ∝ K·F_p^a against the Hertz approach "
            "∝ F_p^(2/3)), so the preload is only as good as the wear coefficient assumed and "
            "is not identifiable with it; give the preload (or wear.torque_scale) instead",
            CalibrationWarning,
            stacklevel=3,
        )


def warn_implausible_scale(result: CalibrationResult) -> None:
    """CalibrationWarning when the fitted torque scale lies outside
    :data:`PLAUSIBLE_TORQUE_SCALE` (most often torques in N·mm read as N·m)."""
    scale = result.values.get("torque_scale")
    low, high = PLAUSIBLE_TORQUE_SCALE
    if scale is not None and not low <= scale <= high:
        warnings.warn(
            f"{result.source}: the fitted torque scale {scale:.4g} is outside the plausible "
            f"{low:g}–{high:g} [GUESS] × the model's drag torque: check the torque's unit (a "
            "column without a unit is read in N·m; name it e.g. 'friction_torque [N*mm]')",
            CalibrationWarning,
            stacklevel=3,
        )


def fit_parameters(
    simulate: Callable[[Mapping[str, float]], WearHistory],
    data: MeasuredHistory,
    fit: Sequence[str],
    start: Mapping[str, float],
    *,
    torque_scale: float = 1.0,
    torque_offset: float = 0.0,
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
        fit: the parameters to fit; ``torque_scale`` and ``torque_offset`` need friction-torque
            data.
        start: the starting value of every model parameter (``wear_coefficient`` and any other
            the model takes); those not fitted stay at it.
        torque_scale: the torque scale the model torques were computed with.
        torque_offset: T_0 added to the model torque [N m] (its start when fitted); the model's
            own torque must not contain it.
        fit_until: fit the points up to these revolutions, predict the rest (None: fit all).
        max_evaluations: most model runs; more raises ConvergenceError.
        diff_step: forward-difference step in the logarithm of each model parameter.
        scan_steps: most decades the scan in K may extend beyond its first three points.
        refine_steps: most surrogate steps in K after the scan (one model run each).
        label: names the solver in a ConvergenceError.
    """
    part = HistoryFit(
        simulate,
        data,
        fit,
        start,
        torque_scale=torque_scale,
        torque_offset=torque_offset,
        fit_until=fit_until,
        max_evaluations=max_evaluations,
        diff_step=diff_step,
        label=label,
    )
    p, n_fit = len(part.names), part.n_fit
    if n_fit <= p:
        raise too_few_points(data.source, n_fit, p, fit_until)
    part.base, scanned, k_bracket = start_values(part, scan_steps, refine_steps)
    x, lower, upper = part.begin(k_bracket)
    x, message = solve(
        part.residuals,
        part.jacobian,
        part.jacobian.difference,
        x,
        (lower, upper),
        n_fit,
        max_evaluations,
        label,
        lambda: part.runs.best_rms,
        data.source,
    )
    part.check_bracket(x, lower, upper)
    r = part.residuals(x)
    jac = part.jacobian.difference(x, central=True)
    cov = _covariance(jac, r, n_fit, part.names, data.source)
    warn_correlated(cov, part.names, data.source)
    noise = part.scale * math.sqrt(float(r @ r) / (n_fit - p))
    return part.result(x, cov, noise, message, scanned)


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


def start_values(
    part: HistoryFit, scan_steps: int, refine_steps: int
) -> tuple[dict[str, float], tuple[tuple[float, float], ...], tuple[float, float] | None]:
    """Starting values: K from a decade scan and surrogate steps (:func:`.search.scan`,
    :func:`.search.refine`); then for each other model parameter in turn the best of
    half-decade trial values, K re-fitted at each by :func:`.search.line_minimum`; the torque
    multiplier and offset in closed form throughout. Returns the start, the decade scan and
    the bracket of ln K (a decade either side of its best). Every run is one of ``part``'s."""
    model, base, names = part.runs, part.base, part.model_names
    fit_k = _K in names

    def line(values: Mapping[str, float]) -> KLine:
        return KLine(model, values, part.fit_scale, part.fit_offset, part.torque_offset)

    first = line(base)
    ln_k = math.log(base[_K])
    scanned_rms: tuple[tuple[float, float], ...] = ()
    if fit_k:
        try:
            best, scanned = scan(first, ln_k, scan_steps)
        except CalibrationError as exc:
            if part.fit_scale and part.fit_offset:
                raise _unidentifiable(part.data.source) from exc
            raise
        ln_k = refine(first, best, scanned, refine_steps)
        scanned_rms = tuple((math.exp(v), first.rms_at(v)[0]) for v in scanned)
    current, rms = {**base, _K: math.exp(ln_k)}, first.rms_at(ln_k)[0]
    for name in (n for n in names if n != _K):
        for trial in _grid(name, current[name])[1:]:
            values = {**current, name: trial}
            try:
                if fit_k:
                    ln_t, rms_t = line_minimum(line(values), math.log(current[_K]))
                else:
                    ln_t, rms_t = ln_k, line(values).rms_at(ln_k)[0]
            except CalibrationError:  # K cannot reach the data at this trial value
                continue
            if rms_t < rms:
                current, rms = {**values, _K: math.exp(ln_t)}, rms_t
    bracket = None
    if fit_k:
        ln_k = math.log(current[_K])
        bracket = (ln_k - LN10, ln_k + LN10)
    return current, scanned_rms, bracket


def _unidentifiable(source: str) -> CalibrationError:
    return CalibrationError(
        f"{source}: K, the torque scale m and the torque offset T_0 are not identifiable "
        "together: while the preload loss is small, T = m·T_p(N; K) + T_0 is linear in K, so "
        "only m·K and m·T_p(0) + T_0 are determined, and these data are best fitted in that "
        "limit (the scan in K ran to the end of its range); fix the torque scale (fit K and "
        "torque_offset with the case's wear.torque_scale) or the offset"
    )


def check_names(fit: Sequence[str], data: MeasuredHistory, option: str = "--fit") -> list[str]:
    """``fit`` checked (known names; the torque scale and offset only for torque data) and in
    column order: the model parameters, then the torque scale and the offset. Errors name
    ``option``, the option the names came from."""
    names = list(dict.fromkeys(fit))
    allowed = ", ".join(FIT_PARAMETERS)
    if not names:
        raise InputError(option, "", f"one or more of {allowed}")
    for name in names:
        if name not in FIT_PARAMETERS:
            raise InputError(option, name, f"one or more of {allowed}")
        if name in LINEAR and data.quantity != "friction_torque":
            raise InputError(option, name, f"only with friction_torque data (got {data.quantity})")
    # the torque multiplier and the offset are the last columns
    return [n for n in names if n not in LINEAR] + [n for n in LINEAR if n in names]


def _covariance(
    jac: np.ndarray, residuals: np.ndarray, n: int, names: list[str], source: str
) -> np.ndarray:
    """RSS/(n − p) · (JᵀJ)⁻¹; CalibrationError naming the parameters when J is rank-deficient."""
    what = " and ".join(FIT_PARAMETERS[n].description for n in names)
    return covariance(jac, residuals, n, len(names), source, what + " together")


def correlations(cov: np.ndarray, names: Sequence[str]) -> dict[str, float]:
    """Correlation of each pair of fitted parameters, keyed ``"a,b"`` (K's of ln K)."""
    sigma = np.sqrt(np.diag(cov))
    return {
        f"{names[i]},{names[j]}": float(cov[i, j] / (sigma[i] * sigma[j]))
        for i in range(len(names))
        for j in range(i + 1, len(names))
        if sigma[i] > 0.0 and sigma[j] > 0.0
    }
