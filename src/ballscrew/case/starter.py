"""A complete, commented case file from a catalogue sheet (``ballscrew init``).

A maker's table gives nominal diameter, lead, ball diameter and the circuits of the nut; the
rest of a case is filled with the standard values of a precision ball screw, each labelled in
the file: conformity 0.53 (makers' Gothic arches are 0.52–0.53), contact angle 45°, steels by
name from :mod:`ballscrew.materials`, a named lubricant, typical ground-raceway roughness, and a
``[design]`` section whose load ratings the check computes from the geometry unless the user
adds the maker's values.

Ball count: a circuit of t turns holds floor(t π d_m/(D_w cos λ)) − 1 balls
(:func:`ballscrew.design.circuit_ball_count`), the nut ``circuits`` of them.

Before the case is written the sheet is checked against the geometry of a thread, so that a
value in the wrong unit is blamed on its own option: the ball is smaller than d0/2 and than the
lead (one groove per lead of a single-start thread); the lead is at most π d_m (lead angle
λ = atan(L/(π d_m)) at most 45°) and at least D_w/2 (makers' balls are at most about 0.8 of the
lead, so a lead below half the ball is taken as a wrong unit and blamed on --lead, one between
D_w/2 and D_w on --ball); the ball-centre diameter d_m lies within one ball diameter of d0
[GUESS: a plausibility bound; THK prints 41.75 mm for a 40 mm screw with 6.35 mm balls]; the
root diameter lies between d_m − 2 D_w and d_m (the case's own rule).
"""

from __future__ import annotations

import json
import math
import tomllib
from dataclasses import dataclass

from ballscrew.case.design_spec import DesignSpec
from ballscrew.case.nut_body import least_nut_outer_diameter
from ballscrew.design import (
    MAX_PRELOAD_SHARE,
    accuracy_factor,
    circuit_ball_count,
    dynamic_load_rating,
    hardness_factor,
)
from ballscrew.errors import InputError
from ballscrew.geometry import ScrewGeometry
from ballscrew.loads.preload_method import preload_methods
from ballscrew.lubrication.lubricant_library import LUBRICANT_LIBRARY
from ballscrew.materials import material
from ballscrew.units import to_si

__all__ = ["CatalogueSheet", "parse_turns", "starter_case"]

CONFORMITY = 0.53
"""Groove radius / ball diameter of screw and nut [-] (makers' Gothic arch: 0.52–0.53)."""

DEFAULT_PRELOAD_SHARE = {1: 0.02, 2: 0.05}
"""Default preload / C_a: 5 % for a double nut (the makers' 'medium' preload, at most 10 %),
2 % for a single nut preloaded by oversized balls [GUESS: a typical value, not a maker's rule]."""

DUTY_LOAD_SHARE = {1: 0.04, 2: 0.08}
"""Axial load of the illustrative duty cycle / the geometric C_a [ASSUMED]: below the lift-off
load 2^1.5 F_p of the default preload (double nut 14 %, single nut 5.7 % of C_a), so the
starter case does not run its own nut into backlash. Not sized to the required life: the
40 × 10 double nut's life is 11 370 h against 20 000 h, and the check's red life margin says
that the duty is an assumed one (``[assumed] duty``)."""

NUT_OD_PER_D0 = 1.6
"""Nut body outer diameter / d0 of the starter, written to both ``[loads]`` (the check's nut
stiffness) and ``[thermal]`` (one nut, one diameter) [TYPICAL: DIN 69051-5 form B flanged
nuts, TBI SFNU/SFU table (catalogue pp. C46–C48): D = 28, 36, 40, 50, 63, 75 mm for
d0 = 16, 20, 25, 32, 40, 50 mm, D/d0 = 1.5–1.8, median 1.59]; at least the least body of
:func:`~ballscrew.case.nut_body.least_nut_outer_diameter`."""

SMALLEST_D0 = 1e-3
"""Nominal diameter [m] at or below which a d0 too small for its ball is taken as a value in the
wrong unit and blamed on --d0 (the smallest ball screws are about 4 mm)."""

MAX_TURNS = 10.0
MAX_CIRCUITS = 12


