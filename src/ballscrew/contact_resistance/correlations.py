"""Gaussian-surface correlations of the thermal contact conductance, rivals of the fractal model.

Theory manual: ``docs/theory/contact-resistance.md``, *Rival models*.

The classical correlations give the conductance per unit apparent area h(p) of a conforming
rough joint from the local apparent pressure p and two roughness numbers of the joint, the RMS
height σ and the RMS absolute profile slope m (for two rough surfaces σ = √(σ₁² + σ₂²),
m = √(m₁² + m₂²)):

- Cooper, Mikic & Yovanovich (1969), plastic asperities:
  h_c = 1.25 λ_s (m/σ) (p/H)^0.95;
- Mikic (1974), elastic asperities: h_c = 1.54 λ_s (m/σ) (√2 p/(m E*))^0.94;
- the interstitial medium across the mean-plane separation Y of the Gaussian surfaces
  (Yovanovich 1982): h_g = λ_f/(Y + M), with M = 0 for a liquid and M = αβΛ for a gas;
  for plastic asperities p/H = ½ erfc(Y/(σ√2)), i.e. Y = σ √2 erfc⁻¹(2p/H).

The contact's conductance is the integral of h over the solved pressure field,
G = ∫ h(p(x, y)) dA, which converges as the grid is refined: it has no cell size at all.
The conversion from the fractal parameters (D, G) of the Majumdar–Bhushan profile to (σ, m) is
:func:`fractal_roughness` (one convention for every model).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.special import erfcinv

from ballscrew.errors import InputError
from ballscrew.fractal import validate_dimension
from ballscrew.lubrication import composite_roughness
from ballscrew.registry import Registry
from ballscrew.validation import nonnegative_array, positive

__all__ = [
    "CORRELATIONS",
    "GaussianJoint",
    "correlation_conductance",
    "fractal_roughness",
    "gas_rarefaction_parameter",
    "joint_gap_conductance",
    "mean_plane_separation",
    "mikic_elastic_conductance",
    "plastic_conductance",
    "plastic_separation",
    "rms_profile_slope",
]

_MAX_RELATIVE_PRESSURE = 0.5
"""p/H above which the plastic separation Y is zero (the Gaussian surfaces touch everywhere)."""


def rms_profile_slope(
    D: float, G: float, sampling_length: float, cutoff_length: float, gamma: float = 1.5
) -> float:
    """RMS profile slope m of the Weierstrass–Mandelbrot profile between 1/L_u and 1/l_c.

        m² = (2π)² G^(2(D−1)) (l_c^(2−2D) − L_u^(2−2D)) / (2 ln γ (2D − 2))

    the second moment of the one-sided power spectrum S(ω) = G^(2(D−1)) ω^(−(5−2D))/(2 ln γ)
    of Majumdar & Bhushan (1990). Unlike σ, m is set by the shortest wavelength l_c: the profile
    has no slope without a short-wavelength cut-off (the stylus or sampling resolution).

    Args:
        D: profile fractal dimension, 1 < D < 2.
        G: fractal roughness, m.
        sampling_length: longest wavelength L_u, m.
        cutoff_length: shortest wavelength l_c (< L_u), m.
        gamma: W-M frequency ratio γ > 1 (default 1.5).

    Returns:
        m (dimensionless).
    """
    D = validate_dimension(D)
    G = positive("G", G, "m")
    L_u = positive("sampling_length", sampling_length, "m")
    l_c = positive("cutoff_length", cutoff_length, "m")
    if not l_c < L_u:
        raise InputError("cutoff_length", l_c, f"< the sampling length {L_u:g} m")
    if not float(gamma) > 1.0:
        raise InputError("gamma", gamma, "W-M frequency ratio > 1")
    e = 2.0 - 2.0 * D
    m2 = (2.0 * math.pi) ** 2 * G ** (2.0 * (D - 1.0)) * (l_c**e - L_u**e)
    return math.sqrt(m2 / (2.0 * math.log(gamma) * (2.0 * D - 2.0)))


def fractal_roughness(
    D: float, G: float, sampling_length: float, cutoff_length: float, gamma: float = 1.5
) -> tuple[float, float]:
    """(σ, m) of a Majumdar–Bhushan profile over the band of wavelengths [l_c, L_u].

    σ from the PSD integral (:func:`ballscrew.lubrication.composite_roughness`, the σ of the
    film parameter),
    m from :func:`rms_profile_slope`. The band is a convention and must be stated with the
    result: L_u is the sampling length of the roughness measurement (σ grows as L_u^(2−D)) and
    l_c its shortest resolved wavelength (m grows as l_c^(1−D)).
    """
    sigma = composite_roughness(D, G, sampling_length, cutoff_length, gamma)
    return sigma, rms_profile_slope(D, G, sampling_length, cutoff_length, gamma)


@dataclass(frozen=True)
class GaussianJoint:
    """Roughness and materials of a conforming rough joint for the correlations."""

    sigma: float
    """Combined RMS roughness σ = √(σ₁² + σ₂²), m."""
    slope: float
    """Combined RMS absolute profile slope m = √(m₁² + m₂²)."""
    lambda_s: float
    """Harmonic-mean solid conductivity 2λ₁λ₂/(λ₁ + λ₂), W/(m K)."""
    lambda_f: float
    """Conductivity of the interstitial medium, W/(m K)."""
    hardness: float
    """Microhardness H of the softer surface, Pa."""
    E_star: float
    """Composite modulus E* = [(1 − ν₁²)/E₁ + (1 − ν₂²)/E₂]⁻¹, Pa."""
    rarefaction: float = 0.0
    """Gas rarefaction parameter M of the medium (:func:`gas_rarefaction_parameter`), m; 0 for
    a liquid."""

    def __post_init__(self) -> None:
        for name, unit in (
            ("sigma", "m"),
            ("slope", ""),
            ("lambda_s", "W/(m K)"),
            ("lambda_f", "W/(m K)"),
            ("hardness", "Pa"),
            ("E_star", "Pa"),
        ):
            positive(name, getattr(self, name), unit)
        _rarefaction(self.rarefaction)


def plastic_conductance(pressure: ArrayLike, joint: GaussianJoint) -> NDArray[np.float64]:
    """Solid-spot conductance h_c = 1.25 λ_s (m/σ)(p/H)^0.95 (Cooper, Mikic & Yovanovich 1969).

    Plastically deformed Gaussian asperities; the correlation fits the CMY theory
    h σ/(λ_s m) = exp(−λ²/2)/(2√(2π)(1 − √(p/H))^1.5), p/H = ½ erfc(λ/√2), within 1.5 % for
    1e-5 ≤ p/H ≤ 2e-2 (Yovanovich 1982); beyond, it falls below the theory (−10 % at
    p/H = 0.1, −15 % at 0.15). Units W/(m² K).
    """
    p = nonnegative_array("pressure", pressure, "Pa")
    return 1.25 * joint.lambda_s * joint.slope / joint.sigma * (p / joint.hardness) ** 0.95


def mikic_elastic_conductance(pressure: ArrayLike, joint: GaussianJoint) -> NDArray[np.float64]:
    """Solid-spot conductance h_c = 1.54 λ_s (m/σ)(√2 p/(m E*))^0.94 (Mikic 1974).

    Elastically deformed Gaussian asperities (Mikic, Int. J. Heat Mass Transfer 17, 1974);
    the "elastic hardness" m E*/√2 replaces the plastic H. Units W/(m² K).
    """
    p = nonnegative_array("pressure", pressure, "Pa")
    relative = math.sqrt(2.0) * p / (joint.slope * joint.E_star)
    return 1.54 * joint.lambda_s * joint.slope / joint.sigma * relative**0.94


def plastic_separation(
    pressure: ArrayLike, *, sigma: float, hardness: float
) -> NDArray[np.float64]:
    """Mean-plane separation Y = σ √2 erfc⁻¹(2p/H) of plastically loaded Gaussian surfaces, m.

    From the CMY force balance p/H = ½ erfc(Y/(σ√2)) (Cooper, Mikic & Yovanovich 1969;
    Yovanovich 1982). Y = ∞ where p = 0 and 0 where p/H ≥ 0.5.

    Args:
        pressure: apparent pressure p (>= 0), Pa.
        sigma: combined RMS roughness σ, m.
        hardness: microhardness H of the softer surface, Pa.
    """
    s = positive("sigma", sigma, "m")
    h = positive("hardness", hardness, "Pa")
    p = nonnegative_array("pressure", pressure, "Pa")
    ratio = np.minimum(2.0 * p / h, 2.0 * _MAX_RELATIVE_PRESSURE)
    with np.errstate(divide="ignore"):
        return s * math.sqrt(2.0) * erfcinv(ratio)


def mean_plane_separation(pressure: ArrayLike, joint: GaussianJoint) -> NDArray[np.float64]:
    """:func:`plastic_separation` Y of the joint's σ and H, m."""
    return plastic_separation(pressure, sigma=joint.sigma, hardness=joint.hardness)


