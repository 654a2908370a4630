"""A complete, commented case file from a catalogue sheet (``ballscrew init``).

A maker's table gives nominal diameter, lead, ball diameter and the circuits of the nut; the
rest of a case is filled with the standard values of a precision ball screw, each labelled in
the file: conformity 0.53 (makers' Gothic arches are 0.52–0.53), contact angle 45°, steels by
name from :mod:`ballscrew.materials`, a named lubricant, typical ground-raceway roughness, and a
``[design]`` section whose load ratings the check computes from the geometry unless the user
adds the maker's values.

Ball count: a circuit of t turns holds floor(t π d_m/(D_w cos λ)) − 1 balls
(:func:`ballscrew.design.circuit_ball_count`), the nut ``circuits`` of them.
"""

from __future__ import annotations

import json
import math
import tomllib
from dataclasses import dataclass

from ballscrew.case.design_spec import DesignSpec
from ballscrew.design import (
    MAX_PRELOAD_SHARE,
    accuracy_factor,
    circuit_ball_count,
    dynamic_load_rating,
    hardness_factor,
)
from ballscrew.errors import InputError
from ballscrew.geometry import ScrewGeometry
from ballscrew.materials import material

__all__ = ["CatalogueSheet", "parse_turns", "starter_case"]

CONFORMITY = 0.53
"""Groove radius / ball diameter of screw and nut [-] (makers' Gothic arch: 0.52–0.53)."""

DEFAULT_PRELOAD_SHARE = {1: 0.02, 2: 0.05}
"""Default preload / C_a: 5 % for a double nut (the makers' 'medium' preload, at most 10 %),
2 % for a single nut preloaded by oversized balls [GUESS: a typical value, not a maker's rule]."""

MAX_TURNS = 10.0
MAX_CIRCUITS = 12


@dataclass(frozen=True)
class CatalogueSheet:
    """What a maker's table says about one screw (SI)."""

    nominal_diameter: float
    """d0 [m], taken as the pitch diameter d_m."""
    lead: float
    """L [m]."""
    ball_diameter: float
    """D_w [m]."""
    turns: float
    """Turns per circuit."""
    circuits: int
    """Circuits per nut."""
    nuts: int = 2
    preload: float | None = None
    """F_p [N]; None = :data:`DEFAULT_PRELOAD_SHARE` × the computed C_a."""
    length: float = 1.0
    """Screw shaft length [m]."""
    nut_length: float | None = None
    """Length of each nut [m]; None = the loaded turns plus one lead at each end."""


def parse_turns(text: str) -> tuple[float, int]:
    """'2.5x2' → (2.5 turns per circuit, 2 circuits); '3' → (3, 1)."""
    turns, _, circuits = text.lower().replace("×", "x").partition("x")
    try:
        t, c = float(turns), int(circuits or 1)
    except ValueError:
        raise InputError("--turns", text, "TURNSxCIRCUITS, e.g. 2.5x2 or 1x4") from None
    if not (0.0 < t <= MAX_TURNS and math.isfinite(t)):
        raise InputError("--turns", text, f"turns per circuit in (0, {MAX_TURNS:g}]")
    if not 1 <= c <= MAX_CIRCUITS:
        raise InputError("--turns", text, f"1 to {MAX_CIRCUITS} circuits")
    return t, c


def _check_fits(sheet: CatalogueSheet) -> float:
    """The nut length [m] after checking that ball, turns and nuts fit."""
    d0, lead, ball = sheet.nominal_diameter, sheet.lead, sheet.ball_diameter
    if not ball < lead:
        raise InputError(
            "--ball",
            f"{ball * 1e3:g} mm",
            f"it must be smaller than the lead {lead * 1e3:g} mm (a "
            "single-start thread has one groove per lead; a larger ball overlaps the next turn)",
        )
    if not ball < d0 / 2.0:
        raise InputError(
            "--ball", f"{ball * 1e3:g} mm", f"it must be smaller than d0/2 = {d0 * 5e2:g} mm"
        )
    loaded = sheet.turns * sheet.circuits * lead
    nut = sheet.nut_length or loaded + 2.0 * lead
    if loaded > nut:
        raise InputError(
            "--turns",
            f"{sheet.turns:g}x{sheet.circuits}",
            f"circuits × turns × lead must fit the nut "
            f"length {nut * 1e3:g} mm (they take {loaded * 1e3:g} mm)",
        )
    if sheet.nuts * nut >= sheet.length:
        raise InputError(
            "--length",
            f"{sheet.length * 1e3:g} mm",
            f"it must be longer than {sheet.nuts} nut(s) of {nut * 1e3:g} mm",
        )
    return nut


_GRADE = DesignSpec.model_fields["accuracy_grade"].default
"""The accuracy grade of the starter's ``[design]`` (the case's default)."""


