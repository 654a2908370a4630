"""Gothic-arch raceways, contact points and local contact frames, (G8)–(G14).

``docs/theory/geometry.md`` (contact points, groove sections, local contact frames): the groove
arcs of Wei, Lin & Horng (2009) in the normal plane (n, b) of the
ball-centre helix, swept helicoidally into the raceway surfaces, and the contact frames whose x̂ is
the rolling direction t and whose ẑ points from the contact point into the ball. Vectorised over
θ (and φ) like :mod:`ballscrew.geometry.helix`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from ballscrew.geometry.helix import FloatArray, frenet_frame, helix_point
from ballscrew.geometry.screw import ScrewGeometry, Side, flank_sign, side_sign
from ballscrew.validation import real_array, same_shape


def contact_direction(
    geometry: ScrewGeometry, theta: ArrayLike = 0.0, flank: int = 1
) -> FloatArray:
    """Unit vector e_A = cosβ n + s sinβ b from the ball centre to the screw contact A, as in (G8).

    The nut contact B lies on the same load line: e_B = −e_A.
    """
    s = flank_sign(flank)
    _, n, b = frenet_frame(geometry, theta)
    beta = geometry.contact_angle
    return np.cos(beta) * n + s * np.sin(beta) * b


def contact_point(
    geometry: ScrewGeometry, side: Side, flank: int = 1, *, theta: ArrayLike = 0.0
) -> FloatArray:
    """Contact point A = C + r_b e_A (screw) or B = C − r_b e_A (nut), (G8), m."""
    g = side_sign(side)
    return helix_point(geometry, theta) + g * geometry.ball_radius * contact_direction(
        geometry, theta, flank
    )


def groove_profile(
    geometry: ScrewGeometry, side: Side, phi: ArrayLike, flank: int = 1
) -> FloatArray:
    """Groove arc r_AS(φ) (screw, (G9)) or r_BS(φ) (nut, (G10)) in (t, n, b) components, m.

    The arc of radius r_s (r_N) is centred (r_s − r_b) behind the ball centre on the load line, so
    φ = β gives the contact point. φ is the paper's β_AS (β_BS).
    """
    g, s = side_sign(side), flank_sign(flank)
    phi = real_array("phi", phi, "rad")
    r_b, beta = geometry.ball_radius, geometry.contact_angle
    radius = geometry.groove_radius(side)
    offset = radius - r_b
    normal = g * (-offset * np.cos(beta) + radius * np.cos(phi))
    binormal = g * s * (-offset * np.sin(beta) + radius * np.sin(phi))
    return np.stack([np.zeros_like(phi), normal, binormal], axis=-1)


def raceway_surface(
    geometry: ScrewGeometry, side: Side, theta: ArrayLike, phi: ArrayLike, flank: int = 1
) -> FloatArray:
    """Helicoidal raceway S(θ, φ) = C(θ) + Tᵀ(θ) r(φ), (G11), in OXYZ, m.

    θ and φ broadcast against each other.
    """
    theta, phi = real_array("theta", theta, "rad"), real_array("phi", phi, "rad")
    same_shape("theta, phi", theta, phi)
    theta, phi = np.broadcast_arrays(theta, phi)
    profile = groove_profile(geometry, side, phi, flank)
    _, n, b = frenet_frame(geometry, theta)
    return helix_point(geometry, theta) + profile[..., 1:2] * n + profile[..., 2:3] * b


@dataclass(frozen=True)
class ContactFrame:
    """Local contact frame: origin O_k and rotation R_k whose rows are x̂, ŷ, ẑ in OXYZ.

    x̂ = t is the rolling direction (minor axis of the patch), ŷ runs across the groove (major
    axis) and ẑ points from the contact point into the ball. Both arrays may carry leading
    dimensions (one frame per θ).
    """

    origin: FloatArray
    """O_k, shape (..., 3), m."""
    rotation: FloatArray
    """R_k, shape (..., 3, 3); rows x̂, ŷ, ẑ."""

    def to_local(self, points: ArrayLike) -> FloatArray:
        """Local coordinates ξ = R_k·(X − O_k) of points X given in OXYZ (G13)–(G14), m."""
        relative = np.asarray(points, dtype=float) - self.origin
        return np.einsum("...ij,...j->...i", self.rotation, relative)


def contact_frame(
    geometry: ScrewGeometry, side: Side, flank: int = 1, *, theta: ArrayLike = 0.0
) -> ContactFrame:
    """Contact frame A X_A Y_A Z_A (screw, (G13)) or B X_B Y_B Z_B (nut, (G14)).

    In (t, n, b) components: screw x̂ = (1, 0, 0), ẑ = −e_A, ŷ = ẑ × x̂ = (0, −s sinβ, cosβ);
    nut x̂ = (1, 0, 0), ẑ = +e_A, ŷ = (0, s sinβ, −cosβ).
    """
    g = side_sign(side)
    t, _, _ = frenet_frame(geometry, theta)
    z_axis = -g * contact_direction(geometry, theta, flank)
    y_axis = np.cross(z_axis, t)
    return ContactFrame(
        origin=contact_point(geometry, side, flank, theta=theta),
        rotation=np.stack([t, y_axis, z_axis], axis=-2),
    )