def gas_rarefaction_parameter(
    mean_free_path: float, accommodation: float, heat_capacity_ratio: float, prandtl: float
) -> float:
    """Rarefaction parameter M = α β Λ of a gas in the gap, m (Yovanovich 1982).

        α = 2 (2 − TAC)/TAC (two like surfaces),  β = 2γ/((γ + 1) Pr)

    Λ is the molecular mean free path at the gas temperature and pressure (air at 20 °C and
    1 atm: 0.064 µm), TAC the thermal accommodation coefficient, γ = c_p/c_v.
    """
    lam = positive("mean_free_path", mean_free_path, "m")
    if not 0.0 < accommodation <= 1.0:
        raise InputError("accommodation", accommodation, "0 < TAC ≤ 1")
    gamma = positive("heat_capacity_ratio", heat_capacity_ratio, "")
    pr = positive("prandtl", prandtl, "")
    alpha = 2.0 * (2.0 - accommodation) / accommodation
    return alpha * 2.0 * gamma / ((gamma + 1.0) * pr) * lam


def _rarefaction(value: float) -> float:
    """M as a float, refused unless finite and ≥ 0."""
    m = float(value)
    if not (math.isfinite(m) and m >= 0.0):
        raise InputError("rarefaction", value, "M ≥ 0 m")
    return m


