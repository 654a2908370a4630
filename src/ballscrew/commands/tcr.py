"""``ballscrew tcr``: thermal contact resistance of the screw."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from ballscrew.commands._common import CaseArg, ForceOpt, OutOpt, log, user_errors_exit_2


@user_errors_exit_2
def tcr(
    case_file: CaseArg,
    out: OutOpt = Path("results/tcr"),
    variant: Annotated[
        str | None, typer.Option(help="element model V2, MT or V1 (default: the case's)")
    ] = None,
    force: ForceOpt = False,
) -> None:
    """Thermal contact resistance of every contact, each nut and the whole screw."""
    from ballscrew.analyses.screw_tcr import screw_tcr
    from ballscrew.case import load_case
    from ballscrew.results import claim_output, write_results

    case = load_case(case_file)
    with claim_output(out, command="tcr", force=force, inputs=[case_file]):
        result = screw_tcr(case, variant=variant)
        log.info("R = %.4g K/W, R'' = %.4g m^2K/W", result.resistance, result.resistance_per_area)
        folder = write_results(result, out, case_file)
    log.info("wrote %s", folder / "report.html")
