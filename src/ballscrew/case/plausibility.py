"""Physically implausible values of a valid case: warnings with the likely intended unit.

A number without a unit is SI, so ``lead = 10`` is a 10 m lead. Such a value may still pass the
field's range; these checks compare it with the rest of the screw and, where a smaller unit
would make sense of it, name that unit: "did you mean '10 mm'?".
"""

from __future__ import annotations

import math
from collections.abc import Callable

from ballscrew.case.models import Case
from ballscrew.errors import ImplausibleValueWarning
from ballscrew.units import DISPLAY_UNITS, format_number, format_quantity

__all__ = [
    "ENGINEERING_D",
    "ENGINEERING_G",
    "MAX_PLAUSIBLE_DN",
    "NUT_LENGTH_FACTOR",
    "ImplausibleValueWarning",
    "implausible_values",
    "speed_hint",
    "unit_hint",
]

NUT_LENGTH_FACTOR = 4.0
"""Longest usual nut as a multiple of the pitch diameter, when the case gives no nut length
(GUESS: catalogue nuts of 2 to 4 circuits are about 1.5 to 3.5 d_m long)."""

SOFTEST_SOLID = 1e9
"""Smallest Young's modulus or hardness of a raceway, ball or nut material [Pa] (polymers
are about 1 to 3 GPa; steels about 200 GPa)."""


MAX_PLAUSIBLE_DN = 200_000.0
"""Largest d·n = pitch diameter [mm] × speed [rpm] of any ball screw (standard nuts are rated
50 000–70 000, the makers' high-speed series 120 000–160 000 and up to about 200 000, e.g.
THK's and NSK's high-speed catalogues). A speed above it was most likely meant in rpm."""


ENGINEERING_D = (1.2, 1.9)
"""Usual profile fractal dimension D of engineering surfaces. Majumdar and Bhushan (1990,
1991) and Majumdar and Tien (1990) report about 1.3 to 1.8 for machined, ground, lapped and
magnetic-media surfaces; the range is widened by 0.1 each side, as D near 1 or 2 is a
degenerate surface (smooth, or all roughness at the finest scale) rather than a unit slip."""

ENGINEERING_G = (1e-16, 1e-8)
"""Usual fractal roughness G of engineering surfaces [m]. The same sources report about
1e-14 to 1e-9 m for machined and ground surfaces; the upper end is raised to 1e-8 m so that
published parameter studies stay quiet (Gao et al., 2019, vary G up to 5e-9 m) and the lower
to 1e-16 m. A G outside it changes the asperity heights and the contact resistance by orders
of magnitude (Mikic's R″ by about ×2000 from G = 9e-10 m to 9e-4 m)."""


def unit_hint(value: float, kind: str, plausible: Callable[[float], bool]) -> str:
    """``"; did you mean '10 mm'?"``: the display unit of ``kind`` (largest first) in which the
    number ``value``, given as SI, would be plausible; ``""`` when none is."""
    for symbol, scale in reversed(DISPLAY_UNITS.get(kind, ())):
        if scale != 1.0 and plausible(value * scale):
            return f"; did you mean '{format_number(value)} {symbol}'?"
    return ""


def _too_soft(value: float) -> bool:
    return value < SOFTEST_SOLID


def implausible_values(case: Case) -> list[str]:
    """One line per implausible value of ``case``: a lead longer than the pitch circle, balls
    that do not fit the nut, a preload above the static load rating C_0a, a modulus or
    hardness below any solid's."""
    screw = case.screw
    found: list[str] = []
    circle = math.pi * screw.pitch_diameter
    if screw.lead > circle:
        found.append(
            f"screw.lead = {format_number(screw.lead)} m is longer than the pitch "
            f"circle (π·d_m = {format_quantity(circle, 'length')})"
            + unit_hint(screw.lead, "length", lambda v: v <= circle)
        )
    elif screw.ball_diameter >= screw.lead:
        found.append(
            f"screw.ball_diameter = {format_quantity(screw.ball_diameter, 'length')} does not fit "
            f"between the thread turns of screw.lead = {format_quantity(screw.lead, 'length')}"
        )
    else:
        found += _balls_fit(case)
    design = case.design
    rating = None if design is None else design.static_load_rating
    if rating is not None and case.operating.preload > rating:
        found.append(
            f"operating.preload = {format_quantity(case.operating.preload, 'force')} is above "
            f"design.static_load_rating = {format_quantity(rating, 'force')} (C_0a)"
        )
    found += _speeds(case)
    found += _roughness(case)
    found += _unsupported_length(case)
    for part in ("ball", "screw", "nut"):
        material = getattr(case.materials, part)
        for name in ("youngs_modulus", "hardness"):
            value = getattr(material, name)
            if _too_soft(value):
                found.append(
                    f"materials.{part}.{name} = {format_number(value)} Pa is below "
                    f"any solid's ({format_quantity(SOFTEST_SOLID, 'pressure')})"
                    + unit_hint(value, "pressure", lambda v: not _too_soft(v))
                )
    return found


