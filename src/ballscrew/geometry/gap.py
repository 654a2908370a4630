"""Initial (unloaded) gap h(x, y) between ball and raceway in the contact frame, (G11)–(G18).

``docs/theory/geometry.md``, exact gap by Newton projection (this project's derivation of what the
paper's Eqs. (8)–(9) do): at every node (x, y) of the tangent-plane grid of contact A (screw) or B
(nut), the ball surface is z_b = r_b − √(r_b² − x² − y²) (the paper's Eq. (1)) and the raceway
height z_r comes from solving [R_k(S(θ, φ) − O_k)]_{x,y} = (x, y) on the helicoidal sweep S (G11)
for (θ, φ); h = z_b − z_r. All 2×2 Newton systems of a grid are solved at once with the analytic
Jacobian. Because the raceway is a helicoid, the gap does not depend on where along the helix the
ball sits, so the contact is put at θ_C = 0.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from functools import partial

import numpy as np
from numpy.typing import ArrayLike

from ballscrew.errors import ConvergenceError, InputError
from ballscrew.geometry.curvature import raceway_curvature
from ballscrew.geometry.helix import FloatArray
from ballscrew.geometry.raceway import contact_frame
from ballscrew.geometry.screw import ScrewGeometry, Side, flank_sign, side_sign
from ballscrew.registry import Registry
from ballscrew.validation import real_array, same_shape

GapFunction = Callable[[ArrayLike, ArrayLike], FloatArray]

_TOLERANCE = 1e-12
"""Newton stops when |residual| ≤ _TOLERANCE·r_b in both tangent-plane coordinates."""
_MAX_ITERATIONS = 50


@dataclass(frozen=True)
class RacewayPoint:
    """Raceway point below tangent-plane coordinates (x, y): sweep parameters and height."""

    theta: FloatArray
    """Helix angle θ of the point, relative to the contact at θ_C = 0, rad."""
    phi: FloatArray
    """Groove-arc parameter φ (β at the contact point), rad."""
    z: FloatArray
    """Raceway height z_r along ẑ (towards the ball), m."""


def ball_height(geometry: ScrewGeometry, x: ArrayLike, y: ArrayLike) -> FloatArray:
    """Ball surface z_b = r_b − √(r_b² − x² − y²) above the tangent plane (the paper's Eq. (1)), m.

    Evaluated as ρ²/(r_b + √(r_b² − ρ²)) to keep full precision near the origin. Points with
    x² + y² ≥ r_b² are not on the ball's lower hemisphere and raise InputError.
    """
    r_b = geometry.ball_radius
    rho2 = np.square(real_array("x", x, "m")) + np.square(real_array("y", y, "m"))
    if not np.all(rho2 < r_b**2):
        worst = float(np.sqrt(np.max(rho2)))
        raise InputError("x, y", worst, f"√(x² + y²) < r_b = {r_b!r} m (the ball's radius)")
    return rho2 / (r_b + np.sqrt(r_b**2 - rho2))


def project_onto_raceway(
    geometry: ScrewGeometry, side: Side, x: ArrayLike, y: ArrayLike, flank: int = 1
) -> RacewayPoint:
    """Solve [R_k(S(θ, φ) − O_k)]_{x,y} = (x, y) for (θ, φ) by vectorised Newton, (G11).

    Starts from the contact point (θ, φ) = (0, β) and stops when the tangent-plane residual is
    below 1e-12 r_b; raises :class:`~ballscrew.errors.ConvergenceError` if it is not reached.
    The groove arc is taken as a full circle: its angular extent β ± β_0 is not a parameter of
    :class:`ScrewGeometry` and is not checked.
    """
    g, s = side_sign(side), flank_sign(flank)
    x, y = real_array("x", x, "m"), real_array("y", y, "m")
    same_shape("x, y", x, y)
    x, y = np.broadcast_arrays(x, y)
    rows = contact_frame(geometry, side, s).rotation
    r_m, p_h, r_b = geometry.pitch_radius, geometry.helix_parameter, geometry.ball_radius
    cos_a, sin_a = np.cos(geometry.lead_angle), np.sin(geometry.lead_angle)
    beta, radius = geometry.contact_angle, geometry.groove_radius(side)
    # Contact point relative to the ball centre, in (n, b) components: ±r_b (cosβ, s sinβ).
    u_c, w_c = g * r_b * np.cos(beta), g * s * r_b * np.sin(beta)
    tolerance = _TOLERANCE * r_b

    theta = np.zeros_like(x)
    psi = np.zeros_like(x)  # ψ = φ − β
    for iteration in range(_MAX_ITERATIONS + 1):
        cos_t, sin_t = np.cos(theta), np.sin(theta)
        versine = 2.0 * np.sin(0.5 * theta) ** 2  # 1 − cosθ without cancellation
        half, mid = np.sin(0.5 * psi), beta + 0.5 * psi
        # Arc point minus contact point, in (n, b) components (G9)/(G10); and d/dψ.
        du = -2.0 * g * radius * np.sin(mid) * half
        dw = 2.0 * g * s * radius * np.cos(mid) * half
        du_psi = -g * radius * np.sin(beta + psi)
        dw_psi = g * s * radius * np.cos(beta + psi)
        u, w = u_c + du, w_c + dw
        # OXYZ components of S(θ, φ) − O_k = [C(θ) − C(0)] + du n(θ) + dw b(θ)
        # + u_c [n(θ) − n(0)] + w_c [b(θ) − b(0)], and of its θ and ψ derivatives.
        offset = (
            -r_m * versine - du * cos_t + dw * sin_a * sin_t + u_c * versine + w_c * sin_a * sin_t,
            r_m * sin_t - du * sin_t - dw * sin_a * cos_t - u_c * sin_t + w_c * sin_a * versine,
            p_h * theta + dw * cos_a,
        )
        d_theta = (
            -r_m * sin_t + u * sin_t + w * sin_a * cos_t,
            r_m * cos_t - u * cos_t + w * sin_a * sin_t,
            np.full_like(theta, p_h),
        )
        d_psi = (
            -du_psi * cos_t + dw_psi * sin_a * sin_t,
            -du_psi * sin_t - dw_psi * sin_a * cos_t,
            dw_psi * cos_a,
        )
        local_x = sum(rows[0, j] * offset[j] for j in range(3))
        local_y = sum(rows[1, j] * offset[j] for j in range(3))
        res_x, res_y = local_x - x, local_y - y
        residual = float(np.max(np.maximum(np.abs(res_x), np.abs(res_y)), initial=0.0))
        if residual <= tolerance:
            z = sum(rows[2, j] * offset[j] for j in range(3))
            return RacewayPoint(theta=theta, phi=beta + psi, z=z)
        if iteration == _MAX_ITERATIONS or not np.isfinite(residual):
            break
        jac_xt = sum(rows[0, j] * d_theta[j] for j in range(3))
        jac_yt = sum(rows[1, j] * d_theta[j] for j in range(3))
        jac_xp = sum(rows[0, j] * d_psi[j] for j in range(3))
        jac_yp = sum(rows[1, j] * d_psi[j] for j in range(3))
        det = jac_xt * jac_yp - jac_xp * jac_yt
        theta = theta - (jac_yp * res_x - jac_xp * res_y) / det
        psi = psi - (jac_xt * res_y - jac_yt * res_x) / det
    raise ConvergenceError(
        f"raceway projection ({side}, flank {s:+d})", iteration, residual, tolerance
    )


GAP_MODELS: Registry[Callable[..., FloatArray]] = Registry(
    "raceway gap model", "numerics.gap_model"
)
"""Raceway gap models: ``exact`` (Newton projection) and ``quadratic`` (Hertz)."""


@GAP_MODELS.register("exact", "exact gap by Newton projection onto the swept raceway")
def gap_exact(
    geometry: ScrewGeometry, side: Side, x: ArrayLike, y: ArrayLike, flank: int = 1
) -> FloatArray:
    """Exact initial gap h(x, y) = z_b − z_r ≥ 0 at contact A (screw) or B (nut), m.

    x (along t, rolling) and y (across the groove) are tangent-plane coordinates of the contact
    frame (G13)/(G14), broadcastable arrays in m, with x² + y² < r_b². Contains the cubic
    (lead-angle asymmetry) and quartic terms that :func:`gap_quadratic` drops.
    """
    z_ball = ball_height(geometry, x, y)
    return z_ball - project_onto_raceway(geometry, side, x, y, flank).z


@GAP_MODELS.register("quadratic", "quadratic (Hertz) gap with the exact Hessian")
def gap_quadratic(
    geometry: ScrewGeometry, side: Side, x: ArrayLike, y: ArrayLike, flank: int = 1
) -> FloatArray:
    """Quadratic gap ½(h_xx x² + 2 h_xy x y + h_yy y²) with the exact Hessian (G17), m.

    The same for both flanks (they map onto each other by (x, y) → (−x, −y)); ``flank`` is
    validated for symmetry with :func:`gap_exact`.
    """
    flank_sign(flank)
    c = raceway_curvature(geometry, side)
    x, y = real_array("x", x, "m"), real_array("y", y, "m")
    same_shape("x, y", x, y)
    return 0.5 * (c.h_xx * x * x + 2.0 * c.h_xy * x * y + c.h_yy * y * y)


def gap_function(
    geometry: ScrewGeometry, side: Side, flank: int = 1, model: str = "exact"
) -> GapFunction:
    """Vectorised h(x, y) for the contact solver's grid; ``model`` names a :data:`GAP_MODELS`."""
    side_sign(side)
    flank_sign(flank)
    return partial(GAP_MODELS[model], geometry, side, flank=flank)
