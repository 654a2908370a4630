"""What the operating-point analysis shows: the coupled state, then the temperature field."""

from __future__ import annotations

import math
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING, Any

import xarray as xr

from ballscrew.analyses import thermal_report
from ballscrew.analyses.result import Figure, Section, Table, quantity
from ballscrew.analyses.roughness import roughness_summary
from ballscrew.lubrication import regime
from ballscrew.plotting import pyplot, save_figure

if TYPE_CHECKING:
    from ballscrew.analyses.operating_point import OperatingPoint, SpeedCurve

CELSIUS = 273.15


def summary(result: OperatingPoint) -> dict[str, Any]:
    """Scalars of the operating point (SI, with units) and the thermal model used; the shaft
    coolant's outlet temperature when the shaft is cooled."""
    scalars = {
        "case": result.case.name,
        "speed": quantity(result.speed, "rad/s"),
        "axial_load": quantity(result.axial_load, "N"),
        "friction_torque": quantity(result.friction_torque, "N*m"),
        "heat": quantity(result.heat, "W"),
        "efficiency": quantity(result.efficiency, ""),
        "efficiency_backdriving": quantity(result.efficiency_backdriving, ""),
        "efficiency_overall": quantity(result.efficiency_overall, "", "at rest: no work done"),
        "nut_temperature": quantity(result.nut_temperature, "K"),
        "screw_temperature": quantity(result.screw_temperature, "K"),
        "max_temperature": quantity(result.max_temperature, "K"),
        "viscosity": quantity(result.viscosity, "Pa*s"),
        "viscosity_source": result.viscosity_source,
        "viscosity_temperature": quantity(result.contact_temperature, "K"),
        "film_thickness": quantity(result.film_thickness, "m"),
        "film_thickness_minimum": quantity(result.film_thickness_minimum, "m"),
        "film_thickness_nut": quantity(result.film_thickness_nut, "m"),
        "film_roughness": quantity(result.film_roughness, "m"),
        "film_thickness_per_nut": {
            f"nut{k}": quantity(h, "m", "lifted off, dry or at rest")
            for k, h in enumerate(result.film_thickness_per_nut, start=1)
        },
        "iterations": result.iterations,
        "thermal_model": result.field.model,
    }
    outlet = result.field.coolant_outlet_temperature
    if outlet is not None:
        scalars["coolant_outlet_temperature"] = quantity(outlet, "K")
    friction = result.friction
    scalars["friction_model"] = friction.model
    scalars["friction_part"] = quantity(result.friction_part, "N*m")
    scalars["torque_parts"] = {k: quantity(v, "N*m") for k, v in friction.parts.items()}
    scalars["preload_torque"] = quantity(result.preload_torque, "N*m")
    scalars["catalogue_preload_torque"] = quantity(result.catalogue_preload_torque, "N*m")
    if math.isfinite(result.film_parameter):
        scalars["film_parameter"] = quantity(result.film_parameter, "")
        scalars["lubrication_regime"] = regime(result.film_parameter)
    if friction.asperity_share is not None:
        scalars["asperity_share"] = quantity(friction.asperity_share, "")
        scalars["surface"] = roughness_summary(result.case, "surface")
    if friction.traction_coefficient is not None:
        scalars["traction_coefficient"] = quantity(friction.traction_coefficient, "")
    if result.curve is not None:
        scalars["speed_curve"] = _curve_summary(result.curve)
    return scalars


#: SI unit of each quantity of a speed curve.
CURVE_UNITS = {
    "speed": "rad/s",
    "friction_torque": "N*m",
    "friction_part": "N*m",
    "heat": "W",
    "efficiency_overall": "",
    "nut_temperature": "K",
    "screw_temperature": "K",
    "viscosity": "Pa*s",
    "film_thickness": "m",
}


def _curve_summary(curve: SpeedCurve) -> dict[str, Any]:
    """The speed curve as lists with their SI units (NaN as None) and each point's warnings."""
    out: dict[str, Any] = {"axial_load": quantity(curve.axial_load, "N")}
    for key, unit in CURVE_UNITS.items():
        values = [float(v) if math.isfinite(v) else None for v in getattr(curve, key)]
        out[key] = {"value": values, "unit": unit}
    out["warnings"] = [list(w) for w in curve.warnings]
    return out


def fields(result: OperatingPoint) -> xr.Dataset:
    """The steady temperature field of the operating point, and its speed curve (dimension
    ``curve_speed``) when computed."""
    data = thermal_report.fields(result.field)
    curve = result.curve
    if curve is None:
        return data
    coords = {"curve_speed": ("curve_speed", curve.speed, {"units": "rad/s"})}
    variables = {
        f"curve_{key}": ("curve_speed", getattr(curve, key), {"units": unit})
        for key, unit in CURVE_UNITS.items()
        if key != "speed"
    }
    return data.merge(xr.Dataset(variables, coords=coords))


