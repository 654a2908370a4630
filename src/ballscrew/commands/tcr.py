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
    command,
    export_formats,
    finish,
    parse_sets,
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
    from ballscrew.case import load_case
    from ballscrew.results import claim_output, write_results

    formats = export_formats(export)
    case = load_case(case_file, parse_sets(set_))
    with claim_output(out, command="tcr", force=force, inputs=[case_file]):
        result = screw_tcr(case, variant=variant)
        folder = write_results(result, out, case_file)
        finish(folder, formats)
