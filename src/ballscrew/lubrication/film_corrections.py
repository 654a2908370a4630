"""Corrections of the isothermal, fully flooded Hamrock–Dowson film: inlet heating, starvation.

All multiply the film of :func:`ballscrew.lubrication.film.hamrock_dowson` by a factor ≤ 1:

* inlet shear heating: Gupta, Cheng, Zhu, Forster & Schrand (1992), and Murch & Wilson (1975)
  for line contacts in pure rolling;
* starvation by an inlet meniscus closer than the critical distance: Hamrock & Dowson (1977,
  Part IV);
* starvation by a thin oil layer on the track: the film-reduction law of Chevalier, Lubrecht,
  Cann, Colin & Dalmaz (1998), as used for elliptical contacts by Damiens, Venner, Cann &
  Lubrecht (2004);
* kinematic starvation of a track that the oil has too little time to replenish between
  overrollings: the reduction factor φ_rs of the SKF model of the frictional moment (SKF Group,
  *Rolling bearings*, PUB BU/P1 10000/2 EN, 2013).

:func:`ballscrew.lubrication.supply.supplied_film_model` applies them to a film model for the
case's ``[lubrication]`` section. SI units.

[UNVERIFIED: the coefficients of the correlations are as quoted in the secondary literature;
the original papers were not available to check them. The SKF factor's form and its K_rs (3e-8
oil bath or jet, 6e-8 grease or oil–air) agree in three independent public reproductions of the
catalogue formula; the catalogue page itself was not read. The thin-layer law's form was read
in a secondary summary of Lugt (2013), its r and γ are ASSUMED (:func:`layer_starvation_factor`).]
"""

from __future__ import annotations

import math

from ballscrew.errors import InputError
from ballscrew.validation import nonnegative, positive

__all__ = [
    "REPLENISHMENT_GEOMETRY",
    "REPLENISHMENT_GREASE",
    "REPLENISHMENT_OIL",
    "STARVATION_EXPONENT",
    "critical_inlet_ratio",
    "dowson_higginson_density",
    "equivalent_inlet_ratio",
    "layer_starvation_factor",
    "replenishment_factor",
    "starvation_factor",
    "thermal_loading",
    "thermal_reduction_gupta",
    "thermal_reduction_murch_wilson",
]


#: K_rs of the SKF model for a low-level oil bath and oil-jet lubrication (SKF 2013).
REPLENISHMENT_OIL = 3e-8
#: K_rs of the SKF model for grease and oil–air lubrication (same source).
REPLENISHMENT_GREASE = 6e-8
#: K_Z, the SKF geometry constant of four-point contact ball bearings (same source): ASSUMED for
#: the Gothic-arch groove of a ball screw, whose balls touch each raceway at ±β as they do.
REPLENISHMENT_GEOMETRY = 3.1
#: γ of the thin-layer starvation law (:func:`layer_starvation_factor`): ASSUMED 3, the value
#: quoted for circular contacts (Lugt 2013, *Grease Lubrication in Rolling Bearings*, §9 on
#: the starvation model of Damiens et al. 2004: γ ≈ 3 circular, up to ≈ 15 for wide elliptical
#: contacts). The lowest value of that range gives the most gradual, i.e. the thinnest, film at
#: r ≈ 1; the published dependence of γ on M, L and the ellipticity was not read.
STARVATION_EXPONENT = 3.0


def thermal_loading(
    temperature_viscosity: float, viscosity: float, speed: float, conductivity: float
) -> float:
    """Thermal loading parameter L = β η₀ u²/λ [-] of the inlet (L = −(∂η/∂T) u²/λ).

    Murch & Wilson (1975); Gupta et al. (1992). ``temperature_viscosity`` β = −(1/η) dη/dT
    [1/K]; ``viscosity`` η₀ [Pa s]; ``speed`` u, the entrainment (rolling) speed [m/s];
    ``conductivity`` λ of the lubricant [W/(m K)].
    """
    beta = nonnegative("temperature_viscosity", temperature_viscosity, "1/K")
    eta = positive("viscosity", viscosity, "Pa s")
    u = nonnegative("entrainment_speed", speed, "m/s")
    lam = positive("conductivity", conductivity, "W/(m K)")
    return beta * eta * u * u / lam


def thermal_reduction_murch_wilson(loading: float) -> float:
    """φ_T = 3.94/(3.94 + L^0.62), line contact in pure rolling.

    Murch, L. E. & Wilson, W. R. D. (1975), "A thermal elastohydrodynamic inlet zone analysis",
    J. Lubr. Technol. 97(2):212–216. ``loading`` L of :func:`thermal_loading`; φ_T = 1 at L = 0.
    """
    load = nonnegative("thermal_loading", loading)
    return 3.94 / (3.94 + load**0.62)


