"""Mixed lubrication: load sharing between the EHL film and the fractal asperities.

Johnson, K. L., Greenwood, J. A. & Poon, S. Y. (1972), "A simple theory of asperity contact in
elastohydrodynamic lubrication", Wear 19:91 — the film is as thick as if it carried its own
share alone, and the asperities at that separation carry the rest. Film: Hamrock & Dowson (1977);
asperities: the 3-D fractal model of Yan & Komvopoulos (1998) with a Gaussian bearing ratio.
Theory manual: ``docs/theory/lubrication.md``, load sharing (E6.1)–(E6.5).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import brentq

from ballscrew.errors import ConvergenceError, InputError
from ballscrew.fractal import yan_komvopoulos as yk
from ballscrew.lubrication.film import FilmModel, FilmThickness, film_function
from ballscrew.validation import real_array, real_number

__all__ = [
    "AsperitySurface",
    "LoadSharing",
    "asperity_pressure",
    "load_sharing_residual",
    "share_load",
]

_T_MIN = math.log(1e-300)


@dataclass(frozen=True)
class AsperitySurface:
    """The rough raceway seen by one contact: 3-D fractal parameters and the micro-contact cell."""

    Ds: float
    """Surface fractal dimension, 2 < Ds < 3 (= profile D + 1)."""
    G: float
    """Fractal roughness G [m]."""
    e_star: float
    """Contact modulus E* of ball and raceway [Pa]."""
    hardness: float
    """Hardness H of the softer (raceway) surface [Pa]."""
    cell_area: float
    """Apparent area ΔA of one micro-contact region [m²]."""
    gamma: float = 1.5
    """W-M frequency density parameter γ."""
    sigma: float | None = None
    """RMS height σ [m]; None = (E5.3) with the sampling length L_s = √ΔA."""

    @property
    def rms_height(self) -> float:
        """σ used in the bearing ratio (E5.15), m."""
        if self.sigma is not None:
            return float(self.sigma)
        return yk.rms_height(self.Ds, self.G, math.sqrt(self.cell_area), self.gamma)

    def pressure(self, separation: ArrayLike) -> NDArray[np.float64]:
        """Mean asperity pressure F_asp,cell(a_l(h))/ΔA at mean-plane separation h, (E6.3), Pa."""
        a_l = yk.largest_area_from_separation(separation, self.rms_height, self.cell_area, self.Ds)
        force = yk.total_force(a_l, self.Ds, self.G, self.e_star, self.hardness, self.gamma)
        return force / self.cell_area


@dataclass(frozen=True)
class LoadSharing:
    """Solution of the JGP load sharing at one contact."""

    psi: float
    """Asperity share ψ = F_asp/Q ∈ [0, 1]."""
    load: float
    """Total normal load Q [N]."""
    separation: float
    """Film thickness h = h_c(F_film) = mean-plane separation [m]; 0 for a dry contact."""
    film: FilmThickness | None
    """Hamrock–Dowson film at the film-borne load; None for a dry contact."""

    @property
    def asperity_force(self) -> float:
        """F_asp = ψ Q [N]."""
        return self.psi * self.load

    @property
    def film_force(self) -> float:
        """F_film = (1 − ψ) Q [N]."""
        return (1.0 - self.psi) * self.load


def _film(
    film_fraction: float,
    load: float,
    rx: float,
    ry: float,
    e_prime: float,
    viscosity: float,
    pressure_viscosity: float,
    speed: float,
    film_model: str | FilmModel = "hamrock_dowson",
) -> FilmThickness:
    film_load = film_fraction * load  # (1 − ψ) Q, passed as 1 − ψ to keep it > 0 near ψ = 1
    film = film_function(film_model)
    return film(rx, ry, e_prime, viscosity, pressure_viscosity, speed, film_load)


def share_load(
    load: float,
    rx: float,
    ry: float,
    viscosity: float,
    pressure_viscosity: float,
    entrainment_speed: float,
    nominal_area: float,
    surface: AsperitySurface,
    *,
    xtol: float = 1e-14,
    film_model: str | FilmModel = "hamrock_dowson",
    film_factor: float = 1.0,
) -> LoadSharing:
    """Asperity share ψ of the normal load Q of one EHL contact, (E6.1)–(E6.4).

        Q = F_film + F_asp,   h = h_c(F_film)  (Hamrock–Dowson, E′ = 2E*),
        F_asp(h) = A_n · F_asp,cell(a_l(h))/ΔA,   r(ψ) = F_asp(h_c((1−ψ)Q)) − ψQ = 0

    r is strictly decreasing with r(0) ≥ 0 and r → −Q as ψ → 1; the root is found by Brent in
    t = ln(1 − ψ) on [ln 1e-300, 0], which always brackets it (on rough surfaces the root lies
    closer to 1 than 1e-12, where the document's bracket [0, 1 − 1e-12] has no sign change).

    ``nominal_area`` A_n: π a b of the Hertz ellipse (or the loaded cells' area). With no
    entrainment (u_e = 0) there is no film and ψ = 1 (dry contact).

    Contact A of the reference screw of ``examples/wear_step_stress.toml``, Ds = 2.4, G = 1e-10 m,
    ΔA = 100 µm², A_n = π a b: Q = 39.41 N gives ψ = 0.767, h = 58.76 nm.

    ``film_factor`` φ ∈ (0, 1] scales the film of a fully flooded inlet, h = φ h_c, for a
    starved or grease-lubricated supply (a lumped supply factor; Hamrock & Dowson 1977, IV,
    give φ for a known inlet meniscus).
    """
    if not (math.isfinite(film_factor) and 0.0 < film_factor <= 1.0):
        raise InputError("film_factor", film_factor, "a supply factor in (0, 1]")
    q = float(load)
    if not (math.isfinite(q) and q > 0.0):
        raise InputError("load", load, "a finite normal load > 0 N")
    area = float(nominal_area)
    if not (math.isfinite(area) and area > 0.0):
        raise InputError("nominal_area", nominal_area, "a finite area > 0 m²")
    if float(entrainment_speed) == 0.0:
        return LoadSharing(1.0, q, 0.0, None)
    e_prime = 2.0 * surface.e_star
    args = (q, rx, ry, e_prime, viscosity, pressure_viscosity, entrainment_speed, film_model)

    def residual_t(t: float) -> float:  # r at ψ = 1 − e^t
        h = film_factor * _film(math.exp(t), *args).central
        return area * float(surface.pressure(h)) + math.expm1(t) * q

    t = 0.0
    if residual_t(0.0) <= 0.0:
        psi = 0.0
    else:
        # Solve in t = ln(1 − ψ): h_c grows only as W^−0.067, so for rough surfaces the root
        # lies within 1e-12 of ψ = 1; at t = ln(1e-300) the flooded film is ~1e20 times thicker
        # than at ψ = 0 and r = −ψQ < 0, so [ln 1e-300, 0] brackets the root. A starved film
        # shrinks again as its load vanishes (its Hertz zone and so its meniscus distance do):
        # then the first sign change on a grid in t brackets the root, and none means the film
        # carries nothing (ψ = 1, dry).
        low = _bracket(residual_t)
        if low is None:
            return LoadSharing(1.0, q, 0.0, None)
        t, info = brentq(residual_t, low[0], low[1], xtol=xtol, rtol=1e-14, full_output=True)
        if not info.converged:  # pragma: no cover - brentq on a bracketed monotone function
            raise ConvergenceError("JGP load sharing", info.iterations, residual_t(t), xtol)
        psi = -math.expm1(t)
    film = _film(math.exp(t), *args)
    return LoadSharing(float(psi), q, film_factor * film.central, film)


def _bracket(residual: Callable[[float], float]) -> tuple[float, float] | None:
    """[a, b] ⊂ [ln 1e-300, 0] with r(a) ≤ 0 < r(b), b the largest such (r(0) > 0 given)."""
    if residual(_T_MIN) <= 0.0:
        return _T_MIN, 0.0
    grid = -np.geomspace(1e-12, -_T_MIN, 97)
    upper = 0.0
    for t in grid:
        if residual(float(t)) <= 0.0:
            return float(t), upper
        upper = float(t)
    return None


def load_sharing_residual(
    psi: ArrayLike,
    load: float,
    rx: float,
    ry: float,
    viscosity: float,
    pressure_viscosity: float,
    entrainment_speed: float,
    nominal_area: float,
    surface: AsperitySurface,
    film_model: str | FilmModel = "hamrock_dowson",
) -> NDArray[np.float64]:
    """r(ψ) = F_asp(h_c((1−ψ)Q)) − ψQ of (E6.4) at each ψ in [0, 1), N (for checks and plots)."""
    e_prime = 2.0 * surface.e_star
    psi = real_array("psi", psi)
    films = np.array(
        [
            _film(
                1.0 - p,
                load,
                rx,
                ry,
                e_prime,
                viscosity,
                pressure_viscosity,
                entrainment_speed,
                film_model,
            ).central
            for p in psi.ravel()
        ]
    ).reshape(psi.shape)
    return nominal_area * surface.pressure(films) - psi * load


def asperity_pressure(pressure: ArrayLike, psi: float) -> NDArray[np.float64]:
    """Per-cell asperity pressure p_asp = ψ p, (E6.5), Pa; the film carries (1 − ψ) p."""
    psi = real_number("psi", psi)
    if not 0.0 <= psi <= 1.0:
        raise InputError("psi", psi, "an asperity share in [0, 1]")
    return psi * real_array("pressure", pressure, "Pa")
