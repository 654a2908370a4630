"""``ballscrew calibrate``: fit the wear coefficient to a measured life-test history."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Any

import typer

from ballscrew.commands._common import CaseArg, Output, log, writes_results

MeasuredOpt = Annotated[
    list[Path],
    typer.Option(
        "--measured",
        "-m",
        help="CSV with a header row: 'revolutions' and one of 'friction_torque' (N·m), "
        "'preload' (N), 'wear_depth' (m); units in brackets are converted, e.g. 'wear_depth "
        "[µm]'. Repeat it for a joint fit of several histories of the screw (e.g. the two "
        "travel directions): the --fit parameters are then shared, the --separate ones each "
        "history's own",
        dir_okay=False,
        metavar="CSV_FILE",
        show_default=False,
    ),
]
SeparateOpt = Annotated[
    str | None,
    typer.Option(
        "--separate",
        help="joint fit only: parameters each history fits on its own, comma-separated "
        "(default for friction_torque data: torque_offset, the torque scale then the case's; "
        "otherwise none)",
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
        "torque_offset (T_0 [N·m] of T = m·K_T·F_p·L/2π + T_0), film_factor, running_in_depth, "
        "preload (with torque_scale only m·F_p is determined: warned) (default: "
        "wear_coefficient, and torque_scale for friction_torque data; with several "
        "--measured: the shared parameters, default wear_coefficient)",
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
    separate: SeparateOpt = None,
    *,
    output: Output,
) -> None:
    """Fit the wear model (K, torque scale, offset, …) to measured histories (--measured).

    One history, or several jointly (repeat --measured)."""
    from dataclasses import replace

    from ballscrew.calibration import DEFAULT_FIT, read_measured
    from ballscrew.calibration import calibrate as calibrate_case
    from ballscrew.calibration.report import fit_table
    from ballscrew.errors import InputError
    from ballscrew.units import format_number, split_list

    case = output.load_case(case_file)
    if not measured:
        raise InputError("--measured", "", "one or more CSV files")
    names: tuple[str, ...] = DEFAULT_FIT if len(measured) == 1 else ("wear_coefficient",)
    if fit is not None:
        names = tuple(split_list(fit))
    if fit_torque_scale and "torque_scale" not in names:
        names = (*names, "torque_scale")
    data = [read_measured(m, min_points=2) for m in measured]
    if fit_torque_scale and data[0].quantity != "friction_torque":
        raise InputError(
            "--fit-torque-scale", True, f"only with friction_torque data (got {data[0].quantity})"
        )
    from ballscrew.calibration.multi import check_names

    check_names(names, data[0])
    if separate:
        check_names(split_list(separate), data[0], "--separate")
    if len(data) > 1:
        _joint(case_file, case, measured, data, names, separate, fit_until, output)
        return
    if separate is not None:
        raise InputError("--separate", separate, "only with two or more --measured files")
    with output.claim(case_file, *measured):
        log.info("fitting to %d %s points of %s", len(data[0]), data[0].quantity, data[0].source)
        result = calibrate_case(case, data[0], fit=names, fit_until=fit_until)
        log.info(
            "K = %s ± %s, torque scale %.4g, RMS residual %s (%d model runs)",
            format_number(result.wear_coefficient),
            format_number(result.standard_error, 3),
            result.torque_scale,
            _si(result.rms_residual, result.unit),
            result.evaluations,
        )
        if result.prediction_rmse is not None:
            log.info("held-out RMS error %s", _si(result.prediction_rmse, result.unit))
        options = _options(case_file, measured, case, fit_until)
        options["fit_torque_scale"] = "torque_scale" in result.values
        options["fit"] = list(result.values)
        result = replace(result, case=case, options=options)
        fit_csv = fit_table(result).encode("utf-8")  # the fit table for spreadsheets
        output.write(result, case_file, {"fit.csv": fit_csv})


def _si(value: float, unit: str) -> str:
    """An SI ``value`` in ``unit`` (N*m, N, m) in engineering units: 0.005094 N·m, 2.43 µm."""
    from ballscrew.results.display import engineering
    from ballscrew.units import format_number

    shown, symbol = engineering(value, unit, "wear_depth" if unit == "m" else "")
    return f"{format_number(shown)} {symbol}".rstrip()


def _options(
    case_file: Path, measured: list[Path], case: Any, fit_until: float | None
) -> dict[str, object]:
    from ballscrew.results import value

    options: dict[str, object] = {
        "case_file": str(case_file),
        "measured_file": str(measured[0]) if len(measured) == 1 else [str(m) for m in measured],
        "fit_until": fit_until,
    }
    if case.wear is not None:  # K is confounded with these
        options["wear_model"] = case.wear.model
        options["stroke"] = value(case.wear.stroke, "m")
        options["programme_revolutions"] = sum(lv.revolutions for lv in case.wear.programme)
    return options


def _joint(
    case_file: Path,
    case: Any,
    measured: list[Path],
    data: list[Any],
    names: tuple[str, ...],
    separate: str | None,
    fit_until: float | None,
    output: Output,
) -> None:
    """The joint fit of several histories (``calibrate_joint``) and its folder."""
    from dataclasses import replace

    from ballscrew.calibration import calibrate_joint
    from ballscrew.calibration.joint_report import fit_table
    from ballscrew.units import format_number

    with output.claim(case_file, *measured):
        log.info("joint fit of %d histories: shared %s", len(data), ", ".join(names))
        result = calibrate_joint(case, data, shared=names, separate=separate, fit_until=fit_until)
        log.info(
            "K = %s, RMS residual %.3g (%d model runs)",
            format_number(result.wear_coefficient),
            result.rms_residual,
            result.evaluations,
        )
        options = _options(case_file, measured, case, fit_until)
        options["shared"], options["separate"] = list(result.shared), list(result.separate)
        result = replace(result, options=options)
        output.write(result, case_file, {"fit.csv": fit_table(result).encode("utf-8")})
