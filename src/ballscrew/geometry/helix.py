"""Ball-centre helix and its Frenet–Serret frame, (G1)–(G7) of ``docs/theory/geometry.md``.

Right-hand thread, screw axis z, screw-fixed frame OXYZ (Lin, Ravani & Velinsky 1994; Wei, Lin &
Horng 2009). Every function is vectorised over the helix angle θ: an input of shape ``S`` gives
vectors of shape ``S + (3,)`` and matrices of shape ``S + (3, 3)``.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ballscrew.geometry.screw import ScrewGeometry
from ballscrew.validation import real_array

FloatArray = NDArray[np.float64]


def helix_point(geometry: ScrewGeometry, theta: ArrayLike) -> FloatArray:
    """Ball-centre helix C(θ) = (r_m cosθ, r_m sinθ, p_h θ), (G1), m."""
    theta = real_array("theta", theta, "rad")
    r_m = geometry.pitch_radius
    return np.stack(
        [r_m * np.cos(theta), r_m * np.sin(theta), geometry.helix_parameter * theta], axis=-1
    )


def frenet_frame(
    geometry: ScrewGeometry, theta: ArrayLike
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Unit tangent t, principal normal n (towards the axis) and binormal b = t × n, (G3)–(G5)."""
    theta = real_array("theta", theta, "rad")
    cos_t, sin_t = np.cos(theta), np.sin(theta)
    cos_a, sin_a = np.cos(geometry.lead_angle), np.sin(geometry.lead_angle)
    zero = np.zeros_like(theta)
    t = np.stack([-cos_a * sin_t, cos_a * cos_t, np.full_like(theta, sin_a)], axis=-1)
    n = np.stack([-cos_t, -sin_t, zero], axis=-1)
    b = np.stack([sin_a * sin_t, -sin_a * cos_t, np.full_like(theta, cos_a)], axis=-1)
    return t, n, b


def frenet_matrix(geometry: ScrewGeometry, theta: ArrayLike) -> FloatArray:
    """The paper's T(θ): rows tᵀ, nᵀ, bᵀ, so that x_tnb = T(θ)·(X − C(θ)) from (G3)–(G5).

    The inverse is X = C(θ) + T(θ)ᵀ x_tnb.
    """
    return np.stack(frenet_frame(geometry, theta), axis=-2)
