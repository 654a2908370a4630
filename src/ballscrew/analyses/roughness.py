"""The case's fractal roughness as each model reads it, and the raceway's one RMS roughness σ_Λ.

A case gives (D, G) of the raceway, of a rough ball and of the as-machined raceway of
``[wear.running_in]`` in one convention, ``surface.G_convention``: the Majumdar–Bhushan (1990)
profile G ('profile', what ``ballscrew surface`` measures) or the 3-D Yan–Komvopoulos (1998)
surface G ('surface'). The two differ for the same surface (same RMS height, theory manual,
*Fractal contact*, roughness conventions); :func:`profile_roughness` and
:func:`surface_roughness` convert once, here, to the G of the model that reads it: the TCR
models and σ_Λ take the profile G, the asperity load sharing and the wear law the surface G.

σ_Λ of the film parameter Λ = h/σ_Λ: ``tcr.rms_roughness`` when measured, else the fractal
profile over the band [``tcr.cutoff_length``, ``tcr.sampling_length``] of a roughness measurement
(``ballscrew.lubrication.composite_roughness``; theory manual, *Lubrication*, E6.6). The fractal
asperity model keeps its own σ over one micro-contact cell (E5.3).
"""

from __future__ import annotations

import math
from typing import Any, Literal

from ballscrew.analyses.result import quantity
from ballscrew.case import Case
from ballscrew.fractal.conventions import (
    profile_roughness_from_surface,
    surface_roughness_from_profile,
)
from ballscrew.lubrication import composite_roughness

__all__ = [
    "ball_roughness",
    "measurement_band",
    "profile_roughness",
    "roughness_input",
    "roughness_summary",
    "roughness_text",
    "surface_roughness",
]

Convention = Literal["profile", "surface"]


def profile_roughness(case: Case, D: float, G: float) -> float:
    """The Majumdar–Bhushan profile G [m] of a (D, G) of ``case`` (its ``surface.G_convention``)."""
    return G if case.surface.G_convention == "profile" else profile_roughness_from_surface(D, G)


def surface_roughness(case: Case, D: float, G: float) -> float:
    """The 3-D Yan–Komvopoulos surface G [m] (dimension D + 1) of a (D, G) of ``case``."""
    return G if case.surface.G_convention == "surface" else surface_roughness_from_profile(D, G)


def _used(case: Case, used: Convention) -> float:
    """The raceway's G [m] in the convention ``used``."""
    convert = profile_roughness if used == "profile" else surface_roughness
    return convert(case, case.surface.D, case.surface.G)


def roughness_summary(case: Case, used: Convention) -> dict[str, Any]:
    """summary.json entry of the raceway roughness: D, G as the case gives it, its
    ``G_convention`` and the G the chain's model read (``G_profile`` for the TCR models,
    ``G_surface`` for the asperity load sharing and the wear law)."""
    surface = case.surface
    return {
        "D": surface.D,
        "G": quantity(surface.G, "m"),
        "G_convention": surface.G_convention,
        f"G_{used}": quantity(_used(case, used), "m"),
    }


def roughness_text(case: Case, used: Convention) -> str:
    """``"D = 1.59, G = 9e-10 m"``: the raceway's D and the G its model read, with the case's
    own G where the conventions differ."""
    surface = case.surface
    text = f"D = {surface.D:g}, {used} G = {_used(case, used):.3g} m"
    if surface.G_convention != used:
        text += f" (converted from the {surface.G_convention} G = {surface.G:.3g} m of the case)"
    return text


def roughness_input(case: Case) -> float | tuple[float, float]:
    """``AsperitySurface.roughness`` of the case's contact: the measured σ [m], the band
    (L_u, l_c) [m] of (F3) for a smooth ball, or with a rough ball (``surface.ball``) the
    composite σ = √(σ_raceway² + σ_ball²) of both profiles over that band (Tallian 1967)."""
    if case.tcr.rms_roughness is not None:
        return float(case.tcr.rms_roughness)
    band = measurement_band(case)
    surface = case.surface
    if surface.ball is None:
        return band
    raceway = composite_roughness(surface.D, profile_roughness(case, surface.D, surface.G), *band)
    return math.hypot(raceway, ball_roughness(case))


def measurement_band(case: Case) -> tuple[float, float]:
    """(L_u, l_c) [m]: the wavelength band of a roughness measurement over which (F3) is taken."""
    return case.tcr.sampling_length, case.tcr.cutoff_length


def ball_roughness(case: Case) -> float:
    """σ_b [m] of a rough ball (``surface.ball``, its profile G) over the band
    [``tcr.cutoff_length``, ``tcr.sampling_length``] of (F3); 0 for a smooth ball."""
    ball = case.surface.ball
    if ball is None:
        return 0.0
    g = profile_roughness(case, ball.D, ball.G)
    return composite_roughness(ball.D, g, *measurement_band(case))
