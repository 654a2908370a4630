"""Basic axial load ratings of a ball screw from its geometry, and its ball count.

ISO 3408-5 (ball screws, load ratings) was not available to us. Its ratings follow the rolling-
bearing theory of Lundberg & Palmgren, so this module computes them from that theory directly,
in the form Harris & Kotzalas (*Rolling Bearing Analysis*, 5th ed., 2006, ch. on fatigue life)
give for a ball–raceway contact; one turn of a ball screw is treated as one row of a thrust ball
bearing of contact angle β on the pitch circle d_m:

* Basic dynamic capacity of one raceway contact [N, D_w in mm]
  Q_c = 98.1 (2f/(2f − 1))^0.41 (1 ∓ γ)^1.39 / (1 ± γ)^(1/3) (γ/cos β)^0.3 D_w^1.8 Z^(−1/3),
  γ = D_w cos β / d_m, upper signs for the screw (convex, "inner") raceway, lower for the nut;
  Z the balls of one turn. Both raceways carry the same load on every ball (pure axial load),
  so the ball's capacity is Q_c = (Q_c,s^(−10/3) + Q_c,n^(−10/3))^(−3/10).
* One turn: C_a1 = Z Q_c sinβ cosλ (λ the lead angle: the axial share of a ball load, as in
  :func:`ballscrew.loads.ball_load`). i loaded turns: C_a = C_a1 i^0.7, the ISO 281 rule for a
  thrust ball bearing of several equal rows (C_a ∝ k^(7/10)).
* Static rating C_0a = N Q_0 sinβ cosλ over the N loaded balls, Q_0 the ball load at which the
  most stressed contact reaches the makers' limit, a permanent deformation of 10⁻⁴ D_w (e.g. NBS
  catalogue §2.5, Rexroth R310RU 3301 p. 98). Two rival readings of that limit
  (:data:`STATIC_RATING_MODELS`): ``iso76``, the Hertz peak pressure p_0 = 4200 MPa that ISO 76
  takes for it in ball bearings (default); ``palmgren``, Palmgren's empirical permanent
  deformation of a steel ball contact, δ_s = 1.3·10⁻⁷ Q² (Σρ_I)(Σρ_II)/D_w [mm, N] (Harris &
  Kotzalas 2006, static load rating), set to 10⁻⁴ D_w with the curvature sums of the screw's
  groove.

Neither the ISO 281 material factor b_m nor a hardness or accuracy factor is applied. Against
twelve HIWIN sizes the dynamic rating is 1–10 % low and the ``iso76`` static rating within ±17 %
at conformity 0.53; Rexroth's static ratings are 0.61 of HIWIN's for equal geometry, so both
rivals exceed them (+45…+60 % and +26…+33 %; tests/validation/test_load_ratings.py).
"""

from __future__ import annotations

import math
from collections.abc import Callable

from ballscrew.contact.hertz import hertz
from ballscrew.errors import InputError
from ballscrew.geometry import RacewayCurvature, ScrewGeometry, raceway_curvature
from ballscrew.geometry.screw import SIDES
from ballscrew.registry import Registry
from ballscrew.validation import positive

__all__ = [
    "LUNDBERG_PALMGREN_CONSTANT",
    "MAX_PRELOAD_SHARE",
    "PERMANENT_DEFORMATION_SHARE",
    "STATIC_CONTACT_PRESSURE",
    "STATIC_RATING_MODELS",
    "TURN_EXPONENT",
    "balls_per_turn",
    "circuit_ball_count",
    "dynamic_load_rating",
    "static_load_rating",
]

LUNDBERG_PALMGREN_CONSTANT = 98.1
"""Constant of Q_c for point contact [N/mm^1.8] (Harris & Kotzalas 2006)."""

STATIC_CONTACT_PRESSURE = 4.2e9
"""Peak Hertz pressure of the static rating of ball contacts [Pa] (ISO 76)."""

PERMANENT_DEFORMATION_SHARE = 1e-4
"""Permanent deformation / D_w that defines C_0a (ISO 76; the ball-screw makers)."""

PALMGREN_DEFORMATION_CONSTANT = 1.3e-19
"""Palmgren's δ_s = k Q² (Σρ_I)(Σρ_II)/D_w in SI [m⁴/N²] (1.3·10⁻⁷ in mm and N; Harris &
Kotzalas 2006). UNVERIFIED: recalled, not read from the book here; it puts the limit of a bearing
inner-ring contact at p_0 ≈ 4050 MPa, near ISO 76's 4200 MPa."""

MAX_PRELOAD_SHARE: dict[int, float] = {1: 0.05, 2: 0.10}
"""Largest preload / C_a by nut count (HIWIN §3.6.2; THK A-687: 0.1 C_a)."""

TURN_EXPONENT = 0.7
"""C_a ∝ i^0.7 over i equal loaded turns (ISO 281, thrust ball bearings of several rows)."""


def balls_per_turn(pitch_diameter: float, ball_diameter: float, lead: float) -> float:
    """Balls that fill one full turn of the helix, π d_m / (D_w cos λ) (not rounded) [-]."""
    d_m = positive("pitch_diameter", pitch_diameter, "m")
    d_w = positive("ball_diameter", ball_diameter, "m")
    lam = math.atan(positive("lead", lead, "m") / (math.pi * d_m))
    return math.pi * d_m / (d_w * math.cos(lam))


