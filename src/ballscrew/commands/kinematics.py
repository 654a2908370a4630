"""``ballscrew kinematics``: ball kinematics, ball balance, EHL film and drag torque."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from ballscrew.commands._common import CaseArg, ForceOpt, OutOpt, log, user_errors_exit_2


@user_errors_exit_2
def kinematics(
    case_file: CaseArg,
    out: OutOpt = Path("results/kinematics"),
    force: ForceOpt = False,
    level: Annotated[
        int | None, typer.Option(help="ball balance level 0, 1 or 2 (default: the case's)")
    ] = None,
    speed: Annotated[
        str | None,
        typer.Option(help='screw speed, e.g. "3000 rpm" or 314.16 (rad/s); default: the case\'s'),
    ] = None,
) -> None:
    """Ball speeds, spins, loads and contact angles, film, asperity share and drag torque."""
    import warnings

    from ballscrew.analyses.kinematics import run_kinematics
    from ballscrew.case import load_case
    from ballscrew.errors import InputError
    from ballscrew.kinematics.limits import SpeedLimitWarning
    from ballscrew.results import claim_output, write_results
    from ballscrew.units import to_si

    case = load_case(case_file)
    omega = None
    if speed is not None:
        try:
            omega = to_si(speed, "angular_velocity")
        except ValueError as exc:
            raise InputError("--speed", speed, str(exc)) from None
    with claim_output(out, command="kinematics", force=force, inputs=[case_file]):
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always", SpeedLimitWarning)
            result = run_kinematics(case, level=level, speed=omega)
        for item in caught:
            if issubclass(item.category, SpeedLimitWarning):
                log.warning("warning: %s", item.message)
        nut = result.states[1]
        log.info(
            "V = %.4g m/s, Q_A = %.4g N, Q_B = %.4g N, T = %.4g N m (catalogue %.4g N m)",
            nut.ball_speed,
            nut.load_screw,
            nut.load_nut,
            result.model_torque,
            result.catalogue_torque,
        )
        folder = write_results(result, out, case_file)
    log.info("wrote %s", folder / "report.html")
