"""The raceway's one RMS roughness σ_Λ for the film parameter Λ = h/σ_Λ and the TCR film path.

A case gives it once: ``tcr.rms_roughness`` when measured, else the fractal profile (``surface.D``,
``surface.G``) over the band [``tcr.cutoff_length``, ``tcr.sampling_length``] of a roughness
measurement (``ballscrew.lubrication.composite_roughness``; theory manual, *Lubrication*,
E6.6). The fractal asperity model keeps its own σ over one micro-contact cell (E5.3).
"""

from __future__ import annotations

import math

from ballscrew.case import Case
from ballscrew.lubrication import composite_roughness

__all__ = ["roughness_input"]


def roughness_input(case: Case) -> float | tuple[float, float]:
    """``AsperitySurface.roughness`` of the case's contact: the measured σ [m], the band
    (L_u, l_c) [m] of (F3) for a smooth ball, or with a rough ball (``surface.ball``) the
    composite σ = √(σ_raceway² + σ_ball²) of both profiles over that band (Tallian 1967)."""
    tcr = case.tcr
    if tcr.rms_roughness is not None:
        return float(tcr.rms_roughness)
    band = (tcr.sampling_length, tcr.cutoff_length)
    ball = case.surface.ball
    if ball is None:
        return band
    raceway = composite_roughness(case.surface.D, case.surface.G, *band)
    return math.hypot(raceway, composite_roughness(ball.D, ball.G, *band))
