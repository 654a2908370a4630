"""Convective heat-transfer coefficients of the screw and the nut (Q5–Q6).

SI throughout: diameters and lengths in m, speeds in rad/s or m/s, h in W/(m² K). Theory manual:
``docs/theory/thermal.md``, convection.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

from ballscrew.validation import positive

GRAVITY = 9.81
"""Standard gravity g [m/s²]."""

KREITH_MAX_REYNOLDS = 4.3e5
"""Largest rotational Reynolds number ω d²/ν of the measurements behind (Q5)."""


@dataclass(frozen=True)
class Air:
    """Properties of the surrounding air (defaults: dry air near 300 K)."""

    kinematic_viscosity: float = 1.589e-5
    """ν [m²/s]."""
    conductivity: float = 0.0263
    """λ [W/(m K)]."""
    prandtl: float = 0.707
    """Pr [-]."""
    temperature: float = 300.0
    """Film temperature [K]; the ideal-gas expansion coefficient is β = 1/T."""

    @property
    def diffusivity(self) -> float:
        """Thermal diffusivity a = ν/Pr [m²/s]."""
        return self.kinematic_viscosity / self.prandtl


def rotating_cylinder(diameter: float, speed: float, air: Air = Air()) -> float:
    """h of a cylinder rotating in quiescent air, Kreith (Q5).

        Nu_d = 0.133 Re_ω^{2/3} Pr^{1/3},   Re_ω = ω d²/ν,   h = Nu λ/d

    (Kreith, "Convection heat transfer in rotating systems", Adv. Heat Transfer 5 (1968); valid
    for Re_ω < 4.3·10⁵, 0.7 < Pr < 670; beyond that it is extrapolated with a warning).
    ``speed`` ω [rad/s]. Example: d = 40 mm, 1000 r/min → Re = 10545, Nu = 56.97,
    h = 37.46 W/(m² K).
    """
    positive("diameter", diameter)
    re = abs(speed) * diameter**2 / air.kinematic_viscosity
    if re > KREITH_MAX_REYNOLDS:
        warnings.warn(
            f"rotating screw: Re_ω = {re:.3g} > {KREITH_MAX_REYNOLDS:.2g}, the range of Kreith's "
            "correlation (Q5); its h is extrapolated",
            stacklevel=2,
        )
    nu = 0.133 * re ** (2.0 / 3.0) * air.prandtl ** (1.0 / 3.0)
    return nu * air.conductivity / diameter


def horizontal_cylinder_natural(
    diameter: float, temperature_difference: float, air: Air = Air()
) -> float:
    """h of natural convection around a horizontal cylinder, Churchill & Chu (1975) (Q6).

        Ra = g β ΔT d³/(ν a),   Nu = {0.60 + 0.387 Ra^{1/6} / [1 + (0.559/Pr)^{9/16}]^{8/27}}²

    (Churchill & Chu, Int. J. Heat Mass Transfer 18 (1975) 1049; valid 10⁻⁵ < Ra < 10¹²).
    Example: d = 70 mm, ΔT = 10 K → Ra = 3.14·10⁵, Nu = 10.55, h = 3.96 W/(m² K).
    """
    positive("diameter", diameter)
    positive("temperature_difference", temperature_difference)
    ra = (
        GRAVITY
        * temperature_difference
        * diameter**3
        / (air.temperature * air.kinematic_viscosity * air.diffusivity)
    )
    psi = (1.0 + (0.559 / air.prandtl) ** (9.0 / 16.0)) ** (8.0 / 27.0)
    nu = (0.60 + 0.387 * ra ** (1.0 / 6.0) / psi) ** 2
    return nu * air.conductivity / diameter


def flat_plate_laminar(length: float, velocity: float, air: Air = Air()) -> float:
    """Mean h of a laminar flat plate, Nu_L = 0.664 Re_L^{1/2} Pr^{1/3} (Q6, moving nut).

    ``length`` L [m] along the motion, ``velocity`` v [m/s] (the feed speed n·L_lead/60).
    (Pohlhausen; Incropera & DeWitt, Eq. 7.30; laminar for Re_L < 5·10⁵.)
    """
    positive("length", length)
    re = abs(velocity) * length / air.kinematic_viscosity
    nu = 0.664 * math.sqrt(re) * air.prandtl ** (1.0 / 3.0)
    return nu * air.conductivity / length
