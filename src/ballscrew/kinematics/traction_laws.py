"""Rival traction laws of the ball contacts: which share of the pressure carries boundary friction.

Both laws feed the shear stress of ``docs/theory/kinematics.md`` (E3.3),

    |τ| = μ_b s p + (1 − s) min(η(p) |Δv|/h, μ_f p),

on every cell of the Hertz grid at the screw contact A (ball balance and losses) and the nut
contact B (Heathcote slip); a law supplies the boundary share s and the two coefficients μ_b, μ_f
(:class:`TractionWeights`). Registered in :data:`TRACTION_LAWS` (``friction.traction``):

* ``film`` (default): s = ψ, the asperity share of the contact load of Johnson, Greenwood & Poon
  (1972), a function of the film parameter Λ = h/σ; μ_b the boundary friction, μ_f = Λ_L the
  limiting shear stress coefficient of the film (Bair & Winer 1979).
* ``skf``: the weighting of the SKF model of the frictional moment (SKF Group, *Rolling
  bearings*, PUB BU/P1 10000/2 EN, 2013, section "The SKF model for calculating the frictional
  moment", "Effect of lubrication on sliding friction"):

      μ_sl = φ_bl μ_bl + (1 − φ_bl) μ_EHL,   φ_bl = 1/exp[2.6·10⁻⁸ (n ν)^1.4 d_m]

  with n the speed [r/min], ν the operating kinematic viscosity [mm²/s], d_m the bearing mean
  diameter [mm], μ_bl ≈ 0.15 ("depending on the additive package") and μ_EHL = 0.05 for mineral
  oils (0.04 synthetic). For the ball screw n is the screw speed and d_m the ball-centre (pitch)
  diameter (ASSUMED: the screw's d·n plays the role of the bearing's). With s = φ_bl, μ_b = μ_bl,
  μ_f = μ_EHL the cell shear is μ_sl p wherever the film shear reaches μ_EHL p.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

from ballscrew.kinematics.model import BallModel
from ballscrew.registry import Registry

__all__ = [
    "SKF_BOUNDARY_FRICTION",
    "SKF_EHL_FRICTION",
    "TRACTION_LAWS",
    "TractionWeights",
    "skf_sliding_friction",
    "skf_weighting",
    "traction_weights",
]

#: μ_bl of the SKF model, "generally ≈ 0.15" (SKF Rolling bearings 2013, effect of lubrication).
SKF_BOUNDARY_FRICTION = 0.15
#: μ_EHL of the SKF model for ball bearings lubricated with mineral oil: 0.05 (same source).
SKF_EHL_FRICTION = 0.05

_RPM = 60.0 / (2.0 * math.pi)


@dataclass(frozen=True)
class TractionWeights:
    """Boundary share s and coefficients of the cell shear μ_b s p + (1 − s) min(η|Δv|/h, μ_f p)."""

    share: float
    """s: share of the pressure with boundary friction (ψ or φ_bl)."""
    boundary_friction: float
    """μ_b [-]."""
    film_friction: float
    """μ_f [-]: the film's shear stress is capped at μ_f p."""


TractionLaw = Callable[[BallModel, float, float], TractionWeights]
TRACTION_LAWS: Registry[TractionLaw] = Registry("traction law", "friction.traction")


def skf_weighting(speed: float, kinematic_viscosity: float, mean_diameter: float) -> float:
    """φ_bl = 1/exp[2.6·10⁻⁸ (n ν)^1.4 d_m] of the SKF model (SKF Rolling bearings 2013).

    SI in: ``speed`` ω [rad/s], ``kinematic_viscosity`` ν [m²/s], ``mean_diameter`` d_m [m];
    converted to the catalogue's r/min, mm²/s and mm. 1 at rest, → 0 at high n ν.
    """
    n = abs(speed) * _RPM
    nu = max(kinematic_viscosity, 0.0) * 1e6
    return math.exp(-2.6e-8 * (n * nu) ** 1.4 * mean_diameter * 1e3)


def skf_sliding_friction(
    weighting: float,
    boundary: float = SKF_BOUNDARY_FRICTION,
    full_film: float = SKF_EHL_FRICTION,
) -> float:
    """μ_sl = φ_bl μ_bl + (1 − φ_bl) μ_EHL of the SKF model."""
    return weighting * boundary + (1.0 - weighting) * full_film


@TRACTION_LAWS.register(
    "film", "JGP asperity share ψ(Λ) with boundary friction, film shear capped at Λ_L p"
)
def film_law(model: BallModel, psi: float, speed: float) -> TractionWeights:
    """s = ψ (Johnson, Greenwood & Poon 1972), μ_b and Λ_L of the model (Bair & Winer 1979)."""
    return TractionWeights(psi, model.boundary_friction, model.limiting_shear)


@TRACTION_LAWS.register(
    "skf", "SKF sliding weighting φ_bl(n ν d_m): μ_sl = φ_bl 0.15 + (1 − φ_bl) 0.05"
)
def skf_law(model: BallModel, psi: float, speed: float) -> TractionWeights:
    """s = φ_bl at the screw speed, the lubricant's ν = η/ρ and the pitch diameter; μ_bl 0.15,
    μ_EHL 0.05 (SKF Rolling bearings 2013). Dry (φ_bl = 1) without a lubricant or at rest."""
    if not model.lubricated or speed == 0.0:
        share = 1.0
    else:
        nu = (model.viscosity or 0.0) / model.lubricant_density
        share = skf_weighting(speed, nu, model.geometry.pitch_diameter)
    return TractionWeights(share, SKF_BOUNDARY_FRICTION, SKF_EHL_FRICTION)


def traction_weights(model: BallModel, psi: float, speed: float) -> TractionWeights:
    """The weights of ``model.traction_law`` for the JGP share ``psi`` at screw speed ω_s."""
    return TRACTION_LAWS.entry(model.traction_law).model(model, psi, speed)
