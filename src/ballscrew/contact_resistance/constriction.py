"""Macro-constriction of the heat path through a ball and the smeared interface conductance.

The fractal TCR (theory manual, ``docs/theory/contact-resistance.md``) is the *micro* resistance of
the rough Hertz patch. A model that does not resolve the balls (the axisymmetric FE model and the
network, which smear the balls around the bore) must add the *macro* constriction of the heat
flowing through the small patches into the ball and into the raceway; a scale check puts it at the
order of 1 K/W for about 100 balls, far above the micro TCR.
"""

from __future__ import annotations

import math

from scipy.special import ellipk

from ballscrew.errors import InputError


def elliptic_constriction_resistance(
    semi_axis_1: float, semi_axis_2: float, conductivity: float
) -> float:
    """Constriction resistance of an isothermal elliptical contact on a half-space [K/W].

        R = K(e²) / (2π λ a),   e² = 1 − (b/a)²,   a ≥ b

    K is the complete elliptic integral of the first kind (parameter e²). It is the capacitance
    of an elliptical disc (Smythe; Yovanovich, AIAA paper 71-430, 1971); a circle (b = a) gives
    Holm's R = 1/(4 λ a).
    """
    a, b = max(semi_axis_1, semi_axis_2), min(semi_axis_1, semi_axis_2)
    if not b > 0.0:
        raise InputError("semi_axis", (semi_axis_1, semi_axis_2), "semi-axes > 0 m")
    if not conductivity > 0.0:
        raise InputError("conductivity", conductivity, "a conductivity > 0 W/(m K)")
    return float(ellipk(1.0 - (b / a) ** 2) / (2.0 * math.pi * conductivity * a))


def ball_contact_constriction(
    semi_axes: tuple[float, float], ball_conductivity: float, raceway_conductivity: float
) -> float:
    """Macro-constriction of one ball–raceway patch: into the ball plus into the raceway [K/W].

    Both bodies are taken as half-spaces on either side of the patch [ASM]; conduction through
    the ball between its two patches (≈ 1/(π λ D_b), about 1 % of this) is neglected.
    """
    a, b = semi_axes
    return elliptic_constriction_resistance(a, b, ball_conductivity) + (
        elliptic_constriction_resistance(a, b, raceway_conductivity)
    )


def smeared_conductance(resistance: float, area: float) -> float:
    """Interface conductance h = 1/(R·A_Γ) [W/(m² K)] that spreads R over the nut bore.

    A model with the balls smeared around the circumference applies the nut's total resistance
    R [K/W] (all its balls in parallel) over the bore area A_Γ [m²]. This keeps the total
    conductance 1/R: applying h_c = 1/R″ (A4) over A_Γ instead would over-state it by
    A_Γ/S, the bore-to-patch area ratio (about 10³).
    """
    if not (resistance > 0.0 and area > 0.0):
        raise InputError("resistance", (resistance, area), "R > 0 K/W and A > 0 m²")
    return 1.0 / (resistance * area)
