"""``ballscrew tcr``: thermal contact resistance of the screw."""

from __future__ import annotations

from typing import Annotated

import typer

from ballscrew.commands._common import CaseArg, Output, writes_results

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
    from ballscrew.analyses.screw_tcr import screw_tcr

    output.analyse(case_file, lambda case: screw_tcr(case, variant=variant))
