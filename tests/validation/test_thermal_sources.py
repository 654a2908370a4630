"""Thermal model against further published data: HIWIN's preload test and THK's elongation example.

* HIWIN (catalogue S99TE20-1610, 2016, section 4.6, Fig 4.30; the same test in BS-08-2-EN-1704-K,
  2017, Fig. 3.26): nut temperature of an R40-10-B2-FDW double nut over 240 min at 500 and
  1500 rpm with 980 and 1960 N preload; the text reads the figure as "doubling the preload of the
  nut will increase the temperature about 5 degrees". A measurement, independent of THK's.
* THK General Catalog, A-715 equation (38) and the example on A-731: a 5 °C rise of a 1000 mm
  thread with ρ = 12e-6 /°C elongates it by 0.06 mm. A maker's worked example (verification of
  the elongation integral ΔL = α∫θ̄ dz), not a measurement.

Each temperature case runs twice: with the catalogue preload torque as the heat (the makers'
reference value) and with the coupled operating point of the physics friction model
(``[friction] model = "ball_model"``, grease supply), whose heat follows from the lubricant's
viscosity at the computed temperature.
"""

from __future__ import annotations

import copy
from typing import Any

import numpy as np
import pytest

import ballscrew
from ballscrew.case import case_from_dict
from ballscrew.thermal.elongation import thermal_elongation

HIWIN_SOURCE = "HIWIN S99TE20-1610 (2016), section 4.6, Fig 4.30"
THK_SOURCE = "THK General Catalog, A-715 eq. (38) and A-731"

HIWIN_ASSUMPTIONS = (
    "R40-10-B2-FDW double nut, ball 6.35 mm, 2 circuits of 2.5 turns, 1500 rpm, preload 980 and "
    "1960 N (100 and 200 kgf), 240 min (source); the preload taken as that of each nut against "
    "the spacer (ASSUMED)",
    "pitch diameter 41.4 mm, the R40-10 B2 nut of HIWIN's example 4.5-5, also the smeared shaft "
    "diameter (ASSUMED from the same catalogue)",
    "'about 5 degrees' read as the rise of the nut temperature at the end of the 1500 rpm curves "
    "(ASSUMED: the sentence names no speed; at 500 rpm the model gives 1.3 K for the same "
    "doubling, the heat being three times smaller)",
    "100 balls per nut (ASSUMED: 5 loaded turns of 20.5 ball pitches less the return gaps), "
    "contact angle 45°, conformity 0.52 (ASSUMED; the catalogue torque does not use them)",
    "shaft length 1200 mm, the overall length of example 4.5-5 (ASSUMED; not printed for the "
    "test), nut at mid-shaft",
    "stroke 250 mm averaged over the shaft, continuous rotation (ASSUMED: the stroke printed "
    "with Fig 4.31 of the same screw; Fig 4.30 gives none; a nut held still gives 3.9 K)",
    "nut OD 1.75 d_m and length 2.5 d_m (GUESS: the thermal model's defaults)",
    "support bearings' heat neglected (ASSUMED; the difference of two preloads of the nut does "
    "not depend on it to first order)",
    "nut seated in a table: the model's default [thermal.mounting] (GUESS); convection by the "
    "model's correlations; ambient 20 °C (ASSUMED)",
    "sensor: the nut body (the network model has one temperature per nut)",
)

HIWIN_CATALOGUE_HEAT = (
    "heat: catalogue preload torque K F_p L/2π of the double nut (0.28 and 0.56 N m, 44 and "
    "88 W), half into the screw (GUESS: the example case's screw_heat_fraction); the lubricant "
    "of the test is not published",
)


def _hiwin_raw(raw: dict[str, Any], data: dict[str, Any], preload: float) -> dict[str, Any]:
    raw["screw"].update(
        pitch_diameter=f"{data['pitch_diameter_mm']} mm",
        lead=f"{data['lead_mm']} mm",
        ball_diameter=f"{data['ball_diameter_mm']} mm",
        balls_per_nut=100,
        nuts=2,
    )
    raw["operating"].update(
        preload=f"{preload} N", axial_load="0 N", speed=f"{data['speed_rpm']} rpm"
    )
    thermal = raw["thermal"]
    for key in ("nut_outer_diameter", "nut_length"):
        del thermal[key]
    thermal.update(
        model="network",
        shaft_length="1200 mm",
        shaft_diameter=f"{data['pitch_diameter_mm']} mm",
        ambient_temperature="20 degC",
        bearings=[],
        drag_torque={"source": "catalogue"},
        stroke={"length": "250 mm", "mode": "averaged"},
        transient={"duration": f"{data['test_duration_min']} min", "time_step": "60 s"},
        sensors=[{"name": "nut", "body": "nut", "r": "36 mm", "z": "600 mm"}],
    )
    return raw


PHYSICS_MODEL = "thermal_field (network) + operating point, friction ball_model"

