"""``ballscrew thermal``: temperature field and thermal elongation of the screw."""

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
def thermal(
    case_file: CaseArg,
    out: OutOpt = Path("results/thermal"),
    model: Annotated[
        str | None,
        typer.Option(
            help="axisymmetric, network or 3d (default: the case's thermal.model)", metavar="NAME"
        ),
    ] = None,
    force: ForceOpt = False,
    set_: SetOpt = None,
    export: ExportOpt = None,
) -> None:
    """Steady and transient temperatures, sensors and thermal elongation (needs [thermal])."""
    from ballscrew.analyses.thermal import thermal_field

    analyse("thermal", case_file, out, (force, set_, export), lambda c: thermal_field(c, model))
