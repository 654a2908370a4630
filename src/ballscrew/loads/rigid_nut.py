"""The nut as a rigid body on its balls: the five directions in which a ball load acts on it.

Ball j sits on the helix at angle θ_j and axial position z_j (pitch radius r = d_m/2), on the
flank σ_j = ±1. In the groove's normal section its contact normal, the direction of the load it
presses on the nut, is (β the contact angle, α the lead angle, right-hand thread)

    n_j = cosβ e_r(θ_j) + σ_j sinβ (cosα e_z − sinα e_θ(θ_j)),

and its line passes through the ball centre p_j = r e_r(θ_j) + (z_j − z_c) e_z (z_c the nut's
centre). A rigid displacement of the nut relative to the screw, w (axial) along e_z, u in the
transverse plane and a small tilt γ about the transverse axes through z_c, moves the nut's
contact point by w e_z + u + γ × p_j and lowers the ball's approach by its projection on n_j:

    Δδ_j = −h_j · (w, u₁, u₂, γ₁, γ₂),   h_j = (n_z, n₁, n₂, (p_j × n_j)₁, (p_j × n_j)₂),

the same h_j that sums the ball loads into the force and moment on the nut, Σ Q_j h_j (virtual
work: the Jacobian of the balance is symmetric). This is the five-degree-of-freedom formulation
of rolling bearings under combined load (Jones 1960; Harris & Kotzalas 2007, *Advanced Concepts
of Bearing Technology*, ch. 1) with the helix's lead angle and the ball's axial position added.
Theory manual, *Loads*.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from ballscrew.errors import InputError

__all__ = ["NUT_SUPPORTS", "ball_directions", "nut_centre", "validate_support"]

NUT_SUPPORTS = ("guided", "free")
"""guided: the housing takes the radial force and tilting moment of the balls (the nut moves
only axially); free: the nut is a rigid body balanced by its balls in all five directions."""


def validate_support(support: str, radial_load: float, tilting_moment: float) -> bool:
    """True for a free nut; refuses an unknown support and external radial loads on a guided
    nut (its housing takes them, the balls never see them)."""
    if support not in NUT_SUPPORTS:
        raise InputError("nut_support", support, " or ".join(NUT_SUPPORTS))
    for name, value in (("radial_load", radial_load), ("tilting_moment", tilting_moment)):
        if not math.isfinite(value) or (support == "guided" and value != 0.0):
            allowed = "0 where the nut is guided" if support == "guided" else "a finite number"
            raise InputError(name, value, allowed)
    return support == "free"


def nut_centre(z: NDArray[np.float64]) -> float:
    """z_c: middle of the balls' axial extent [m], the point the tilt turns about."""
    return 0.5 * float(z.min() + z.max())


def ball_directions(
    z: NDArray[np.float64],
    angle: NDArray[np.float64],
    flank: NDArray[np.float64],
    pitch_radius: float,
    contact_angle: float,
    lead_angle: float,
) -> NDArray[np.float64]:
    """h_j = (n_z, n₁, n₂, (p × n)₁, (p × n)₂) of every ball, shape (balls, 5) [-, -, -, m, m].

    With ζ = z − z_c, s = sinβ cosα, t = sinβ sinα and e_r = (cosθ, sinθ),
    e_θ = (−sinθ, cosθ) in the transverse plane:

        n_⊥ = cosβ e_r − σ t e_θ,
        (p × n)_⊥ = (ζ cosβ − σ r s) e_θ + σ ζ t e_r.
    """
    zeta = z - nut_centre(z)
    cb = math.cos(contact_angle)
    s = math.sin(contact_angle) * math.cos(lead_angle)
    t = math.sin(contact_angle) * math.sin(lead_angle)
    cos, sin = np.cos(angle), np.sin(angle)
    arm_theta = zeta * cb - flank * pitch_radius * s
    arm_r = flank * zeta * t
    return np.stack(
        [
            flank * s,
            cb * cos + flank * t * sin,
            cb * sin - flank * t * cos,
            -arm_theta * sin + arm_r * cos,
            arm_theta * cos + arm_r * sin,
        ],
        axis=1,
    )