def joint_gap_conductance(
    pressure: ArrayLike, joint: GaussianJoint, rarefaction: float | None = None
) -> NDArray[np.float64]:
    """Conductance h_g = λ_f/(Y + M) of the medium between the asperities, W/(m² K).

    Yovanovich's (1982) simple gap model across the mean-plane separation Y
    (:func:`mean_plane_separation`); M = 0 for a liquid (oil, grease), M from
    :func:`gas_rarefaction_parameter` for a gas; None takes the joint's ``rarefaction``.
    """
    m = _rarefaction(joint.rarefaction if rarefaction is None else rarefaction)
    with np.errstate(divide="ignore"):
        return joint.lambda_f / (mean_plane_separation(pressure, joint) + m)


Correlation = Callable[[NDArray[np.float64], GaussianJoint], NDArray[np.float64]]
CORRELATIONS: Registry[Correlation] = Registry("conductance correlation", "tcr.models")
"""Joint conductance h(p) per unit apparent area [W/(m² K)]: solid spots plus the gap (a liquid,
or a gas with the joint's rarefaction parameter M)."""


@CORRELATIONS.register("CMY", "Cooper–Mikic–Yovanovich plastic contacts + Yovanovich gap")
def _cmy(pressure: NDArray[np.float64], joint: GaussianJoint) -> NDArray[np.float64]:
    return plastic_conductance(pressure, joint) + joint_gap_conductance(pressure, joint)


@CORRELATIONS.register("Mikic", "Mikic elastic contacts + Yovanovich gap")
def _mikic(pressure: NDArray[np.float64], joint: GaussianJoint) -> NDArray[np.float64]:
    return mikic_elastic_conductance(pressure, joint) + joint_gap_conductance(pressure, joint)


def correlation_conductance(
    pressure: ArrayLike, dx: float, dy: float, joint: GaussianJoint, model: str
) -> float:
    """Conductance G = Σ h(p_ij) Δx Δy of a solved contact by the correlation ``model``, W/K.

    The quadrature of ∫ h(p) dA over the pressure field; it converges with the solver grid
    because h(p) is a smooth function of the local pressure (no fractal cell).
    """
    h = CORRELATIONS[model]
    p = nonnegative_array("pressure", pressure, "Pa")
    loaded = p > 0.0
    if not loaded.any():
        raise InputError("pressure", "all zero", "at least one cell with p > 0")
    area = positive("dx", dx, "m") * positive("dy", dy, "m")
    return float(np.sum(h(p[loaded], joint)) * area)
