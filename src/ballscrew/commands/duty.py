"""``ballscrew duty``: temperatures and thermal elongation over the case's duty cycle."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from ballscrew.commands._common import CaseArg, ForceOpt, OutOpt, log, user_errors_exit_2


@user_errors_exit_2
def duty(
    case_file: CaseArg,
    out: OutOpt = Path("results/duty"),
    force: ForceOpt = False,
    model: Annotated[
        str | None,
        typer.Option(help="axisymmetric, network or 3d (default: the case's thermal.model)"),
    ] = None,
) -> None:
    """A working day of thermal error: elongation and temperatures over the [[duty]] cycle."""
    from ballscrew.analyses.duty_thermal import thermal_duty
    from ballscrew.case import load_case
    from ballscrew.results import claim_output, write_results

    case = load_case(case_file)
    with claim_output(out, command="duty", force=force, inputs=[case_file]):
        result = thermal_duty(case, model)
        log.info(
            "peak elongation %.4g µm, peak temperature %.1f °C over %.3g h (%s model)",
            1e6 * float(result.elongation.max()),
            float(result.max_temperature.max()) - 273.15,
            result.time[-1] / 3600.0,
            result.model,
        )
        folder = write_results(result, out, case_file)
    log.info("wrote %s", folder / "report.html")
