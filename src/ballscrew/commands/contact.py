"""``ballscrew contact``: pressure at the screw and nut contacts of one ball."""

from __future__ import annotations

from pathlib import Path

from ballscrew.commands._common import CaseArg, ForceOpt, OutOpt, log, user_errors_exit_2


@user_errors_exit_2
def contact(
    case_file: CaseArg, out: OutOpt = Path("results/contact"), force: ForceOpt = False
) -> None:
    """Solve the screw-side and nut-side contact of one ball of the loaded nut."""
    from ballscrew.analyses.ball_contact import solve_ball_contacts
    from ballscrew.case import load_case
    from ballscrew.results import claim_output, write_results

    case = load_case(case_file)
    with claim_output(out, command="contact", force=force, inputs=[case_file]):
        result = solve_ball_contacts(case)
        folder = write_results(result, out, case_file)
    log.info("wrote %s", folder / "report.html")