def _rating_factor() -> float:
    """f_H f_ac by which ``ballscrew check`` scales the geometric ratings of the starter's
    steels (the softer raceway, the 42CrMo4 shaft) and :data:`_GRADE`."""
    softer = min(material(name).hardness for name in ("42CrMo4", "100Cr6"))
    return hardness_factor(softer) * accuracy_factor(_GRADE)


def _mm(value: float) -> str:
    return f'"{value * 1e3:.6g} mm"'


def starter_case(sheet: CatalogueSheet, name: str = "my_screw") -> str:
    """The TOML text of a complete case for ``sheet`` (every command accepts it)."""
    nut_length = _check_fits(sheet)
    d0, lead, ball = sheet.nominal_diameter, sheet.lead, sheet.ball_diameter
    per_circuit = circuit_ball_count(d0, ball, lead, sheet.turns)
    balls = per_circuit * sheet.circuits
    geometry = ScrewGeometry(d0, lead, ball, CONFORMITY, CONFORMITY, math.pi / 4.0)
    ca = dynamic_load_rating(geometry, balls)
    preload = sheet.preload
    if preload is None:
        preload = round(DEFAULT_PRELOAD_SHARE[sheet.nuts] * ca, -1)
    text = _TEMPLATE.format(
        name=json.dumps(name, ensure_ascii=False),  # a TOML basic string, escapes and all
        d0=_mm(d0),
        d0_mm=f"{d0 * 1e3:.6g}",
        lead_mm=f"{lead * 1e3:.6g}",
        lead=_mm(lead),
        ball=_mm(ball),
        turns=f"{sheet.turns:g}",
        circuits=sheet.circuits,
        per_circuit=per_circuit,
        balls=balls,
        nuts=sheet.nuts,
        conformity=CONFORMITY,
        preload=f'"{preload:.6g} N"',
        ca_kn=f"{ca * 1e-3:.3g}",
        ca_rated_kn=f"{_rating_factor() * ca * 1e-3:.3g}",
        rating_factor=f"{_rating_factor():.2f}",
        grade=_GRADE,
        preload_note="given" if sheet.preload is not None else (
            f"{DEFAULT_PRELOAD_SHARE[sheet.nuts]:.0%} of the geometric C_a [GUESS]"
        ),
        max_share=f"{MAX_PRELOAD_SHARE[sheet.nuts]:.0%} of C_a",
        assumed_preload="" if sheet.preload is not None else (
            f'"operating.preload" = "{DEFAULT_PRELOAD_SHARE[sheet.nuts]:.0%} of the geometric '
            'C_a, a typical preload"\n'
        ),
        length=_mm(sheet.length),
        duty_load=f"\"{round(0.08 * ca, -1):.6g} N\"",
        stroke=_mm(0.5 * (sheet.length - sheet.nuts * nut_length)),
        unsupported=_mm(0.9 * sheet.length),
        nut_length=_mm(nut_length),
        nut_length_note="given" if sheet.nut_length is not None else (
            "the loaded turns plus one lead at each end [ASSUMED]"
        ),
        assumed_nut_length="" if sheet.nut_length is not None else (
            '"thermal.nut_length" = "the loaded turns plus one lead at each end"\n'
        ),
        nut_od=_mm(1.75 * d0),
    )  # fmt: skip
    _check_case(text, sheet)
    return text


#: The ``init`` option behind the case fields it sets (prefixes); others follow from --d0.
_OPTION_OF = (
    ("screw.lead", "--lead"),
    ("screw.ball_diameter", "--ball"),
    ("screw.balls_per_nut", "--ball"),  # π d0 × turns × circuits / ball: a ball far too small
    ("operating.preload", "--preload"),
    ("thermal.nut_length", "--nut-length"),
    ("thermal.shaft_length", "--length"),
    ("thermal.bearings", "--length"),
    ("design.unsupported_length", "--length"),
    ("duty.0.stroke", "--length"),
)


def _check_case(text: str, sheet: CatalogueSheet) -> None:
    """InputError naming the option whose value makes the starter case ``text`` invalid."""
    from ballscrew.case.loader import CaseError, case_from_dict

    try:
        case_from_dict(tomllib.loads(text), source="init")
    except CaseError as exc:
        problem = exc.problems[0]
        given: dict[str, float | None] = {
            "--d0": sheet.nominal_diameter,
            "--lead": sheet.lead,
            "--ball": sheet.ball_diameter,
            "--preload": sheet.preload,
            "--nut-length": sheet.nut_length,
            "--length": sheet.length,
        }
        option = next(
            (o for field, o in _OPTION_OF if problem.startswith(field) and given[o] is not None),
            "--d0",
        )
        value = float(given[option] or 0.0)
        shown = f"{value:g} N" if option == "--preload" else f"{value * 1e3:g} mm"
        allowed = f"a value that gives a valid case; it gives {problem}"
        raise InputError(option, shown, allowed) from None


