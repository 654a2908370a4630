"""``ballscrew contact``: pressure at the screw and nut contacts of one ball."""

from __future__ import annotations

from pathlib import Path

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
def contact(
    case_file: CaseArg,
    out: OutOpt = Path("results/contact"),
    force: ForceOpt = False,
    set_: SetOpt = None,
    export: ExportOpt = None,
) -> None:
    """Solve the screw-side and nut-side contact of one ball of the loaded nut."""
    from ballscrew.analyses.ball_contact import solve_ball_contacts
    from ballscrew.case import load_case
    from ballscrew.results import claim_output, write_results

    formats = export_formats(export)
    case = load_case(case_file, parse_sets(set_))
    with claim_output(out, command="contact", force=force, inputs=[case_file]):
        result = solve_ball_contacts(case)
        folder = write_results(result, out, case_file)
        finish(folder, formats)