PHYSICS_ASSUMPTIONS = (
    "heat: the coupled operating point of the physics friction model (ball_model: traction, EHL "
    "rolling, hysteresis, ball–ball friction, drag; no seals), its heat split between nut and "
    "screw by the model; the other friction parameters are the example case's GUESSES",
    "lubricant: grease supply of the library grease named in the row (ASSUMED: the test's "
    "lubricant is not published, or published without its base-oil viscosity)",
)


SKF_ASSUMPTION = (
    "traction law skf: SKF sliding weighting φ_bl = exp[−2.6e-8 (n ν)^1.4 d_m], μ_bl = 0.15, "
    "μ_EHL = 0.05 (SKF Rolling bearings 2013), n the screw speed, ν the base oil's at the "
    "operating point, d_m the pitch diameter (ASSUMED mapping of the bearing's mean diameter)"
)


def physics_raw(raw: dict[str, Any], lubricant: str, traction: str = "film") -> dict[str, Any]:
    """``raw`` with the balls' heat from the physics friction model, greased with ``lubricant``,
    with the traction law ``traction`` of ``[friction]``."""
    raw["friction"] = {"model": "ball_model", "seals": 0, "traction": traction}
    raw["medium"] = {"name": lubricant, "lubricant": lubricant, "thermal_conductivity": 0.14}
    raw.setdefault("lubrication", {})["supply"] = "grease"
    raw["thermal"]["drag_torque"] = {"source": "operating_point"}
    return raw


def _nut_rise(raw: dict[str, Any]) -> float:
    field = ballscrew.thermal_field(case_from_dict(raw), model="network")
    return field.sensors[0].final - field.ambient_temperature


HIWIN_TOLERANCE = (
    "the source states 'about 5 degrees' read off a figure (±1 K), and each of the two rises "
    "scales with its catalogue torque, whose real values lie ±20 % to ±35 % from the formula "
    "(THK A-689 Table13): ±30 % of the 5 K difference is ±1.5 K; together ±2.5 K (the physics "
    "model is held to the same band)"
)


@pytest.mark.parametrize(
    ("heat", "known_miss"),
    [("catalogue", False), ("physics", True), ("physics_skf", True)],
    ids=["catalogue", "physics", "physics_skf"],
)
def test_hiwin_r40_preload_doubling(validation, dataset, base_raw, heat, known_miss) -> None:
    data = dataset("thermal", "hiwin_r40_preload_doubling")
    low = _hiwin_raw(copy.deepcopy(base_raw), data, data["preload_low_N"])
    high = _hiwin_raw(base_raw, data, data["preload_high_N"])
    model, assumptions = "thermal_field (network)", (*HIWIN_ASSUMPTIONS, *HIWIN_CATALOGUE_HEAT)
    if heat != "catalogue":
        skf = heat == "physics_skf"
        traction = "skf" if skf else "film"
        low, high = (physics_raw(r, "lithium_nlgi2_vg100", traction) for r in (low, high))
        model = PHYSICS_MODEL + (", traction law skf" if skf else "")
        assumptions = (
            *HIWIN_ASSUMPTIONS,
            *PHYSICS_ASSUMPTIONS,
            "grease lithium_nlgi2_vg100 (ASSUMED: HIWIN recommends lithium soap grease, "
            "section 4.6; the base-oil grade is a GUESS)",
            *((SKF_ASSUMPTION,) if skf else ()),
        )
    validation.check(
        f"hiwin_r40_nut_rise_preload_doubled_{heat}",
        model=model,
        source=HIWIN_SOURCE,
        reference=data,
        quantity="increase of the nut temperature after 240 min at 1500 rpm when the preload "
        "doubles from 980 to 1960 N",
        unit="K",
        measured=data["temperature_increase_K"],
        predicted=_nut_rise(high) - _nut_rise(low),
        tolerance=2.5,
        relative=False,
        tolerance_basis=HIWIN_TOLERANCE,
        assumptions=assumptions,
        known_miss=known_miss,
    )


def test_thk_thermal_displacement_example(validation, dataset) -> None:
    data = dataset("thermal", "thk_thermal_displacement_example")
    length = data["thread_length_mm"] * 1e-3
    z = np.linspace(0.0, length, 11)
    rise = np.full_like(z, data["temperature_rise_K"])
    validation.check(
        "thk_thermal_displacement_example",
        kind="verification",
        model="thermal elongation ΔL = α∫θ̄ dz (Q7)",
        source=THK_SOURCE,
        reference=data,
        quantity="elongation of a 1000 mm thread warmed uniformly by 5 K, α = 12e-6 /K",
        unit="mm",
        measured=data["elongation_mm"],
        predicted=thermal_elongation(z, rise, data["expansion_per_K"]) * 1e3,
        tolerance=0.005,
        relative=True,
        tolerance_basis="a calculation with exact inputs: only rounding (the printed 0.06 mm is "
        "exact); ±0.5 % as the other worked-example verifications",
        assumptions=(
            "uniform rise of 5 K over the effective thread length 1000 mm, ρ = 12e-6 /K "
            "(source); the integral over 11 stations",
            "not a measurement: THK's design assumption of the rise, a check of the elongation "
            "bookkeeping that turns every thermal model's mean rise into ΔL",
        ),
    )