_TEMPLATE = """\
# Written by `ballscrew init` from a catalogue sheet. Every value not on the sheet is a
# standard or typical one, labelled; replace it with the maker's value when you have it.
# Units are written in strings ("40 mm"); bare numbers are SI.

name = {name}
description = "{d0_mm} x {lead_mm} mm ball screw, {turns} turns x {circuits} circuits, {nuts} nuts"

[screw]
pitch_diameter = {d0}        # d_m: the nominal diameter d0 [ASSUMED: catalogues rarely print d_m]
lead = {lead}
ball_diameter = {ball}
screw_conformity = {conformity}          # groove radius / ball diameter [TYPICAL: 0.52-0.53]
nut_conformity = {conformity}            # [TYPICAL]
contact_angle = "45 deg"         # Gothic-arch standard [TYPICAL]
# {circuits} circuit(s) x {per_circuit} balls, floor(turns pi d_m/(D_w cos lambda)) - 1 per circuit
balls_per_nut = {balls}
nuts = {nuts}                         # 2: double nut preloaded by a spacer; 1: single nut

# Steels by name (ballscrew.materials); any property written below a name overrides it.
[materials.ball]
material = "100Cr6"              # bearing steel AISI 52100 / SUJ2
[materials.screw]
material = "42CrMo4"             # induction-hardened shaft steel SCM440 / AISI 4140
[materials.nut]
material = "100Cr6"

# Raceway roughness as a Weierstrass-Mandelbrot profile [TYPICAL ground raceway: D = 1.59,
# G = 9e-10 m, measured by Gao et al. 2019 on a precision screw]; the ball is taken as smooth.
[surface]
D = 1.59
G = "9e-10 m"

# Oil between the asperities; the named lubricant fills its viscosity (ballscrew.lubrication).
[medium]
name = "ISO VG 68 mineral oil"
thermal_conductivity = 0.14      # W/(m K) [TYPICAL mineral oil or grease 0.13-0.15]

[kinematics]
lubricant = "iso_vg_68"

[operating]
preload = {preload}            # {preload_note}; the makers allow at most {max_share}
axial_load = "0 N"
speed = "1000 rpm"

[numerics]
cells_across = 32                # grid cells across each Hertz contact (64 for final numbers)

# Thermal model: the nut(s) in the middle of the shaft, convection to still air, support
# bearings left out (add [[thermal.bearings]]). Dimensions not on the sheet are [TYPICAL].
[thermal]
model = "network"                # fast; "axisymmetric" for the finite-element model
shaft_length = {length}
nut_length = {nut_length}          # each nut: {nut_length_note}
nut_outer_diameter = {nut_od}  # 1.75 d0 [TYPICAL flange-nut body]
ambient_temperature = "20 degC"

[thermal.transient]
duration = "1 h"
time_step = "60 s"

# Design check (`ballscrew check`). Without the maker's ratings the check computes C_a and C_0a
# from the geometry (here C_a = {ca_rated_kn} kN: {ca_kn} kN of the geometry times the hardness
# and accuracy factors f_H f_ac = {rating_factor} of the 42CrMo4 shaft and grade {grade}) and says
# so; add the sheet's values when known:
#   dynamic_load_rating = "... kN"
#   static_load_rating = "... kN"
[design]
mounting = "fixed-supported"
unsupported_length = {unsupported}   # 90 % of the shaft between the bearings [ASSUMED]
required_life = "20000 h"

# A working cycle for `ballscrew duty` and the life of `ballscrew check` [ASSUMED, illustrative:
# write your machine's]: strokes at 1000 rpm under 8 % of the geometric C_a, then rest.
[[duty]]
speed = "1000 rpm"
axial_load = {duty_load}
stroke = {stroke}
dwell = "1 s"
duration = "40 min"

[[duty]]
speed = 0
duration = "20 min"

# The values above that are not on the sheet: every summary and report lists them with the
# guesses. Delete a line when you write the maker's or your measured value.
[assumed]
"screw.pitch_diameter" = "d_m taken as the nominal diameter d0"
"screw.screw_conformity" = "typical Gothic-arch conformity 0.52-0.53"
"screw.nut_conformity" = "typical Gothic-arch conformity 0.52-0.53"
"screw.contact_angle" = "Gothic-arch standard 45 deg"
"surface.D" = "typical ground raceway (Gao et al. 2019)"
"surface.G" = "typical ground raceway (Gao et al. 2019)"
"medium.thermal_conductivity" = "typical mineral oil or grease 0.13-0.15 W/(m K)"
"thermal.nut_outer_diameter" = "1.75 d0, a typical flange-nut body"
"design.unsupported_length" = "90 % of the shaft between the bearings"
"duty" = "an illustrative cycle, not your machine's"
{assumed_preload}{assumed_nut_length}"""
