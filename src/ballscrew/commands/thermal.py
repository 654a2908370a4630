"""``ballscrew thermal``: temperature field and thermal elongation of the screw, at the operating
point and over the case's ``[[duty]]`` cycle when it has one."""

from __future__ import annotations

from typing import Annotated

import typer

from ballscrew.commands._common import CaseArg, Output, ThermalModelOpt, writes_results

DutyOpt = Annotated[
    bool,
    typer.Option(
        "--duty/--no-duty",
        help="also follow the case's [[duty]] cycle when it has one (the run of `ballscrew "
        "duty`); --no-duty: the single operating point only",
    ),
]


@writes_results
def thermal(
    case_file: CaseArg, model: ThermalModelOpt = None, duty: DutyOpt = True, *, output: Output
) -> None:
    """Temperatures and elongation at the operating point and over [[duty]] (needs [thermal]).

    The steady and transient field, sensors and elongation at the case's [operating] point; a
    case with a [[duty]] list is also followed through its cycle, as by `ballscrew duty`
    (--no-duty: the operating point only)."""
    from ballscrew.analyses.thermal import thermal_field

    output.analyse(case_file, lambda case: thermal_field(case, model, duty=duty))