def thermal_reduction_gupta(
    loading: float, pressure_ratio: float, slide_roll: float = 0.0
) -> float:
    """φ_T = [1 − 13.2 (p_h/E′) L^0.42] / [1 + 0.213 (1 + 2.23 S^0.83) L^0.64].

    Gupta, P. K., Cheng, H. S., Zhu, D., Forster, N. H. & Schrand, J. B. (1992), "Viscoelastic
    effects in MIL-L-7808-type lubricant, Part I: analytical formulation", Tribol. Trans.
    35(2):269–274: inlet shear-heating reduction of the isothermal film. ``loading`` L of
    :func:`thermal_loading`; ``pressure_ratio`` p_h/E′ (Hertz peak pressure over E′);
    ``slide_roll`` S = Δu/u_e ≥ 0. φ_T = 1 at L = 0; the numerator limits the fit to
    13.2 (p_h/E′) L^0.42 < 1 (refused otherwise).
    """
    load = nonnegative("thermal_loading", loading)
    ratio = nonnegative("pressure_ratio", pressure_ratio)
    s = nonnegative("slide_roll", slide_roll)
    numerator = 1.0 - 13.2 * ratio * load**0.42
    if numerator <= 0.0:
        raise InputError("thermal_loading", loading, "13.2 (p_h/E′) L^0.42 < 1 (Gupta et al.)")
    return numerator / (1.0 + 0.213 * (1.0 + 2.23 * s**0.83) * load**0.64)


def critical_inlet_ratio(rx: float, semi_axis: float, film: float, central: bool = True) -> float:
    """Critical inlet distance m* of Hamrock & Dowson (1977, Part IV) [-].

        central:  m* = 1 + 3.06 [(R_x/b)² H_c]^0.58,   minimum:  m* = 1 + 3.34 [(R_x/b)² H_min]^0.56

    H = h/R_x the fully flooded dimensionless film; ``rx`` R_x [m]; ``semi_axis`` b, the Hertz
    semi-axis along the rolling direction [m]; ``film`` h [m]. An inlet meniscus at m ≥ m*
    (distance from the contact centre in units of b) leaves the film fully flooded.
    """
    rx, b = positive("rx", rx, "m"), positive("semi_axis", semi_axis, "m")
    h = nonnegative("film", film, "m")
    group = (rx / b) ** 2 * (h / rx)
    return 1.0 + (3.06 * group**0.58 if central else 3.34 * group**0.56)


def starvation_factor(inlet_ratio: float, critical_ratio: float, central: bool = True) -> float:
    """h_starved/h_flooded = [(m − 1)/(m* − 1)]^0.29 (central), ^0.25 (minimum), for m < m*.

    Hamrock, B. J. & Dowson, D. (1977), "Isothermal elastohydrodynamic lubrication of point
    contacts, Part IV — starvation results", J. Lubr. Technol. 99(1):15–23. ``inlet_ratio`` m:
    the inlet meniscus distance from the contact centre over b (m ≥ 1); ``critical_ratio`` m*
    of :func:`critical_inlet_ratio`. 1 when m ≥ m* (flooded); → 0 as m → 1 (meniscus at the
    Hertz edge).
    """
    m = float(inlet_ratio)
    if math.isnan(m) or m < 1.0:
        raise InputError("inlet_ratio", inlet_ratio, ">= 1 (meniscus outside the Hertz zone)")
    m_star = positive("critical_ratio", critical_ratio)
    if m >= m_star:
        return 1.0
    return ((m - 1.0) / (m_star - 1.0)) ** (0.29 if central else 0.25)


def equivalent_inlet_ratio(factor: float, critical_ratio: float, central: bool = True) -> float:
    """The inlet meniscus m whose starvation (:func:`starvation_factor`) thins the film by
    ``factor``: m = 1 + (m* − 1) φ^(1/0.29) (central), φ^(1/0.25) (minimum).

    The inverse of Hamrock & Dowson (1977, Part IV) for 0 < φ ≤ 1: φ = 1 gives the critical
    distance m*, φ → 0 the Hertz edge m = 1. ``critical_ratio`` m* of
    :func:`critical_inlet_ratio`.
    """
    phi = positive("starvation_factor", factor)
    if phi > 1.0:
        raise InputError("starvation_factor", factor, "<= 1 (a film factor of a starved inlet)")
    m_star = positive("critical_ratio", critical_ratio)
    return 1.0 + (m_star - 1.0) * phi ** (1.0 / (0.29 if central else 0.25))


