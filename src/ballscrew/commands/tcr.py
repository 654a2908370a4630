"""``ballscrew tcr``: thermal contact resistance of the screw."""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated

import typer

from ballscrew.commands._common import CaseArg, Output, is_quiet, writes_results

if TYPE_CHECKING:
    from ballscrew.case import Case

VariantOpt = Annotated[
    str | None,
    typer.Option(
        help="headline: element model V2, MT or V1 on the paper's Δ_f cells (default: the "
        "case's [tcr] headline, CMY)",
        metavar="NAME",
    ),
]


@writes_results
def tcr(case_file: CaseArg, variant: VariantOpt = None, *, output: Output) -> None:
    """Thermal contact resistance of every contact, each nut and the whole screw."""
    from ballscrew.analyses.screw_tcr import ScrewTCR, screw_tcr
    from ballscrew.analyses.tcr_report import console_line

    def run(case: Case) -> ScrewTCR:
        result = screw_tcr(case, variant=variant)
        if not is_quiet():  # which model the numbers below are (before them)
            typer.echo(console_line(result))
        return result

    output.analyse(case_file, run)
