"""``ballscrew operating-point``: screw and friction torque, heat, temperatures, viscosity, film,
and the same against speed."""

from __future__ import annotations

import dataclasses
from typing import Annotated

import numpy as np
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
CurveToOpt = Annotated[
    str | None,
    typer.Option(
        "--curve-to",
        help='top speed of the speed curve, e.g. "3000 rpm"; default: twice the speed '
        "(1000 rpm at rest)",
        metavar="SPEED",
    ),
]
CurvePointsOpt = Annotated[
    int,
    typer.Option(
        "--curve-points",
        help="speeds of the curve, evenly from top/N to the top speed (0: no curve)",
        min=0,
        max=50,
        metavar="N",
    ),
]

#: Top speed of the curve of a case at rest [rad/s] (1000 rpm).
REST_CURVE_TOP = 1000.0 * np.pi / 30.0


@writes_results
def operating_point(
    case_file: CaseArg,
    speed: SpeedOpt = None,
    axial_load: AxialLoadOpt = None,
    curve_to: CurveToOpt = None,
    curve_points: CurvePointsOpt = 8,
    *,
    output: Output,
) -> None:
    """The coupled steady state: torque, heat, efficiency, temperatures, film; curves over speed.

    The screw and friction torque, heat, driving and back-driving efficiency, nut and screw
    temperatures, viscosity and film at the case's (or the given) speed and load, and the same
    at --curve-points speeds up to --curve-to."""
    from ballscrew.analyses.operating_point import operating_point as solve
    from ballscrew.analyses.operating_point import speed_curve
    from ballscrew.case.base import MAX_SPEED

    omega = quantity_option("--speed", speed, "angular_velocity")
    load = quantity_option("--axial-load", axial_load, "force")
    top = quantity_option("--curve-to", curve_to, "angular_velocity")
    if top is not None and not 0.0 < top <= MAX_SPEED:
        raise typer.BadParameter(
            f"{curve_to!r}: a speed > 0 and at most {MAX_SPEED:g} rad/s", param_hint="--curve-to"
        )

    def run(case):  # type: ignore[no-untyped-def]
        point = solve(case, omega, load)
        if not curve_points:
            return point
        end = top if top is not None else min(2.0 * point.speed, MAX_SPEED) or REST_CURVE_TOP
        speeds = np.linspace(end / curve_points, end, curve_points)
        return dataclasses.replace(point, curve=speed_curve(case, speeds, point.axial_load))

    output.analyse(case_file, run)
