"""``ballscrew calibrate``: fit the wear coefficient to a measured life-test history."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from ballscrew.commands._common import (
    CaseArg,
    ExportOpt,
    ForceOpt,
    OutOpt,
    SetOpt,
    command,
    export_formats,
    finish,
    log,
    parse_sets,
)

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


@command
def calibrate(
    case_file: CaseArg,
    measured: MeasuredOpt,
    out: OutOpt = Path("results/calibrate"),
    fit_torque_scale: Annotated[
        bool,
        typer.Option(
            "--fit-torque-scale",
            help="also fit the drag-torque scale (friction_torque data only)",
        ),
    ] = False,
    force: ForceOpt = False,
    set_: SetOpt = None,
    export: ExportOpt = None,
) -> None:
    """Fit the wear coefficient (and the torque scale) to a measured history."""
    from dataclasses import replace

    from ballscrew.calibration import calibrate as fit
    from ballscrew.calibration import read_measured
    from ballscrew.calibration.report import fit_table
    from ballscrew.case import load_case
    from ballscrew.results import claim_output, value, write_results

    formats = export_formats(export)
    case = load_case(case_file, parse_sets(set_))
    data = read_measured(measured, min_points=3 if fit_torque_scale else 2)
    inputs = [case_file, measured]
    with claim_output(out, command="calibrate", force=force, inputs=inputs):
        log.info("fitting to %d %s points of %s", len(data), data.quantity, data.source)
        result = fit(case, data, fit_torque_scale=fit_torque_scale)
        options: dict[str, object] = {
            "case_file": str(case_file),
            "measured_file": str(measured),
            "fit_torque_scale": fit_torque_scale,
        }
        if case.wear is not None:  # K is confounded with these
            options["wear_model"] = case.wear.model
            options["stroke"] = value(case.wear.stroke, "m")
            options["programme_revolutions"] = sum(lv.revolutions for lv in case.wear.programme)
        result = replace(result, case=case, options=options)
        fit_csv = fit_table(result).encode("utf-8")  # the fit table for spreadsheets
        folder = write_results(result, out, case_file, {"fit.csv": fit_csv})
        finish(folder, formats)
