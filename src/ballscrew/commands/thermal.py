"""``ballscrew thermal``: temperature field and thermal elongation of the screw."""

from __future__ import annotations

from ballscrew.commands._common import CaseArg, Output, ThermalModelOpt, writes_results


@writes_results
def thermal(case_file: CaseArg, model: ThermalModelOpt = None, *, output: Output) -> None:
    """Steady and transient temperatures, sensors and thermal elongation (needs [thermal])."""
    from ballscrew.analyses.thermal import thermal_field

    output.analyse(case_file, lambda case: thermal_field(case, model))
