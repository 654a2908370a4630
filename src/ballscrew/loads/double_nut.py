"""Double-nut (spacer-preloaded) ball screw: load split, axial stiffness and preload loss by wear.

Each nut deflects axially as δ_a = C_a F^(2/3) (Hertz point contacts, screw/nut bodies rigid).
The spacer fixes the total axial interference 2 C_a F_p^(2/3); an external axial load F_a moves the
nut body by x, loading nut 1 and unloading nut 2.

Sources: Hertz δ ∝ Q^(2/3) (Johnson 1985); Steinmeyer technical notes (lift-off at 2.83 F_p);
theory manual ``docs/theory/loads.md`` (P1)–(P4), (E1.7)–(E1.13).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import brentq

from ballscrew.errors import ConvergenceError, InputError
from ballscrew.loads.ball_load import validate_angles, validate_balls
from ballscrew.validation import nonnegative_array, positive, positive_array, same_shape

__all__ = [
    "NutForces",
    "axial_deflection_from_approaches",
    "nut_axial_compliance",
    "nut_axial_deflection",
    "nut_forces",
    "preload_after_wear",
    "preloaded_axial_stiffness",
]

_U_XTOL = 1.0e-15
_U_RTOL = 1.0e-15
_WEAR_NEWTON_STEPS = 40
"""Newton steps on F^(1/3) for the preload after wear with bodies (quadratic convergence from
above; 40 reach rounding from any start the closed form gives)."""


class NutForces(NamedTuple):
    """Axial forces of the two nuts of a preloaded double nut (unpacks as ``f1, f2``)."""

    f1: float
    """Axial force of the loaded nut 1 (the nut the external load presses on), N."""
    f2: float
    """Axial force of the unloaded nut 2, N (0 after lift-off)."""


def nut_forces(preload: float, axial_load: float) -> NutForces:
    """Forces (F1, F2) of a spacer-preloaded double nut under an axial load, (P1)–(P3).

    With u = x/δ₀ the nut-body displacement relative to the preload deflection δ₀,

        F1 = F_p (1 + u)^(3/2),   F2 = F_p max(1 − u, 0)^(3/2),   F1 − F2 = F_a,

    i.e. F1^(2/3) + F2^(2/3) = 2 F_p^(2/3) while both nuts touch. A ball contact cannot carry
    tension, hence the max(·, 0): the residual (1+u)^(3/2) − max(1−u, 0)^(3/2) − F_a/F_p is
    continuous and strictly increasing in u, and one Brent solve on [0, max(1, (F_a/F_p)^(2/3))]
    covers both regimes. Lift-off of nut 2 (u = 1, F_a = 2^(3/2) F_p ≈ 2.8284 F_p) therefore
    emerges from the equations; beyond it F1 = F_a and F2 = 0 (P3). F2 is computed from u and
    F1 = F_a + F2, so F1 − F2 = F_a holds to rounding.

    Args:
        preload: preload F_p of each nut (> 0), N.
        axial_load: external axial load F_a (>= 0), N. Sign convention: a positive load presses
            on nut 1 and unloads nut 2; for the opposite direction swap the roles of the nuts.

    Returns:
        NutForces(f1, f2) in N, loaded nut first. E.g. F_p = 1500 N, F_a = 2000 N →
        (2614.586, 614.586) N.

    Raises:
        InputError: if preload <= 0 or axial_load < 0 (or either is not finite).
        ConvergenceError: if Brent's method fails (not expected).
    """
    f_p = positive("preload", preload, "N")
    f_a = float(axial_load)
    if not (math.isfinite(f_a) and f_a >= 0.0):
        raise InputError(
            "axial_load",
            axial_load,
            "a finite number >= 0 N (axial_load >= 0 loads nut 1 and unloads nut 2; "
            "for the other direction swap the nuts)",
        )
    ratio = f_a / f_p

    def residual(u: float) -> float:
        return (1.0 + u) ** 1.5 - max(1.0 - u, 0.0) ** 1.5 - ratio

    u_hi = max(1.0, ratio ** (2.0 / 3.0))
    u, info = brentq(residual, 0.0, u_hi, xtol=_U_XTOL, rtol=_U_RTOL, full_output=True, disp=False)
    if not info.converged:
        raise ConvergenceError(
            "nut_forces (Brent on u, P1)", info.iterations, abs(residual(u)), _U_XTOL
        )
    f2 = f_p * max(1.0 - u, 0.0) ** 1.5
    return NutForces(f1=f_a + f2, f2=f2)


def preloaded_axial_stiffness(force: ArrayLike, axial_deflection: ArrayLike) -> NDArray[np.float64]:
    """Axial stiffness dF/dδ_a = 1.5 F/δ_a of one nut with δ_a = C_a F^(2/3), (P4).

    Args:
        force: axial force F of the nut (>= 0), N.
        axial_deflection: its axial deflection δ_a (> 0), m.

    Returns:
        Stiffness in N/m (broadcast shape); e.g. 1500 N at 4.0217 µm → 5.595e8 N/m.
    """
    f = nonnegative_array("force", force, "N")
    d = positive_array("axial_deflection", axial_deflection, "m")
    same_shape("force, axial_deflection", f, d)
    return 1.5 * f / d


def axial_deflection_from_approaches(
    delta_a: ArrayLike, delta_b: ArrayLike, contact_angle: float, lead_angle: float
) -> NDArray[np.float64]:
    """Axial deflection of one nut from its normal approaches, (E1.7).

        δ_a = (δ_A + δ_B)/(sinβ cosα)

    Args:
        delta_a: normal elastic approach δ_A at the ball–screw contact, m.
        delta_b: normal elastic approach δ_B at the ball–nut contact, m.
        contact_angle: contact angle β, rad.
        lead_angle: lead angle α (λ), rad.

    Returns:
        δ_a in m (broadcast shape).
    """
    beta, alpha = validate_angles(contact_angle, lead_angle)
    da = nonnegative_array("delta_a", delta_a, "m")
    db = nonnegative_array("delta_b", delta_b, "m")
    same_shape("delta_a, delta_b", da, db)
    return (da + db) / (math.sin(beta) * math.cos(alpha))


def nut_axial_compliance(
    k_a: float, k_b: float, balls: int, contact_angle: float, lead_angle: float
) -> float:
    """Nut compliance constant C_a = (K_A + K_B) / [sinβ cosα (n_b sinβ cosα)^(2/3)], (E1.8).

    Follows from the Hertz deflection δ_k = K_k Q^(2/3), Q = F/(n_b sinβ cosα) (Q1) and (E1.7).
    Screw and nut body compliance is neglected.

    Args:
        k_a: Hertz constant K_A of the ball–screw contact (δ_A = K_A Q^(2/3)), m N^(-2/3).
        k_b: Hertz constant K_B of the ball–nut contact, m N^(-2/3).
        balls: loaded balls per nut n_b.
        contact_angle: contact angle β, rad.
        lead_angle: lead angle α (λ), rad.

    Returns:
        C_a in m N^(-2/3), so that δ_a = C_a F^(2/3).
    """
    beta, alpha = validate_angles(contact_angle, lead_angle)
    n_b = validate_balls(balls)
    k_sum = positive("k_a", k_a, "m N^-2/3") + positive("k_b", k_b, "m N^-2/3")
    s = math.sin(beta) * math.cos(alpha)
    return k_sum / (s * (n_b * s) ** (2.0 / 3.0))


def nut_axial_deflection(force: ArrayLike, compliance_constant: float) -> NDArray[np.float64]:
    """Axial deflection δ_a = C_a F^(2/3) of one nut, (E1.8).

    Args:
        force: axial force F of the nut (>= 0), N.
        compliance_constant: C_a (> 0), m N^(-2/3).

    Returns:
        δ_a in m, same shape as ``force``.
    """
    c_a = positive("compliance_constant", compliance_constant, "m N^-2/3")
    return c_a * nonnegative_array("force", force, "N") ** (2.0 / 3.0)


def preload_after_wear(
    initial_preload: float,
    compliance_constant: float,
    max_wear_depth: ArrayLike,
    contact_angle: float,
    lead_angle: float,
    body_compliance: float = 0.0,
) -> NDArray[np.float64]:
    """Preload left after screw-raceway wear, equation (E1.13) [reconstructed].

        δ_a' = C_a F_p0^(2/3) − h_max/(sinβ cosα)
        F_p' = (δ_a'/C_a)^(3/2)   (F_p' = 0 if δ_a' <= 0)

    The wear depth h_max (along the contact normal, equal on both flanks under symmetric
    reciprocation) lowers each nut's axial interference by h_max/(sinβ cosα). With the elastic
    bodies of the preload loop in series (``body_compliance`` c_b per nut, m/N) the interference
    is C_a F^(2/3) + c_b F, and F_p' solves C_a F'^(2/3) + c_b F' = C_a F_p0^(2/3) + c_b F_p0 −
    h_max/(sinβ cosα) (Newton on F^(1/3) from above, where the cubic is convex).

    Args:
        initial_preload: initial preload F_p0 (> 0), N.
        compliance_constant: nut compliance C_a (> 0), m N^(-2/3); see
            :func:`nut_axial_compliance`.
        max_wear_depth: largest wear depth h_max (>= 0), m; any shape.
        contact_angle: contact angle β, rad.
        lead_angle: lead angle α (λ), rad.
        body_compliance: c_b (>= 0) of shaft and nut body in the preload loop, per nut, m/N.

    Returns:
        F_p' in N, same shape as ``max_wear_depth``; e.g. F_p0 = 1500 N, C_a = 3.749e-8,
        h_max = 1 µm → 899.7 N.
    """
    f_p0 = positive("initial_preload", initial_preload, "N")
    c_a = positive("compliance_constant", compliance_constant, "m N^-2/3")
    beta, alpha = validate_angles(contact_angle, lead_angle)
    h = nonnegative_array("max_wear_depth", max_wear_depth, "m")
    c_b = float(body_compliance)
    if not (math.isfinite(c_b) and c_b >= 0.0):
        raise InputError("body_compliance", body_compliance, "a finite number >= 0 m/N")
    delta = c_a * f_p0 ** (2.0 / 3.0) + c_b * f_p0 - h / (math.sin(beta) * math.cos(alpha))
    rhs = np.maximum(delta, 0.0)
    if c_b == 0.0:
        return rhs**1.5 / c_a**1.5
    u = np.sqrt(rhs / c_a)  # F^(1/3) without the bodies: above the root
    for _ in range(_WEAR_NEWTON_STEPS):
        slope = np.maximum(2.0 * c_a * u + 3.0 * c_b * u**2, np.finfo(float).tiny)
        u = u - (c_a * u**2 + c_b * u**3 - rhs) / slope
    return u**3