@dataclass(frozen=True)
class CatalogueSheet:
    """What a maker's table says about one screw (SI)."""

    nominal_diameter: float
    """d0 [m]; also the pitch diameter d_m unless :attr:`pitch_diameter` is given."""
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
    """F_p [N]; None = :data:`DEFAULT_PRELOAD_SHARE` × the computed C_a; 0 = a single nut
    without preload (one loaded flank)."""
    length: float = 1.0
    """Screw shaft length [m]."""
    nut_length: float | None = None
    """Length of each nut [m]; None = the loaded turns plus one lead at each end."""
    pitch_diameter: float | None = None
    """Ball-centre (pitch circle) diameter d_m [m]; None = d0."""
    root_diameter: float | None = None
    """Thread root (minor) diameter d_r [m]; None = the groove bottom."""
    preload_method: str | None = None
    """``screw.preload_method``; None = spacer for 2 nuts, oversized_balls for 1."""

    @property
    def d_m(self) -> float:
        """The pitch diameter d_m [m]: the sheet's ball-centre diameter, else d0."""
        return self.nominal_diameter if self.pitch_diameter is None else self.pitch_diameter


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


def _plural(count: float, word: str) -> str:
    """'1 nut', '2 nuts', '2.5 turns'."""
    return f"{count:g} {word}" + ("" if count == 1 else "s")


def _in_mm(value: float) -> str:
    return f"{value * 1e3:g} mm"


def _unit_hint(value: float, low: float, high: float) -> str:
    """'; did you mean 10 mm?' when ``value`` × 1000 or / 1000 (metres taken for millimetres
    or the reverse) lies in (``low``, ``high``]; else empty."""
    fits = [v for v in (value * 1e3, value * 1e-3) if low < v <= high]
    return f"; did you mean {_in_mm(fits[0])}?" if fits else ""


def _check_diameters(sheet: CatalogueSheet) -> None:
    """InputError unless d_m lies within one ball of d0 and the root in (d_m − 2 D_w, d_m)."""
    d0, d_m, ball = sheet.nominal_diameter, sheet.d_m, sheet.ball_diameter
    if not abs(d_m - d0) < ball:
        raise InputError(
            "--dp",
            _in_mm(d_m),
            f"a ball-centre diameter within one ball of d0: {_in_mm(d0 - ball)} to "
            f"{_in_mm(d0 + ball)}{_unit_hint(d_m, d0 - ball, d0 + ball)}",
        )
    root = sheet.root_diameter
    if root is not None and not d_m - 2.0 * ball < root < d_m:
        low = d_m - 2.0 * ball
        raise InputError(
            "--root",
            _in_mm(root),
            f"a thread root between d_m - 2 D_w = {_in_mm(low)} and d_m = {_in_mm(d_m)}"
            f"{_unit_hint(root, low, d_m)}",
        )


def _check_fits(sheet: CatalogueSheet) -> float:
    """The nut length [m] after checking that diameters, lead, ball, turns and nuts fit."""
    d0, lead, ball = sheet.nominal_diameter, sheet.lead, sheet.ball_diameter
    if not ball < d0 / 2.0:
        if d0 <= SMALLEST_D0 and ball < 1e3 * d0 / 2.0:  # d0 in metres taken as mm
            raise InputError(
                "--d0",
                _in_mm(d0),
                f"a nominal diameter above 2 D_w = {_in_mm(2.0 * ball)}; did you mean "
                f"{_in_mm(1e3 * d0)}?",
            )
        raise InputError(
            "--ball",
            _in_mm(ball),
            f"it must be smaller than d0/2 = {_in_mm(d0 / 2)}"
            f"{_unit_hint(ball, d0 / 100.0, d0 / 2.0)}",
        )
    _check_diameters(sheet)
    low, high = ball / 2.0, math.pi * sheet.d_m
    if not low <= lead <= high:
        raise InputError(
            "--lead",
            _in_mm(lead),
            f"a lead from D_w/2 = {_in_mm(low)} to pi d_m = {_in_mm(high)} (helix angle at "
            f"most 45 deg){_unit_hint(lead, low, high)}",
        )
    if not ball < lead:
        raise InputError(
            "--ball",
            _in_mm(ball),
            f"it must be smaller than the lead {_in_mm(lead)} (a "
            "single-start thread has one groove per lead; a larger ball overlaps the next turn)",
        )
    if sheet.preload == 0.0 and sheet.nuts != 1:
        raise InputError(
            "--preload", "0 N", "> 0 N for a double nut (0 only for a single nut, --nuts 1)"
        )
    loaded = sheet.turns * sheet.circuits * lead
    nut = sheet.nut_length or loaded + 2.0 * lead
    if loaded > nut:
        raise InputError(
            "--turns",
            f"{sheet.turns:g}x{sheet.circuits}",
            f"circuits × turns × lead must fit the nut "
            f"length {_in_mm(nut)} (they take {_in_mm(loaded)})",
        )
    if sheet.nuts * nut >= sheet.length:
        raise InputError(
            "--length",
            _in_mm(sheet.length),
            f"it must be longer than {_plural(sheet.nuts, 'nut')} of {_in_mm(nut)}",
        )
    return nut