def _unsupported_length(case: Case) -> list[str]:
    """The shaft between the bearings ([design], buckling and whirling) is longer than the nut
    it carries (``thermal.nut_length``, else 4 d_m) and, where ``thermal.shaft_length`` is
    written, at most the whole shaft (the check does not read ``[thermal]``, so the two
    sections may describe two different screws unnoticed)."""
    design, thermal = case.design, case.thermal
    if design is None:
        return []
    length = design.unsupported_length
    nut = thermal.nut_length if thermal is not None else None
    nut = NUT_LENGTH_FACTOR * case.screw.pitch_diameter if nut is None else nut
    if length < nut:
        return [
            f"design.unsupported_length = {format_quantity(length, 'length')} is shorter than "
            f"a nut ({format_quantity(nut, 'length')}); did you mean the shaft between the "
            "bearings?"
        ]
    if thermal is not None and "shaft_length" in thermal.model_fields_set:
        shaft = thermal.shaft_length
        if length > shaft:
            return [
                f"design.unsupported_length = {format_quantity(length, 'length')} is longer "
                f"than the whole shaft, thermal.shaft_length = "
                f"{format_quantity(shaft, 'length')}; the span between the bearings lies on "
                "the shaft"
            ]
    return []


def _roughness(case: Case) -> list[str]:
    """Fractal D and G of the raceways (and the ball) outside :data:`ENGINEERING_D` and
    :data:`ENGINEERING_G`."""
    surfaces = [("surface", case.surface)]
    if case.surface.ball is not None:
        surfaces.append(("surface.ball", case.surface.ball))
    (d_lo, d_hi), (g_lo, g_hi) = ENGINEERING_D, ENGINEERING_G
    found = []
    for key, surface in surfaces:
        if not d_lo <= surface.D <= d_hi:
            found.append(
                f"{key}.D = {format_number(surface.D)} is outside the usual {d_lo:g} to "
                f"{d_hi:g} of engineering surfaces"
            )
        if not g_lo <= surface.G <= g_hi:
            found.append(
                f"{key}.G = {format_number(surface.G)} m is outside the usual "
                f"{format_number(g_lo)} to {format_number(g_hi)} m of engineering surfaces (G sets "
                "the asperity heights: the contact resistance changes by orders of magnitude)"
            )
    return found


def speed_hint(speed: float, pitch_diameter: float) -> str:
    """``"; if given without a unit (rad/s), did you mean '1500 rpm'?"`` when ``speed``
    [rad/s] on a screw of ``pitch_diameter`` [m] exceeds :data:`MAX_PLAUSIBLE_DN` but would not
    in rpm, and the number looks like a speed typed in rpm; ``""`` otherwise (the case holds SI
    values: how the speed was typed is unknown).

    Rule: people type a speed in rpm as a whole number (1500, 3000), while a speed meant in
    rad/s is usually converted from rpm (628.3 rad/s = 6000 rpm) and is not whole; only a whole
    number gets the hint (the d·n warning itself stays).
    """
    highest = MAX_PLAUSIBLE_DN / (1e3 * pitch_diameter) * math.pi / 30.0  # rad/s
    if speed <= highest or speed * math.pi / 30.0 > highest or speed != round(speed):
        return ""
    return f"; if given without a unit (rad/s), did you mean '{format_number(speed)} rpm'?"


def _speeds(case: Case) -> list[str]:
    """Screw speeds whose d·n exceeds :data:`MAX_PLAUSIBLE_DN`: a number without a unit is
    rad/s, so ``speed = 1500`` (1500 rpm meant) turns the screw at 14 324 rpm."""
    d_mm = 1e3 * case.screw.pitch_diameter
    highest = MAX_PLAUSIBLE_DN / d_mm * math.pi / 30.0  # rad/s

    given: list[tuple[str, float]] = [("operating.speed", case.operating.speed)]
    if case.kinematics.speed_range is not None:
        given += [
            (f"kinematics.speed_range[{i}]", w) for i, w in enumerate(case.kinematics.speed_range)
        ]
    given += [(f"duty[{i}].speed", seg.speed) for i, seg in enumerate(case.duty)]
    if case.wear is not None:
        given += [
            (f"wear.programme[{i}].speed", lv.speed) for i, lv in enumerate(case.wear.programme)
        ]
    return [
        f"{key} = {format_number(speed)} rad/s ({format_quantity(speed, 'angular_velocity')}) "
        f"gives d·n = {d_mm * speed * 30.0 / math.pi:.3g} mm·rpm, above any ball screw's "
        f"{MAX_PLAUSIBLE_DN:.0f}" + speed_hint(speed, case.screw.pitch_diameter)
        for key, speed in given
        if speed > highest
    ]


def _balls_fit(case: Case) -> list[str]:
    """The balls of a nut must fit along the ball track of its length: turns × helix length."""
    screw = case.screw
    given = case.thermal.nut_length if case.thermal is not None else None
    length = given if given is not None else NUT_LENGTH_FACTOR * screw.pitch_diameter
    track = length / screw.lead * math.hypot(math.pi * screw.pitch_diameter, screw.lead)
    room = math.floor(track / screw.ball_diameter)
    if screw.balls_per_nut <= room:
        return []
    source = "thermal.nut_length" if given is not None else f"{NUT_LENGTH_FACTOR:g} d_m"
    return [
        f"screw.balls_per_nut = {screw.balls_per_nut} balls of "
        f"{format_quantity(screw.ball_diameter, 'length')} do not fit a nut "
        f"{format_quantity(length, 'length')} long ({source}): its ball track of "
        f"{format_quantity(track, 'length')} holds about {room}"
    ]
