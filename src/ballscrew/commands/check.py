"""``ballscrew check``: the design check — life, static safety, speed, buckling, stiffness."""

from __future__ import annotations

from ballscrew.commands._common import CaseArg, Output, writes_results


@writes_results
def check(case_file: CaseArg, *, output: Output) -> None:
    """Every design value of the screw with its margin (needs a [design] section)."""
    from ballscrew.analyses.design_check import design_check

    output.analyse(case_file, design_check)
