"""Mixed lubrication: load sharing between the EHL film and the fractal asperities.

Johnson, K. L., Greenwood, J. A. & Poon, S. Y. (1972), "A simple theory of asperity contact in
elastohydrodynamic lubrication", Wear 19:91 — the film is as thick as if it carried its own
share alone, and the asperities at that separation carry the rest. Film: Hamrock & Dowson (1977);
asperities: the 3-D fractal model of Yan & Komvopoulos (1998) with a Gaussian bearing ratio.
Theory manual: ``docs/theory/lubrication.md``, load sharing (E6.1)–(E6.5).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from functools import cached_property

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ballscrew.errors import InputError
from ballscrew.fractal import majumdar_bhushan as mb
from ballscrew.fractal import yan_komvopoulos as yk
from ballscrew.fractal.conventions import profile_roughness_from_surface
from ballscrew.lubrication.film import (
    FilmModel,
    FilmThickness,
    film_function,
    hamrock_dowson,
    hamrock_dowson_central,
)
from ballscrew.lubrication.roots import bracketed_roots
from ballscrew.validation import real_array, real_number

__all__ = [
    "BOUNDARY_FILM_PARAMETER",
    "AsperitySurface",
    "LoadSharing",
    "asperity_pressure",
    "composite_roughness",
    "film_parameter",
    "load_sharing_residual",
    "regime",
    "share_load",
    "share_loads",
]

_T_MIN = math.log(1e-300)

#: Film parameter Λ below which a contact runs in boundary lubrication (Hamrock 1994).
BOUNDARY_FILM_PARAMETER = 1.0


def composite_roughness(
    D: float, G: float, sampling_length: float, cutoff_length: float, gamma: float = 1.5
) -> float:
    """RMS roughness σ of a raceway for the film parameter Λ = h/σ (E6.6), m.

    The Majumdar–Bhushan (1990) profile (D, G) over the wavelengths [l_c, L_u] of a roughness
    measurement, (F3): σ² = G^(2(D−1)) (L_u^(4−2D) − l_c^(4−2D)) / (2 ln γ (4 − 2D)). With a
    smooth ball this is the composite √(σ₁² + σ₂²) of the contact (Tallian 1967); a rough ball's
    own σ over the same band adds in quadrature. The same σ is the one of the TCR correlations
    and of their film path.
    """
    return mb.profile_rms_roughness(D, G, sampling_length, 1.0 / cutoff_length, gamma)


def film_parameter(film_thickness: float, roughness: float) -> float:
    """Film parameter Λ = h/σ_Λ (E6.6): a film thickness over the composite RMS roughness of
    :func:`composite_roughness` (0 for a dry contact, ∞ on a smooth one)."""
    return film_thickness / roughness if roughness > 0.0 else math.inf


def regime(film: float) -> str:
    """Lubrication regime of a film parameter Λ (Hamrock 1994: <1 boundary, 1–3 mixed, >3 EHL)."""
    if film < BOUNDARY_FILM_PARAMETER:
        return "boundary"
    return "mixed" if film < 3.0 else "EHL"


@dataclass(frozen=True)
class AsperitySurface:
    """The rough raceway seen by one contact: 3-D fractal parameters and the micro-contact cell."""

    Ds: float
    """Surface fractal dimension, 2 < Ds < 3 (= profile D + 1)."""
    G: float
    """Fractal roughness G of the 3-D Yan–Komvopoulos surface [m] (not the profile G:
    :mod:`ballscrew.fractal.conventions`)."""
    e_star: float
    """Contact modulus E* of ball and raceway [Pa]."""
    hardness: float
    """Hardness H of the softer (raceway) surface [Pa]."""
    cell_area: float
    """Apparent area ΔA of one micro-contact region [m²]."""
    gamma: float = 1.5
    """W-M frequency density parameter γ."""
    sigma: float | None = None
    """RMS height σ [m] of the asperities in one cell; None = (E5.3) with the sampling length
    L_s = √ΔA."""
    roughness: float | tuple[float, float] | None = None
    """Composite RMS roughness σ_Λ of the film parameter Λ = h/σ_Λ (E6.6): a measured σ [m], or
    the band (L_u, l_c) [m] of the roughness measurement for (F3); None = :attr:`rms_height`."""

    @cached_property
    def rms_height(self) -> float:
        """σ used in the bearing ratio (E5.15), m."""
        if self.sigma is not None:
            return float(self.sigma)
        return yk.rms_height(self.Ds, self.G, math.sqrt(self.cell_area), self.gamma)

    @cached_property
    def film_roughness(self) -> float:
        """σ_Λ of the film parameter (E6.6), m: :func:`composite_roughness` over the band
        :attr:`roughness` of the profile (D = Ds − 1) with the RMS height of this surface
        (:func:`~ballscrew.fractal.conventions.profile_roughness_from_surface`), a measured σ as
        given, or :attr:`rms_height` without either."""
        if self.roughness is None:
            return self.rms_height
        if isinstance(self.roughness, tuple):
            d = self.Ds - 1.0
            g = profile_roughness_from_surface(d, self.G, self.gamma)
            return composite_roughness(d, g, *self.roughness, gamma=self.gamma)
        return float(self.roughness)

    @cached_property
    def film_heights(self) -> AsperitySurface:
        """This surface with the asperity heights of the film parameter, σ = σ_Λ
        (:attr:`film_roughness`), so that the share ψ of (E6.4) is a function of Λ = h/σ_Λ.

        Johnson, Greenwood & Poon (1972) take the asperity pressure at separation h from the
        Greenwood–Williamson height distribution of the combined roughness of the two
        surfaces, σ = √(σ₁² + σ₂²) (Greenwood & Tripp 1970), the σ of Λ (Tallian 1967): the
        traction and friction of the ball model share it; the wear model keeps the σ (E5.3) of
        its micro-contact cell.
        """
        return replace(self, sigma=self.film_roughness)

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

    One contact of :func:`share_loads` (which gives the solve and its tolerance).

    ``nominal_area`` A_n: π a b of the Hertz ellipse (or the loaded cells' area). With no
    entrainment (u_e = 0) there is no film and ψ = 1 (dry contact).

    Contact A of the reference screw of ``examples/wear_step_stress.toml``, Ds = 2.4, G = 1e-10 m,
    ΔA = 100 µm², A_n = π a b: Q = 39.41 N gives ψ = 0.767, h = 58.76 nm.

    ``film_factor`` φ ∈ (0, 1] scales the film of a fully flooded inlet, h = φ h_c, for a
    starved or grease-lubricated supply (a lumped supply factor; Hamrock & Dowson 1977, IV,
    give φ for a known inlet meniscus).
    """
    return share_loads(
        [load],
        rx,
        ry,
        viscosity,
        pressure_viscosity,
        entrainment_speed,
        [nominal_area],
        surface,
        xtol=xtol,
        film_model=film_model,
        film_factor=film_factor,
    )[0]


