"""Isothermal EHL film thickness of elliptical contacts (Hamrock & Dowson 1977).

Hamrock, B. J. & Dowson, D. (1977), "Isothermal elastohydrodynamic lubrication of point
contacts, Part III — fully flooded results", J. Lubr. Technol. 99:264. Theory manual:
``docs/theory/lubrication.md``. SI units; E′ = 2E* is Hamrock's reduced modulus.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import TypeVar

import numpy as np
from numpy.typing import NDArray

from ballscrew.errors import InputError
from ballscrew.registry import Registry
from ballscrew.validation import nonnegative, positive

__all__ = [
    "FilmModel",
    "FilmThickness",
    "dimensionless_groups",
    "film_function",
    "hamrock_dowson",
    "hamrock_dowson_central",
]

FloatLike = TypeVar("FloatLike", float, NDArray[np.float64])


@dataclass(frozen=True)
class FilmThickness:
    """Hamrock–Dowson film thickness and the dimensionless groups it came from."""

    central: float
    """Central film thickness h_c [m]."""
    minimum: float
    """Minimum film thickness h_min [m]."""
    speed_parameter: float
    """U = η₀ u_e/(E′ R_x) [-]."""
    materials_parameter: float
    """Ḡ = α_p E′ [-]."""
    load_parameter: float
    """W = Q_f/(E′ R_x²) [-]."""
    ellipticity: float
    """κ_HD = 1.03 (R_y/R_x)^0.64 [-]."""


def dimensionless_groups(
    rx: float,
    ry: float,
    e_prime: float,
    viscosity: float,
    pressure_viscosity: float,
    entrainment_speed: float,
    load: float,
) -> tuple[float, float, float, float]:
    """(U, Ḡ, W, κ_HD) of (E6.1 inputs), Hamrock & Dowson (1977).

        U = η₀ u_e/(E′ R_x),  Ḡ = α_p E′,  W = Q_f/(E′ R_x²),  κ_HD = 1.03 (R_y/R_x)^0.64

    R_x is the relative radius along the entrainment (rolling) direction.
    """
    rx, ry = positive("rx", rx, "m"), positive("ry", ry, "m")
    e_prime = positive("e_prime", e_prime, "Pa")
    eta = positive("viscosity", viscosity, "Pa s")
    alpha = nonnegative("pressure_viscosity", pressure_viscosity, "1/Pa")
    u_e = nonnegative("entrainment_speed", entrainment_speed, "m/s")
    q = nonnegative("load", load, "N")
    return (
        eta * u_e / (e_prime * rx),
        alpha * e_prime,
        q / (e_prime * rx * rx),
        1.03 * (ry / rx) ** 0.64,
    )


FilmModel = Callable[..., FilmThickness]
"""A film-thickness model ``(rx, ry, E′, η₀, α_p, u_e, Q_f) → FilmThickness``."""

FILM_MODELS: Registry[FilmModel] = Registry("film thickness model", "medium.film_model")
"""Rival EHL film-thickness models, each ``(rx, ry, E′, η₀, α_p, u_e, Q_f) → FilmThickness``."""


def film_function(model: str | FilmModel) -> FilmModel:
    """The film model ``model``: a registered name, or a model already bound to its supply and
    lubricant (``ballscrew.lubrication.supply.supplied_film_model``), returned as it is."""
    return FILM_MODELS[model] if isinstance(model, str) else model


@FILM_MODELS.register("hamrock_dowson", "Hamrock & Dowson (1977), isothermal, fully flooded")
def hamrock_dowson(
    rx: float,
    ry: float,
    e_prime: float,
    viscosity: float,
    pressure_viscosity: float,
    entrainment_speed: float,
    load: float,
) -> FilmThickness:
    """Central and minimum EHL film thickness of an elliptical contact, (E6.1), m.

        h_c   = R_x · 2.69 U^0.67 Ḡ^0.53 W^−0.067 (1 − 0.61 e^(−0.73 κ_HD))
        h_min = R_x · 3.63 U^0.68 Ḡ^0.49 W^−0.073 (1 − e^(−0.68 κ_HD))

    Hamrock & Dowson (1977), isothermal, fully flooded; the h_min formula and κ_HD are as
    printed in the paper's abstract (J. Lubr. Technol. 99(2):264). ``rx`` along the entrainment
    direction, ``ry`` across it [m]; ``e_prime`` = E′ = 2E* [Pa]; ``viscosity`` η₀ [Pa s];
    ``pressure_viscosity`` α_p [1/Pa]; ``entrainment_speed`` u_e [m/s] (mean rolling speed; a
    ball screw: the rolling speed of the contact, E2.8); ``load`` Q_f [N], the load the film
    carries. u_e = 0 gives a zero film. Q_f → 0 makes the film grow without bound (W^−0.067);
    Q_f = 0 is rejected.

    Contact A of the reference screw of ``examples/wear_step_stress.toml`` (R_x = 2.820 mm, R_y =
    34.93 mm, η₀ = 0.06 Pa s, α_p = 2.1e-8 1/Pa, u_e = 0.09333 m/s, Q = 39.41 N): h_c = 53.30 nm,
    h_min = 41.70 nm.
    """
    u, g, w, k = dimensionless_groups(
        rx, ry, e_prime, viscosity, pressure_viscosity, entrainment_speed, load
    )
    if w <= 0.0:
        raise InputError("load", load, "a film load > 0 N (the film thickness diverges at 0)")
    central = _central(rx, u, g, w, k)
    minimum = rx * 3.63 * u**0.68 * g**0.49 * w**-0.073 * (1.0 - math.exp(-0.68 * k))
    return FilmThickness(central, minimum, u, g, w, k)


def _central(rx: float, u: float, g: float, w: FloatLike, k: float) -> FloatLike:
    """h_c = R_x · 2.69 U^0.67 Ḡ^0.53 W^−0.067 (1 − 0.61 e^(−0.73 κ_HD)) of (E6.1), m."""
    return rx * 2.69 * u**0.67 * g**0.53 * w**-0.067 * (1.0 - 0.61 * math.exp(-0.73 * k))


def hamrock_dowson_central(
    rx: float,
    ry: float,
    e_prime: float,
    viscosity: float,
    pressure_viscosity: float,
    entrainment_speed: float,
) -> Callable[[NDArray[np.float64]], NDArray[np.float64]]:
    """Central film h_c(Q_f) of :func:`hamrock_dowson` as a function of the film loads Q_f (an
    array, all > 0), elementwise as that function computes it [m]; the inputs checked once."""
    u, g, _, k = dimensionless_groups(
        rx, ry, e_prime, viscosity, pressure_viscosity, entrainment_speed, 0.0
    )
    scale = e_prime * rx * rx

    def central(loads: NDArray[np.float64]) -> NDArray[np.float64]:
        q = np.asarray(loads, dtype=float)
        if not np.all(q > 0.0):
            raise InputError(
                "load", float(np.min(q)), "a film load > 0 N (the film thickness diverges at 0)"
            )
        return _central(rx, u, g, q / scale, k)

    return central
