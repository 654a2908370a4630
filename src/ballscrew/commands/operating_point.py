"""``ballscrew operating-point``: friction torque, heat, temperatures, viscosity and film."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from ballscrew.commands._common import (
    CaseArg,
    ExportOpt,
    ForceOpt,
    OutOpt,
    SetOpt,
    command,
    export_formats,
    finish,
    parse_sets,
)


@command
def operating_point(
    case_file: CaseArg,
    out: OutOpt = Path("results/operating-point"),
    force: ForceOpt = False,
    speed: Annotated[
        str | None,
        typer.Option(
            help='screw speed, e.g. "1500 rpm" or 157.1 (rad/s); default: the case\'s',
            metavar="SPEED",
        ),
    ] = None,
    axial_load: Annotated[
        str | None,
        typer.Option(
            "--axial-load", help='axial load, e.g. "2 kN"; default: the case\'s', metavar="FORCE"
        ),
    ] = None,
    set_: SetOpt = None,
    export: ExportOpt = None,
) -> None:
    """The coupled steady state: friction torque, heat, efficiency, temperatures and film."""
    from ballscrew.analyses.operating_point import operating_point as solve
    from ballscrew.case import load_case
    from ballscrew.errors import InputError
    from ballscrew.results import claim_output, write_results
    from ballscrew.units import to_si

    formats = export_formats(export)
    case = load_case(case_file, parse_sets(set_))
    values = {}
    for option, text, kind in (
        ("--speed", speed, "angular_velocity"),
        ("--axial-load", axial_load, "force"),
    ):
        if text is not None:
            try:
                values[option] = to_si(text, kind)
            except ValueError as exc:
                raise InputError(option, text, str(exc)) from None
    with claim_output(out, command="operating-point", force=force, inputs=[case_file]):
        result = solve(case, values.get("--speed"), values.get("--axial-load"))
        folder = write_results(result, out, case_file)
        finish(folder, formats)
