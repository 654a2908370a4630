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
    command,
    export_formats,
    finish,
    parse_sets,
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
    from ballscrew.case import load_case
    from ballscrew.results import claim_output, write_results

    formats = export_formats(export)
    case = load_case(case_file, parse_sets(set_))
    with claim_output(out, command="thermal", force=force, inputs=[case_file]):
        result = thermal_field(case, model=model)
        folder = write_results(result, out, case_file)
        finish(folder, formats)
