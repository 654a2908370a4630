"""Every analysis of the package, described once for the command line, sweeps and the index.

Adding an analysis is one composer module, one entry here and one command module.
"""

from __future__ import annotations

from ballscrew.analyses.ball_contact import contact_scalars
from ballscrew.analyses.design_check import design_scalars
from ballscrew.analyses.duty_thermal import duty_scalars
from ballscrew.analyses.operating_point import operating_point_scalars
from ballscrew.analyses.result import ANALYSES, Analysis
from ballscrew.analyses.screw_tcr import tcr_scalars
from ballscrew.analyses.thermal import (
    thermal_fe_scalars,
    thermal_network_scalars,
    thermal_scalars,
)
from ballscrew.errors import InputError

__all__ = ["ANALYSES", "sweep_function"]

_THERMAL_HEADLINES = (
    "steady.max_temperature_rise",
    "steady.elongation",
    "heat_balance.heat_input",
)

for _analysis in (
    Analysis(
        "contact",
        "pressure at the screw and nut contacts of one ball against Hertz",
        scalars=contact_scalars,
        headlines=(
            "ball_load",
            "contacts.screw.numerical.peak_pressure",
            "contacts.screw.relative_difference_to_hertz.peak_pressure",
        ),
        key_figure="pressure_screw.png",
    ),
    Analysis(
        "tcr",
        "thermal contact resistance of every contact, nut and the screw",
        scalars=tcr_scalars,
        headlines=("resistance", "resistance_per_area", "apparent_area"),
        key_figure="tcr_nut1_screw.png",
    ),
    Analysis(
        "thermal",
        "temperature field and thermal elongation (the case's [thermal] model)",
        scalars=thermal_scalars,
        headlines=(*_THERMAL_HEADLINES, "duty.peak_elongation", "duty.final_elongation"),
        labels={
            "duty.peak_elongation": "duty cycle: peak elongation",
            "duty.final_elongation": "duty cycle: final elongation",
        },
        key_figure="temperature_map.png",
    ),
    Analysis(
        "thermal-network",
        "steady temperature field of the 1-D network model (fast sweeps)",
        scalars=thermal_network_scalars,
        headlines=_THERMAL_HEADLINES,
    ),
    Analysis(
        "thermal-fe",
        "steady temperature field of the axisymmetric FE model (sweeps)",
        scalars=thermal_fe_scalars,
        headlines=_THERMAL_HEADLINES,
    ),
    Analysis(
        "operating-point",
        "coupled friction torque, heat, temperatures, viscosity and film",
        scalars=operating_point_scalars,
        headlines=(
            "friction_torque",
            "friction_part",
            "heat",
            "efficiency",
            "nut_temperature",
            "screw_temperature",
            "viscosity",
            "film_thickness",
        ),
        labels={
            "friction_torque": "screw torque (work on the load included)",
            "friction_part": "friction torque",
            "efficiency": "driving efficiency",
            "viscosity": "viscosity at the contacts",
            "film_thickness": "central film, screw contact",
        },
        key_figure="temperature_map.png",
    ),
    Analysis(
        "duty",
        "temperatures and thermal elongation over the [[duty]] cycle",
        scalars=duty_scalars,
        headlines=("peak_elongation", "final_elongation", "peak_temperature"),
        key_figure="duty_day.png",
    ),
    Analysis(
        "check",
        "design check: life, static safety, speed, buckling and stiffness with margins",
        scalars=design_scalars,
        headlines=(
            "rating_life",
            "life_hours",
            "static_safety_factor",
            "drive_stiffness",
            "axial_stiffness",
            "nut_stiffness",
            "margins.speed.ratio",
        ),
        key_figure="stiffness_curve.png",
    ),
    Analysis(
        "kinematics",
        "ball speeds, spins, loads, film, asperity share and drag torque",
        headlines=(
            "nuts.nut1.orbital_speed",
            "nuts.nut1.spin_screw",
            "nuts.nut1.asperity_share",
            "nuts.nut1.film_thickness_central",
            "viscosity",
            "drag_torque.contact_losses",
            "drag_torque.catalogue",
        ),
        labels={
            "viscosity": "viscosity of the film (see viscosity_source)",
            "drag_torque.contact_losses": "drag torque: ball contacts' losses only",
            "drag_torque.catalogue": "drag torque: catalogue preload torque",
        },
        key_figure="sliding_high_speed.png",
    ),
    Analysis(
        "wear",
        "raceway wear, preload and drag torque over the load programme",
        headlines=(
            "revolutions",
            "max_wear_depth",
            "final_preload",
            "final_torque",
            "ellipse_major_axis",
        ),
        key_figure="torque_preload.png",
    ),
    Analysis(
        "calibrate",
        "wear coefficient (and torque scale) fitted to a measured history",
        headlines=(
            "wear_coefficient",
            "wear_coefficient_standard_error",
            "torque_scale",
            "torque_offset",
            "rms_residual",
        ),
    ),
    Analysis(
        "surface",
        "fractal D and G of a measured or synthetic profile",
        headlines=("recommended.D", "recommended.G"),
        key_figure="psd.png",
    ),
):
    ANALYSES.add(_analysis.name, _analysis.title, _analysis)


def sweep_function(name: str, field: str = "--analysis") -> Analysis:
    """The descriptor of the sweepable analysis ``name``; else an :class:`InputError` naming
    ``field`` (the command's option, or ``analysis`` from Python)."""
    sweepable = [n for n, a in ANALYSES.items() if a.scalars is not None]
    if name not in sweepable:
        raise InputError(field, name, f"one of {', '.join(sweepable)}")
    return ANALYSES[name]
