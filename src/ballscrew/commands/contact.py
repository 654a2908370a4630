"""``ballscrew contact``: pressure at the screw and nut contacts of one ball."""

from __future__ import annotations

from ballscrew.commands._common import CaseArg, Output, writes_results


@writes_results
def contact(case_file: CaseArg, *, output: Output) -> None:
    """Solve the screw-side and nut-side contact of one ball of the loaded nut."""
    from ballscrew.analyses.ball_contact import solve_ball_contacts

    output.analyse(case_file, solve_ball_contacts)
