"""``ballscrew tcr``: thermal contact resistance of the screw."""

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
def tcr(
    case_file: CaseArg,
    out: OutOpt = Path("results/tcr"),
    variant: Annotated[
        str | None,
        typer.Option(help="element model V2, MT or V1 (default: the case's)", metavar="NAME"),
    ] = None,
    force: ForceOpt = False,
    set_: SetOpt = None,
    export: ExportOpt = None,
) -> None:
    """Thermal contact resistance of every contact, each nut and the whole screw."""
    from ballscrew.analyses.screw_tcr import screw_tcr

    analyse("tcr", case_file, out, (force, set_, export), lambda c: screw_tcr(c, variant=variant))
