"""``ballscrew duty``: temperatures and thermal elongation over the case's duty cycle."""

from __future__ import annotations

from ballscrew.commands._common import CaseArg, Output, ThermalModelOpt, writes_results


@writes_results
def duty(case_file: CaseArg, model: ThermalModelOpt = None, *, output: Output) -> None:
    """A working day of thermal error: elongation and temperatures over the [[duty]] cycle.

    The duty run alone; `ballscrew thermal` writes it too, next to the field at the operating
    point."""
    from ballscrew.analyses.duty_thermal import thermal_duty

    output.analyse(case_file, lambda case: thermal_duty(case, model))