_GRADE = DesignSpec.model_fields["accuracy_grade"].default
"""The accuracy grade of the starter's ``[design]`` (the case's default)."""


def _rating_factor() -> float:
    """f_H f_ac by which ``ballscrew check`` scales the geometric ratings of the starter's
    steels (the softer raceway, the 42CrMo4 shaft) and :data:`_GRADE`."""
    softer = min(material(name).hardness for name in ("42CrMo4", "100Cr6"))
    return hardness_factor(softer) * accuracy_factor(_GRADE)


def _nut_outer_diameter(sheet: CatalogueSheet) -> tuple[float, str, str]:
    """:data:`NUT_OD_PER_D0` d0, at least the least nut body d_m + 2 D_b [m], which (the
    ``[assumed]`` note) and its label in the file; the least as the case reads it back (d_m
    and D_b written to six digits), rounded up to six digits so that its written value is not
    below it."""
    least = least_nut_outer_diameter(_written(sheet.d_m), _written(sheet.ball_diameter))
    typical = NUT_OD_PER_D0 * sheet.nominal_diameter
    if _written(typical) >= least:
        note = f"{NUT_OD_PER_D0:g} d0, a typical DIN 69051 flanged nut body"
        return typical, note, "[TYPICAL: DIN 69051 flanged nuts, D = 1.5-1.8 d0]"
    body = least
    while _written(body) < least:  # one step of the sixth digit up
        body += 10.0 ** (math.floor(math.log10(body * 1e3)) - 5) * 1e-3
    note = "d_m + 2 D_b, the least nut body around balls this large"
    return body, note, f"[ASSUMED: {note}]"


def _mm(value: float) -> str:
    return f'"{value * 1e3:.6g} mm"'


def _written(value: float) -> float:
    """A length [m] as the case reads back its :func:`_mm` text."""
    return to_si(_mm(value).strip('"'), "length")


_OIL = "iso_vg_68"
"""The starter's lubricant (:data:`~ballscrew.lubrication.lubricant_library.LUBRICANT_LIBRARY`)
[ASSUMED: an oil of the usual grade; many nuts are delivered greased]."""


def _optional(value: float | None, line: str, unknown: str) -> str:
    """``line`` with the value in mm when the sheet gives it, else the comment ``unknown``."""
    return unknown if value is None else line.format(_mm(value))


