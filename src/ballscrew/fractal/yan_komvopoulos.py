"""3-D fractal micro-contact of a rigid smooth ball on a rough raceway (Yan & Komvopoulos 1998).

Sources:
- Yan, W. & Komvopoulos, K. (1998), J. Appl. Phys. 84:3617 — 3-D Weierstrass–Mandelbrot surface
  (E5.1), asperity interference, elastic and plastic asperity forces, critical truncated area
  (E5.5)–(E5.9) and the size distribution of truncated areas (E5.10)–(E5.13).
- Ausloos, M. & Berman, D. H. (1985), Proc. R. Soc. A 400:331 — the 3-D W-M function (E5.1).
- Majumdar, A. & Bhushan, B. (1990), J. Tribol. 112:205 — structure function of a profile (E5.4).

Theory manual: ``docs/theory/fractal-contact.md``, Yan–Komvopoulos 3-D surface model. SI throughout:
lengths in m, areas in m², forces in N, moduli and hardness in Pa.

**Dimension convention.** Every function here takes the *surface* fractal dimension
``Ds`` with 2 < Ds < 3. A case stores the *profile* dimension D (1 < D < 2) of the
Majumdar–Bhushan model; convert with :func:`surface_dimension` (Ds = D + 1), never store both.
The only exception is :func:`structure_function`, which is a property of a measured profile and
takes the profile dimension.

Functions are vectorised over their area, force or separation argument; the surface parameters
are scalars. Scalar inputs give NumPy float64 scalars.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.special import erfc, exprel
from scipy.special import gamma as gamma_function

from ballscrew.errors import InputError
from ballscrew.validation import nonnegative_array, positive

__all__ = [
    "SaturatedCellWarning",
    "asperity_elastic_force",
    "asperity_interference",
    "asperity_plastic_force",
    "asperity_tip_radius",
    "bearing_ratio",
    "cell_forces",
    "critical_area",
    "elastic_coefficient",
    "largest_area_from_force",
    "largest_area_from_separation",
    "max_largest_area",
    "real_contact_area",
    "rms_height",
    "size_distribution",
    "structure_function",
    "structure_function_constant",
    "surface_dimension",
    "total_force",
    "truncated_area",
    "weierstrass_mandelbrot_surface",
]

FloatArray = NDArray[np.float64]


class SaturatedCellWarning(UserWarning):
    """A cell force needs more truncated area than the cell has (A' > ΔA): a_l was clamped (E5.16).

    Filter with ``warnings.filterwarnings("ignore", category=SaturatedCellWarning)``.
    """


# --------------------------------------------------------------------------- validation helpers


def surface_dimension(profile_dimension: float) -> float:
    """Surface fractal dimension Ds = D + 1 from the profile dimension 1 < D < 2."""
    d = float(profile_dimension)
    if not (math.isfinite(d) and 1.0 < d < 2.0):
        raise InputError("D", profile_dimension, "a profile fractal dimension 1 < D < 2")
    return d + 1.0


def _dimension(Ds: float) -> float:
    d = float(Ds)
    if not (math.isfinite(d) and 2.0 < d < 3.0):
        raise InputError("Ds", Ds, "a surface fractal dimension 2 < Ds < 3 (Ds = profile D + 1)")
    return d


def _gamma(gamma: float) -> float:
    g = float(gamma)
    if not (math.isfinite(g) and g > 1.0):
        raise InputError("gamma", gamma, "a frequency density parameter > 1 (usually 1.5)")
    return g


# ---------------------------------------------------------------------------- surface (E5.1)–(E5.4)


def rms_height(Ds: float, G: float, length: float, gamma: float = 1.5) -> float:
    """RMS height σ of the 3-D W-M surface (E5.1) over the sampling length L_s, (E5.3), m.

        σ = L_s^(3−Ds) G^(Ds−2) √( ln γ / (2 (1 − γ^(2(Ds−3)))) )

    Summed over all frequency indices n ≥ 0. The raceway of ``examples/wear_step_stress.toml``
    (Ds = 2.4, G = 1e-10 m) with L_s = 10 µm: σ = 7.254e-8 m.
    """
    d, g, ls, gam = _dimension(Ds), positive("G", G), positive("length", length), _gamma(gamma)
    return (
        ls ** (3.0 - d)
        * g ** (d - 2.0)
        * math.sqrt(math.log(gam) / (2.0 * (1.0 - gam ** (2.0 * (d - 3.0)))))
    )


def structure_function_constant(profile_dimension: float, G: float, gamma: float = 1.5) -> float:
    """Prefactor C of the profile structure function S(τ) = C τ^(4−2D_p), (E5.4), m^(2D_p−2).

        C = G^(2(D_p−1)) Γ(2D_p−3) sin[(2D_p−3)π/2] / [(4−2D_p) ln γ]

    (Majumdar & Bhushan 1990). Takes the *profile* dimension 1 < D_p < 2. The expression is
    regular at D_p = 1.5, where Γ(2D_p−3) sin[(2D_p−3)π/2] → π/2.
    """
    dp = float(profile_dimension)
    if not (math.isfinite(dp) and 1.0 < dp < 2.0):
        raise InputError("D", profile_dimension, "a profile fractal dimension 1 < D < 2")
    g, gam = positive("G", G), _gamma(gamma)
    z = 2.0 * dp - 3.0
    # Γ(z) sin(zπ/2) = Γ(1+z) sin(zπ/2)/z, finite at z = 0.
    if abs(z) < 1e-8:
        product = math.pi / 2.0
    else:
        product = float(gamma_function(1.0 + z)) * math.sin(z * math.pi / 2.0) / z
    return g ** (2.0 * (dp - 1.0)) * product / ((4.0 - 2.0 * dp) * math.log(gam))


def structure_function(
    lag: ArrayLike, profile_dimension: float, G: float, gamma: float = 1.5
) -> FloatArray:
    """S(τ) = ⟨[z(x+τ) − z(x)]²⟩ = C τ^(4−2D_p) of a W-M profile, (E5.4), m².

    Fit log S against log τ on a measured, form-removed profile: slope m gives D_p = (4 − m)/2,
    Ds = D_p + 1, and the intercept gives G.
    """
    tau = nonnegative_array("lag", lag)
    c = structure_function_constant(profile_dimension, G, gamma)
    return c * tau ** (4.0 - 2.0 * float(profile_dimension))


def weierstrass_mandelbrot_surface(
    x: ArrayLike,
    y: ArrayLike,
    Ds: float,
    G: float,
    length: float,
    *,
    gamma: float = 1.5,
    ridges: int = 10,
    cutoff: float | None = None,
    rng: np.random.Generator | int | None = None,
) -> FloatArray:
    """One realisation z(x, y) of the 3-D W-M surface (E5.1) (Ausloos & Berman 1985), m.

        z = L_s (G/L_s)^(Ds−2) (ln γ/M)^½ Σ_m Σ_n γ^((Ds−3)n)
            { cos φ_mn − cos[2π γ^n r/L_s · cos(θ − πm/M) + φ_mn] }

    with r = √(x² + y²), θ = atan2(y, x), m = 1..M (``ridges``), n = 0..n_max, n_max =
    int[log(L_s/L_cut)/log γ] and random phases φ_mn ~ U(0, 2π). ``cutoff`` L_cut defaults to
    L_s/γ^17 (n_max = 17, as sampled for the σ example above). ``x`` and ``y`` broadcast; the sum is
    vectorised over (m, n).
    """
    d, g, ls, gam = _dimension(Ds), positive("G", G), positive("length", length), _gamma(gamma)
    if isinstance(ridges, bool) or int(ridges) != ridges or ridges < 1:
        raise InputError("ridges", ridges, "an integer >= 1")
    cut = ls / gam**17 if cutoff is None else positive("cutoff", cutoff)
    n_max = int(math.log(ls / cut) / math.log(gam) + 1e-9)
    gen = rng if isinstance(rng, np.random.Generator) else np.random.default_rng(rng)
    x, y = np.broadcast_arrays(np.asarray(x, dtype=float), np.asarray(y, dtype=float))
    r = np.hypot(x, y)[..., None, None]
    theta = np.arctan2(y, x)[..., None, None]
    m = np.arange(1, int(ridges) + 1)[:, None]
    n = np.arange(n_max + 1)[None, :]
    phase = gen.uniform(0.0, 2.0 * math.pi, size=(int(ridges), n_max + 1))
    amplitude = gam ** ((d - 3.0) * n)
    argument = 2.0 * math.pi * gam**n * r / ls * np.cos(theta - math.pi * m / ridges) + phase
    terms = amplitude * (np.cos(phase) - np.cos(argument))
    prefactor = ls * (g / ls) ** (d - 2.0) * math.sqrt(math.log(gam) / ridges)
    return prefactor * terms.sum(axis=(-2, -1))


# ----------------------------------------------------------------------- one asperity (E5.5)–(E5.9)


def asperity_interference(area: ArrayLike, Ds: float, G: float, gamma: float = 1.5) -> FloatArray:
    """Interference (cap height) δ(a') = 2^(4−Ds) G^(Ds−2) (ln γ)^½ (a'/π)^((3−Ds)/2), (E5.5), m."""
    d, g, gam = _dimension(Ds), positive("G", G), _gamma(gamma)
    a = nonnegative_array("area", area)
    return (
        2.0 ** (4.0 - d)
        * g ** (d - 2.0)
        * math.sqrt(math.log(gam))
        * (a / math.pi) ** ((3.0 - d) / 2.0)
    )


def asperity_tip_radius(area: ArrayLike, Ds: float, G: float, gamma: float = 1.5) -> FloatArray:
    """Tip radius R(a') = r'²/(2δ) of the spherical cap of base radius r' = √(a'/π), (E5.6), m."""
    a = nonnegative_array("area", area)
    with np.errstate(divide="ignore", invalid="ignore"):
        return (a / math.pi) / (2.0 * asperity_interference(a, Ds, G, gamma))


def elastic_coefficient(Ds: float, G: float, E_star: float, gamma: float = 1.5) -> float:
    """C_e of f_e = C_e a'^((4−Ds)/2), (E5.7), SI (N m^(Ds−4)).

        C_e = 2^((11−2Ds)/2) (ln γ)^½ G^(Ds−2) E* / (3 π^((4−Ds)/2))

    from Hertz f = (4/3) E* R^½ δ^(3/2) with (E5.5)–(E5.6). Ds = 2.4, G = 1e-10 m,
    E* = 1.1319e11 Pa: C_e = 8.244e6.
    """
    d, g, gam = _dimension(Ds), positive("G", G), _gamma(gamma)
    e = positive("E_star", E_star)
    return (
        2.0 ** ((11.0 - 2.0 * d) / 2.0)
        * math.sqrt(math.log(gam))
        * g ** (d - 2.0)
        * e
        / (3.0 * math.pi ** ((4.0 - d) / 2.0))
    )


def asperity_elastic_force(
    area: ArrayLike, Ds: float, G: float, E_star: float, gamma: float = 1.5
) -> FloatArray:
    """Elastic (Hertz) force of one asperity f_e(a') = C_e a'^((4−Ds)/2), (E5.7), N."""
    a = nonnegative_array("area", area)
    return elastic_coefficient(Ds, G, E_star, gamma) * a ** ((4.0 - _dimension(Ds)) / 2.0)


def asperity_plastic_force(area: ArrayLike, H: float) -> FloatArray:
    """Fully plastic force of one asperity f_p(a') = H a', (E5.8), N."""
    return positive("H", H) * nonnegative_array("area", area)


def critical_area(Ds: float, G: float, E_star: float, H: float, gamma: float = 1.5) -> float:
    """Critical truncated area a_c = (C_e/H)^(2/(Ds−2)), (E5.9), m².

    Where f_e(a_c) = H a_c: asperities with a' > a_c deform elastically, those with a' ≤ a_c
    plastically (for Ds > 2 the interference ratio δ/δ_c falls as a' grows). E* = 1.1319e11 Pa,
    H = 7 GPa, G = 1e-10 m: a_c = 1.497e-13 / 2.265e-15 / 1.833e-16 m² at Ds = 2.3 / 2.4 / 2.5.
    """
    d = _dimension(Ds)
    ratio = elastic_coefficient(d, G, E_star, gamma) / positive("H", H)
    return ratio ** (2.0 / (d - 2.0))


# ------------------------------------------------------------- population of a cell (E5.10)–(E5.13)


def size_distribution(area: ArrayLike, largest: float, Ds: float) -> FloatArray:
    """n(a') = ((Ds−1)/2) a_l^((Ds−1)/2) a'^(−(Ds+1)/2) for 0 < a' ≤ a_l, else 0, (E5.10), m⁻²."""
    d = _dimension(Ds)
    a_l = positive("largest", largest)
    a = nonnegative_array("area", area)
    with np.errstate(divide="ignore"):
        n = 0.5 * (d - 1.0) * a_l ** (0.5 * (d - 1.0)) * a ** (-0.5 * (d + 1.0))
    return np.where((a > 0.0) & (a <= a_l), n, 0.0)


def truncated_area(largest: ArrayLike, Ds: float) -> FloatArray:
    """Total truncated area A' = (Ds−1)/(3−Ds) · a_l of a cell, (E5.11), m²."""
    d = _dimension(Ds)
    return (d - 1.0) / (3.0 - d) * nonnegative_array("largest", largest)


def max_largest_area(cell_area: float, Ds: float) -> float:
    """Physical limit of a_l, where A' = ΔA: a_l,max = (3−Ds)/(Ds−1) · ΔA, (E5.16), m²."""
    d = _dimension(Ds)
    return (3.0 - d) / (d - 1.0) * positive("cell_area", cell_area)


def _ratio_power(a_c: float, a_l: FloatArray, exponent: float) -> FloatArray:
    """(a_c/a_l)^exponent, 0 where a_l = 0 is replaced by the fully plastic branch later."""
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(a_l > 0.0, (a_c / np.where(a_l > 0.0, a_l, 1.0)) ** exponent, 1.0)


def cell_forces(
    largest: ArrayLike, Ds: float, G: float, E_star: float, H: float, gamma: float = 1.5
) -> tuple[FloatArray, FloatArray]:
    """Elastic and plastic force (F_e, F_p) of a cell with largest truncated area a_l, (E5.12), N.

    For a_l > a_c:

        F_e = C_e (Ds−1)/(5−2Ds) a_l^((4−Ds)/2) [1 − (a_c/a_l)^((5−2Ds)/2)]
        F_p = H (Ds−1)/(3−Ds) a_l^((Ds−1)/2) a_c^((3−Ds)/2)

    evaluated as C_e (Ds−1)/2 a_l^((4−Ds)/2) ln(a_l/a_c) exprel(k ln(a_c/a_l)), k = (5−2Ds)/2,
    which is continuous through Ds = 2.5 (the logarithmic branch). For a_l ≤ a_c every asperity
    is plastic: F_e = 0, F_p = H A'.
    """
    d = _dimension(Ds)
    a_l = nonnegative_array("largest", largest)
    h = positive("H", H)
    c_e = elastic_coefficient(d, G, E_star, gamma)
    a_c = critical_area(d, G, E_star, h, gamma)
    elastic_regime = a_l > a_c
    safe = np.where(elastic_regime, a_l, a_c)
    log_ratio = np.log(safe / a_c)  # ln(a_l/a_c) ≥ 0
    k = 0.5 * (5.0 - 2.0 * d)
    f_e = 0.5 * c_e * (d - 1.0) * safe ** (0.5 * (4.0 - d)) * log_ratio * exprel(-k * log_ratio)
    f_p_elastic = h * (d - 1.0) / (3.0 - d) * safe ** (0.5 * (d - 1.0)) * a_c ** (0.5 * (3.0 - d))
    f_p_plastic = h * truncated_area(a_l, d)
    return (
        np.where(elastic_regime, f_e, 0.0),
        np.where(elastic_regime, f_p_elastic, f_p_plastic),
    )


def total_force(
    largest: ArrayLike, Ds: float, G: float, E_star: float, H: float, gamma: float = 1.5
) -> FloatArray:
    """Total asperity force of a cell F_asp(a_l) = F_e + F_p, (E5.12), N. Increasing in a_l."""
    f_e, f_p = cell_forces(largest, Ds, G, E_star, H, gamma)
    return f_e + f_p


def real_contact_area(
    largest: ArrayLike, Ds: float, G: float, E_star: float, H: float, gamma: float = 1.5
) -> FloatArray:
    """Real contact area A_r of a cell (elastic spots count a'/2, plastic ones a'), (E5.13), m²."""
    d = _dimension(Ds)
    a_l = nonnegative_array("largest", largest)
    a_c = critical_area(d, G, E_star, H, gamma)
    ratio = np.minimum(_ratio_power(a_c, a_l, 0.5 * (3.0 - d)), 1.0)
    scale = (d - 1.0) / (3.0 - d) * a_l
    return 0.5 * scale * (1.0 - ratio) + scale * ratio


# ------------------------------------------------------------------------ separation and force


def bearing_ratio(separation: ArrayLike, sigma: float) -> FloatArray:
    """Gaussian bearing ratio Φ(h) = ½ erfc(h/(√2 σ)), the fraction above height h, (E5.15)."""
    s = positive("sigma", sigma)
    return 0.5 * erfc(np.asarray(separation, dtype=float) / (math.sqrt(2.0) * s))


def largest_area_from_separation(
    separation: ArrayLike, sigma: float, cell_area: float, Ds: float
) -> FloatArray:
    """a_l(h) = (3−Ds)/(Ds−1) · Φ(h) ΔA at mean-plane separation h, (E5.15), m²."""
    return max_largest_area(cell_area, Ds) * bearing_ratio(separation, sigma)


def largest_area_from_force(
    force: ArrayLike,
    cell_area: float,
    Ds: float,
    G: float,
    E_star: float,
    H: float,
    gamma: float = 1.5,
    *,
    rtol: float = 1e-12,
) -> FloatArray:
    """Invert F_asp(a_l) = F per cell, (E5.16), m²; vectorised over ``force``.

    Bisection on ln a_l over [1e-30, 10 ΔA] m², all cells at once (F_asp is strictly
    increasing), to a relative width ``rtol``. A root above the physical limit
    a_l,max = (3−Ds)/(Ds−1) ΔA (A' > ΔA) is clamped to it and a :class:`SaturatedCellWarning`
    is issued. Cells with F = 0 give a_l = 0.
    """
    f = nonnegative_array("force", force)
    cell = positive("cell_area", cell_area)
    limit = max_largest_area(cell, Ds)
    lo = np.full(f.shape, math.log(1e-30))
    hi = np.full(f.shape, math.log(10.0 * cell))
    width = math.log(10.0 * cell) - math.log(1e-30)
    steps = math.ceil(math.log2(width / max(rtol, 1e-15))) + 1
    for _ in range(steps):  # fixed count: vectorised over every cell
        mid = 0.5 * (lo + hi)
        above = total_force(np.exp(mid), Ds, G, E_star, H, gamma) > f
        hi = np.where(above, mid, hi)
        lo = np.where(above, lo, mid)
    root = np.where(f > 0.0, np.exp(0.5 * (lo + hi)), 0.0)
    saturated = root > limit
    if np.any(saturated):
        warnings.warn(
            f"{int(np.count_nonzero(saturated))} cell(s) saturated: the asperity force needs a "
            f"truncated area above the cell area; a_l clamped to {limit:.3e} m² (E5.16)",
            SaturatedCellWarning,
            stacklevel=2,
        )
    return np.minimum(root, limit)