def figures(result: OperatingPoint) -> list[Figure]:
    """The speed curve (when computed), the steady temperature field and the elongation."""
    out = thermal_report.figures(result.field)
    if result.curve is not None:
        caption = (
            f"Torque, heat and temperatures against speed at F_a = {result.axial_load:g} N "
            "(coupled steady points, network model); the case's point marked."
        )
        out.insert(0, Figure("speed_curve", caption, partial(curve_plot, result)))
    return out


def curve_plot(result: OperatingPoint, path: Path) -> Path:
    """Screw and friction torque, heat, nut and screw temperatures against speed."""
    from ballscrew.analyses.operating_point import NUT_WARNING_TEMPERATURE

    curve = result.curve
    assert curve is not None
    plt = pyplot()
    rpm = curve.speed * 30.0 / math.pi
    fig, (torque, temp) = plt.subplots(1, 2, figsize=(9.0, 3.6), layout="constrained")
    torque.plot(rpm, curve.friction_torque, "b-o", ms=3, label="screw torque T")
    torque.plot(rpm, curve.friction_part, "b--", label="friction torque T_f")
    torque.set_xlabel("speed [rpm]")
    torque.set_ylabel("torque [N·m]", color="b")
    heat = torque.twinx()
    heat.plot(rpm, curve.heat, "r-s", ms=3, label="friction heat (right axis)")
    heat.set_ylabel("friction heat [W]", color="r")
    torque.grid(alpha=0.3)
    temp.plot(rpm, curve.nut_temperature - CELSIUS, "g-o", ms=3, label="nut")
    temp.plot(rpm, curve.screw_temperature - CELSIUS, "m-s", ms=3, label="screw under the nut")
    temp.axhline(NUT_WARNING_TEMPERATURE - CELSIUS, color="k", ls=":", lw=0.8, label="60 °C")
    temp.set_xlabel("speed [rpm]")
    temp.set_ylabel("temperature [°C]")
    temp.grid(alpha=0.3)
    if result.speed > 0.0:
        for ax in (torque, temp):
            ax.axvline(result.speed * 30.0 / math.pi, color="0.5", lw=0.8, label="this point")
    lines = [*torque.get_lines(), *heat.get_lines()]
    torque.legend(
        lines,
        [line.get_label() for line in lines],
        loc="upper left",
        bbox_to_anchor=(0.0, 0.93),
        fontsize=7,
    )
    temp.legend(fontsize=7)
    return save_figure(fig, path)


def _curve_section(curve: SpeedCurve) -> Section:
    """The speed curve as a table in engineering units, with each point's warnings."""
    rows = tuple(
        (
            w * 30.0 / math.pi,
            t,
            tf,
            q,
            e,
            tn - CELSIUS,
            ts - CELSIUS,
            1e3 * eta,
            1e9 * h,
            "; ".join(warn) or "–",
        )
        for w, t, tf, q, e, tn, ts, eta, h, warn in zip(
            curve.speed,
            curve.friction_torque,
            curve.friction_part,
            curve.heat,
            curve.efficiency_overall,
            curve.nut_temperature,
            curve.screw_temperature,
            curve.viscosity,
            curve.film_thickness,
            curve.warnings,
            strict=True,
        )
    )
    header = (
        "speed [rpm]",
        "screw torque T [N·m]",
        "friction torque [N·m]",
        "heat [W]",
        "efficiency F_a·L/(2π T) [-]",
        "nut [°C]",
        "screw [°C]",
        "viscosity [mPa·s]",
        "central film h_c [nm]",
        "warnings",
    )
    return Section(
        "Speed curve",
        paragraphs=(
            f"The coupled steady operating point at each speed and F_a = {curve.axial_load:g} N "
            "(network thermal model, the same friction model and lubricant).",
        ),
        tables=(Table(header, rows),),
        figures=("speed_curve",),
    )


#: Readable names of the torque parts of :class:`~ballscrew.friction.torque.FrictionTorque`.
PART_NAMES = {
    "work": "work on the load F_a·L/2π",
    "load": "friction of the working load",
    "preload": "preload drag (catalogue)",
    "sliding": "sliding and spin at the screw contacts",
    "groove_slip": "differential slip at the nut contacts",
    "ehl_rolling": "EHL rolling resistance",
    "hysteresis": "elastic hysteresis",
    "ball_ball": "ball–ball friction",
    "drag": "viscous drag on the balls",
    "seals": "seals and wipers",
    "recirculation": "ball returns",
}