def starter_case(sheet: CatalogueSheet, name: str = "my_screw") -> str:
    """The TOML text of a complete case for ``sheet`` (every command accepts it)."""
    nut_length = _check_fits(sheet)
    d0, d_m, lead, ball = sheet.nominal_diameter, sheet.d_m, sheet.lead, sheet.ball_diameter
    per_circuit = circuit_ball_count(d_m, ball, lead, sheet.turns)
    balls = per_circuit * sheet.circuits
    if sheet.preload_method == "offset_lead" and balls % 2:
        raise InputError(
            "--preload-method",
            "offset_lead",
            f"two equal halves of the nut's balls; --turns {sheet.turns:g}x{sheet.circuits} "
            f"gives {balls}: give an even number of circuits or oversized_balls",
        )
    geometry = ScrewGeometry(d_m, lead, ball, CONFORMITY, CONFORMITY, math.pi / 4.0)
    ca = dynamic_load_rating(geometry, balls)
    preload = sheet.preload
    if preload is None:
        preload = round(DEFAULT_PRELOAD_SHARE[sheet.nuts] * ca, -1)
    oil = LUBRICANT_LIBRARY[_OIL]
    duty_load = round(DUTY_LOAD_SHARE[sheet.nuts] * ca, -1)
    nut_od, nut_od_note, nut_od_label = _nut_outer_diameter(sheet)
    bare = preload == 0.0  # a single nut without preload: its one flank needs a load
    root = "root_diameter = {}   # thread root (minor) diameter from the sheet\n"
    text = _TEMPLATE.format(
        name=json.dumps(name, ensure_ascii=False),  # a TOML basic string, escapes and all
        d_m=_mm(d_m),
        d_m_note="ball-centre diameter from the sheet" if sheet.pitch_diameter is not None else (
            "d0 [ASSUMED: give the sheet's ball-centre diameter by --dp]"
        ),
        d0_mm=f"{d0 * 1e3:.6g}",
        lead_mm=f"{lead * 1e3:.6g}",
        lead=_mm(lead),
        ball=_mm(ball),
        turns=_plural(sheet.turns, "turn"),
        circuits=_plural(sheet.circuits, "circuit"),
        circuit_count=sheet.circuits,
        per_circuit=per_circuit,
        balls=balls,
        nuts=_plural(sheet.nuts, "nut"),
        nut_count=sheet.nuts,
        preload_method=sheet.preload_method or preload_methods(sheet.nuts)[0],
        conformity=CONFORMITY,
        oil_name=json.dumps(oil.name),
        oil_key=json.dumps(_OIL),
        oil_density=f'"{oil.density_15:g} kg/m^3"',
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
        assumed_d_m="" if sheet.pitch_diameter is not None else (
            '"screw.pitch_diameter" = "d_m taken as the nominal diameter d0"\n'
        ),
        length=_mm(sheet.length),
        duty_load=f'"{duty_load:.6g} N"',
        duty_share=f"{DUTY_LOAD_SHARE[sheet.nuts]:.0%}",
        axial_load=(
            f'"{duty_load:.6g} N"          # the duty\'s load [ASSUMED]: a nut without preload '
            "has no stiffness at 0 N"
            if bare
            else '"0 N"'
        ),
        rest_load=(
            f'axial_load = "{duty_load:.6g} N"   # the load stays on the nut at rest: a nut '
            "without preload needs one in every segment\n"
            if bare
            else ""
        ),
        assumed_axial_load=(
            '"operating.axial_load" = "the duty\'s load; a nut without preload needs one"\n'
            if bare
            else ""
        ),
        stroke=_mm(0.5 * (sheet.length - sheet.nuts * nut_length)),
        unsupported=_mm(0.9 * sheet.length),
        kinematics_root=_optional(sheet.root_diameter, root, ""),
        design_root=_optional(
            sheet.root_diameter,
            root,
            '# root_diameter = "... mm"   # the sheet\'s thread root; default the groove bottom\n',
        ),
        nut_length=_mm(nut_length),
        nut_length_note="given" if sheet.nut_length is not None else (
            "the loaded turns plus one lead at each end [ASSUMED]"
        ),
        assumed_nut_length="" if sheet.nut_length is not None else (
            '"thermal.nut_length" = "the loaded turns plus one lead at each end"\n'
        ),
        nut_od=_mm(nut_od),
        nut_od_note=json.dumps(nut_od_note),
        nut_od_label=nut_od_label,
    )  # fmt: skip
    _check_case(text, sheet)
    return text


