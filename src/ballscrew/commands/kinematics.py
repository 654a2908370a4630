"""``ballscrew kinematics``: ball kinematics, ball balance, EHL film and drag torque."""

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


@command
def kinematics(
    case_file: CaseArg,
    out: OutOpt = Path("results/kinematics"),
    force: ForceOpt = False,
    level: Annotated[
        int | None,
        typer.Option(help="ball balance level 0, 1 or 2 (default: the case's)", metavar="LEVEL"),
    ] = None,
    speed: Annotated[
        str | None,
        typer.Option(
            help='screw speed, e.g. "3000 rpm" or 314.16 (rad/s); default: the case\'s',
            metavar="SPEED",
        ),
    ] = None,
    set_: SetOpt = None,
    export: ExportOpt = None,
) -> None:
    """Ball speeds, spins, loads and contact angles, film, asperity share and drag torque."""
    import warnings

    from ballscrew.analyses.kinematics import run_kinematics
    from ballscrew.case import load_case
    from ballscrew.errors import InputError
    from ballscrew.kinematics.limits import SpeedLimitWarning
    from ballscrew.results import claim_output, write_results
    from ballscrew.units import to_si

    formats = export_formats(export)
    case = load_case(case_file, parse_sets(set_))
    omega = None
    if speed is not None:
        try:
            omega = to_si(speed, "angular_velocity")
        except ValueError as exc:
            raise InputError("--speed", speed, str(exc)) from None
    with claim_output(out, command="kinematics", force=force, inputs=[case_file]):
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always", SpeedLimitWarning)
            result = run_kinematics(case, level=level, speed=omega)
        for item in caught:
            if issubclass(item.category, SpeedLimitWarning):
                log.warning("warning: %s", item.message)
        folder = write_results(result, out, case_file)
        finish(folder, formats)
