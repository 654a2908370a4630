"""What a calibration returns and reads: the fitted result, the model history it compares with
the measurements, and the errors it raises."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from types import ModuleType
from typing import Any, ClassVar, Protocol

import numpy as np
import xarray as xr
from numpy.typing import NDArray

from ballscrew.analyses.result import Presented
from ballscrew.calibration import report as calibration_report
from ballscrew.calibration.diagnostics import effective_points, error_inflation
from ballscrew.calibration.measured import MeasuredHistory
from ballscrew.case.inputs import resolved_inputs
from ballscrew.errors import BallscrewError, InputError

__all__ = [
    "HISTORY_FIELD",
    "CalibrationError",
    "CalibrationResult",
    "WearHistory",
    "covering_history",
    "model_values",
]

#: Attribute of the model history that each measured quantity is compared with.
HISTORY_FIELD: dict[str, str] = {
    "friction_torque": "friction_torque",
    "preload": "preload",
    "wear_depth": "max_wear_depth",
}


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
        parameters: number of fitted parameters.
        evaluations: number of wear-model runs.
        initial_coefficient: the K the scan started from.
        revolutions: measured revolutions.
        measured: measured values (SI).
        fitted: the fitted model at the measured revolutions.
        model_revolutions: revolutions of the fitted model's own history.
        model_values: the fitted model's history of the quantity (SI).
        scan: (K, RMS residual) of the coarse scan, in the order evaluated.
        message: the least-squares solver's termination message.
        case: the case given to the fit, which :func:`~ballscrew.calibration.calibrated_case`
            calibrates (None for :func:`fit_wear_coefficient` on its own); a test-bench
            schedule is not in it (the fit ran it as ``[[duty]]``).
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
    torque_offset: float = 0.0
    """Preload-independent torque T_0 added to the model torque [N m] (fitted or the case's)."""
    correlations: Mapping[str, float] = field(default_factory=dict)
    """Correlation of each pair of fitted parameters from the covariance, keyed ``"a,b"``."""
    data_notes: tuple[str, ...] = ()
    """What the measured file says about its data (its leading comment lines)."""

    analysis: ClassVar[str] = "calibrate"
    presentation: ClassVar[ModuleType] = calibration_report
    dataset_name: ClassVar[str] = "fit"

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

    def to_xarray(self) -> xr.Dataset:
        return calibration_report.fit_dataset(self)

    @property
    def relative_error(self) -> float:
        """σ_K / K."""
        return self.standard_error / self.wear_coefficient

    @property
    def _n_residuals(self) -> int:
        """The number of fitted residuals (the diagnostics' n)."""
        return self.n_fit or self.n_points

    @property
    def effective_points(self) -> float | None:
        """n_eff = n (1 − r₁)/(1 + r₁) of the fitted residuals (Bayley & Hammersley 1946; n
        for r₁ ≤ 0); None without residual diagnostics."""
        r1 = self.diagnostics.get("lag1_autocorrelation")
        return None if r1 is None else effective_points(self._n_residuals, r1)

    @property
    def inflated_errors(self) -> dict[str, float] | None:
        """:attr:`errors` with the residual variance over n_eff − p degrees of freedom instead
        of n − p (:func:`~ballscrew.calibration.diagnostics.error_inflation`): the errors
        allowing for correlated residuals; None when n_eff ≤ p or without diagnostics. Like
        :attr:`errors` they leave out the model-form error."""
        r1 = self.diagnostics.get("lag1_autocorrelation")
        factor = None if r1 is None else error_inflation(self._n_residuals, self.parameters, r1)
        return None if factor is None else {k: e * factor for k, e in self.errors.items()}

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