#: The ``init`` option behind the case fields it sets (prefixes); others follow from --d0.
_OPTION_OF = (
    ("screw.pitch_diameter", "--dp"),
    ("screw.lead", "--lead"),
    ("screw.ball_diameter", "--ball"),
    ("screw.balls_per_nut", "--ball"),  # π d0 × turns × circuits / ball: a ball far too small
    ("operating.preload", "--preload"),
    ("thermal.nut_length", "--nut-length"),
    ("thermal.shaft_length", "--length"),
    ("thermal.bearings", "--length"),
    ("design.unsupported_length", "--length"),
    ("duty.0.stroke", "--length"),
    ("thermal.stroke", "--length"),
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
            "--dp": sheet.pitch_diameter,
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
description = "{d0_mm} x {lead_mm} mm ball screw, {turns} x {circuits}, {nuts}"
duty_repeat = 1                  # runs of the one-hour duty cycle at the end; 8: a working day

[screw]
pitch_diameter = {d_m}        # d_m: {d_m_note}
lead = {lead}
ball_diameter = {ball}
screw_conformity = {conformity}          # groove radius / ball diameter [TYPICAL: 0.52-0.53]
nut_conformity = {conformity}            # [TYPICAL]
contact_angle = "45 deg"         # Gothic-arch standard [TYPICAL]
# {circuits} x {per_circuit} balls, floor(turns pi d_m/(D_w cos lambda)) - 1 per circuit
balls_per_nut = {balls}
nuts = {nut_count}                         # 2: double nut preloaded by a spacer; 1: single nut
preload_method = "{preload_method}"      # spacer (2 nuts); oversized_balls or offset_lead (1 nut)

# Steels by name (ballscrew.materials); any property written below a name overrides it.
[materials.ball]
material = "100Cr6"              # bearing steel AISI 52100 / SUJ2
[materials.screw]
material = "42CrMo4"             # induction-hardened shaft steel SCM440 / AISI 4140 [TYPICAL]
[materials.nut]
material = "100Cr6"

# Raceway roughness as a Weierstrass-Mandelbrot profile [TYPICAL ground raceway: D = 1.59,
# G = 9e-10 m, measured by Gao et al. 2019 on a precision screw]; the ball is taken as smooth.
[surface]
D = 1.59
G = "9e-10 m"

# Oil between the asperities [ASSUMED: many nuts are delivered greased; name your lubricant].
# The named lubricant (ballscrew.lubrication) gives the viscosity and the density.
[medium]
name = {oil_name}
density_15 = {oil_density}   # of the named oil at 15 degC
thermal_conductivity = 0.14      # W/(m K) [TYPICAL mineral oil or grease 0.13-0.15]

[kinematics]
lubricant = {oil_key}
{kinematics_root}
[friction]
circuits = {circuit_count}                     # ball circuits (returns) per nut, from --turns

[operating]
preload = {preload}            # {preload_note}; the makers allow at most {max_share}
axial_load = {axial_load}
speed = "1000 rpm"               # [ASSUMED]

[numerics]
cells_across = 32                # grid cells across each Hertz contact (64 for final numbers)

# The nut body: one outer diameter for the check's nut stiffness (here) and the thermal model.
[loads]
nut_outer_diameter = {nut_od}  # {nut_od_label}

# Thermal model: the nut(s) in the middle of the shaft, convection to still air, support
# bearings left out (add [[thermal.bearings]]). Dimensions not on the sheet are [TYPICAL].
[thermal]
model = "network"                # fast; "axisymmetric" for the finite-element model
shaft_length = {length}
nut_length = {nut_length}          # each nut: {nut_length_note}
nut_outer_diameter = {nut_od}  # the nut body of [loads]
ambient_temperature = "20 degC"

[thermal.transient]
duration = "1 h"
time_step = "60 s"

# The nut reciprocates over the stroke of the duty cycle below [ASSUMED].
[thermal.stroke]
length = {stroke}

# Design check (`ballscrew check`). Without the maker's ratings the check computes C_a and C_0a
# from the geometry (here C_a = {ca_rated_kn} kN: {ca_kn} kN of the geometry times the hardness
# and accuracy factors f_H f_ac = {rating_factor} of the 42CrMo4 shaft and grade {grade}) and says
# so; add the sheet's values when known by removing the '#' below:
[design]
#   dynamic_load_rating = "... kN"
#   static_load_rating = "... kN"
mounting = "fixed-supported"
unsupported_length = {unsupported}   # 90 % of the shaft between the bearings [ASSUMED]
{design_root}required_life = "20000 h"          # [ASSUMED]
load_factor = 1.2                # f_w: smooth running, no shocks [ASSUMED]
accuracy_grade = {grade}               # C{grade} / P{grade} [ASSUMED]

# A one-hour working cycle for `ballscrew duty` (run duty_repeat times, at the top) and the life
# of `ballscrew check` [ASSUMED, illustrative: write your machine's]: 40 min of strokes at
# 1000 rpm under {duty_share} of the geometric C_a, then 20 min of rest. It is not sized to this
# screw: its life may fall short of the required life above (the check's life margin is then
# red and says why) until you write your machine's cycle.
[[duty]]
speed = "1000 rpm"
axial_load = {duty_load}
stroke = {stroke}
dwell = "1 s"
duration = "40 min"

[[duty]]
speed = 0
{rest_load}duration = "20 min"

# The values above that are neither on the sheet nor computed from it (the ball count and the
# oil's density are computed): every summary and report lists them with the guesses. Delete a
# line when you write the maker's or your measured value.
[assumed]
{assumed_d_m}"screw.screw_conformity" = "typical Gothic-arch conformity 0.52-0.53"
"screw.nut_conformity" = "typical Gothic-arch conformity 0.52-0.53"
"screw.contact_angle" = "Gothic-arch standard 45 deg"
"materials.screw.material" = "a typical induction-hardened shaft steel"
"surface.D" = "typical ground raceway (Gao et al. 2019)"
"surface.G" = "typical ground raceway (Gao et al. 2019)"
"medium.name" = "an oil of the usual grade; many nuts are delivered greased"
"kinematics.lubricant" = "an oil of the usual grade; many nuts are delivered greased"
"medium.thermal_conductivity" = "typical mineral oil or grease 0.13-0.15 W/(m K)"
"operating.speed" = "an illustrative speed"
"loads.nut_outer_diameter" = {nut_od_note}
"thermal.nut_outer_diameter" = {nut_od_note}
"thermal.stroke.length" = "the stroke of the illustrative duty cycle"
"design.unsupported_length" = "90 % of the shaft between the bearings"
"design.required_life" = "a typical requirement of a machine tool"
"design.load_factor" = "smooth running without shocks (f_w 1-1.2)"
"design.accuracy_grade" = "a typical precision grade"
"duty" = "an illustrative cycle, not your machine's"
{assumed_preload}{assumed_nut_length}{assumed_axial_load}"""
