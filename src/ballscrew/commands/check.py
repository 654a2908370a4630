"""``ballscrew check``: the design check — life, static safety, speed, buckling, stiffness."""

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
def check(
    case_file: CaseArg,
    out: OutOpt = Path("results/check"),
    force: ForceOpt = False,
    set_: SetOpt = None,
    export: ExportOpt = None,
) -> None:
    """Every design value of the screw with its margin (needs a [design] section)."""
    from ballscrew.analyses.design_check import design_check
    from ballscrew.case import load_case
    from ballscrew.results import claim_output, write_results

    formats = export_formats(export)
    case = load_case(case_file, parse_sets(set_))
    with claim_output(out, command="check", force=force, inputs=[case_file]):
        result = design_check(case)
        folder = write_results(result, out, case_file)
        finish(folder, formats)
