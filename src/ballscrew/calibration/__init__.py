"""Calibration of the wear model against a test bench.

1. ``data = read_measured("bench.csv")`` reads a measured history of friction torque, preload
   or wear depth against screw revolutions (header row; units in brackets are converted).
2. ``result = calibrate(case, data)`` fits the wear coefficient K (and, with
   ``fit_torque_scale=True`` on torque data, the drag-torque scale) by nonlinear least squares on
   ln K, running :func:`ballscrew.wear_life` on the case for each trial K.
   :func:`fit_wear_coefficient` is the same fit with any model callable ``K -> history``.
3. ``result.wear_coefficient``, ``result.standard_error``, ``result.torque_scale`` and
   ``result.rms_residual`` are the fit; ``ballscrew.results.write_results`` writes its folder.

K is confounded with the stroke and the revolution count of the case (theory manual, *Wear*):
report it together with them.
"""

from ballscrew.calibration.fit import (
    CalibrationError,
    CalibrationResult,
    calibrate,
    fit_wear_coefficient,
)
from ballscrew.calibration.measured import (
    QUANTITIES,
    MeasuredHistory,
    measured_history,
    read_measured,
)

__all__ = [
    "QUANTITIES",
    "CalibrationError",
    "CalibrationResult",
    "MeasuredHistory",
    "calibrate",
    "fit_wear_coefficient",
    "measured_history",
    "read_measured",
]
