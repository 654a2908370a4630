"""``ballscrew calibrate``: fit the wear coefficient to a measured life-test history."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from ballscrew.commands._common import CaseArg, Output, log, writes_results

MeasuredOpt = Annotated[
    Path,
    typer.Option(
        "--measured",
        "-m",
        help="CSV with a header row: 'revolutions' and one of 'friction_torque' (N·m), "
        "'preload' (N), 'wear_depth' (m); units in brackets are converted, e.g. 'wear_depth [µm]'",
        dir_okay=False,
        metavar="CSV_FILE",
        show_default=False,
    ),
]

FitTorqueScaleOpt = Annotated[
    bool,
    typer.Option(
        "--fit-torque-scale",
        help="also fit the drag-torque scale (friction_torque data only; the default there)",
    ),
]
FitOpt = Annotated[
    str | None,
    typer.Option(
        "--fit",
        help="parameters to fit, comma-separated: wear_coefficient, torque_scale, "
        "film_factor, running_in_depth (default: wear_coefficient, and torque_scale for "
        "friction_torque data)",
        show_default=False,
    ),
]
FitUntilOpt = Annotated[
    float | None,
    typer.Option(
        "--fit-until",
        help="fit the points up to N revolutions and report the prediction error on the rest",
        show_default=False,
    ),
]


@writes_results
def calibrate(
    case_file: CaseArg,
    measured: MeasuredOpt,
    fit_torque_scale: FitTorqueScaleOpt = False,
    fit: FitOpt = None,
    fit_until: FitUntilOpt = None,
    *,
    output: Output,
) -> None:
    """Fit the wear model (K, torque scale, …) to a measured history."""
    from dataclasses import replace

    from ballscrew.calibration import DEFAULT_FIT, read_measured
    from ballscrew.calibration import calibrate as calibrate_case
    from ballscrew.calibration.report import fit_table
    from ballscrew.errors import InputError
    from ballscrew.results import value

    case = output.load_case(case_file)
    names: tuple[str, ...] = DEFAULT_FIT
    if fit is not None:
        names = tuple(n.strip() for n in fit.split(",") if n.strip())
    if fit_torque_scale and "torque_scale" not in names:
        names = (*names, "torque_scale")
    data = read_measured(measured, min_points=2)
    if fit_torque_scale and data.quantity != "friction_torque":
        raise InputError(
            "--fit-torque-scale", True, f"only with friction_torque data (got {data.quantity})"
        )
    with output.claim(case_file, measured):
        log.info("fitting to %d %s points of %s", len(data), data.quantity, data.source)
        result = calibrate_case(case, data, fit=names, fit_until=fit_until)
        log.info(
            "K = %.4e ± %.2e, torque scale %.4g, RMS residual %.3g %s (%d model runs)",
            result.wear_coefficient,
            result.standard_error,
            result.torque_scale,
            result.rms_residual,
            result.unit,
            result.evaluations,
        )
        if result.prediction_rmse is not None:
            log.info("held-out RMS error %.3g %s", result.prediction_rmse, result.unit)
        options: dict[str, object] = {
            "case_file": str(case_file),
            "measured_file": str(measured),
            "fit_torque_scale": "torque_scale" in result.values,
            "fit": list(result.values),
            "fit_until": fit_until,
        }
        if case.wear is not None:  # K is confounded with these
            options["wear_model"] = case.wear.model
            options["stroke"] = value(case.wear.stroke, "m")
            options["programme_revolutions"] = sum(lv.revolutions for lv in case.wear.programme)
        result = replace(result, case=case, options=options)
        fit_csv = fit_table(result).encode("utf-8")  # the fit table for spreadsheets
        output.write(result, case_file, {"fit.csv": fit_csv})