def _torque_section(result: OperatingPoint) -> Section:
    """The friction model's torque by part, with the regime it ran in."""
    friction = result.friction
    rows = [(PART_NAMES.get(k, k), 1e3 * v) for k, v in friction.parts.items()]
    notes = [f"Friction model {friction.model!r}; the parts add up to the screw torque T."]
    if friction.model != "catalogue":
        catalogue = result.catalogue_preload_torque
        ratio = result.preload_torque / catalogue if catalogue > 0.0 else math.nan
        notes.append(
            f"Its torque at the preload (without the work on the load, the working load's "
            f"friction and the seals) is {1e3 * result.preload_torque:.4g} mN·m, "
            + (
                f"{ratio:.2f} × the makers' catalogue preload torque K F_p L/2π = "
                f"{1e3 * catalogue:.4g} mN·m (a reference value: makers allow ±20–35 % "
                "around it, THK A-689 Table 13; outside 0.5–2 × is a warning)."
                if math.isfinite(ratio)
                else "and the catalogue preload torque is 0 (no preload)."
            )
        )
    lam = result.film_parameter
    if math.isfinite(lam):
        notes.append(
            f"Film parameter Λ = h_c/σ = {lam:.3g} at the screw contact of the "
            f"loaded nut ({regime(lam)} lubrication)"
            + (
                f", asperity share ψ = {friction.asperity_share:.3g} (JGP, on the same σ), "
                f"traction coefficient μ = {friction.traction_coefficient:.3g}."
                if friction.asperity_share is not None and friction.traction_coefficient is not None
                else "."
            )
        )
    table = Table(("part", "torque [mN·m]"), tuple(rows))
    return Section("Torque by part", paragraphs=(" ".join(notes),), tables=(table,))


def sections(result: OperatingPoint) -> list[Section]:
    """The coupled state in engineering units, then the thermal model's own sections."""
    part = "flank" if result.case.screw.nuts == 1 else "nut"
    unloaded = "at rest" if result.speed == 0.0 else "lifted off or dry"

    def _film(h: float) -> float | str:
        return 1e9 * h if math.isfinite(h) else f"— ({unloaded})"

    rows: list[tuple[Any, ...]] = [
        ("speed [rpm]", result.speed * 30.0 / math.pi),
        ("axial load [N]", result.axial_load),
        ("screw torque T, work F_a·L/2π included [N·m]", result.friction_torque),
        ("friction part of T = heat / ω [N·m]", result.friction_part),
        ("friction heat [W]", result.heat),
        ("driving efficiency η = tan λ/tan(λ + ρ′) [-]", result.efficiency),
        (
            "back-driving efficiency η′ = tan(λ − ρ′)/tan λ (≤ 0: self-locking) [-]",
            result.efficiency_backdriving,
        ),
        (
            "efficiency at this point F_a·L/(2π T), preload and seals included [-]",
            result.efficiency_overall,
        ),
        ("nut temperature [°C]", result.nut_temperature - CELSIUS),
        ("screw temperature under the nut [°C]", result.screw_temperature - CELSIUS),
        ("largest temperature of the field [°C]", result.max_temperature - CELSIUS),
        ("lubricant viscosity at the contacts [mPa·s]", 1e3 * result.viscosity),
        ("viscosity from", result.viscosity_source),
        ("central film h_c, screw contact A of nut 1 [nm]", 1e9 * result.film_thickness),
        ("minimum film h_min, screw contact A [nm]", 1e9 * result.film_thickness_minimum),
        ("central film h_c, nut contact B [nm]", 1e9 * result.film_thickness_nut),
        *(
            (f"central film h_c, screw contact A of {part} {k} at its ball load [nm]", _film(h))
            for k, h in enumerate(result.film_thickness_per_nut, start=1)
            if k > 1
        ),
        ("raceway roughness σ of Λ [nm]", 1e9 * result.film_roughness),
        ("film parameter Λ = h_c/σ [-]", result.film_parameter),
        ("fixed-point iterations", result.iterations),
    ]
    coupled = Section(
        "Coupled operating point",
        paragraphs=(
            "Temperature, lubricant viscosity, friction torque and heat solved together: the "
            "friction heat of the nut heats screw and nut, which thins the lubricant, which "
            f"changes the friction; the {result.field.model} thermal model in steady state, "
            "iterated to 0.01 K.",
        ),
        tables=(Table(("quantity", "value"), tuple(rows)),),
    )
    curve = [] if result.curve is None else [_curve_section(result.curve)]
    return [coupled, _torque_section(result), *curve, *thermal_report.sections(result.field)]
