"""``ballscrew contact``: pressure at the screw and nut contacts of one ball."""

from __future__ import annotations

from pathlib import Path

from ballscrew.commands._common import (
    CaseArg,
    ExportOpt,
    ForceOpt,
    OutOpt,
    SetOpt,
    analyse,
    command,
)


@command
def contact(
    case_file: CaseArg,
    out: OutOpt = Path("results/contact"),
    force: ForceOpt = False,
    set_: SetOpt = None,
    export: ExportOpt = None,
) -> None:
    """Solve the screw-side and nut-side contact of one ball of the loaded nut."""
    from ballscrew.analyses.ball_contact import solve_ball_contacts

    analyse("contact", case_file, out, (force, set_, export), solve_ball_contacts)
