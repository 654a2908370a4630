"""``ballscrew operating-point``: screw and friction torque, heat, temperatures, viscosity, film."""

from __future__ import annotations

from typing import Annotated

import typer

from ballscrew.commands._common import (
    CaseArg,
    Output,
    SpeedOpt,
    quantity_option,
    writes_results,
)

AxialLoadOpt = Annotated[
    str | None,
    typer.Option(
        "--axial-load",
        help='axial load, e.g. "2 kN" or 2000 (N); default: the case\'s',
        metavar="FORCE",
    ),
]


@writes_results
def operating_point(
    case_file: CaseArg,
    speed: SpeedOpt = None,
    axial_load: AxialLoadOpt = None,
    *,
    output: Output,
) -> None:
    """The coupled steady state: screw and friction torque, heat, efficiency, temperatures, film."""
    from ballscrew.analyses.operating_point import operating_point as solve

    omega = quantity_option("--speed", speed, "angular_velocity")
    load = quantity_option("--axial-load", axial_load, "force")
    output.analyse(case_file, lambda case: solve(case, omega, load))
