"""Wear strips across the groove, the working raceway length and reciprocation (E8.1)–(E8.4).

Theory manual: ``docs/theory/wear.md``, wear strips and the working raceway. The cell wear rates
w_ij of one ball's contact (axis 0 = i along the helix tangent X_A, axis 1 = j across the groove
Y_A) are summed along the rolling direction into strips, multiplied by the Z balls of the nut and
spread over the whole working raceway of helix length L_w.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ballscrew.errors import InputError
from ballscrew.validation import nonnegative_array, positive, same_shape

__all__ = [
    "depth_per_revolution",
    "raceway_depth_rate",
    "reciprocating_rate",
    "strip_wear_speed",
    "working_raceway_length",
]

FloatArray = NDArray[np.float64]


def strip_wear_speed(cell_rates: ArrayLike, dx: float) -> FloatArray:
    """Per-ball strip wear speed ``W_j = Σ_i w_ij Δx``, (E8.1), m²/s.

    ``cell_rates`` [m/s] has axis 0 along the helix tangent (i) and axis 1 across the groove (j).
    Example: w = [[1, 2, 1], [0.5, 1, 0.5]]e-9 m/s, Δx = 10 µm → W = [1.5, 3.0, 1.5]e-14 m²/s.
    """
    w = nonnegative_array("cell_rates", cell_rates, "m/s")
    if w.ndim != 2:
        raise InputError("cell_rates", w.shape, "a 2-D array (along the helix, across the groove)")
    return w.sum(axis=0) * positive("dx", dx, "m")


def working_raceway_length(
    stroke: float, lead: float, pitch_radius: float, ball_radius: float, contact_angle: float
) -> float:
    """Helix length of the worn raceway ``L_w = (S/L) √((2π ρ_A)² + L²)``, (E8.3), m.

    ρ_A = r_m − r_b cosβ is the radius of contact A. For the reference screw of
    ``examples/wear_step_stress.toml`` with S = 0.3 m: ρ_A = 17.755 mm,
    one helix turn 112.00 mm, L_w = 3.3601 m.
    """
    s = positive("stroke", stroke, "m")
    lead = positive("lead", lead, "m")
    rho = positive("pitch_radius", pitch_radius, "m") - positive(
        "ball_radius", ball_radius, "m"
    ) * math.cos(contact_angle)
    if not rho > 0.0:
        raise InputError("contact radius", rho, "r_m − r_b cosβ > 0 m")
    return s / lead * math.hypot(2.0 * math.pi * rho, lead)


def raceway_depth_rate(strip_speed: ArrayLike, balls: int, raceway_length: float) -> FloatArray:
    """Wear-depth speed of the raceway ``ḣ_j = Z W_j / L_w``, (E8.2), m/s.

    Example (that of :func:`strip_wear_speed`): W = [1.5, 3.0, 1.5]e-14 m²/s, Z = 54, L_w = 3.3601 m
    → [2.411, 4.821, 2.411]e-13 m/s.
    """
    if not (isinstance(balls, int | np.integer) and balls >= 1):
        raise InputError("balls", balls, "an integer number of balls >= 1")
    return (
        int(balls)
        * nonnegative_array("strip_speed", strip_speed, "m²/s")
        / positive("raceway_length", raceway_length, "m")
    )


def depth_per_revolution(depth_rate: ArrayLike, screw_speed: float) -> FloatArray:
    """Wear depth per screw revolution ``Δh_j = ḣ_j · 2π/ω_s``, (E8.2), m/rev."""
    return nonnegative_array("depth_rate", depth_rate, "m/s") * (
        2.0 * math.pi / positive("screw_speed", screw_speed, "rad/s")
    )


def reciprocating_rate(rate_loaded: ArrayLike, rate_unloaded: ArrayLike | None) -> FloatArray:
    """Flank rate under reciprocation ``ḣ = ½ ḣ(F_1) + ½ ḣ(F_2)``, (E8.4) [assumed].

    Each flank spends half the time under the loaded nut (F_1) and half under the unloaded one
    (F_2). ``rate_unloaded = None`` means the unloaded nut has lifted off (F_2 = 0): it adds 0.
    """
    loaded = nonnegative_array("rate_loaded", rate_loaded, "m/s")
    if rate_unloaded is None:
        return 0.5 * loaded
    unloaded = nonnegative_array("rate_unloaded", rate_unloaded, "m/s")
    same_shape("rate_loaded, rate_unloaded", loaded, unloaded)
    return 0.5 * (loaded + unloaded)
