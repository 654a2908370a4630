"""Friction heat of the support bearings and of the ball screw (Q2–Q4).

All functions take and return SI values: torques in N·m, speeds in rad/s, heat in W. The
Palmgren coefficients are defined in N·mm, mm, mm²/s and r/min; the conversion happens inside.
Theory manual: ``docs/theory/thermal.md``, heat sources.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ballscrew.errors import InputError

_RAD_S_TO_RPM = 60.0 / (2.0 * math.pi)


def friction_heat(torque: float, speed: float) -> float:
    """Heat of a friction torque, Q = M·ω [W] (Q2, Q4; Gao et al. 2019).

    ``torque`` M [N·m] ≥ 0, ``speed`` ω [rad/s] (its magnitude is used).
    """
    if not torque >= 0.0:
        raise InputError("torque", torque, "a friction torque ≥ 0 N·m")
    return float(torque * abs(speed))


@dataclass(frozen=True)
class PalmgrenTorque:
    """Bearing friction torque M = M₀ + M₁ of Palmgren (1959) [N·m]."""

    load_independent: float
    """M₀, viscous (load-independent) torque [N·m]."""
    load_dependent: float
    """M₁ = f₁ P₁ d_m, load-dependent torque [N·m]."""

    @property
    def total(self) -> float:
        """M = M₀ + M₁ [N·m]."""
        return self.load_independent + self.load_dependent


def palmgren_torque(
    speed: float,
    f0: float,
    viscosity: float,
    mean_diameter: float,
    axial_load: float,
    static_load_rating: float,
    radial_load: float = 0.0,
    f1: float | None = None,
) -> PalmgrenTorque:
    """Friction torque of an angular-contact ball bearing, Palmgren/Harris estimate (Q3).

        M₀ = 10⁻⁷ f₀ (ν₀ n)^{2/3} d_m³        if ν₀ n ≥ 2000,  else 160·10⁻⁷ f₀ d_m³   [N·mm]
        M₁ = f₁ P₁ d_m,   f₁ = 0.001 (P₀/C₀)^{0.33},   P₁ = F_a − 0.1 F_r,   P₀ = F_a

    with ν₀ in mm²/s, n in r/min and d_m in mm (Palmgren 1959; Harris & Kotzalas, Rolling
    Bearing Analysis). P₀ = F_a is the static equivalent load of an axially loaded (preloaded)
    bearing, as in this example: f₀ = 2, ν₀ = 20 mm²/s, n = 1000 r/min,
    d_m = 46 mm, F_a = 2000 N, C₀ = 12000 N → M₀ = 14.34 N·mm, M₁ = 50.93 N·mm.

    Inputs in SI: ``speed`` ω [rad/s], ``viscosity`` ν₀ [m²/s], ``mean_diameter`` [m], loads
    and ``static_load_rating`` [N]. ``f1`` overrides the load-dependent factor.
    """
    for name, value in (
        ("f0", f0),
        ("viscosity", viscosity),
        ("mean_diameter", mean_diameter),
        ("static_load_rating", static_load_rating),
    ):
        if not value > 0.0:
            raise InputError(name, value, "a value > 0")
    if not (axial_load >= 0.0 and radial_load >= 0.0):
        raise InputError("axial_load", (axial_load, radial_load), "loads ≥ 0 N")
    n_rpm = abs(speed) * _RAD_S_TO_RPM
    nu_mm2 = viscosity * 1e6
    dm_mm = mean_diameter * 1e3
    nu_n = nu_mm2 * n_rpm
    if nu_n >= 2000.0:
        m0 = 1e-7 * f0 * nu_n ** (2.0 / 3.0) * dm_mm**3
    else:
        m0 = 160e-7 * f0 * dm_mm**3
    p1 = max(axial_load - 0.1 * radial_load, 0.0)
    if f1 is None:
        f1 = 0.001 * (axial_load / static_load_rating) ** 0.33
    m1 = f1 * p1 * dm_mm
    return PalmgrenTorque(load_independent=m0 * 1e-3, load_dependent=m1 * 1e-3)


def nut_heat_shares(total: float, nut_forces: tuple[float, ...]) -> tuple[float, ...]:
    """Split the ball-screw friction heat between the nuts in proportion to their axial force.

    Friction at a ball grows with its load, so at zero external load the two preloaded nuts of
    a double nut get half each; a lifted-off nut (force 0) gets nothing [ASM].
    """
    forces = [max(float(f), 0.0) for f in nut_forces]
    s = sum(forces)
    if s <= 0.0:
        return tuple(total / len(forces) for _ in forces)
    return tuple(total * f / s for f in forces)
