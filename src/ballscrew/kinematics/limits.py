"""Speed limits of a ball screw: shaft whirling (critical) speed and the d·n limit.

* Whirling: first bending natural frequency of the screw shaft as an Euler–Bernoulli beam of
  the root diameter d_r, ω_cr = (λ₁/l)² √(E I/(ρ A)) = (λ₁/l)² (d_r/4) √(E/ρ), with the
  eigenvalue λ₁ of the end fixity (Blevins, *Formulas for Natural Frequency and Mode Shape*,
  1979, Table 8-1: 1.8751 fixed–free, π supported–supported, 3.9266 fixed–supported, 4.7300
  fixed–fixed). Catalogues (THK, NSK; ISO 3408-5) allow 80 % of it.
* d·n: pitch diameter [mm] × speed [rpm], limited by the ball return (catalogue value ~70 000
  for standard precision nuts).

Exceeding a limit is a :class:`SpeedLimitWarning`, not an error: silence it with
``[kinematics] speed_warnings = false`` or ``warnings.filterwarnings("ignore",
category=SpeedLimitWarning)``.
"""

from __future__ import annotations

import math

from ballscrew.errors import InputError
from ballscrew.geometry import ScrewGeometry

__all__ = [
    "MOUNTING_EIGENVALUES",
    "SpeedLimitWarning",
    "critical_speed",
    "dn_value",
    "groove_root_diameter",
]

MOUNTING_EIGENVALUES: dict[str, float] = {
    "fixed-free": 1.8751,
    "supported-supported": math.pi,
    "fixed-supported": 3.9266,
    "fixed-fixed": 4.7300,
}
"""First eigenvalue λ₁ = β₁ l of a uniform beam for each end fixity (Blevins 1979)."""


class SpeedLimitWarning(UserWarning):
    """The screw speed exceeds the allowed whirling speed or the d·n limit."""


def groove_root_diameter(geometry: ScrewGeometry) -> float:
    """Root (groove-bottom) diameter of the screw for a Gothic-arch groove, m.

    Each arc of radius r_s is centred (r_s − r_b) behind the ball centre on the load line of its
    flank, at radius r_m + (r_s − r_b) cosβ and axial offset ∓(r_s − r_b) sinβ; the two arcs
    meet on the groove's centre line at radius r_m + (r_s − r_b) cosβ − √(r_s² − (r_s − r_b)²
    sin²β). Reference screw (d_m = 40 mm, D_w = 6.35 mm, f_s = 0.55, β = 45°): 33.478 mm.
    """
    r_s, r_b, beta = geometry.screw_groove_radius, geometry.ball_radius, geometry.contact_angle
    arm = r_s - r_b
    root = (
        geometry.pitch_radius
        + arm * math.cos(beta)
        - math.sqrt(r_s**2 - (arm * math.sin(beta)) ** 2)
    )
    return 2.0 * root


def critical_speed(
    root_diameter: float, length: float, youngs_modulus: float, density: float, mounting: str
) -> float:
    """First whirling speed ω_cr = (λ₁/l)² (d_r/4) √(E/ρ) of the screw shaft, rad/s."""
    for name, value in (
        ("root_diameter", root_diameter),
        ("unsupported_length", length),
        ("youngs_modulus", youngs_modulus),
        ("density", density),
    ):
        if not (math.isfinite(value) and value > 0.0):
            raise InputError(name, value, "a finite number > 0")
    try:
        eigenvalue = MOUNTING_EIGENVALUES[mounting]
    except KeyError:
        raise InputError("mounting", mounting, ", ".join(MOUNTING_EIGENVALUES)) from None
    return (eigenvalue / length) ** 2 * root_diameter / 4.0 * math.sqrt(youngs_modulus / density)


def dn_value(pitch_diameter: float, speed: float) -> float:
    """d·n = pitch diameter [mm] × speed [rpm] (speed given in rad/s, diameter in m)."""
    return pitch_diameter * 1e3 * speed * 60.0 / (2.0 * math.pi)
