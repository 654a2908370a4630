"""Fractal thermal contact resistance of one grid element ("diminutive area").

Theory manual: ``docs/theory/contact-resistance.md``, element resistance (T1)–(T8) and the variants
of G_s and of the gap thickness.

Each element of apparent area A carries a load P = p·A. Majumdar–Bhushan contact
(``docs/theory/fractal-contact.md``, package :mod:`ballscrew.fractal`) gives its largest spot a_l
and real area A_r; the element then conducts through the solid spots (G_s) and, in parallel, through
the interstitial medium across a gap of thickness L_g (G_g): R = 1/(G_s + G_g).

Variants of G_s (option ``variant``):

- ``"V2"`` (default, T5) **[REC]**: a *reconstruction* of the paper's lost Eq. (43). It is chosen
  because it reproduces the trends the paper reports, not because its exact form was seen.
- ``"MT"`` (T2a): Majumdar & Tien (1991) spot integral with a fixed lower cut-off a_s.
- ``"V1"``: one equivalent circular spot of area A_r per element.

Mesh dependence (theory manual, *Re-binning onto fractal cells*): a_l grows with the element area A
at fixed pressure, so the summed contact resistance depends on the element size (V2: −30 % when the
cell side is halved from 6.1 µm). The element size Δ_f is therefore a model parameter and must be
reported with every result (see :func:`ballscrew.thermal.aggregation.contact_tcr`).

Model artefact to be aware of: with the reconstructed gap thickness (T6), L_g ∝ a_l^((2−D)/2) → 0 as
P → 0, so G_g → ∞ and R → 0 for vanishing load; in V2 the unit-area R″ *rises* with pressure (theory
manual, *Contact resistance*, known artefact). Lightly loaded elements therefore conduct best; the
load threshold of :func:`~ballscrew.thermal.aggregation.contact_tcr` controls which of them count.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ballscrew.contact_resistance.correlations import plastic_separation
from ballscrew.errors import InputError
from ballscrew.fractal import (
    largest_spot_area,
    profile_rms_roughness,
    real_contact_area,
    size_distribution_constant,
    validate_dimension,
)
from ballscrew.registry import Registry
from ballscrew.validation import nonnegative_array, positive, positive_array

__all__ = [
    "GAP_MODELS",
    "VARIANTS",
    "ElementTCR",
    "FractalTCRModel",
    "constriction_alleviation_factor",
    "cooper_mikic_yovanovich_conductance",
    "element_tcr",
    "gap_conductance",
    "gap_thickness",
    "harmonic_mean_conductivity",
    "solid_conductance_mt",
    "solid_conductance_v1",
    "solid_conductance_v2",
    "spot_conductance",
]

SolidConductance = Callable[
    [NDArray[np.float64], NDArray[np.float64], "FractalTCRModel"], NDArray[np.float64]
]
ELEMENT_MODELS: Registry[SolidConductance] = Registry("element TCR model", "tcr.variant")
"""Solid-spot conductance G_s(a_l, A_r, model) of an element: V2, MT, V1 (registered below)."""

_GAP_COEFFICIENTS: dict[str, float] = {
    "mean_cap": 2.0 / math.pi,
    "cap_clearance": 1.0 - 2.0 / math.pi,
    "interference": 1.0,
}
_ROUGHNESS_GAP_MODELS: tuple[str, ...] = ("two_sigma", "mean_plane")
"""Gap models set by the RMS roughness σ over the sampling length (need ``sampling_length``)."""
GAP_MODELS: tuple[str, ...] = (*_GAP_COEFFICIENTS, *_ROUGHNESS_GAP_MODELS)
"""Gap-thickness models: mean_cap (T6, default), cap_clearance, interference, two_sigma,
mean_plane (Yovanovich's mean-plane separation Y, T9)."""


# --------------------------------------------------------------------------------------------
# Building blocks (T1)–(T7)
# --------------------------------------------------------------------------------------------


def harmonic_mean_conductivity(lambda_1: float, lambda_2: float) -> float:
    """Effective solid conductivity λ_s = 2λ₁λ₂/(λ₁ + λ₂) of two half-spaces, (T1).

    Args:
        lambda_1: conductivity of body 1 (ball), W/(m K).
        lambda_2: conductivity of body 2 (raceway), W/(m K).

    Returns:
        λ_s in W/(m K).
    """
    l1 = positive("lambda_1", lambda_1, "W/(m K)")
    l2 = positive("lambda_2", lambda_2, "W/(m K)")
    return 2.0 * l1 * l2 / (l1 + l2)


def spot_conductance(a: ArrayLike, *, lambda_s: float) -> NDArray[np.float64]:
    """Spreading conductance g = 2 λ_s r = 2 λ_s √(a/π) of one isothermal circular spot, (T1).

    Args:
        a: spot area(s), m².
        lambda_s: harmonic-mean conductivity λ_s, W/(m K).

    Returns:
        g in W/K, same shape as ``a``.
    """
    lam = positive("lambda_s", lambda_s, "W/(m K)")
    return 2.0 * lam * np.sqrt(nonnegative_array("a", a, "m²") / math.pi)


def solid_conductance_v2(a_l: ArrayLike, *, D: float, lambda_s: float) -> NDArray[np.float64]:
    """Solid-spot conductance of variant V2, (T5) **[REC]** (reconstruction of paper Eq. (43)).

        G_s = (2λ_s/√π) (D/(D−1)) ψ^((2−D)/2) a_l^(1/2)

    This is (T2a) evaluated at its upper limit only, i.e. (T2a) with a_s = 2^(−2/(D−1)) a_l. Element
    results depend on the element size (mesh dependence). Sources: Majumdar & Tien (1991) for the
    spot network; Wang & Komvopoulos (1994) for ψ.

    Args:
        a_l: largest spot area(s), m².
        D: profile fractal dimension, 1 < D < 2.
        lambda_s: harmonic-mean conductivity λ_s, W/(m K).

    Returns:
        G_s in W/K, same shape as ``a_l``.
    """
    D = validate_dimension(D)
    lam = positive("lambda_s", lambda_s, "W/(m K)")
    c = size_distribution_constant(D)
    a_arr = nonnegative_array("a_l", a_l, "m²")
    return 2.0 * lam / math.sqrt(math.pi) * D / (D - 1.0) * c * np.sqrt(a_arr)


def solid_conductance_mt(
    a_l: ArrayLike, *, D: float, lambda_s: float, cutoff_area: ArrayLike = 1.0e-16
) -> NDArray[np.float64]:
    """Solid-spot conductance of variant MT, (T2a) (Majumdar & Tien 1991), with cut-off a_s.

        G_s = (2λ_s/√π) ψ^((2−D)/2) (D/(D−1)) a_l^(D/2) [a_s^((1−D)/2) − a_l^((1−D)/2)],  a_s < a_l

    i.e. ∫_{a_s}^{a_l} g(a) n(a) da with (T1) and (F9). The integral diverges as a_s → 0 for
    every 1 < D < 2, hence the fixed lower cut-off. When a_l <= a_s no spot exceeds the cut-off
    and G_s = 0. G_s ∝ a_s^((1−D)/2) for a_s ≪ a_l.

    Args:
        a_l: largest spot area(s), m².
        D: profile fractal dimension, 1 < D < 2.
        lambda_s: harmonic-mean conductivity λ_s, W/(m K).
        cutoff_area: lower spot-area cut-off a_s (> 0), m² (default 1e-16 m², i.e. a lower
            fractal cut-off length ≈ 10 nm); broadcast against ``a_l``.

    Returns:
        G_s in W/K (broadcast shape).
    """
    D = validate_dimension(D)
    lam = positive("lambda_s", lambda_s, "W/(m K)")
    a_arr, a_s = np.broadcast_arrays(
        nonnegative_array("a_l", a_l, "m²"), np.asarray(cutoff_area, dtype=np.float64)
    )
    if np.any(~np.isfinite(a_s) | (a_s <= 0.0)):
        raise InputError("cutoff_area", cutoff_area, "finite values > 0 m²")
    g = np.zeros(a_arr.shape)
    m = a_arr > a_s
    k = 2.0 * lam / math.sqrt(math.pi) * size_distribution_constant(D) * D / (D - 1.0)
    e = (1.0 - D) / 2.0
    g[m] = k * a_arr[m] ** (D / 2.0) * (a_s[m] ** e - a_arr[m] ** e)
    return g[()]


def solid_conductance_v1(real_area: ArrayLike, *, lambda_s: float) -> NDArray[np.float64]:
    """Solid conductance of variant V1: one equivalent spot of area A_r, G_s = 2λ_s √(A_r/π).

    ((T1) applied to the whole real area.)

    Args:
        real_area: real contact area(s) A_r of the element, m².
        lambda_s: harmonic-mean conductivity λ_s, W/(m K).

    Returns:
        G_s in W/K, same shape as ``real_area``.
    """
    return spot_conductance(real_area, lambda_s=lambda_s)


@ELEMENT_MODELS.register(
    "V2", "reconstructed spot conductance at the largest spot (the paper's model, default variant)"
)
def _element_v2(
    a_l: NDArray[np.float64], _: NDArray[np.float64], model: FractalTCRModel
) -> NDArray[np.float64]:
    return solid_conductance_v2(a_l, D=model.D, lambda_s=model.lambda_s)


@ELEMENT_MODELS.register("MT", "Majumdar–Tien spot network with a lower cut-off a_s")
def _element_mt(
    a_l: NDArray[np.float64], _: NDArray[np.float64], model: FractalTCRModel
) -> NDArray[np.float64]:
    return solid_conductance_mt(
        a_l, D=model.D, lambda_s=model.lambda_s, cutoff_area=model.cutoff_area
    )


@ELEMENT_MODELS.register("V1", "one equivalent spot of the real contact area")
def _element_v1(
    _: NDArray[np.float64], a_r: NDArray[np.float64], model: FractalTCRModel
) -> NDArray[np.float64]:
    return solid_conductance_v1(a_r, lambda_s=model.lambda_s)


VARIANTS: tuple[str, ...] = ELEMENT_MODELS.names
"""Element conductance variants: V2 (default, T5, [REC]), MT (T2a), V1 (one equivalent spot)."""


def gap_thickness(
    a_l: ArrayLike,
    *,
    D: float,
    G: float,
    model: str = "mean_cap",
    factor: float = 1.0,
    sampling_length: float | None = None,
    pressure: ArrayLike | None = None,
    hardness: float | None = None,
) -> NDArray[np.float64]:
    """Thickness L_g of the interstitial gap of an element, (T6) **[REC]** and the other gap models.

    With δ_l = G^(D−1) a_l^((2−D)/2) the interference (height) of the largest asperity (F5):

    - ``"mean_cap"`` (default, T6): L_g = (2/π) δ_l, the mean height of the largest asperity's MB
      cosine cap z(x) = G^(D−1) L_u^(2−D) cos(πx/L_u) over its domain L_u = a_l^(1/2);
    - ``"cap_clearance"``: L_g = (1 − 2/π) δ_l, the mean clearance under the flat;
    - ``"interference"``: L_g = δ_l;
    - ``"two_sigma"``: L_g = 2σ with σ from (F3) over the sampling length L_u (independent of a_l);
    - ``"mean_plane"`` (T9): L_g = Y = σ √2 erfc⁻¹(2p/H), the mean-plane separation of Gaussian
      surfaces of the same σ (F3 over L_u) carrying the element's apparent pressure p = P/A
      plastically (Cooper, Mikic & Yovanovich 1969; Yovanovich 1982; Bahrami et al. 2004 take
      the gas gap across the same local separation). The mean gap of a rough joint is several σ,
      not the height of one cap.

    The result is multiplied by ``factor``. Elements with a_l = 0 are out of contact: L_g = ∞.
    Reconstruction of the paper's Eq. (44) (source: Liu Zhifeng et al. 2015, paywalled).

    Args:
        a_l: largest spot area(s), m².
        D: profile fractal dimension, 1 < D < 2.
        G: fractal roughness, m.
        model: one of :data:`GAP_MODELS`.
        factor: multiplier (> 0) on the modelled thickness.
        sampling_length: sampling length L_u, m (required by ``"two_sigma"`` and
            ``"mean_plane"``).
        pressure: apparent element pressure p = P/A, Pa (required by ``"mean_plane"``;
            broadcast against ``a_l``).
        hardness: microhardness H of the softer surface, Pa (required by ``"mean_plane"``).

    Returns:
        L_g in m, same shape as ``a_l``.

    Raises:
        InputError: unknown model, bad factor, or missing sampling length, pressure or hardness.
    """
    D = validate_dimension(D)
    G = positive("G", G, "m")
    fac = positive("factor", factor, "")
    a_arr = nonnegative_array("a_l", a_l, "m²")
    out = np.full(a_arr.shape, np.inf)
    loaded = a_arr > 0.0
    if model in _ROUGHNESS_GAP_MODELS:
        if sampling_length is None:
            raise InputError("sampling_length", None, f"a length > 0 m for gap model {model!r}")
        sigma = profile_rms_roughness(D, G, sampling_length)
        if model == "two_sigma":
            out[loaded] = fac * 2.0 * sigma
        else:
            if pressure is None or hardness is None:
                missing = "pressure" if pressure is None else "hardness"
                raise InputError(missing, None, "a value > 0 for gap model 'mean_plane'")
            p = np.broadcast_to(nonnegative_array("pressure", pressure, "Pa"), a_arr.shape)
            peak = float(p[loaded].max(initial=0.0)) / positive("hardness", hardness, "Pa")
            if peak >= 0.5:  # Y = 0: the Gaussian surfaces touch everywhere, no gap is left
                raise InputError("pressure", f"p/H = {peak:.3g}", "p/H < 0.5 for 'mean_plane'")
            y = plastic_separation(p[loaded], sigma=sigma, hardness=hardness)
            out[loaded] = fac * y
    elif model in _GAP_COEFFICIENTS:
        coeff = fac * _GAP_COEFFICIENTS[model] * G ** (D - 1.0)
        out[loaded] = coeff * a_arr[loaded] ** ((2.0 - D) / 2.0)
    else:
        raise InputError("gap_model", model, f"one of {', '.join(GAP_MODELS)}")
    return out[()]


def gap_conductance(
    real_area: ArrayLike,
    thickness: ArrayLike,
    *,
    apparent_area: ArrayLike,
    lambda_f: float,
    rarefaction: float = 0.0,
) -> NDArray[np.float64]:
    """Conductance G_g = λ_f (A − A_r)/(L_g + M) of the interstitial medium, (T3)/(T7)/(T10).

    M is the gas rarefaction (temperature-jump) parameter M = αβΛ (Yovanovich 1982; Song &
    Yovanovich 1987; Bahrami et al. 2004): 0 for a liquid (oil, grease) — then (T7) unchanged —
    and of the order of the mean free path for a gas (air at 1 atm: M ≈ 0.27 µm), which bounds
    G_g by the free-molecular limit λ_f (A − A_r)/M when L_g ≪ M.
    A_r is capped at A (G_g = 0 when the element is fully in contact); L_g = ∞ gives 0.

    Args:
        real_area: real contact area(s) A_r, m².
        thickness: gap thickness(es) L_g (> 0, may be ∞), m.
        apparent_area: apparent element area A, m².
        lambda_f: conductivity of the interstitial medium (oil, grease, air), W/(m K).
        rarefaction: M >= 0, m (from :func:`~.correlations.gas_rarefaction_parameter` for a
            gas; 0, the default, for a liquid).

    Returns:
        G_g in W/K (broadcast shape).
    """
    area = positive_array("apparent_area", apparent_area, "m²")
    lam = positive("lambda_f", lambda_f, "W/(m K)")
    m = _rarefaction(rarefaction)
    a_r = nonnegative_array("real_area", real_area, "m²")
    lg = np.asarray(thickness, dtype=np.float64)
    if np.any(np.isnan(lg) | (lg <= 0.0)):
        raise InputError("thickness", thickness, "values > 0 m (∞ allowed)")
    return lam * np.maximum(area - a_r, 0.0) / (lg + m)


def _rarefaction(value: float) -> float:
    """M validated: finite and >= 0 m."""
    m = float(value)
    if not (math.isfinite(m) and m >= 0.0):
        raise InputError("rarefaction", value, "M ≥ 0 m (0 for a liquid)")
    return m


def constriction_alleviation_factor(
    real_area: ArrayLike, *, apparent_area: ArrayLike
) -> NDArray[np.float64]:
    """Constriction-alleviation divisor (1 − √(A_r/A))^1.5 for G_s (optional refinement).

    Divide G_s by this factor to account for neighbouring spots; it matters only when
    A_r/A > 0.2. A_r is capped at A (divisor 0 → perfect contact).

    Args:
        real_area: real contact area(s) A_r, m².
        apparent_area: apparent element area A, m².

    Returns:
        The dimensionless divisor, same shape as ``real_area``.
    """
    area = positive_array("apparent_area", apparent_area, "m²")
    ratio = np.minimum(nonnegative_array("real_area", real_area, "m²") / area, 1.0)
    return (1.0 - np.sqrt(ratio)) ** 1.5


def cooper_mikic_yovanovich_conductance(
    pressure: ArrayLike, *, lambda_s: float, slope: float, sigma: float, hardness: float
) -> NDArray[np.float64]:
    """Plastic contact conductance h_c = 1.25 λ_s (m/σ) (p/H)^0.95 (Cooper–Mikic–Yovanovich 1969).

    A Gaussian-surface cross-check of the fractal models, per unit apparent area.

    Args:
        pressure: apparent contact pressure p (>= 0), Pa.
        lambda_s: harmonic-mean conductivity λ_s, W/(m K).
        slope: RMS absolute profile slope m (dimensionless).
        sigma: RMS roughness σ, m.
        hardness: microhardness H of the softer surface, Pa.

    Returns:
        h_c in W/(m² K), same shape as ``pressure``; e.g. λ_s = 40, m = 0.05, σ = 0.2 µm,
        p/H = 0.15 → 2.06e6 W/(m² K).
    """
    lam = positive("lambda_s", lambda_s, "W/(m K)")
    m = positive("slope", slope, "")
    s = positive("sigma", sigma, "m")
    h = positive("hardness", hardness, "Pa")
    p = nonnegative_array("pressure", pressure, "Pa")
    return 1.25 * lam * (m / s) * (p / h) ** 0.95


# --------------------------------------------------------------------------------------------
# Model parameters and element evaluation (T8)
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class FractalTCRModel:
    """Parameters of the fractal element thermal-contact-resistance model.

    Validated on construction; an unknown ``variant`` or ``gap_model`` raises
    :class:`~ballscrew.errors.InputError` listing the allowed values.
    """

    D: float
    """Profile fractal dimension of the rough raceway, 1 < D < 2 (paper: 1.59)."""
    G: float
    """Fractal roughness, m (paper: 9e-10 m)."""
    E_star: float
    """Composite contact modulus E* (K1), Pa."""
    H: float
    """Hardness of the softer surface, Pa."""
    lambda_1: float
    """Thermal conductivity of the ball, W/(m K)."""
    lambda_2: float
    """Thermal conductivity of the raceway, W/(m K)."""
    lambda_f: float
    """Thermal conductivity of the interstitial medium (oil/grease ≈ 0.14, air 0.026), W/(m K)."""
    variant: str = "V2"
    """Solid-conductance variant, one of :data:`VARIANTS` (default V2, a reconstruction [REC])."""
    cutoff_area: float = 1.0e-16
    """Lower spot-area cut-off a_s of variant MT, m²."""
    gap_model: str = "mean_cap"
    """Gap-thickness model, one of :data:`GAP_MODELS` (default T6, for liquids too: no measured
    rough joint in a liquid decides between it and ``"mean_plane"``; theory manual, *Gap
    thickness in a liquid*)."""
    gap_factor: float = 1.0
    """Multiplier on the gap thickness L_g (dimensionless)."""
    sampling_length: float | None = None
    """Sampling length L_u for gap model ``two_sigma``, m."""
    constriction_alleviation: bool = False
    """Divide G_s by (1 − √(A_r/A))^1.5 (optional refinement)."""
    rarefaction: float = 0.0
    """Gas rarefaction parameter M = αβΛ of the medium (T10), m: 0 for a liquid (default), e.g.
    0.27 µm for air at 20 °C and 1 atm (Yovanovich 1982)."""
    lambda_s: float = field(init=False)
    """Harmonic-mean solid conductivity 2λ₁λ₂/(λ₁+λ₂) (T1), W/(m K); derived."""

    def __post_init__(self) -> None:
        validate_dimension(self.D)
        for name, unit in (("G", "m"), ("E_star", "Pa"), ("H", "Pa"), ("lambda_f", "W/(m K)")):
            positive(name, getattr(self, name), unit)
        positive("cutoff_area", self.cutoff_area, "m²")
        positive("gap_factor", self.gap_factor, "")
        ELEMENT_MODELS.check(self.variant)
        if self.gap_model not in GAP_MODELS:
            raise InputError("gap_model", self.gap_model, f"one of {', '.join(GAP_MODELS)}")
        if self.gap_model in _ROUGHNESS_GAP_MODELS:
            if self.sampling_length is None:
                raise InputError("sampling_length", None, f"a length > 0 m for {self.gap_model!r}")
            positive("sampling_length", self.sampling_length, "m")
        _rarefaction(self.rarefaction)
        lam = harmonic_mean_conductivity(self.lambda_1, self.lambda_2)
        object.__setattr__(self, "lambda_s", lam)


@dataclass(frozen=True)
class ElementTCR:
    """Thermal contact resistance of a set of elements of equal apparent area (T1)–(T8).

    Array fields have the shape of the load array. Unloaded elements (P = 0) are out of contact:
    a_l = A_r = G_s = G_g = 0, L_g = ∞ and R = ∞.
    """

    variant: str
    """Solid-conductance variant that produced the result (V2, MT or V1)."""
    apparent_area: NDArray[np.float64]
    """Apparent area A of each element, m²."""
    load: NDArray[np.float64]
    """Element load P = p·A, N."""
    largest_spot_area: NDArray[np.float64]
    """Largest contact spot a_l (inverse of F15), m²."""
    real_area: NDArray[np.float64]
    """Real contact area A_r (F11), capped at A, m²."""
    gap_thickness: NDArray[np.float64]
    """Interstitial gap thickness L_g (T6 or alternative), m."""
    solid_conductance: NDArray[np.float64]
    """Solid-spot conductance G_s, W/K."""
    gap_conductance: NDArray[np.float64]
    """Interstitial-medium conductance G_g (T7), W/K."""
    resistance: NDArray[np.float64]
    """Element resistance R = 1/(G_s + G_g) (T8), K/W."""

    @property
    def unit_area_resistance(self) -> NDArray[np.float64]:
        """Unit-area resistance R″ = A·R (T8), m² K/W."""
        return self.apparent_area * self.resistance


def element_tcr(load: ArrayLike, apparent_area: ArrayLike, model: FractalTCRModel) -> ElementTCR:
    """Element thermal contact resistance R = 1/(G_s + G_g) for every element load, (T8).

    Chain per element (all elements at once, no loop): a_l from P (F15 inverted), A_r (F11,
    capped at A), L_g (T6 or option), G_s (T5 for V2 [REC], T2a for MT, 2λ_s√(A_r/π) for V1),
    G_g (T7; with the gas term M of T10), R (T8). The result depends on the element size A
    (mesh dependence).

    Sources: Majumdar & Bhushan (1990, J. Tribol. 112:205; 1991); Wang & Komvopoulos (1994);
    Majumdar & Tien (1991).

    Args:
        load: element loads P = p·A (>= 0), N; any shape.
        apparent_area: apparent area A of the elements, m²: one value for all, or one per
            element (broadcast against ``load``; > 0).
        model: model parameters and variant.

    Returns:
        :class:`ElementTCR` with per-element arrays.
    """
    p = nonnegative_array("load", load, "N")
    area = np.broadcast_to(positive_array("apparent_area", apparent_area, "m²"), p.shape)
    a_l = largest_spot_area(p, D=model.D, G=model.G, E_star=model.E_star, H=model.H)
    a_r = np.minimum(real_contact_area(a_l, D=model.D), area)
    l_g = gap_thickness(
        a_l,
        D=model.D,
        G=model.G,
        model=model.gap_model,
        factor=model.gap_factor,
        sampling_length=model.sampling_length,
        pressure=p / area,
        hardness=model.H,
    )
    g_s = ELEMENT_MODELS[model.variant](np.asarray(a_l), a_r, model)
    loaded = p > 0.0
    if model.constriction_alleviation:
        divisor = constriction_alleviation_factor(a_r, apparent_area=area)
        with np.errstate(divide="ignore"):  # divisor 0 ⇔ A_r = A: perfect contact, G_s = ∞
            g_s = np.where(loaded, g_s / divisor, g_s)
    g_s = np.asarray(g_s, dtype=np.float64)
    g_g = np.asarray(
        gap_conductance(
            a_r, l_g, apparent_area=area, lambda_f=model.lambda_f, rarefaction=model.rarefaction
        )
    )
    g = g_s + g_g
    resistance = np.full(p.shape, np.inf)
    resistance[loaded] = 1.0 / g[loaded]
    return ElementTCR(
        variant=model.variant,
        apparent_area=area,
        load=p,
        largest_spot_area=np.asarray(a_l),
        real_area=np.asarray(a_r),
        gap_thickness=np.asarray(l_g),
        solid_conductance=g_s,
        gap_conductance=g_g,
        resistance=resistance,
    )