def share_loads(
    loads: Sequence[float],
    rx: float,
    ry: float,
    viscosity: float,
    pressure_viscosity: float,
    entrainment_speed: float,
    nominal_areas: Sequence[float],
    surface: AsperitySurface,
    *,
    xtol: float = 1e-14,
    film_model: str | FilmModel = "hamrock_dowson",
    film_factor: float = 1.0,
) -> tuple[LoadSharing, ...]:
    """:func:`share_load` of several contacts that share the curvature, lubricant, speed and
    surface and differ in load Q_k and nominal area A_n,k, all solved together.

    r is strictly decreasing with r(0) ≥ 0 and r → −Q as ψ → 1; each root is found in
    t = ln(1 − ψ) on [ln 1e-300, 0], which always brackets it (on rough surfaces the root lies
    closer to 1 than 1e-12, where the document's bracket [0, 1 − 1e-12] has no sign change), by
    Chandrupatla's (1997) bracketed method for all contacts at once
    (:func:`~ballscrew.lubrication.roots.bracketed_roots`): t lies in a bracket with a sign
    change no wider than ``xtol`` + 2e-14 |t|, else :class:`ConvergenceError`.
    """
    if not (math.isfinite(film_factor) and 0.0 < film_factor <= 1.0):
        raise InputError("film_factor", film_factor, "a supply factor in (0, 1]")
    q = np.array([_positive("load", v, "a finite normal load > 0 N") for v in loads])
    area = np.array([_positive("nominal_area", v, "a finite area > 0 m²") for v in nominal_areas])
    if q.shape != area.shape:
        raise InputError("nominal_areas", len(area), f"one area per load ({q.size})")
    if float(entrainment_speed) == 0.0:
        return tuple(LoadSharing(1.0, float(v), 0.0, None) for v in q)
    e_prime = 2.0 * surface.e_star
    film = film_function(film_model)
    args = (rx, ry, e_prime, viscosity, pressure_viscosity, entrainment_speed)

    vectorised = hamrock_dowson_central(*args) if film is hamrock_dowson else None

    def films(t: NDArray[np.float64], k: NDArray[np.intp]) -> list[FilmThickness]:
        # film load (1 − ψ) Q = e^t Q, passed through t to keep it > 0 near ψ = 1
        return [
            film(*args, math.exp(tt) * q[kk]) for tt, kk in zip(t.tolist(), k.tolist(), strict=True)
        ]

    def residual(t: NDArray[np.float64], k: NDArray[np.intp]) -> NDArray[np.float64]:
        if vectorised is not None:
            central = vectorised(np.exp(t) * q[k])
        else:
            central = np.array([f.central for f in films(t, k)])
        h = film_factor * central
        return area[k] * surface.pressure(h) + np.expm1(t) * q[k]

    every = np.arange(q.size)
    t = np.zeros(q.size)
    r_high = residual(t, every)
    dry = np.zeros(q.size, dtype=bool)
    wet = np.flatnonzero(r_high > 0.0)  # r(0) ≤ 0: the film carries all, ψ = 0
    if wet.size:
        low, high, r_low, r_top, none = _brackets(residual, wet, q[wet], r_high[wet])
        dry[wet[none]] = True
        keep = ~none
        t[wet[keep]] = bracketed_roots(
            lambda x, k: residual(x, wet[keep][k]),
            low[keep],
            high[keep],
            r_low[keep],
            r_top[keep],
            xtol,
            1e-14,
            "JGP load sharing",
        )
    final = films(t, every)
    return tuple(
        LoadSharing(1.0, float(qk), 0.0, None)
        if dk
        else LoadSharing(float(-math.expm1(tk)), float(qk), film_factor * fk.central, fk)
        for qk, tk, dk, fk in zip(q, t, dry, final, strict=True)
    )


