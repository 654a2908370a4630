"""``ballscrew thermal``: temperature field and thermal elongation of the screw."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from ballscrew.commands._common import CaseArg, ForceOpt, OutOpt, log, user_errors_exit_2


@user_errors_exit_2
def thermal(
    case_file: CaseArg,
    out: OutOpt = Path("results/thermal"),
    model: Annotated[
        str | None,
        typer.Option(help="axisymmetric, network or 3d (default: the case's thermal.model)"),
    ] = None,
    force: ForceOpt = False,
) -> None:
    """Steady and transient temperatures, sensors and thermal elongation (needs [thermal])."""
    from ballscrew.analyses.thermal import thermal_field
    from ballscrew.case import load_case
    from ballscrew.results import claim_output, write_results

    case = load_case(case_file)
    with claim_output(out, command="thermal", force=force, inputs=[case_file]):
        result = thermal_field(case, model=model)
        log.info(
            "max rise %.3g K, elongation %.4g um, heat %.4g W (%s, %d unknowns)",
            result.max_temperature_rise,
            result.elongation * 1e6,
            result.heat_input,
            result.model,
            result.unknowns,
        )
        folder = write_results(result, out, case_file)
    log.info("wrote %s", folder / "report.html")
