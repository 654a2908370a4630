"""Cell wear rates of a rough fractal raceway under a smooth sliding ball (Models A and C).

Each grid cell of the contact solution is a micro-contact region of apparent area ΔA carrying
the asperity force F = p_asp ΔA (p_asp = ψ p, the film share removed, (E6.5)). The largest
truncated area a_l follows from F_asp(a_l) = F (E5.16, Yan & Komvopoulos 1998); the cell's wear
rate w (worn volume per unit time per unit apparent area = wear-depth speed, m/s) then follows
from the local sliding speed |Δv| (E2.7). Theory manual: ``docs/theory/wear.md``, cell wear rate.

* Model A ((E7.2), default): adhesive particles only at plastic asperities, hemispherical
  particles of radius r' removed with probability K per encounter (Archard 1953):
  ``w = K |Δv| F_p(a_l) / (3 H ΔA)``; the Archard limit ``w = K |Δv| p/(3H)`` for fully plastic
  cells.
* Model C ((E7.3)): cap volume a'δ(a')/2 per encounter summed over all asperities (Zhou, Leu &
  Blackmore 1993): ``w = (K|Δv|/ΔA) √π (Ds−1)/(4(5−2Ds)) δ_l a_l^(Ds−2) a_up^((5−2Ds)/2)``,
  a_up = a_l; requires Ds < 2.5.

All functions are vectorised over the grid (any array shape).
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ballscrew.errors import InputError
from ballscrew.fractal import yan_komvopoulos as yk
from ballscrew.registry import Registry

__all__ = ["WEAR_LAWS", "cell_wear_rate", "wear_rate_model_a", "wear_rate_model_c"]

FloatArray = NDArray[np.float64]
WEAR_LAWS: Registry[Callable[..., NDArray[np.float64]]] = Registry("wear law", "wear.model")
"""Cell wear-rate laws: Model ``A`` (plastic asperities) and ``C`` (see each function)."""


def _check(coefficient: float, cell_area: float, hardness: float) -> None:
    if not (math.isfinite(coefficient) and coefficient > 0.0):
        raise InputError("coefficient", coefficient, "a wear coefficient K > 0")
    if not (math.isfinite(cell_area) and cell_area > 0.0):
        raise InputError("cell_area", cell_area, "a cell area ΔA > 0 m²")
    if not (math.isfinite(hardness) and hardness > 0.0):
        raise InputError("hardness", hardness, "a hardness H > 0 Pa")


def _largest_area(
    force: FloatArray, cell_area: float, Ds: float, G: float, e_star: float, hardness: float
) -> FloatArray:
    """a_l of the loaded cells only (F > 0), 0 elsewhere (E5.16).

    Newton's method on ln F_asp(ln a_l) = ln F (F_asp is close to a power law in a_l, so a few
    steps from the fully plastic root a_l = (3−Ds)/(Ds−1) F/H reach 1e-11 in ln a_l), the slope
    by a difference of 1e-6 in ln a_l. Cells it does not settle, and roots above the physical
    limit, go to the bisection of :func:`ballscrew.fractal.yan_komvopoulos.largest_area_from_force`.
    """
    a_l = np.zeros_like(force)
    loaded = force > 0.0
    if not np.any(loaded):
        return a_l
    f = force[loaded]
    d = Ds

    def ln_force(ln_a: FloatArray) -> FloatArray:
        return np.log(yk.total_force(np.exp(ln_a), d, G, e_star, hardness))

    target = np.log(f)
    ln_a = np.log(f * (3.0 - d) / ((d - 1.0) * hardness))
    settled = np.zeros(f.shape, dtype=bool)
    for _ in range(_NEWTON_STEPS):
        here = ln_force(ln_a)
        slope = (ln_force(ln_a + _SLOPE_STEP) - here) / _SLOPE_STEP
        with np.errstate(divide="ignore", invalid="ignore"):
            step = (target - here) / slope
        step = np.where(np.isfinite(step), step, np.inf)
        settled = np.abs(step) < 1e-11
        ln_a = ln_a + np.where(np.isfinite(step), np.clip(step, -2.0, 2.0), 0.0)
        if settled.all():
            break
    root = np.exp(ln_a)
    rest = ~settled | (root > yk.max_largest_area(cell_area, d))
    if np.any(rest):
        root[rest] = yk.largest_area_from_force(
            f[rest], cell_area, Ds, G, e_star, hardness, rtol=1e-10
        )
    a_l[loaded] = root
    return a_l


_NEWTON_STEPS = 12
_SLOPE_STEP = 1e-6


def _inputs(asperity_pressure: ArrayLike, sliding_speed: ArrayLike) -> tuple[FloatArray, ...]:
    p = np.asarray(asperity_pressure, dtype=float)
    v = np.abs(np.asarray(sliding_speed, dtype=float))
    if p.shape != v.shape:
        raise InputError("sliding_speed", v.shape, f"an array of the pressure's shape {p.shape}")
    if not (np.all(np.isfinite(p)) and np.all(p >= 0.0)):
        raise InputError("asperity_pressure", "array", "finite pressures >= 0 Pa")
    if not np.all(np.isfinite(v)):
        raise InputError("sliding_speed", "array", "finite speeds")
    return p, v


@WEAR_LAWS.register("A", "Archard wear of the plastically deformed fractal asperities")
def wear_rate_model_a(
    asperity_pressure: ArrayLike,
    sliding_speed: ArrayLike,
    cell_area: float,
    Ds: float,
    G: float,
    e_star: float,
    hardness: float,
    coefficient: float,
    gamma: float = 1.5,
) -> FloatArray:
    """Model A cell wear rate ``w = K |Δv| F_p(a_l) / (3 H ΔA)``, (E7.2), m/s.

    Per plastic asperity v = (2/3)π r'³ removed with probability K per encounter of duration
    2r'/|Δv|, so dv/dt = (K/3) a' |Δv|; integrated over n(a') (E5.10) up to a_w = min(a_l, a_c)
    this is K|Δv| F_p/(3HΔA) with F_p of (E5.12). Fully plastic cells give Archard's
    w = K|Δv| p_asp/(3H). Example: Ds = 2.4, G = 1e-10 m, ΔA = 100 µm², p_asp = 500 MPa,
    |Δv| = 2.637e-3 m/s, K = 1e-4, H = 7 GPa → w = 1.328e-9 m/s.

    Args:
        asperity_pressure: p_asp = ψ p per cell [Pa].
        sliding_speed: local sliding speed |Δv| per cell [m/s] (sign ignored).
        cell_area: ΔA [m²]; Ds, G [m], e_star [Pa], hardness [Pa]: the fractal raceway.
        coefficient: wear coefficient K [-].
    """
    _check(coefficient, cell_area, hardness)
    p, v = _inputs(asperity_pressure, sliding_speed)
    force = p * cell_area
    a_l = _largest_area(force, cell_area, Ds, G, e_star, hardness)
    _, f_plastic = yk.cell_forces(a_l, Ds, G, e_star, hardness, gamma)
    return coefficient * v * f_plastic / (3.0 * hardness * cell_area)


@WEAR_LAWS.register("C", "wear by the cap volume of the largest asperity (needs Ds < 2.5)")
def wear_rate_model_c(
    asperity_pressure: ArrayLike,
    sliding_speed: ArrayLike,
    cell_area: float,
    Ds: float,
    G: float,
    e_star: float,
    hardness: float,
    coefficient: float,
    gamma: float = 1.5,
) -> FloatArray:
    """Model C cell wear rate (cap volume, (E7.3)), m/s; requires Ds < 2.5.

        w = (K |Δv| / ΔA) · √π (Ds−1)/(4(5−2Ds)) · δ_l · √a_l,   δ_l = δ(a_l) (E5.5)

    (a_up = a_l). The Model A example's inputs give w = 1.381e-9 m/s with δ_l = 6.246e-8 m.
    Raises :class:`InputError` for Ds ≥ 2.5, where the sum over small asperities diverges.
    """
    _check(coefficient, cell_area, hardness)
    if not Ds < 2.5:
        raise InputError("surface dimension", Ds, "Ds = D + 1 < 2.5 for wear Model C (use Model A)")
    p, v = _inputs(asperity_pressure, sliding_speed)
    a_l = _largest_area(p * cell_area, cell_area, Ds, G, e_star, hardness)
    depth = np.where(a_l > 0.0, yk.asperity_interference(a_l, Ds, G, gamma), 0.0)
    factor = math.sqrt(math.pi) * (Ds - 1.0) / (4.0 * (5.0 - 2.0 * Ds))
    return coefficient * v / cell_area * factor * depth * np.sqrt(a_l)


def cell_wear_rate(
    model: str,
    asperity_pressure: ArrayLike,
    sliding_speed: ArrayLike,
    cell_area: float,
    Ds: float,
    G: float,
    e_star: float,
    hardness: float,
    coefficient: float,
    gamma: float = 1.5,
) -> FloatArray:
    """Wear rate per cell of the registered law ``model`` (:data:`WEAR_LAWS`), m/s."""
    return WEAR_LAWS[model](
        asperity_pressure, sliding_speed, cell_area, Ds, G, e_star, hardness, coefficient, gamma
    )
