"""Thermal model: THK's heat-generation test of a BLK3232 screw (catalogue page A-821)."""

from __future__ import annotations

from typing import Any

import pytest

import ballscrew
from ballscrew.case import case_from_dict

from .test_thermal_sources import PHYSICS_ASSUMPTIONS, PHYSICS_MODEL, SKF_ASSUMPTION, physics_raw

SOURCE = "THK General Catalog, A-821"

ASSUMPTIONS = (
    "shaft Ø 32 mm, lead 32 mm, 1000 rpm, stroke 1000 mm, internal load 0.98 kN taken as the "
    "preload of a single nut, 90 min (source)",
    "pitch (ball-centre) diameter 33.75 mm, also the smeared shaft diameter (ASSUMED; THK's "
    "SBN3210, a 32 mm screw, has d_p = 33.75 mm, catalogue B-576)",
    "ball Ø 6.35 mm, 60 loaded balls (3.6 turns), contact angle 45°, conformity 0.52 (ASSUMED; "
    "not printed)",
    "shaft length 1426 mm = the overall length of the model code '+1426L' (ASSUMED)",
    "nut OD 1.75 d_m = 59 mm and length 2.5 d_m = 84 mm (GUESS: the thermal model's defaults; "
    "a 73 × 80 mm nut gives 10.0 K instead)",
    "heat: catalogue preload torque K F_p L/2π (0.454 N m, 47.6 W), half into the screw (GUESS: "
    "the example case's screw_heat_fraction 0.5); the AFG grease is not modelled",
    "continuous motion at 1000 rpm, the 100 ms accelerations and the reversals ignored (ASSUMED; "
    "the mean speed is a few % lower)",
    "stroke heat and contact averaged over the 1000 mm stroke (stroke mode 'averaged')",
    "support bearings' heat neglected (ASSUMED; mounting not published; the example case's "
    "bearings at both ends add 0.02 K at mid-shaft)",
    "convection: the model's correlations (Kreith rotating cylinder for the screw, laminar flat "
    "plate for the nut, Churchill–Chu at the computed surface rise); ambient = initial "
    "temperature 25.6 °C = 34.5 − 8.9 (source)",
    "nut seated in a table: the model's default [thermal.mounting] (GUESS: h_c = 2000 W/(m² K) "
    "over half the nut's outer area, a 1 m² table at 10 W/(m² K)); the test bed's mounting was "
    "not published (a free nut in still air gives 10.7 K)",
    "sensor on the shaft axis at mid-length ('temperature at shaft center area'; ASSUMED), "
    "value at 90 min (the end of the printed curve)",
    "ball contact: the headline TCR (CMY) of the example case's raceway (D = 1.59, G = 9e-10 m; "
    "ASSUMED)",
)


SUBJECT = {"model": "thermal_field (network)", "source": SOURCE, "assumptions": ASSUMPTIONS}
"""What every comparison of this module shares."""


def _blk3232_raw(raw: dict[str, Any], data: dict[str, Any]) -> dict[str, Any]:
    raw["screw"].update(pitch_diameter="33.75 mm", lead="32 mm", balls_per_nut=60, nuts=1)
    raw["operating"].update(
        preload=f"{data['internal_load_N']} N", axial_load="0 N", speed="1000 rpm"
    )
    ambient = data["temperature_no_seal_degC"] - data["temperature_rise_no_seal_K"]
    thermal = raw["thermal"]
    for key in ("nut_outer_diameter", "nut_length"):
        del thermal[key]
    thermal.update(
        model="network",
        shaft_length=f"{data['overall_length_mm']} mm",
        shaft_diameter="33.75 mm",
        ambient_temperature=f"{ambient} degC",
        bearings=[],
        drag_torque={"source": "catalogue"},
        stroke={"length": f"{data['stroke_mm']} mm", "mode": "averaged"},
        transient={"duration": f"{data['test_duration_min']} min", "time_step": "30 s"},
        sensors=[
            {
                "name": "shaft centre",
                "body": "screw",
                "r": "0 mm",
                "z": f"{data['overall_length_mm'] / 2} mm",
            }
        ],
    )
    return raw


CATALOGUE_BASIS = (
    "the rise is proportional to the heat input, and the heat comes from the catalogue torque, "
    "whose real values may lie ±20 % (C0) to ±35 % (C5) from it (THK A-689 Table13, row "
    "600-1000 N mm, L/d <= 40; the row of this screw, 454 N mm and L/d = 45, was not in the "
    "retrieved text, so the quoted C5 value is used); the printed 0.1 K resolution is negligible"
)

PHYSICS_HEAT = (
    *PHYSICS_ASSUMPTIONS,
    "grease polyurea_nlgi2_vg100 (ASSUMED: THK AFG is a urea-thickened grease on a 'low "
    "viscosity' synthetic base oil, A-968, grade not printed; the library's lithium VG 32 grease "
    "gives 1.4 K instead of 1.6 K)",
)


@pytest.mark.parametrize("heat", ["catalogue", "physics", "physics_skf"])
def test_thk_blk3232_shaft_temperature_rise(validation, dataset, base_raw, heat) -> None:
    """The catalogue preload torque, or the physics friction model's operating point (film or
    SKF traction law), as heat."""
    data = dataset("thermal", "thk_blk3232_heat_test")
    raw = _blk3232_raw(base_raw, data)
    subject, record, basis = SUBJECT, "thk_blk3232_shaft_rise_no_seal", CATALOGUE_BASIS
    if heat != "catalogue":
        skf = heat == "physics_skf"
        raw = physics_raw(raw, "polyurea_nlgi2_vg100", "skf" if skf else "film")
        common = tuple(a for a in ASSUMPTIONS if not a.startswith("heat:"))
        heat_assumptions = (*PHYSICS_HEAT, *((SKF_ASSUMPTION,) if skf else ()))
        model = PHYSICS_MODEL + (", traction law skf" if skf else "")
        subject = {**SUBJECT, "model": model, "assumptions": (*common, *heat_assumptions)}
        record += "_physics" + ("_skf" if skf else "")
        basis = (
            "the band of the catalogue row (±35 %, the makers' scatter of real preload torques "
            "about their formula): a physical model should do at least as well"
        )
    field = ballscrew.thermal_field(case_from_dict(raw), model="network")
    validation.check(
        record,
        **subject,
        reference=data,
        quantity="shaft-centre temperature rise after 90 min, no seal",
        unit="K",
        measured=data["temperature_rise_no_seal_K"],
        predicted=field.sensors[0].final - field.ambient_temperature,
        tolerance=0.35,
        relative=True,
        tolerance_basis=basis,
        known_miss=heat != "catalogue",
    )


def test_thk_blk3232_wiper_ring(validation, dataset) -> None:
    data = dataset("thermal", "thk_blk3232_heat_test")
    validation.not_compared(
        "thk_blk3232_shaft_rise_wiper",
        **SUBJECT,
        reference=data,
        quantity="shaft-centre temperature rise after 90 min, with wiper ring W",
        unit="K",
        measured=data["temperature_rise_wiper_K"],
        reason="no published torque of the wiper ring W: the heat of a seal enters through the "
        "friction model ([friction] seals, seal_force × d_m/2, half into the screw) with "
        "drag_torque.source = 'operating_point', but its 5 N lip force is a GUESS; THK prints "
        "seal resistance only for its LM blocks (A-372 to A-374), not for ball-screw wipers "
        "(A-819 to A-821). Missing: a measured wiper torque.",
    )