def circuit_ball_count(
    pitch_diameter: float, ball_diameter: float, lead: float, turns: float, gap: int = 1
) -> int:
    """Loaded balls of one circuit of ``turns`` turns: floor(turns π d_m/(D_w cos λ)) − gap.

    ``gap`` ball spaces per circuit are lost where the balls leave and re-enter the thread
    (deflector or return-tube pick-up) [ASSUMED: one, not a maker's stated value].
    """
    full = math.floor(
        positive("turns", turns) * balls_per_turn(pitch_diameter, ball_diameter, lead)
    )
    count = full - gap
    if count < 1:
        raise InputError("turns", turns, f"enough turns for more than {gap} ball(s) per circuit")
    return count


def _contact_capacity(d_w_mm: float, gamma: float, cos_beta: float, z: float, f: float,
                      sign: float) -> float:  # fmt: skip
    """Q_c of one raceway: sign +1 for the screw (inner), −1 for the nut (outer) [N]."""
    return (
        LUNDBERG_PALMGREN_CONSTANT
        * (2.0 * f / (2.0 * f - 1.0)) ** 0.41
        * (1.0 - sign * gamma) ** 1.39
        / (1.0 + sign * gamma) ** (1.0 / 3.0)
        * (gamma / cos_beta) ** 0.3
        * d_w_mm**1.8
        * z ** (-1.0 / 3.0)
    )


def dynamic_load_rating(geometry: ScrewGeometry, balls: float) -> float:
    """Basic dynamic axial load rating C_a of ``balls`` loaded balls of one nut [N].

    Z = :func:`balls_per_turn` per turn and i = balls/Z turns; see the module docstring.
    """
    n = positive("balls", balls)
    g = geometry
    z = balls_per_turn(g.pitch_diameter, g.ball_diameter, g.lead)
    cos_b = math.cos(g.contact_angle)
    gamma = g.ball_diameter * cos_b / g.pitch_diameter
    d_mm = g.ball_diameter * 1e3
    screw = _contact_capacity(d_mm, gamma, cos_b, z, g.screw_conformity, +1.0)
    nut = _contact_capacity(d_mm, gamma, cos_b, z, g.nut_conformity, -1.0)
    q_c = (screw ** (-10.0 / 3.0) + nut ** (-10.0 / 3.0)) ** (-0.3)
    one_turn = z * q_c * math.sin(g.contact_angle) * math.cos(g.lead_angle)
    return one_turn * (n / z) ** TURN_EXPONENT


StaticBallLoad = Callable[[RacewayCurvature, float, float, float], float]
"""Q_0 [N] of one raceway contact from (curvature, D_w [m], E* [Pa], pressure limit [Pa])."""

STATIC_RATING_MODELS: Registry[StaticBallLoad] = Registry(
    "static load rating model", "design.static_rating_model"
)


@STATIC_RATING_MODELS.register("iso76", "Hertz peak pressure 4200 MPa (ISO 76, ball bearings)")
def hertz_limit_ball_load(
    curvature: RacewayCurvature, ball_diameter: float, e_star: float, pressure: float
) -> float:
    """Q_0 at which the exact Hertz peak pressure reaches ``pressure``: p_0 ∝ Q^(1/3), so
    Q_0 = (pressure / p_0(1 N))³ N."""
    unit = hertz(curvature.rx, curvature.ry, positive("contact_moduli", e_star, "Pa"), 1.0)
    return (pressure / unit.p0) ** 3


@STATIC_RATING_MODELS.register(
    "palmgren", "permanent deformation 1e-4 D_w by Palmgren's formula (Harris & Kotzalas 2006)"
)
def permanent_deformation_ball_load(
    curvature: RacewayCurvature, ball_diameter: float, e_star: float, pressure: float
) -> float:
    """Q_0 at which Palmgren's permanent deformation of ball and raceway,
    δ_s = 1.3·10⁻⁷ Q² (Σρ_I)(Σρ_II)/D_w [mm, N] (Palmgren; Harris & Kotzalas 2006), reaches
    10⁻⁴ D_w: Q_0 = D_w √(10⁻⁴ / (k Σρ_I Σρ_II)), k = 1.3·10⁻¹⁹ m⁴/N² in SI.

    An empirical law of hardened bearing steel: ``e_star`` and ``pressure`` do not enter. At an
    inner-ring contact of conformity 0.52 and γ = 0.2 it gives p_0 ≈ 4050 MPa, the calibration
    behind ISO 76's 4200 MPa.
    """
    d_w = positive("ball_diameter", ball_diameter, "m")
    sums = curvature.h_xx * curvature.h_yy
    return d_w * math.sqrt(PERMANENT_DEFORMATION_SHARE / (PALMGREN_DEFORMATION_CONSTANT * sums))


def static_load_rating(
    geometry: ScrewGeometry,
    balls: float,
    contact_moduli: tuple[float, float],
    pressure: float = STATIC_CONTACT_PRESSURE,
    model: str = "iso76",
) -> float:
    """Basic static axial load rating C_0a = N Q_0 sinβ cosλ [N].

    Q_0 is the ball load at the static limit of the more stressed contact (screw or nut,
    composite moduli ``contact_moduli`` = (E*_screw, E*_nut) [Pa]) by the rival ``model`` of
    :data:`STATIC_RATING_MODELS`: ``iso76`` (Hertz peak pressure ``pressure``, ISO 76: 4200
    MPa) or ``palmgren`` (permanent deformation 10⁻⁴ D_w).
    """
    n = positive("balls", balls)
    limit = positive("pressure", pressure, "Pa")
    ball_load = STATIC_RATING_MODELS.entry(model).model
    loads = [
        ball_load(raceway_curvature(geometry, side), geometry.ball_diameter, e_star, limit)
        for side, e_star in zip(SIDES, contact_moduli, strict=True)
    ]
    return n * min(loads) * math.sin(geometry.contact_angle) * math.cos(geometry.lead_angle)