def _positive(field: str, value: float, allowed: str) -> float:
    out = float(value)
    if not (math.isfinite(out) and out > 0.0):
        raise InputError(field, value, allowed)
    return out


def _brackets(
    residual: Callable[[NDArray[np.float64], NDArray[np.intp]], NDArray[np.float64]],
    k: NDArray[np.intp],
    load: NDArray[np.float64],
    r_zero: NDArray[np.float64],
) -> tuple[NDArray[np.float64], ...]:
    """Brackets [a, b] ⊂ [ln 1e-300, 0] with r(a) ≤ 0 < r(b) of the contacts k (loads Q_k,
    r(0) = ``r_zero`` > 0), their residuals, and which have none (dry, ψ = 1).

    First two steps of the fixed-point map ψ ↦ g(ψ) = F_asp(h_c((1−ψ)Q))/Q from ψ₀ = 0: g falls
    as ψ grows where the film thickens as its load falls, so ψ₁ = g(0) ≥ ψ* ≥ ψ₂ = g(ψ₁); each
    end is kept only where its residual has the right sign. Where ψ₁ ≥ 1 or r(t₁) > 0: the first
    sign change down the coarse points t = −1, −3, …, −243, ln 1e-300 (at ln 1e-300 the flooded
    film is ~1e20 times thicker than at ψ = 0 and r = −ψQ < 0). A starved film shrinks again as
    its load vanishes (its Hertz zone and so its meniscus distance do): where r(ln 1e-300) > 0 the
    first sign change on a fine grid in t down from 0 brackets the root, and none means the film
    carries nothing.
    """
    low, high = np.full(k.size, _T_MIN), np.zeros(k.size)
    r_low, r_high = np.full(k.size, np.nan), r_zero.copy()
    psi1 = r_zero / load
    fixed = np.flatnonzero(psi1 < 1.0)
    t1 = np.maximum(np.log1p(-psi1[fixed]), _T_MIN)
    r1 = residual(t1, k[fixed])
    near, below = fixed[r1 <= 0.0], r1 <= 0.0
    low[near], r_low[near] = t1[below], r1[below]
    if near.size:
        # g(ψ₁) Q = F_asp at t₁ = r(t₁) − expm1(t₁) Q
        psi2 = np.clip((r_low[near] - np.expm1(low[near]) * load[near]) / load[near], 0.0, 1.0)
        with np.errstate(divide="ignore"):
            t2 = np.clip(np.log1p(-psi2), low[near], 0.0)
        r2 = residual(t2, k[near])
        upper = r2 > 0.0
        high[near[upper]], r_high[near[upper]] = t2[upper], r2[upper]
        low[near[~upper]], r_low[near[~upper]] = t2[~upper], r2[~upper]
    open_ = np.setdiff1d(np.arange(k.size), near)
    open_ = _scan(
        residual,
        k,
        open_,
        (-1.0, -3.0, -9.0, -27.0, -81.0, -243.0, _T_MIN),
        low,
        high,
        r_low,
        r_high,
    )
    high[open_], r_high[open_] = 0.0, r_zero[open_]
    open_ = _scan(residual, k, open_, -np.geomspace(1e-12, -_T_MIN, 97), low, high, r_low, r_high)
    none = np.zeros(k.size, dtype=bool)
    none[open_] = True
    return low, high, r_low, r_high, none


def _scan(
    residual: Callable[[NDArray[np.float64], NDArray[np.intp]], NDArray[np.float64]],
    k: NDArray[np.intp],
    open_: NDArray[np.intp],
    points: Sequence[float] | NDArray[np.float64],
    low: NDArray[np.float64],
    high: NDArray[np.float64],
    r_low: NDArray[np.float64],
    r_high: NDArray[np.float64],
) -> NDArray[np.intp]:
    """Walk the contacts ``open_`` down ``points`` to their first r ≤ 0, updating their
    brackets in place; those that find none are returned."""
    for point in points:
        if open_.size == 0:
            break
        r = residual(np.full(open_.size, point), k[open_])
        found = r <= 0.0
        low[open_[found]], r_low[open_[found]] = point, r[found]
        rest = open_[~found]
        high[rest], r_high[rest] = point, r[~found]
        open_ = rest
    return open_


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
