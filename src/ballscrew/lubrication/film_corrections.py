"""Corrections of the isothermal, fully flooded Hamrock–Dowson film: inlet heating, starvation.

Both multiply the film of :func:`ballscrew.lubrication.film.hamrock_dowson` by a factor ≤ 1:

* inlet shear heating: Gupta, Cheng, Zhu, Forster & Schrand (1992) (registered as
  ``hamrock_dowson_thermal``), and Murch & Wilson (1975) for line contacts in pure rolling;
* starvation by an inlet meniscus closer than the critical distance: Hamrock & Dowson (1977,
  Part IV) (registered as ``hamrock_dowson_starved``).

The registered models keep the registry's signature ``(rx, ry, E′, η₀, α_p, u_e, Q_f)``; their
extra lubricant or supply inputs are keyword arguments with defaults. :func:`thermal_film_model`
and :func:`starved_film_model` bind them for one lubricant or inlet. SI units.

[UNVERIFIED: the coefficients of all three correlations are as quoted in the secondary EHL
literature; the original papers were not available to check them.]
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import replace

from ballscrew.contact.hertz import hamrock_brewe
from ballscrew.errors import InputError
from ballscrew.lubrication.film import FILM_MODELS, FilmThickness, hamrock_dowson
from ballscrew.lubrication.lubricant_library import LUBRICANT_LIBRARY
from ballscrew.validation import nonnegative, positive

__all__ = [
    "critical_inlet_ratio",
    "hamrock_dowson_starved",
    "hamrock_dowson_thermal",
    "starvation_factor",
    "starved_film_model",
    "thermal_film_model",
    "thermal_loading",
    "thermal_reduction_gupta",
    "thermal_reduction_murch_wilson",
]

_REF_OIL = LUBRICANT_LIBRARY["iso_vg_68"].at(313.15)
"""Defaults of the registered thermal model: ISO VG 68 mineral oil at 40 °C (β, λ)."""


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


def _scaled(film: FilmThickness, central: float, minimum: float) -> FilmThickness:
    return replace(film, central=film.central * central, minimum=film.minimum * minimum)


@FILM_MODELS.register(
    "hamrock_dowson_thermal",
    "Hamrock & Dowson (1977) × inlet shear-heating factor of Gupta et al. (1992)",
)
def hamrock_dowson_thermal(
    rx: float,
    ry: float,
    e_prime: float,
    viscosity: float,
    pressure_viscosity: float,
    entrainment_speed: float,
    load: float,
    *,
    temperature_viscosity: float = _REF_OIL.temperature_viscosity,
    conductivity: float = _REF_OIL.conductivity,
    slide_roll: float = 0.0,
) -> FilmThickness:
    """Hamrock–Dowson film times φ_T of :func:`thermal_reduction_gupta`, m.

        h = φ_T(L, p_h/E′, S) · h_HD,   L = β η₀ u_e²/λ,   p_h: Hertz peak pressure
        (Hamrock & Brewe 1983 fits, E* = E′/2)

    Positional arguments as :func:`ballscrew.lubrication.film.hamrock_dowson`. Keyword:
    ``temperature_viscosity`` β [1/K] and ``conductivity`` λ [W/(m K)] of the lubricant at the
    inlet (defaults: ISO VG 68 mineral oil at 40 °C of the lubricant library), ``slide_roll`` S.
    Both central and minimum films take the same factor.
    """
    film = hamrock_dowson(rx, ry, e_prime, viscosity, pressure_viscosity, entrainment_speed, load)
    p_h = hamrock_brewe(rx, ry, 0.5 * e_prime, load).p0
    loading = thermal_loading(temperature_viscosity, viscosity, entrainment_speed, conductivity)
    phi = thermal_reduction_gupta(loading, p_h / e_prime, slide_roll)
    return _scaled(film, phi, phi)


@FILM_MODELS.register(
    "hamrock_dowson_starved",
    "Hamrock & Dowson (1977) with the starved-inlet reduction of Hamrock & Dowson (1977, IV)",
)
def hamrock_dowson_starved(
    rx: float,
    ry: float,
    e_prime: float,
    viscosity: float,
    pressure_viscosity: float,
    entrainment_speed: float,
    load: float,
    *,
    inlet_ratio: float = math.inf,
) -> FilmThickness:
    """Hamrock–Dowson film reduced for an inlet meniscus at ``inlet_ratio`` m, m.

        h_c = h_c,F [(m − 1)/(m*_c − 1)]^0.29,   h_min = h_min,F [(m − 1)/(m*_min − 1)]^0.25

    with m*_c, m*_min of :func:`critical_inlet_ratio` and b the Hertz semi-axis along the rolling
    direction x (Hamrock & Brewe 1983 fits, E* = E′/2). Positional arguments as
    :func:`ballscrew.lubrication.film.hamrock_dowson`; ``inlet_ratio`` m = meniscus distance from
    the contact centre over b (default ∞: fully flooded).
    """
    film = hamrock_dowson(rx, ry, e_prime, viscosity, pressure_viscosity, entrainment_speed, load)
    b = hamrock_brewe(rx, ry, 0.5 * e_prime, load).a
    factors = (
        starvation_factor(inlet_ratio, critical_inlet_ratio(rx, b, h, central), central)
        for h, central in ((film.central, True), (film.minimum, False))
    )
    return _scaled(film, *factors)


def thermal_film_model(
    temperature_viscosity: float, conductivity: float, slide_roll: float = 0.0
) -> Callable[..., FilmThickness]:
    """:func:`hamrock_dowson_thermal` bound to one lubricant (β [1/K], λ [W/(m K)]) and S.

    The result has the registry signature ``(rx, ry, E′, η₀, α_p, u_e, Q_f) → FilmThickness``;
    feed it ``LibraryLubricant.at(T)``'s ``temperature_viscosity`` and ``conductivity``.
    """
    nonnegative("temperature_viscosity", temperature_viscosity, "1/K")
    positive("conductivity", conductivity, "W/(m K)")
    nonnegative("slide_roll", slide_roll)

    def model(*args: float) -> FilmThickness:
        return hamrock_dowson_thermal(
            *args,
            temperature_viscosity=temperature_viscosity,
            conductivity=conductivity,
            slide_roll=slide_roll,
        )

    return model


def starved_film_model(inlet_ratio: float) -> Callable[..., FilmThickness]:
    """:func:`hamrock_dowson_starved` bound to one inlet meniscus ratio m (≥ 1)."""
    if not float(inlet_ratio) >= 1.0:
        raise InputError("inlet_ratio", inlet_ratio, ">= 1 (meniscus outside the Hertz zone)")

    def model(*args: float) -> FilmThickness:
        return hamrock_dowson_starved(*args, inlet_ratio=inlet_ratio)

    return model
