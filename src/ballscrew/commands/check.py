"""``ballscrew check``: the design check — life, static safety, speed, buckling, stiffness."""

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
def check(
    case_file: CaseArg,
    out: OutOpt = Path("results/check"),
    force: ForceOpt = False,
    set_: SetOpt = None,
    export: ExportOpt = None,
) -> None:
    """Every design value of the screw with its margin (needs a [design] section)."""
    from ballscrew.analyses.design_check import design_check

    analyse("check", case_file, out, (force, set_, export), design_check)
