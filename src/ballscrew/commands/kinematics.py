"""``ballscrew kinematics``: ball kinematics, ball balance, EHL film and drag torque."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Any

import typer

from ballscrew.commands._common import (
    CaseArg,
    ExportOpt,
    ForceOpt,
    OutOpt,
    SetOpt,
    analyse,
    command,
    log,
    quantity_option,
)


@command
def kinematics(
    case_file: CaseArg,
    out: OutOpt = Path("results/kinematics"),
    force: ForceOpt = False,
    level: Annotated[
        int | None,
        typer.Option(help="ball balance level 0, 1 or 2 (default: the case's)", metavar="LEVEL"),
    ] = None,
    speed: Annotated[
        str | None,
        typer.Option(
            help='screw speed, e.g. "3000 rpm" or 314.16 (rad/s); default: the case\'s',
            metavar="SPEED",
        ),
    ] = None,
    set_: SetOpt = None,
    export: ExportOpt = None,
) -> None:
    """Ball speeds, spins, loads and contact angles, film, asperity share and drag torque."""
    import warnings

    from ballscrew.analyses.kinematics import run_kinematics
    from ballscrew.kinematics.limits import SpeedLimitWarning

    omega = quantity_option("--speed", speed, "angular_velocity")

    def run(case: Any) -> Any:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always", SpeedLimitWarning)
            result = run_kinematics(case, level=level, speed=omega)
        for item in caught:
            if issubclass(item.category, SpeedLimitWarning):
                log.warning("warning: %s", item.message)
        return result

    analyse("kinematics", case_file, out, (force, set_, export), run)
