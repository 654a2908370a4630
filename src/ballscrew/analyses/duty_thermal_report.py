"""What the duty-cycle run shows: elongation and temperatures over the day, per segment."""

from __future__ import annotations

from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import xarray as xr

from ballscrew.analyses.result import Figure, Section, Table, quantity
from ballscrew.plotting import legend_outside, line_styles, plain, pyplot, save_figure
from ballscrew.units import format_quantity

if TYPE_CHECKING:
    from ballscrew.analyses.duty_thermal import DutyThermal

CELSIUS = 273.15


def summary(result: DutyThermal) -> dict[str, Any]:
    """Peak and final elongation and temperatures, the heat of each segment, the balance."""
    return {
        "case": result.case.name,
        "model": result.model,
        "duration": quantity(result.time[-1], "s"),
        "peak_elongation": quantity(float(result.elongation.max()), "m"),
        "final_elongation": quantity(float(result.elongation[-1]), "m"),
        "peak_temperature": quantity(float(result.max_temperature.max()), "K"),
        "final_temperature": quantity(float(result.max_temperature[-1]), "K"),
        "segment_heat": [quantity(q, "W") for q in result.segment_heat],
        "peak_friction_heat": quantity(float(result.friction_heat.max()), "W"),
        "final_contact_temperature": quantity(float(result.contact_temperature[-1]), "K"),
        "final_viscosity": quantity(float(result.viscosity[-1]), "Pa*s"),
        "heat_in": quantity(result.heat_in, "J"),
        "heat_balance_error": quantity(result.heat_balance_error, ""),
    } | _coolant_summary(result)


def _coolant_summary(result: DutyThermal) -> dict[str, Any]:
    """Peak and final outlet temperature of the shaft coolant (nothing for a solid shaft)."""
    outlet = result.coolant_outlet_temperature
    if outlet is None:
        return {}
    return {
        "peak_coolant_outlet_temperature": quantity(float(outlet.max()), "K"),
        "final_coolant_outlet_temperature": quantity(float(outlet[-1]), "K"),
    }


def fields(result: DutyThermal) -> xr.Dataset:
    """The time histories with units."""
    outlet = result.coolant_outlet_temperature
    cooled = (
        {} if outlet is None else {"coolant_outlet_temperature": ("time", outlet, {"units": "K"})}
    )
    return xr.Dataset(
        {
            **cooled,
            "max_temperature": ("time", result.max_temperature, {"units": "K"}),
            "elongation": ("time", result.elongation, {"units": "m"}),
            "sensor_temperature": (("time", "sensor"), result.sensors, {"units": "K"}),
            "friction_heat": ("time", result.friction_heat, {"units": "W"}),
            "contact_temperature": ("time", result.contact_temperature, {"units": "K"}),
            "viscosity": ("time", result.viscosity, {"units": "Pa*s"}),
        },
        coords={
            "time": ("time", result.time, {"units": "s"}),
            "sensor": ("sensor", list(result.sensor_names)),
        },
        attrs={"case": result.case.name, "model": result.model},
    )


def day_plot(result: DutyThermal, path: Path) -> Path:
    """Elongation and temperatures against time, the moving segments shaded."""
    plt = pyplot()
    hours = result.time / 3600.0
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7.5, 5.5), sharex=True, layout="constrained")
    for ax in (top, bottom):
        for phase in result.phases:
            if phase.mean_speed > 0.0:
                ax.axvspan(phase.start / 3600.0, phase.end / 3600.0, color="0.93", lw=0)
    top.plot(hours, 1e6 * result.elongation, color="C0")
    top.set_ylabel("thermal elongation [µm]")
    bottom.plot(hours, result.max_temperature - CELSIUS, color="k", lw=1.8, label="largest")
    styles = line_styles(len(result.sensor_names))
    for k, name in enumerate(result.sensor_names):
        style = {**styles[k], "marker": None}
        bottom.plot(hours, result.sensors[:, k] - CELSIUS, lw=1, label=plain(name), **style)
    bottom.set_ylabel("temperature [°C]")
    bottom.set_xlabel("time [h] (shaded: the screw turns)")
    legend_outside(bottom, fontsize=8)
    fig.suptitle(plain(f"{result.case.name}: duty cycle ({result.model} model)"), fontsize=10)
    return save_figure(fig, path)


def figures(result: DutyThermal) -> list[Figure]:
    """The day's elongation and temperatures."""
    return [
        Figure(
            "duty_day",
            "Thermal elongation and temperatures over the duty cycle.",
            partial(day_plot, result),
        )
    ]


def time_base(result: DutyThermal) -> str:
    """What the histories span: ``2 segments (1 h) run 8 times: 8 h in all``."""
    repeat = result.case.duty_repeat
    cycle = sum(segment.duration for segment in result.case.duty)
    return (
        f"{len(result.case.duty)} segments ({format_quantity(cycle, 'time')}) run {repeat} "
        f"{'time' if repeat == 1 else 'times'}: {format_quantity(result.time[-1], 'time')} "
        "in all"
    )


def sections(result: DutyThermal) -> list[Section]:
    """The segments with their mean heat, then the day's peaks."""
    rows = tuple(
        (
            k + 1,
            segment.speed * 30.0 / np.pi,
            segment.axial_load,
            1e3 * segment.stroke,
            segment.dwell,
            segment.duration / 60.0,
            heat,
        )
        for k, (segment, heat) in enumerate(zip(result.case.duty, result.segment_heat, strict=True))
    )
    peaks = (
        ("peak elongation [µm]", 1e6 * float(result.elongation.max())),
        ("final elongation [µm]", 1e6 * float(result.elongation[-1])),
        ("peak temperature [°C]", float(result.max_temperature.max()) - CELSIUS),
        ("peak friction heat [W]", float(result.friction_heat.max())),
        ("final contact temperature [°C]", float(result.contact_temperature[-1]) - CELSIUS),
        ("heat balance error [-]", result.heat_balance_error),
    )
    if result.coolant_outlet_temperature is not None:
        peaks += (
            (
                "peak shaft coolant outlet temperature [°C]",
                float(result.coolant_outlet_temperature.max()) - CELSIUS,
            ),
        )
    return [
        Section(
            "Duty cycle",
            paragraphs=(
                f"{time_base(result)}, averaged over strokes and dwells. The friction heat of "
                "each time step is taken "
                "with the lubricant at the contact temperature of the step before; the table "
                "gives each segment's heat at its steady coupled operating point.",
            ),
            tables=(
                Table(
                    (
                        "segment",
                        "speed [rpm]",
                        "axial load [N]",
                        "stroke [mm]",
                        "dwell [s]",
                        "duration [min]",
                        "steady mean friction heat [W]",
                    ),
                    rows,
                ),
            ),
        ),
        Section(
            "Temperatures and elongation over the day",
            tables=(Table(("quantity", "value"), peaks),),
            figures=("duty_day",),
        ),
    ]
