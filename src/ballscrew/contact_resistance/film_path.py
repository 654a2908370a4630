"""Conduction through the lubricant around a ball, outside its Hertz patch (theory manual:
*Contact resistance*, *Film path around the ball*).

A ball touches a raceway only in its Hertz patch, but the lubricant fills the narrow gap around
the patch and conducts across it. Across a gap h(x, y) whose slope is small the film conducts
locally as a slab (the thin-film approximation of lubrication theory), so the film conductance of
the wetted area Ω is

    G_f = ∫∫_Ω λ_f / (h + M) dA                                                       (P1)

(M the gas's temperature-jump distance, 0 for a liquid; Yovanovich 1982). Lubricated bearing
models that add this path to the Hertz contacts are compared by Ghosh, McHale, Takeuchi, Frantz,
Batliner & Fisher (2025, thermal conductance of static lubricated ball bearings).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np
from scipy.integrate import quad
from scipy.optimize import brentq
from scipy.special import elliprd, elliprf

from ballscrew.contact.hertz import HertzContact
from ballscrew.errors import InputError
from ballscrew.validation import nonnegative, positive

__all__ = [
    "FilmPath",
    "ellipse_gap_conductance",
    "groove_clearance",
    "hertz_separation",
    "loaded_film_conductance",
    "meniscus_thickness",
    "wetted_semi_axes",
    "with_film_path",
]


def _check_film(
    conductivity: float, rx: float, ry: float, h0: float, h_max: float, rarefaction: float
) -> None:
    """Refuse what (P1) cannot take: λ_f, R_x, R_y, h0 > 0, h_max ≥ 0 and M ≥ 0, all finite."""
    positive("conductivity", conductivity, "W/(m K)")
    positive("rx", rx, "m")
    positive("ry", ry, "m")
    positive("h0", h0, "m")
    nonnegative("h_max", h_max, "m")
    nonnegative("rarefaction", rarefaction, "m")


def ellipse_gap_conductance(
    conductivity: float,
    rx: float,
    ry: float,
    h0: float,
    h_max: float,
    rarefaction: float = 0.0,
) -> float:
    """(P1) over the paraboloid gap h = h0 + x²/(2R_x) + y²/(2R_y), wetted up to h_max [W/K].

        G_f = 2π λ_f √(R_x R_y) ln[(h_max + M)/(h0 + M)]                                (P2)

    With x = √(2R_x) s cosθ, y = √(2R_y) s sinθ the gap is h0 + s² and dA = 2√(R_x R_y) s ds dθ,
    so the integral is elementary. It is the gap around an unloaded ball (h0 its clearance). A
    loaded contact's gap (:func:`hertz_separation`) is narrower, the paraboloid less δ − u ≥ 0,
    and its film conducts more (25 % on the reference screw). h_max ≤ h0 gives 0.
    """
    _check_film(conductivity, rx, ry, h0, h_max, rarefaction)
    if h_max <= h0:
        return 0.0
    ratio = (h_max + rarefaction) / (h0 + rarefaction)
    return 2.0 * math.pi * conductivity * math.sqrt(rx * ry) * math.log(ratio)


def hertz_separation(x: float, y: float, hertz: HertzContact, rx: float, ry: float) -> float:
    """Gap between the loaded bodies outside the Hertz ellipse (0 inside) [m].

        h = x²/(2R_x) + y²/(2R_y) − δ + u(x, y),
        u = (p0 a b / 2E*) ∫_λ^∞ [1 − x²/(a² + w) − y²/(b² + w)] dw / √((a² + w)(b² + w) w)

    with λ the largest root of x²/(a² + λ) + y²/(b² + λ) = 1 (λ = 0 inside): the surface
    displacement of both bodies under the Hertz pressure (Johnson 1985, §3.6 and §4.2; the
    ellipsoid potential). In Carlson's form ∫ dw/√(…) = 2R_F(a² + λ, b² + λ, λ) and
    ∫ dw/((a² + w)√(…)) = ⅔R_D(b² + λ, λ, a² + λ). E* follows from δ = u(0, 0). Near the edge the
    gap opens as (distance)^{3/2}; far away it tends to the rigid paraboloid less δ.
    """
    a2, b2 = hertz.a**2, hertz.b**2
    x2, y2 = x * x, y * y
    if x2 / a2 + y2 / b2 <= 1.0:
        return 0.0
    s = a2 + b2 - x2 - y2
    lam = 0.5 * (-s + math.sqrt(s * s - 4.0 * (a2 * b2 - x2 * b2 - y2 * a2)))
    rf = float(elliprf(a2 + lam, b2 + lam, lam))
    rd_x = float(elliprd(b2 + lam, lam, a2 + lam))
    rd_y = float(elliprd(a2 + lam, lam, b2 + lam))
    # u/δ: the prefactor p0 a b/(2E*) cancels against δ = u(0, 0) = (p0 a b/2E*)·2R_F(a², b², 0)
    u = (2.0 * rf - (2.0 / 3.0) * (x2 * rd_x + y2 * rd_y)) / (2.0 * _centre_rf(a2, b2))
    return max(x2 / (2.0 * rx) + y2 / (2.0 * ry) - hertz.approach * (1.0 - u), 0.0)


@functools.lru_cache(maxsize=64)
def _centre_rf(a2: float, b2: float) -> float:
    """R_F(a², b², 0) of δ = u(0, 0): one per contact, not per quadrature point."""
    return float(elliprf(a2, b2, 0.0))


def loaded_film_conductance(
    conductivity: float,
    rx: float,
    ry: float,
    hertz: HertzContact,
    h0: float,
    h_max: float,
    rarefaction: float = 0.0,
    nodes: int = 48,
) -> float:
    """(P1) over the film around a loaded Hertz patch, h = h0 + :func:`hertz_separation` [W/K].

    Ω is the ring between the Hertz ellipse and the contour h = h_max. In elliptic coordinates
    x = a s cosθ, y = b s sinθ (dA = a b s ds dθ) the radial integral is adaptive (quad), with
    s − 1 = t² to resolve the (s − 1)^{3/2} opening at the edge, and θ Gauss–Legendre over a
    quadrant (the gap is symmetric). h0 is the film or roughness that separates the surfaces;
    it offsets the whole gap.
    """
    _check_film(conductivity, rx, ry, h0, h_max, rarefaction)
    if h_max <= h0:
        return 0.0
    a, b = hertz.a, hertz.b
    nodes_t, weights = np.polynomial.legendre.leggauss(nodes)
    total = 0.0
    for tt, w in zip(nodes_t, weights, strict=True):
        theta = 0.25 * math.pi * (tt + 1.0)
        c, s_ = math.cos(theta), math.sin(theta)

        def gap(s: float, c: float = c, s_: float = s_) -> float:
            return h0 + hertz_separation(a * s * c, b * s * s_, hertz, rx, ry)

        upper = 2.0
        while gap(upper) < h_max:
            upper *= 2.0
        s_max = brentq(lambda s, g=gap: g(s) - h_max, 1.0, upper, xtol=1e-12)
        t_max = math.sqrt(s_max - 1.0)
        inner, _ = quad(
            lambda t, g=gap: 2.0 * t * (1.0 + t * t) / (g(1.0 + t * t) + rarefaction),
            0.0,
            t_max,
            limit=200,
            epsabs=0.0,
            epsrel=1e-8,
        )
        total += w * inner
    return float(math.pi * conductivity * a * b * total)


def meniscus_thickness(
    hertz: HertzContact, rx: float, ry: float, inlet_ratio: float, h0: float
) -> float:
    """Gap at the inlet meniscus of a starved contact, h0 + h(m·a, 0) [m].

    Hamrock & Dowson (1977, Part IV) place the meniscus of a starved contact m Hertz semi-axes
    upstream of the centre along the rolling direction x. This model takes the wetted region as
    the one bounded by the gap contour through that point [ASSUMED: the oil layer fills the gap
    up to one thickness all round].
    """
    if not inlet_ratio >= 1.0:
        raise InputError("lubrication.inlet_ratio", inlet_ratio, ">= 1 (outside the Hertz zone)")
    return h0 + hertz_separation(inlet_ratio * hertz.a, 0.0, hertz, rx, ry)


def groove_clearance(ball_radius: float, groove_radius: float, contact_angle: float) -> float:
    """Gap at the groove bottom of a gothic arch, (r_g − r_b)(1 − cos β) [m].

    Ball and groove arc touch at the contact angle β; the gap of two circles of radii r_b < r_g
    touching at one point is (r_g − r_b)(1 − cos ψ) at an angle ψ from it, and the flank ends at
    the groove bottom, ψ = β. A flooded contact is taken as wetted up to this gap [ASSUMED].
    """
    positive("ball_radius", ball_radius, "m")
    if not groove_radius > ball_radius:
        raise InputError("groove_radius", groove_radius, f"> the ball radius {ball_radius:g} m")
    return (groove_radius - ball_radius) * (1.0 - math.cos(contact_angle))


def wetted_semi_axes(rx: float, ry: float, h_max: float) -> tuple[float, float]:
    """Semi-axes (√(2R_x h_max), √(2R_y h_max)) of the wetted ellipse, where the undeformed
    paraboloid gap reaches h_max [m] (the deformation shrinks it by less than δ/h_max)."""
    return math.sqrt(2.0 * rx * h_max), math.sqrt(2.0 * ry * h_max)


@dataclass(frozen=True)
class FilmPath:
    """The film of one ball–raceway contact."""

    conductance: float
    """G_f of (P1) [W/K]."""
    h0: float
    """Separation of the surfaces the film starts from [m]."""
    h_max: float
    """Gap at the film's edge [m]."""


def with_film_path(patch_resistance: float, film_conductance: float) -> float:
    """One contact with its film: the patch path and the film in parallel [K/W].

        R = 1 / (1/R_patch + G_f)                                                         (P3)

    R_patch = ∞ (no patch: an unloaded ball) leaves the film alone; G_f = 0 the patch alone.
    """
    g = film_conductance + (0.0 if math.isinf(patch_resistance) else 1.0 / patch_resistance)
    return math.inf if g == 0.0 else 1.0 / g
