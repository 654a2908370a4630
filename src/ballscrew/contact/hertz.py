"""Hertz contact of two bodies with the initial gap h = x²/(2 rx) + y²/(2 ry).

Exact elliptical solution (H2)-(H4) (Johnson 1985, Contact Mechanics, §4.2), its circular limit
(H1), and the Hamrock & Brewe (1983) curve fits (H5)-(H7) (J. Lubr. Technol. 105:171).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy.optimize import brentq
from scipy.special import elliprd, elliprf

from ballscrew.backend import array_module
from ballscrew.contact._validation import composite_modulus_checked, positive

__all__ = ["HertzContact", "hamrock_brewe", "hertz"]


@dataclass(frozen=True)
class HertzContact:
    """Elliptical Hertz contact; ``a`` lies along x and ``b`` along y whichever is longer."""

    a: float
    """Semi-axis along x [m]."""
    b: float
    """Semi-axis along y [m]."""
    p0: float
    """Peak pressure at the centre [Pa]."""
    approach: float
    """Rigid-body approach δ of the two bodies [m]."""
    load: float
    """Normal load W [N]."""

    @property
    def eccentricity(self) -> float:
        """e = √(1 − minor²/major²) [-]."""
        minor, major = sorted((self.a, self.b))
        return float(np.sqrt(1.0 - (minor / major) ** 2))

    @property
    def area(self) -> float:
        """Contact area π a b [m²]."""
        return float(np.pi * self.a * self.b)

    @property
    def mean_pressure(self) -> float:
        """Mean pressure W / (π a b) = 2 p0 / 3 [Pa]."""
        return 2.0 * self.p0 / 3.0

    def pressure(self, x: Any, y: Any) -> Any:
        """p = p0 √(1 − x²/a² − y²/b²) inside the ellipse, 0 outside [Pa]; x, y [m] broadcast."""
        xp = array_module(x)
        inside = 1.0 - (x / self.a) ** 2 - (y / self.b) ** 2
        return self.p0 * xp.sqrt(xp.maximum(inside, 0.0))


def _elliptic_k_d(k_prime: float) -> tuple[float, float]:
    """K(m) and D(m) = (K − E)/m for m = 1 − k′², from Carlson's R_F and R_D.

    K = R_F(0, k′², 1), D = R_D(0, k′², 1)/3 (DLMF 19.25.1): no cancellation as m → 0 or 1.
    """
    kp2 = k_prime * k_prime
    return float(elliprf(0.0, kp2, 1.0)), float(elliprd(0.0, kp2, 1.0)) / 3.0


def _curvature_ratio(k_prime: float) -> float:
    """B/A of (H2) at k′ = minor/major: [E/(1 − e²) − K]/(K − E) = (K − D)/(k′² D)."""
    k, d = _elliptic_k_d(k_prime)
    return (k - d) / (k_prime * k_prime * d)


def _oriented(rx: float, ry: float, major: float, minor: float) -> tuple[float, float]:
    """(a, b) along (x, y): the major axis lies along the larger relative radius."""
    return (major, minor) if rx >= ry else (minor, major)


def hertz(rx: float, ry: float, e_star: float, load: float) -> HertzContact:
    """Exact Hertz contact for the gap h = x²/(2 rx) + y²/(2 ry) under the normal load W.

    With A = 1/(2 max(rx, ry)) ≤ B = 1/(2 min(rx, ry)), k′ = minor/major and m = e² = 1 − k′²
    (Johnson 1985, §4.2):

    (H2) B/A = [E(e)/(1 − e²) − K(e)] / [K(e) − E(e)]        solved for e (Brent);
    (H3) major³ = 3 W [K(e) − E(e)] / (2π e² E* A),  minor = major·√(1 − e²);
    (H4) p0 = 3 W / (2π a b),  δ = p0 · minor · K(e) / E*.

    K − E and K are taken from Carlson's integrals, so the circular limit is continuous; rx == ry
    uses (H1) directly: a = (3 W R / (4 E*))^(1/3), p0 = 3 W / (2π a²), δ = a²/R, with R = rx = ry.

    rx, ry [m] relative radii of curvature along x and y; e_star [Pa] composite modulus (K1);
    load [N]. The semi-axis ``a`` lies along x.
    """
    rx, ry = positive("rx", rx), positive("ry", ry)
    e_star, load = composite_modulus_checked("e_star", e_star), positive("load", load)
    if rx == ry:
        radius = rx
        a = (3.0 * load * radius / (4.0 * e_star)) ** (1.0 / 3.0)
        return HertzContact(a, a, 3.0 * load / (2.0 * np.pi * a * a), a * a / radius, load)
    small_a = 0.5 / max(rx, ry)
    target = max(rx, ry) / min(rx, ry)
    k_prime = brentq(
        lambda kp: _curvature_ratio(kp) - target, 1e-12, 1.0, xtol=1e-300, rtol=1e-15, maxiter=500
    )
    k, d = _elliptic_k_d(k_prime)
    major = (3.0 * load * d / (2.0 * np.pi * e_star * small_a)) ** (1.0 / 3.0)
    minor = major * k_prime
    p0 = 3.0 * load / (2.0 * np.pi * major * minor)
    a, b = _oriented(rx, ry, major, minor)
    return HertzContact(a, b, p0, p0 * minor * k / e_star, load)


def hamrock_brewe(rx: float, ry: float, e_star: float, load: float) -> HertzContact:
    """Hertz contact from the Hamrock & Brewe (1983) curve fits.

    Within ~1 % of :func:`hertz` for R_y/R_x ≳ 3 (ball-raceway contacts); near the circle the fits
    are up to ~5 % off (k = 1.0339 instead of 1 and δ 5 % low at R_y = R_x).

    With R_x ≤ R_y the principal radii, α_r = R_y/R_x, E′ = 2E*, 1/R = 1/R_x + 1/R_y:

    (H5) k = 1.0339 α_r^0.6360,  ℰ = 1.0003 + 0.5968/α_r,  ℱ = 1.5277 + 0.6023 ln α_r;
    (H6) D_y = 2 (6 k² ℰ W R/(π E′))^(1/3),  D_x = 2 (6 ℰ W R/(π k E′))^(1/3);
    (H7) δ = ℱ [(9/(2 ℰ R)) (W/(π k E′))²]^(1/3),  p0 = 6 W/(π D_x D_y).

    The major axis D_y lies along the larger radius; ``a`` of the result lies along x.
    """
    rx, ry = positive("rx", rx), positive("ry", ry)
    e_star, load = composite_modulus_checked("e_star", e_star), positive("load", load)
    r_small, r_large = sorted((rx, ry))
    alpha_r = r_large / r_small
    e_prime = 2.0 * e_star
    radius = 1.0 / (1.0 / rx + 1.0 / ry)
    k = 1.0339 * alpha_r**0.6360
    e_int = 1.0003 + 0.5968 / alpha_r
    f_int = 1.5277 + 0.6023 * np.log(alpha_r)
    d_major = 2.0 * (6.0 * k * k * e_int * load * radius / (np.pi * e_prime)) ** (1.0 / 3.0)
    d_minor = 2.0 * (6.0 * e_int * load * radius / (np.pi * k * e_prime)) ** (1.0 / 3.0)
    approach = f_int * ((9.0 / (2.0 * e_int * radius)) * (load / (np.pi * k * e_prime)) ** 2) ** (
        1.0 / 3.0
    )
    p0 = 6.0 * load / (np.pi * d_minor * d_major)
    a, b = _oriented(rx, ry, 0.5 * d_major, 0.5 * d_minor)
    return HertzContact(a, b, p0, float(approach), load)
