"""Geometric parameters of a ball screw and the quantities derived from them.

Symbols and equations follow ``docs/theory/geometry.md`` (G1)–(G12), which rebuild Lin, Ravani &
Velinsky (1994) and Wei, Lin & Horng (2009). SI units throughout: lengths in m, angles in rad.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, fields
from functools import cached_property
from typing import Literal

from ballscrew.errors import InputError

Side = Literal["screw", "nut"]
"""The raceway a ball touches: 'screw' (contact A) or 'nut' (contact B)."""
SIDES: tuple[Side, Side] = ("screw", "nut")
"""Which raceway a contact belongs to: ``"screw"`` (contact A) or ``"nut"`` (contact B)."""


@dataclass(frozen=True)
class ScrewGeometry:
    """Ball-screw geometry: pitch circle, lead, ball, Gothic-arch grooves and contact angle.

    Validated on construction; every violation raises :class:`~ballscrew.errors.InputError`
    naming the field. Derived quantities are cached properties.
    """

    pitch_diameter: float
    """d_m, diameter of the ball-centre helix, m."""
    lead: float
    """L, axial advance per revolution (single start: the pitch), m."""
    ball_diameter: float
    """D_b, m; must be smaller than d_m."""
    screw_conformity: float
    """f_s = r_s/D_b, screw groove arc radius over ball diameter, > 0.5."""
    nut_conformity: float
    """f_N = r_N/D_b, nut groove arc radius over ball diameter, > 0.5."""
    contact_angle: float
    """β, measured in the normal plane (n, b) from the principal normal n, rad, in (0, π/2)."""

    def __post_init__(self) -> None:
        for item in fields(self):
            value = getattr(self, item.name)
            try:
                number = float(value)
            except (TypeError, ValueError):
                raise InputError(item.name, value, "a real number") from None
            if not math.isfinite(number):
                raise InputError(item.name, value, "a finite real number")
            object.__setattr__(self, item.name, number)
        for name in ("pitch_diameter", "lead", "ball_diameter"):
            if getattr(self, name) <= 0.0:
                raise InputError(name, getattr(self, name), "a length > 0 m")
        for name in ("screw_conformity", "nut_conformity"):
            if getattr(self, name) <= 0.5:
                raise InputError(name, getattr(self, name), "a conformity ratio > 0.5")
        if not 0.0 < self.contact_angle < math.pi / 2:
            raise InputError("contact_angle", self.contact_angle, "0 < β < π/2 rad")
        if self.ball_diameter >= self.pitch_diameter:
            raise InputError(
                "ball_diameter",
                self.ball_diameter,
                f"smaller than pitch_diameter = {self.pitch_diameter!r} m",
            )

    @classmethod
    def from_spec(cls, spec: object) -> ScrewGeometry:
        """Build from any object (or mapping) with the six fields of this class as SI floats.

        This is how a case's ``screw`` section becomes a geometry without importing the case
        package.
        """
        values = {}
        for item in fields(cls):
            if isinstance(spec, Mapping):
                present = item.name in spec
                value = spec.get(item.name)
            else:
                present = hasattr(spec, item.name)
                value = getattr(spec, item.name, None)
            if not present:
                raise InputError(item.name, None, "required field of the screw geometry")
            values[item.name] = value
        return cls(**values)

    @cached_property
    def pitch_radius(self) -> float:
        """r_m = d_m/2, m."""
        return self.pitch_diameter / 2.0

    @cached_property
    def ball_radius(self) -> float:
        """r_b = D_b/2, m."""
        return self.ball_diameter / 2.0

    @cached_property
    def helix_parameter(self) -> float:
        """p_h = L/(2π), axial advance per radian of θ, m/rad."""
        return self.lead / (2.0 * math.pi)

    @cached_property
    def lead_angle(self) -> float:
        """α = atan(L/(π d_m)) of the ball-centre helix, (G2), rad."""
        return math.atan2(self.lead, math.pi * self.pitch_diameter)

    @cached_property
    def helix_speed(self) -> float:
        """ds/dθ = √(r_m² + p_h²), arc length of the ball-centre helix per radian, (G7), m."""
        return math.hypot(self.pitch_radius, self.helix_parameter)

    @cached_property
    def curvature(self) -> float:
        """κ = r_m/(r_m² + p_h²) = cos²α/r_m of the ball-centre helix, (G6), 1/m."""
        return self.pitch_radius / self.helix_speed**2

    @cached_property
    def torsion(self) -> float:
        """τ = p_h/(r_m² + p_h²) = sinα cosα/r_m of the ball-centre helix, (G6), 1/m."""
        return self.helix_parameter / self.helix_speed**2

    @cached_property
    def screw_groove_radius(self) -> float:
        """r_s = f_s D_b, m."""
        return self.screw_conformity * self.ball_diameter

    @cached_property
    def nut_groove_radius(self) -> float:
        """r_N = f_N D_b, m."""
        return self.nut_conformity * self.ball_diameter

    @cached_property
    def screw_contact_radius(self) -> float:
        """r_A, distance of the screw contact point A from the screw axis, (G12), m."""
        return self._contact_helix_radius(+1.0)

    @cached_property
    def nut_contact_radius(self) -> float:
        """r_B, distance of the nut contact point B from the screw axis, (G12), m."""
        return self._contact_helix_radius(-1.0)

    @cached_property
    def screw_contact_lead_angle(self) -> float:
        """α_A = atan(L/(2π r_A)), lead angle of the helix traced by contact A, (G12), rad."""
        return math.atan2(self.helix_parameter, self.screw_contact_radius)

    @cached_property
    def nut_contact_lead_angle(self) -> float:
        """α_B = atan(L/(2π r_B)), lead angle of the helix traced by contact B, (G12), rad."""
        return math.atan2(self.helix_parameter, self.nut_contact_radius)

    def groove_radius(self, side: Side) -> float:
        """Groove arc radius r_s (``"screw"``) or r_N (``"nut"``), m."""
        return self.screw_groove_radius if side_sign(side) > 0 else self.nut_groove_radius

    def _contact_helix_radius(self, sign: float) -> float:
        r_b, beta = self.ball_radius, self.contact_angle
        radial = self.pitch_radius - sign * r_b * math.cos(beta)
        return math.hypot(radial, r_b * math.sin(beta) * math.sin(self.lead_angle))


def side_sign(side: object) -> int:
    """+1 for the screw raceway (contact A), −1 for the nut raceway (contact B)."""
    if side == "screw":
        return 1
    if side == "nut":
        return -1
    raise InputError("side", side, "'screw' or 'nut'")


def flank_sign(flank: object) -> int:
    """Validate the loaded flank s = ±1 (opposite for the two nuts of a double nut)."""
    if flank in (1, -1) and not isinstance(flank, bool):
        return 1 if flank == 1 else -1
    raise InputError("flank", flank, "+1 or -1")


def as_geometry(obj: object) -> ScrewGeometry:
    """Coerce a :class:`ScrewGeometry`, a screw specification, or a case with ``.screw``."""
    if isinstance(obj, ScrewGeometry):
        return obj
    screw = obj.get("screw") if isinstance(obj, Mapping) else getattr(obj, "screw", None)
    return ScrewGeometry.from_spec(obj if screw is None else screw)


def lead_angle(case: object) -> float:
    """Lead angle α = atan(L/(π d_m)) of the ball-centre helix, (G2), rad.

    ``case`` may be a :class:`ScrewGeometry`, any object with its six fields, or a case object
    whose ``screw`` attribute holds them.
    """
    return as_geometry(case).lead_angle