def replenishment_factor(
    kinematic_viscosity: float,
    speed: float,
    mean_diameter: float,
    section: float,
    constant: float = REPLENISHMENT_GREASE,
    geometry: float = REPLENISHMENT_GEOMETRY,
) -> float:
    """Kinematic replenishment/starvation reduction factor of the SKF model [-]:

        φ_rs = 1 / exp[K_rs ν n (d + D) √(K_Z / (2 (D − d)))]

    in the catalogue's units, ν [mm²/s], n [r/min], d, D [mm] (SKF Group, *Rolling bearings*,
    PUB BU/P1 10000/2 EN, 2013, "The SKF model for calculating the frictional moment",
    kinematic replenishment/starvation reduction factor). Inputs here are SI:
    ``kinematic_viscosity`` ν [m²/s] of the oil or the grease's base oil; ``speed`` n [rad/s];
    ``mean_diameter`` d_m = (d + D)/2 [m]; ``section`` D − d [m]; ``constant`` K_rs
    (:data:`REPLENISHMENT_GREASE`, :data:`REPLENISHMENT_OIL`); ``geometry`` K_Z. φ_rs = 1 at
    rest or for an inviscid oil, and falls monotonically with ν n: the faster and more viscous
    the oil, the less of it flows back into the track between overrollings.
    """
    nu = nonnegative("kinematic_viscosity", kinematic_viscosity, "m^2/s") * 1e6  # mm²/s
    n = nonnegative("speed", speed, "rad/s") * 30.0 / math.pi  # r/min
    d_sum = 2e3 * positive("mean_diameter", mean_diameter, "m")  # d + D, mm
    d_diff = 1e3 * positive("section", section, "m")  # D − d, mm
    k_rs = nonnegative("replenishment_constant", constant)
    k_z = positive("replenishment_geometry", geometry)
    return math.exp(-k_rs * nu * n * d_sum * math.sqrt(k_z / (2.0 * d_diff)))


def dowson_higginson_density(pressure: float) -> float:
    """ρ̄ = ρ(p)/ρ₀ = 1 + 0.6 p/(1 + 1.7 p), p in GPa [-] (Dowson & Higginson 1966).

    The compressibility of a mineral oil at gauge pressure ``pressure`` p [Pa]; 1.22 at 1 GPa,
    → 1 + 0.6/1.7 = 1.353 as p → ∞.
    """
    p = nonnegative("pressure", pressure, "Pa") * 1e-9
    return 1.0 + 0.6 * p / (1.0 + 1.7 * p)


def layer_starvation_factor(
    layer: float, film: float, density_ratio: float, exponent: float = STARVATION_EXPONENT
) -> float:
    """h_c/h_c,ff = r/(1 + r^γ)^(1/γ),  r = h_oil,∞/(ρ̄ h_c,ff)  [-].

    Film reduction of an EHL point contact fed by a uniform oil layer of thickness h_oil,∞ on
    the track: Chevalier, F., Lubrecht, A. A., Cann, P. M. E., Colin, F. & Dalmaz, G. (1998),
    "Film thickness in starved EHL point contacts", J. Tribol. 120(1):126–133; elliptical
    contacts: Damiens, B., Venner, C. H., Cann, P. M. E. & Lubrecht, A. A. (2004), "Starved
    lubrication of elliptical EHD contacts", J. Tribol. 126(1):105–111. ``layer`` h_oil,∞ [m]
    (≥ 0); ``film`` h_c,ff ≥ 0, the fully flooded central film [m] (0: nothing to starve,
    factor 1); ``density_ratio`` ρ̄ = ρ/ρ₀ of the oil in the contact
    (:func:`dowson_higginson_density`); ``exponent`` γ > 0, the starvation (side-flow
    resistance) parameter (:data:`STARVATION_EXPONENT`).

    Limits: r → ∞ gives 1 (fully flooded); r → 0 gives h_c → h_oil,∞/ρ̄, all the oil of the
    layer passing the contact (mass conservation); monotone in the layer.

    [Read, in a secondary summary of Lugt (2013), *Grease Lubrication in Rolling Bearings*,
    eq. 9.73: the form r/(1 + r^γ)^(1/γ) and γ ≈ 3 (circular) to 15 (wide elliptical). ASSUMED:
    r = h_oil,∞/(ρ̄ h_c,ff) with ρ̄ at the Hertz peak pressure (the mass balance of the law's
    r → 0 limit); the originals were not available.]
    """
    h_oil = nonnegative("inlet_layer", layer, "m")
    h_ff = nonnegative("film", film, "m")
    rho = positive("density_ratio", density_ratio)
    gamma = positive("starvation_exponent", exponent)
    if h_ff == 0.0:
        return 1.0  # no film to starve (u_e = 0)
    r = h_oil / (rho * h_ff)
    if r == 0.0:
        return 0.0
    # r/(1 + r^γ)^(1/γ) = (1 + r^−γ)^(−1/γ) = exp(−softplus(−γ ln r)/γ): no overflow at either end
    x = -gamma * math.log(r)
    softplus = x + math.log1p(math.exp(-x)) if x > 0.0 else math.log1p(math.exp(x))
    return math.exp(-softplus / gamma)
