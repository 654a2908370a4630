"""Ball mass, polar moment of inertia, centrifugal force and gyroscopic moment.

``docs/theory/kinematics.md``, (E3.1)–(E3.2) (Harris & Kotzalas 2006, high-speed ball
bearings; Wei, Lin & Horng 2009 for ball screws). SI units.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

__all__ = ["ball_inertia", "ball_mass", "centrifugal_force", "gyroscopic_moment"]


def ball_mass(diameter: float, density: float) -> float:
    """m = ρ π D_w³/6, kg. D_w = 6.35 mm, ρ = 7850 kg/m³: 1.0524e-3 kg."""
    return density * math.pi * diameter**3 / 6.0


def ball_inertia(diameter: float, density: float) -> float:
    """Polar moment of inertia J = m D_w²/10 of a solid ball, kg m² (4.2436e-9 for that ball)."""
    return ball_mass(diameter, density) * diameter**2 / 10.0


def centrifugal_force(mass: float, radius: float, orbital_speed: float) -> float:
    """F_c = m r ω_c², N, acting outward (−n), (E3.1). Reference screw, 100 rpm: 4.555e-4 N."""
    return mass * radius * orbital_speed**2


def gyroscopic_moment(
    inertia: float, orbital_speed: float, axis: NDArray[np.float64], spin: NDArray[np.float64]
) -> NDArray[np.float64]:
    """Gyroscopic inertia moment M_g = −J ω_c ẑ × Ω on the ball, (E3.2), N m.

    |M_g| = J ω_c ω_B √(1 − (cosβ cosλ)²) for the nut-controlled Ω: 4.116e-7 N m at 100 rpm for
    the reference screw of ``examples/wear_step_stress.toml``, 3.705e-4 N m at 3000 rpm.
    """
    return -inertia * orbital_speed * np.cross(axis, spin)
