"""What the operating-point analysis shows: the coupled state, then the temperature field."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import xarray as xr

from ballscrew.analyses import thermal_report
from ballscrew.analyses.result import Figure, Section, Table, quantity
from ballscrew.lubrication import regime

if TYPE_CHECKING:
    from ballscrew.analyses.operating_point import OperatingPoint

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
    if math.isfinite(result.film_parameter):
        scalars["film_parameter"] = quantity(result.film_parameter, "")
        scalars["lubrication_regime"] = regime(result.film_parameter)
    if friction.asperity_share is not None:
        scalars["asperity_share"] = quantity(friction.asperity_share, "")
    if friction.traction_coefficient is not None:
        scalars["traction_coefficient"] = quantity(friction.traction_coefficient, "")
    return scalars


def fields(result: OperatingPoint) -> xr.Dataset:
    """The steady temperature field of the operating point."""
    return thermal_report.fields(result.field)


def figures(result: OperatingPoint) -> list[Figure]:
    """The steady temperature field and the screw's elongation."""
    return thermal_report.figures(result.field)


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
    return [coupled, _torque_section(result), *thermal_report.sections(result.field)]
