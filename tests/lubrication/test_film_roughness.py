"""One RMS roughness σ_Λ of the raceway for the film parameter Λ = h/σ_Λ and the TCR film path."""

from __future__ import annotations

import dataclasses
import math

import pytest
from scipy.integrate import quad

import ballscrew
from ballscrew.analyses.kinematics import ball_model
from ballscrew.analyses.parameters import ScrewParameters
from ballscrew.analyses.tcr_models import gaussian_joint
from ballscrew.fractal import yan_komvopoulos as yk
from ballscrew.fractal.conventions import (
    profile_roughness_from_surface,
    surface_roughness_from_profile,
)
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
    """The band's σ_Λ is the one of the profile with this 3-D surface's RMS height: the surface
    G = 1.87 × 9e-10 m of the profile G = 9e-10 m gives that profile's 302 nm."""
    g = surface_roughness_from_profile(1.59, 9e-10)
    base = {"Ds": 2.59, "G": g, "e_star": 1e11, "hardness": 6e9, "cell_area": 1e-10}
    cell = AsperitySurface(**base)
    banded = AsperitySurface(**base, roughness=(8e-4, 2.5e-6))
    measured = AsperitySurface(**base, roughness=0.2e-6)
    assert cell.film_roughness == cell.rms_height
    assert banded.film_roughness == pytest.approx(302.0e-9, rel=2e-3)
    assert banded.film_roughness == pytest.approx(
        composite_roughness(1.59, 9e-10, 8e-4, 2.5e-6), rel=1e-12
    )
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


def test_the_share_reads_the_asperity_heights_of_the_film_parameter():
    """The JGP share of the ball model sees the asperities at h through the Gaussian bearing
    ratio of σ_Λ (E5.15): at h = t σ_Λ the cell's largest contact is a_l = (3 − Ds)/(Ds − 1)
    · ½ erfc(t/√2) ΔA whatever the cell's own σ (E5.3), which the wear model keeps."""
    base = {"Ds": 2.59, "G": 9e-10, "e_star": 1.13e11, "hardness": 6.5e9, "cell_area": 1e-10}
    cell = AsperitySurface(**base, roughness=(8e-4, 2.5e-6))
    film = cell.film_heights
    sigma = composite_roughness(1.59, profile_roughness_from_surface(1.59, 9e-10), 8e-4, 2.5e-6)
    assert film.rms_height == pytest.approx(sigma, rel=1e-12) == film.film_roughness
    assert cell.rms_height == pytest.approx(34e-9, rel=0.05)  # one 10 µm cell, (E5.3)
    for t in (0.5, 1.0, 2.0):
        a_l = 0.41 / 1.59 * 0.5 * math.erfc(t / math.sqrt(2)) * 1e-10
        force = yk.total_force(a_l, 2.59, 9e-10, 1.13e11, 6.5e9)
        assert film.pressure(t * sigma) == pytest.approx(force / 1e-10, rel=1e-12)


@pytest.fixture(scope="module")
def wear_model():
    """The ball model of the wear reference screw at 100 rpm and its ball load at 1500 N."""
    case = ballscrew.load_case("examples/wear_step_stress.toml")
    model = ball_model(case)
    g = model.geometry
    load = 1500.0 / (model.balls * math.sin(g.contact_angle) * math.cos(g.lead_angle))
    return model, load


@pytest.mark.parametrize("sigma", [30e-9, 50e-9, 100e-9, 300e-9])
def test_the_share_follows_the_regimes_of_the_film_parameter(wear_model, sigma):
    """ψ and Λ read one σ: the asperities carry most of the load in boundary lubrication
    (Λ < 1) and almost none in full film (Λ > 3) (Hamrock 1994's regimes), and ψ falls as the
    film thickens."""
    model, load = wear_model
    model = dataclasses.replace(model, surface=dataclasses.replace(model.surface, roughness=sigma))
    shares = []
    for u_e in (0.01, 0.1, 1.0, 10.0):
        lam = model.film(load, u_e).central / sigma
        psi = model.sharing(load, u_e).psi
        shares.append(psi)
        if lam < 1.0:
            assert psi > 0.5, (lam, psi)
        if lam > 3.0:
            assert psi < 0.01, (lam, psi)
    assert shares == sorted(shares, reverse=True)


def test_a_rough_ball_raises_the_asperity_share():
    """The ball's σ over the band adds in quadrature to σ_Λ (Tallian 1967), so a rough ball
    carries more of the load on asperities at the same film."""
    smooth = ballscrew.load_case("examples/gao2019_tcr.toml")
    twin = {"surface.ball": {"D": smooth.surface.D, "G": smooth.surface.G}}
    rough = ballscrew.load_case("examples/gao2019_tcr.toml", twin)
    shares = [ball_model(c).sharing(50.0, 5.0).psi for c in (smooth, rough)]
    assert 0.0 < shares[0] < shares[1]
