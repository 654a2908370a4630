"""One convention for the fractal roughness G of a profile and of a surface.

The Majumdar–Bhushan (1990) profile and the Yan–Komvopoulos (1998) 3-D surface both write the
roughness as (D, G), but the two G are not the same number: for equal D they give different RMS
heights. :func:`surface_roughness_from_profile` is the conversion that makes the two descriptions
of one surface agree on σ at every sampling length L (theory manual, *Fractal contact*):

    MB profile:   σ² = G_p^(2(D−1)) L^(4−2D) / (2 ln γ (4 − 2D))
    YK surface:   σ² = G_s^(2(D−1)) L^(4−2D) ln γ / (2 (1 − γ^(2(D−2))))      (D_s = D + 1)

    ⇒  G_s = G_p [ (1 − γ^(2(D−2))) / ((ln γ)² (4 − 2D)) ]^(1/(2(D−1)))

L cancels, so the conversion holds for any band that starts at the sampling length.
"""

from __future__ import annotations

import math

from ballscrew.errors import InputError
from ballscrew.fractal.domain_extension import validate_dimension
from ballscrew.validation import positive

__all__ = ["profile_roughness_from_surface", "surface_roughness_from_profile"]


def _factor(D: float, gamma: float) -> float:
    D = validate_dimension(D)
    if not float(gamma) > 1.0:
        raise InputError("gamma", gamma, "W-M frequency ratio > 1")
    ln_g = math.log(gamma)
    ratio = (1.0 - gamma ** (2.0 * (D - 2.0))) / (ln_g**2 * (4.0 - 2.0 * D))
    return ratio ** (1.0 / (2.0 * (D - 1.0)))


def surface_roughness_from_profile(D: float, G: float, gamma: float = 1.5) -> float:
    """G of the 3-D Yan–Komvopoulos surface with the RMS height of the MB profile (D, G), m."""
    return positive("G", G, "m") * _factor(D, gamma)


def profile_roughness_from_surface(D: float, G: float, gamma: float = 1.5) -> float:
    """G of the MB profile with the RMS height of the 3-D surface (D + 1, G), m."""
    return positive("G", G, "m") / _factor(D, gamma)
