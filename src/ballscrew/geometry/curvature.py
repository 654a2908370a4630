"""Raceway curvatures and the gap Hessian at the contact points, (G15)–(G18).

Theory manual ``docs/theory/geometry.md``, closed-form curvatures (this project's derivation):
second fundamental form of the helicoidal sweep (G11) in the contact frame (G13)/(G14), with x̂ = t
(rolling) and ŷ across the groove. The closed forms are exact at the contact point; the initial gap
near the contact is h ≈ ½(h_xx x² + 2 h_xy x y + h_yy y²). The Harris-type curvature sum Σρ and
difference F(ρ) (Harris & Kotzalas) are given for reference, as is the common cosα simplification of
the rolling-direction curvature used in ball-screw papers (G18).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

from ballscrew.errors import InputError
from ballscrew.geometry.screw import ScrewGeometry, Side, side_sign

CurvatureModel = Literal["exact", "harris"]


@dataclass(frozen=True)
class RacewayCurvature:
    """Curvature of one raceway at its contact point and the resulting gap Hessian, 1/m.

    ``k_x`` is the signed normal curvature of the raceway along the rolling direction, positive
    where the raceway curves away from the ball (Harris's ρ_II1): the screw is convex
    (k_x = k_sx > 0, (G15)), the nut concave (k_x = −k_Nx < 0, (G16)). The gap Hessian (G17) is
    h_xx = 1/r_b + k_x, h_yy = 1/r_b − 1/r_groove, and the twist term h_xy.
    """

    side: Side
    k_x: float
    h_xx: float
    h_yy: float
    h_xy: float

    @property
    def rx(self) -> float:
        """Relative radius along the rolling direction, R_x = 1/h_xx (Hertz A = h_xx/2), m."""
        return 1.0 / self.h_xx

    @property
    def ry(self) -> float:
        """Relative radius across the groove, R_y = 1/h_yy (Hertz B = h_yy/2), m."""
        return 1.0 / self.h_yy

    @property
    def principal_angle(self) -> float:
        """Angle from x̂ to the principal axis of the larger curvature, ½ atan2(2h_xy, h_xx − h_yy).

        About 5e-4 rad for typical screws (theory manual, *Raceway geometry*), so the patch axes are
        x̂ and ŷ in practice.
        """
        return 0.5 * math.atan2(2.0 * self.h_xy, self.h_xx - self.h_yy)

    @property
    def principal_curvatures(self) -> tuple[float, float]:
        """Eigenvalues (larger, smaller) of the gap Hessian, 1/m."""
        mean = 0.5 * (self.h_xx + self.h_yy)
        radius = math.hypot(0.5 * (self.h_xx - self.h_yy), self.h_xy)
        return mean + radius, mean - radius

    @property
    def curvature_sum(self) -> float:
        """Harris Σρ = 4/D_b − 1/(f D_b) + ρ_II1 = h_xx + h_yy, (G18), 1/m."""
        return self.h_xx + self.h_yy

    @property
    def curvature_difference(self) -> float:
        """Harris F(ρ) = [(ρ_I1 − ρ_I2) + (ρ_II1 − ρ_II2)]/Σρ, (G18).

        Equal to (h_xx − h_yy)/(h_xx + h_yy).
        """
        return (self.h_xx - self.h_yy) / (self.h_xx + self.h_yy)


def rolling_curvature(geometry: ScrewGeometry, side: Side) -> float:
    """Exact signed rolling-direction curvature k_x of the raceway at its contact point, 1/m.

    With g = +1 (screw) or −1 (nut):
    k_x = [g κ cosβ − κ² r_b cos²β + τ² r_b (1 − r_b/r_g)]/(1 − g κ r_b cosβ)², i.e.

    (G15) screw: k_sx = [κ cosβ − κ² r_b cos²β + τ² r_b (1 − r_b/r_s)]/(1 − κ r_b cosβ)²;
    (G16) nut: k_Nx = [κ cosβ + κ² r_b cos²β − τ² r_b (1 − r_b/r_N)]/(1 + κ r_b cosβ)², returned
    as k_x = −k_Nx (concave).
    """
    g = side_sign(side)
    kappa, tau = geometry.curvature, geometry.torsion
    r_b, cos_b = geometry.ball_radius, math.cos(geometry.contact_angle)
    radius = geometry.groove_radius(side)
    numerator = g * kappa * cos_b - kappa**2 * r_b * cos_b**2 + tau**2 * r_b * (1.0 - r_b / radius)
    return numerator / (1.0 - g * kappa * r_b * cos_b) ** 2


def harris_rolling_curvature(geometry: ScrewGeometry, side: Side) -> float:
    """Common simplification ρ_II1 ≈ ±2 cosβ cosα/(d_m ∓ D_b cosβ), (G18), 1/m.

    Signed like :attr:`RacewayCurvature.k_x`. About 0.4 % (screw) and 0.25 % (nut) larger in
    magnitude than the exact (G15)/(G16) at α = 4.55°.
    """
    g = side_sign(side)
    cos_b = math.cos(geometry.contact_angle)
    return (
        g
        * 2.0
        * cos_b
        * math.cos(geometry.lead_angle)
        / (geometry.pitch_diameter - g * geometry.ball_diameter * cos_b)
    )


def raceway_curvature(
    geometry: ScrewGeometry, side: Side, model: CurvatureModel = "exact"
) -> RacewayCurvature:
    """Rolling curvature and gap Hessian (G17) at contact A (``"screw"``) or B (``"nut"``).

    ``model="exact"`` uses (G15)–(G17), which equal the Hessian of the exact gap (Newton projection)
    at the origin. ``model="harris"`` replaces k_x by the cosα simplification and drops the small
    twist term h_xy, as ball-screw papers do (G18). The result is the same for both flanks.
    """
    g = side_sign(side)
    if model == "exact":
        k_x = rolling_curvature(geometry, side)
        radius = geometry.groove_radius(side)
        r_b = geometry.ball_radius
        stretch = 1.0 - g * geometry.curvature * r_b * math.cos(geometry.contact_angle)
        h_xy = -geometry.torsion * (radius - r_b) / (radius * stretch)
    elif model == "harris":
        k_x = harris_rolling_curvature(geometry, side)
        h_xy = 0.0
    else:
        raise InputError("model", model, "'exact' or 'harris'")
    inverse_r_b = 1.0 / geometry.ball_radius
    return RacewayCurvature(
        side=side,
        k_x=k_x,
        h_xx=inverse_r_b + k_x,
        h_yy=inverse_r_b - 1.0 / geometry.groove_radius(side),
        h_xy=h_xy,
    )
