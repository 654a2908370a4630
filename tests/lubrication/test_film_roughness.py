"""One RMS roughness σ_Λ of the raceway for the film parameter Λ = h/σ_Λ and the TCR film path."""

from __future__ import annotations

import math

import pytest
from scipy.integrate import quad

import ballscrew
from ballscrew.analyses.kinematics import ball_model
from ballscrew.analyses.parameters import ScrewParameters
from ballscrew.analyses.tcr_models import gaussian_joint
from ballscrew.lubrication import AsperitySurface, composite_roughness


def test_composite_roughness_is_the_psd_integral_over_the_band():
    """σ² = ∫ S(ω) dω over [1/L_u, 1/l_c] of the W-M profile's PSD S(ω) = G^(2(D−1))
    ω^(−(5−2D))/(2 ln γ) (Majumdar & Bhushan 1990), integrated numerically over ln ω."""
    d, g, lu, lc, gamma = 1.59, 9e-10, 8e-4, 2.5e-6, 1.5

    def psd(w: float) -> float:
        return g ** (2 * (d - 1)) * w ** (-(5 - 2 * d)) / (2 * math.log(gamma))

    variance, _ = quad(lambda t: psd(math.exp(t)) * math.exp(t), -math.log(lu), -math.log(lc))
    assert composite_roughness(d, g, lu, lc, gamma) == pytest.approx(math.sqrt(variance), rel=1e-6)
    assert composite_roughness(d, g, lu, lc) == pytest.approx(302.0e-9, rel=2e-3)


def test_composite_roughness_grows_as_the_sampling_length_to_2_minus_d():
    d, g = 1.4, 1e-9
    ratio = composite_roughness(d, g, 2e-3, 1e-9) / composite_roughness(d, g, 1e-3, 1e-9)
    assert ratio == pytest.approx(2 ** (2 - d), rel=1e-6)


def test_the_surface_takes_a_band_a_measured_sigma_or_its_cell_sigma():
    base = {"Ds": 2.59, "G": 9e-10, "e_star": 1e11, "hardness": 6e9, "cell_area": 1e-10}
    cell = AsperitySurface(**base)
    banded = AsperitySurface(**base, roughness=(8e-4, 2.5e-6))
    measured = AsperitySurface(**base, roughness=0.2e-6)
    assert cell.film_roughness == cell.rms_height
    assert banded.film_roughness == pytest.approx(composite_roughness(1.59, 9e-10, 8e-4, 2.5e-6))
    assert measured.film_roughness == 0.2e-6
    assert banded.rms_height == cell.rms_height  # the asperity model keeps its cell σ


@pytest.mark.parametrize("measured", [None, 0.25e-6])
def test_ball_model_and_tcr_film_path_share_one_sigma(measured):
    """The friction model's Λ and the TCR correlations read the same σ of one raceway (before,
    34 nm over one fractal cell against 302 nm over the measurement band)."""
    overrides = {} if measured is None else {"tcr.rms_roughness": measured, "tcr.rms_slope": 0.05}
    case = ballscrew.load_case("examples/gao2019_tcr.toml", overrides)
    tcr = gaussian_joint(ScrewParameters.from_case(case), case.tcr, "screw").sigma
    assert ball_model(case).surface.film_roughness == pytest.approx(tcr, rel=1e-12)


def test_a_rough_ball_adds_its_sigma_in_quadrature():
    """σ_Λ = √(σ_raceway² + σ_ball²) over the same band (Tallian 1967): a ball as rough as the
    raceway gives √2 × the smooth-ball value, a ball of another (D, G) its own band σ."""
    smooth = ballscrew.load_case("examples/gao2019_tcr.toml")
    sigma = ball_model(smooth).surface.film_roughness
    twin = {"surface.ball": {"D": smooth.surface.D, "G": smooth.surface.G}}
    rough = ballscrew.load_case("examples/gao2019_tcr.toml", twin)
    assert ball_model(rough).surface.film_roughness == pytest.approx(math.sqrt(2) * sigma)
    ball = {"D": 1.5, "G": 1e-10}
    other = ballscrew.load_case("examples/gao2019_tcr.toml", {"surface.ball": ball})
    band = (smooth.tcr.sampling_length, smooth.tcr.cutoff_length)
    expected = math.hypot(sigma, composite_roughness(1.5, 1e-10, *band))
    assert ball_model(other).surface.film_roughness == pytest.approx(expected, rel=1e-12)
