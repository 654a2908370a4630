"""Calibration of the wear model against a test bench.

1. ``data = read_measured("bench.csv")`` reads a measured history of friction torque, preload
   or wear depth against screw revolutions (header row; units in brackets are converted).
2. ``result = calibrate(case, data, fit=("wear_coefficient", "torque_scale"), fit_until=None)``
   fits any subset of K, the torque scale (torque data; fitted by default), the
   preload-independent torque offset T_0 (torque data), the film supply
   factor and the running-in depth by nonlinear least squares, running
   :func:`ballscrew.wear_life` on the case for each trial; ``fit_until`` holds the rest of the
   data out and reports ``prediction_rmse`` on it. :func:`fit_wear_coefficient` is the K-only
   fit with any model callable ``K -> history``; :func:`fit_parameters` the general one.
   ``calibrate_joint(case, [a, b], shared=("wear_coefficient",))`` fits several histories
   of one screw type together (e.g. two specimens on one programme): one K, each history its
   own offset T_0, and its own torque scale when ``separate`` names it
   (:mod:`ballscrew.calibration.joint`).
3. ``result.wear_coefficient``, ``result.standard_error``, ``result.torque_scale`` and
   ``result.rms_residual`` are the fit; ``ballscrew.results.write_results`` writes its folder.

K is confounded with the stroke and the revolution count of the case (theory manual, *Wear*):
report it together with them.
"""

from ballscrew.calibration.api import DEFAULT_FIT, as_measured, calibrate, calibrated_case
from ballscrew.calibration.diagnostics import ResidualDiagnostics, residual_diagnostics
from ballscrew.calibration.fit import fit_wear_coefficient
from ballscrew.calibration.joint import JointCalibrationResult, calibrate_joint, fit_joint
from ballscrew.calibration.measured import (
    QUANTITIES,
    MeasuredHistory,
    measured_history,
    read_measured,
    read_table,
)
from ballscrew.calibration.multi import FIT_PARAMETERS, CalibrationWarning, fit_parameters
from ballscrew.calibration.result import CalibrationError, CalibrationResult

__all__ = [
    "DEFAULT_FIT",
    "FIT_PARAMETERS",
    "QUANTITIES",
    "CalibrationError",
    "CalibrationResult",
    "CalibrationWarning",
    "JointCalibrationResult",
    "MeasuredHistory",
    "ResidualDiagnostics",
    "as_measured",
    "calibrate",
    "calibrate_joint",
    "calibrated_case",
    "fit_joint",
    "fit_parameters",
    "fit_wear_coefficient",
    "measured_history",
    "read_measured",
    "read_table",
    "residual_diagnostics",
]
