"""Driving and back-driving efficiency of the screw and the torque of the working load.

Makers' formulas (THK General Catalog, Ball Screw, A-664 to A-666, Fig. 1, Fig. 2 and eqs. (2),
(4); the same forms in NSK and HIWIN catalogues), with the lead angle λ (tan λ = L/(π d_m)) and
the friction angle ρ′ = atan μ of an effective rolling-friction coefficient μ:

    η  = tan λ / tan(λ + ρ′)   (rotation → translation, "positive efficiency" η₁),
    η′ = tan(λ − ρ′) / tan λ   (translation → rotation, "reverse efficiency" η₂),
    T  = F_a L / (2π η)        (driving torque against the axial load F_a).

THK's worked example (A-666): d_m = 33 mm, L = 10 mm, μ = 0.003 → η = 0.96 and 24 N mm against
14.7 N. Only F_a L/(2π) of T does work on the load; the rest, F_a L/(2π)(1/η − 1), is heat.
"""

from __future__ import annotations

import math

from ballscrew.errors import InputError

__all__ = [
    "backdriving_efficiency",
    "driving_efficiency",
    "friction_angle",
    "load_friction_torque",
    "load_torque",
]

#: Effective rolling-friction coefficient of a ball screw in THK's efficiency chart and worked
#: example (A-664, A-666: "μ = 0.003, η = 0.96"); the chart spans 0.003–0.01.
CATALOGUE_ROLLING_FRICTION = 0.003


def _check(lead_angle: float, mu: float) -> None:
    if not 0.0 < lead_angle < math.pi / 2:
        raise InputError("lead_angle", lead_angle, "an angle in (0, π/2) rad")
    if not (math.isfinite(mu) and 0.0 <= mu < 1.0):
        raise InputError("friction.rolling_friction", mu, "a coefficient in [0, 1)")


def friction_angle(mu: float) -> float:
    """ρ′ = atan μ [rad]."""
    return math.atan(mu)


def driving_efficiency(lead_angle: float, mu: float) -> float:
    """η = tan λ / tan(λ + ρ′) (THK A-664 Fig. 1); 0 when λ + ρ′ ≥ π/2."""
    _check(lead_angle, mu)
    total = lead_angle + friction_angle(mu)
    return 0.0 if total >= math.pi / 2 else math.tan(lead_angle) / math.tan(total)


def backdriving_efficiency(lead_angle: float, mu: float) -> float:
    """η′ = tan(λ − ρ′)/tan λ (THK A-664 Fig. 2); ≤ 0 means self-locking (ρ′ ≥ λ)."""
    _check(lead_angle, mu)
    return math.tan(lead_angle - friction_angle(mu)) / math.tan(lead_angle)


def load_torque(axial_load: float, lead: float, lead_angle: float, mu: float) -> float:
    """Driving torque against the axial load, T = F_a L/(2π η) (THK A-665 eq. (2)) [N m]."""
    eta = driving_efficiency(lead_angle, mu)
    work = abs(axial_load) * lead / (2.0 * math.pi)
    if work == 0.0:
        return 0.0
    if eta <= 0.0:
        raise InputError("friction.rolling_friction", mu, "a coefficient with λ + atan μ < 90°")
    return work / eta


def load_friction_torque(axial_load: float, lead: float, lead_angle: float, mu: float) -> float:
    """The part of :func:`load_torque` that is heat, F_a L/(2π)(1/η − 1) [N m]."""
    return load_torque(axial_load, lead, lead_angle, mu) - abs(axial_load) * lead / (2.0 * math.pi)
