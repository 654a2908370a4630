"""``ballscrew duty``: temperatures and thermal elongation over the case's duty cycle."""

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
)


@command
def duty(
    case_file: CaseArg,
    out: OutOpt = Path("results/duty"),
    force: ForceOpt = False,
    model: Annotated[
        str | None,
        typer.Option(
            help="axisymmetric, network or 3d (default: the case's thermal.model)", metavar="NAME"
        ),
    ] = None,
    set_: SetOpt = None,
    export: ExportOpt = None,
) -> None:
    """A working day of thermal error: elongation and temperatures over the [[duty]] cycle."""
    from ballscrew.analyses.duty_thermal import thermal_duty

    analyse("duty", case_file, out, (force, set_, export), lambda case: thermal_duty(case, model))
