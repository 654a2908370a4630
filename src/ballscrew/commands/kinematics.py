"""``ballscrew kinematics``: ball kinematics, ball balance, EHL film and drag torque."""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated

import typer

from ballscrew.commands._common import (
    CaseArg,
    Output,
    SpeedOpt,
    log,
    quantity_option,
    writes_results,
)

if TYPE_CHECKING:
    from ballscrew.analyses.kinematics import KinematicsRun
    from ballscrew.case import Case

LevelOpt = Annotated[
    int | None,
    typer.Option(help="ball balance level 0, 1 or 2 (default: the case's)", metavar="LEVEL"),
]


@writes_results
def kinematics(
    case_file: CaseArg, level: LevelOpt = None, speed: SpeedOpt = None, *, output: Output
) -> None:
    """Ball speeds, spins, loads and contact angles, film, asperity share and drag torque."""
    import warnings

    from ballscrew.analyses.kinematics import run_kinematics
    from ballscrew.kinematics.limits import SpeedLimitWarning

    omega = quantity_option("--speed", speed, "angular_velocity")

    def run(case: Case) -> KinematicsRun:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always", SpeedLimitWarning)
            result = run_kinematics(case, level=level, speed=omega)
        for item in caught:
            if issubclass(item.category, SpeedLimitWarning):
                log.warning("warning: %s", item.message)
        return result

    output.analyse(case_file, run)
