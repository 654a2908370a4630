"""``ballscrew operating-point``: friction torque, heat, temperatures, viscosity and film."""

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
    analyse,
    command,
    quantity_option,
)


@command
def operating_point(
    case_file: CaseArg,
    out: OutOpt = Path("results/operating-point"),
    force: ForceOpt = False,
    speed: Annotated[
        str | None,
        typer.Option(
            help='screw speed, e.g. "1500 rpm" or 157.1 (rad/s); default: the case\'s',
            metavar="SPEED",
        ),
    ] = None,
    axial_load: Annotated[
        str | None,
        typer.Option(
            "--axial-load", help='axial load, e.g. "2 kN"; default: the case\'s', metavar="FORCE"
        ),
    ] = None,
    set_: SetOpt = None,
    export: ExportOpt = None,
) -> None:
    """The coupled steady state: friction torque, heat, efficiency, temperatures and film."""
    from ballscrew.analyses.operating_point import operating_point as solve

    omega = quantity_option("--speed", speed, "angular_velocity")
    load = quantity_option("--axial-load", axial_load, "force")
    analyse(
        "operating-point", case_file, out, (force, set_, export), lambda c: solve(c, omega, load)
    )
