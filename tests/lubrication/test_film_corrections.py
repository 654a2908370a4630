"""Inlet-heating, starvation and replenishment corrections of the Hamrock–Dowson film (REF
contact A)."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

from ballscrew.contact.hertz import hamrock_brewe
from ballscrew.errors import InputError
from ballscrew.lubrication.film import FILM_MODELS, hamrock_dowson
from ballscrew.lubrication.film_corrections import (
    REPLENISHMENT_GREASE,
    REPLENISHMENT_OIL,
    critical_inlet_ratio,
    dowson_higginson_density,
    equivalent_inlet_ratio,
    layer_starvation_factor,
    replenishment_factor,
    starvation_factor,
    thermal_loading,
    thermal_reduction_gupta,
    thermal_reduction_murch_wilson,
)
from ballscrew.lubrication.supply import supplied_film_model

LAM = math.atan(0.010 / (math.pi * 0.040))
RX = 1.0 / (2 / 6.35e-3 + 2 * math.cos(math.pi / 4) * math.cos(LAM) / (0.040 - 6.35e-3 / 2**0.5))
RY = 1.0 / (2 / 6.35e-3 - 1 / (0.55 * 6.35e-3))
E_PRIME = 2.2637e11
ARGS = (RX, RY, E_PRIME, 0.06, 2.1e-8, 0.09333, 39.41)


def thermal_film_model(beta, conductivity):
    return supplied_film_model("hamrock_dowson", thermal=(beta, conductivity))


def starved_film_model(m):
    return supplied_film_model("hamrock_dowson", inlet_ratio=m)


def test_corrections_are_case_options_not_rival_film_models():
    # the case applies them through [lubrication] supply / thermal, on any film model
    assert "hamrock_dowson_thermal" not in FILM_MODELS
    assert "hamrock_dowson_starved" not in FILM_MODELS


def test_thermal_loading_is_beta_eta_u2_over_lambda():
    assert thermal_loading(0.05, 0.06, 10.0, 0.13) == pytest.approx(0.05 * 0.06 * 100 / 0.13)


def test_murch_wilson_factor():
    assert thermal_reduction_murch_wilson(0.0) == 1.0
    assert thermal_reduction_murch_wilson(1.0) == pytest.approx(3.94 / 4.94)
    big = 1e6
    assert thermal_reduction_murch_wilson(big) == pytest.approx(3.94 * big**-0.62, rel=1e-3)


def test_gupta_factor_limits_and_trends():
    assert thermal_reduction_gupta(0.0, 0.005, 0.3) == 1.0
    assert thermal_reduction_gupta(2.0, 0.0) == pytest.approx(1 / (1 + 0.213 * 2.0**0.64))
    loads = [0.1, 1.0, 10.0, 100.0]
    phis = [thermal_reduction_gupta(x, 0.005) for x in loads]
    assert all(a > b for a, b in itertools.pairwise(phis))
    assert thermal_reduction_gupta(10.0, 0.005, 0.5) < thermal_reduction_gupta(10.0, 0.005, 0.0)
    with pytest.raises(InputError, match=r"^thermal_loading = .*Gupta"):
        thermal_reduction_gupta(1e6, 0.01)


def test_no_inlet_heating_gives_the_isothermal_film():
    flooded = hamrock_dowson(*ARGS)
    assert thermal_film_model(0.0, 0.13)(*ARGS) == flooded


def test_thermal_film_at_speed():
    fast = (*ARGS[:5], 10.0, ARGS[6])
    film = thermal_film_model(0.05, 0.13)(*fast)
    p_h = hamrock_brewe(RX, RY, E_PRIME / 2, ARGS[6]).p0
    phi = thermal_reduction_gupta(thermal_loading(0.05, 0.06, 10.0, 0.13), p_h / E_PRIME)
    assert film.central == pytest.approx(hamrock_dowson(*fast).central * phi)
    assert 0.5 < phi < 0.8


def test_critical_inlet_distance_of_contact_a():
    film = hamrock_dowson(*ARGS)
    b = hamrock_brewe(RX, RY, E_PRIME / 2, ARGS[6]).a
    group = RX * film.central / b**2
    assert critical_inlet_ratio(RX, b, film.central) == pytest.approx(1 + 3.06 * group**0.58)
    assert 1.2 < critical_inlet_ratio(RX, b, film.central) < 2.0


def test_fully_flooded_inlet_leaves_the_film_unchanged():
    flooded = hamrock_dowson(*ARGS)
    assert supplied_film_model("hamrock_dowson") == "hamrock_dowson"
    assert starved_film_model(5.0)(*ARGS) == flooded


def test_starvation_reduces_the_film_towards_zero_at_the_hertz_edge():
    flooded = hamrock_dowson(*ARGS)
    b = hamrock_brewe(RX, RY, E_PRIME / 2, ARGS[6]).a
    m_star = critical_inlet_ratio(RX, b, flooded.central)
    half = starved_film_model(1 + (m_star - 1) / 2)(*ARGS)
    assert half.central / flooded.central == pytest.approx(0.5**0.29)
    ratios = [starved_film_model(m)(*ARGS).central for m in (1.3, 1.1, 1.01, 1.0001)]
    assert all(a > b for a, b in itertools.pairwise(ratios))
    assert starved_film_model(1.0)(*ARGS).central == 0.0
    assert starvation_factor(1.0 + 1e-12, 1.5) < 1e-3


@pytest.mark.parametrize("m", [0.9, float("nan")])
def test_meniscus_inside_the_hertz_zone_is_refused(m):
    with pytest.raises(InputError, match=r"^lubrication.inlet_ratio = "):
        starved_film_model(m)
    with pytest.raises(InputError, match=r"^inlet_ratio = "):
        starvation_factor(m, 1.5)


RPM = math.pi / 30.0  # rad/s per r/min


def test_replenishment_factor_is_the_skf_formula_in_catalogue_units():
    # 6205 deep-groove bearing, d = 25 mm, D = 52 mm, grease of ν = 100 mm²/s base oil at
    # 3000 r/min, K_Z = 3.1: φ_rs = exp[−6e-8 · 100 · 3000 · 77 · √(3.1/54)] (SKF 2013)
    expected = math.exp(-6e-8 * 100 * 3000 * 77 * math.sqrt(3.1 / 54))
    phi = replenishment_factor(100e-6, 3000 * RPM, 38.5e-3, 27e-3, REPLENISHMENT_GREASE, 3.1)
    assert phi == pytest.approx(expected, rel=1e-12)
    assert phi == pytest.approx(0.7174, abs=1e-4)


def test_replenishment_is_flooded_at_rest_and_thins_with_speed_and_viscosity():
    def phi(nu, rpm):
        return replenishment_factor(nu, rpm * RPM, 0.020, 0.021)

    assert phi(68e-6, 0.0) == 1.0 and phi(0.0, 3000.0) == 1.0
    speeds = [phi(68e-6, n) for n in (1.0, 100.0, 1000.0, 3000.0, 1e6)]
    assert speeds[0] == pytest.approx(1.0, abs=1e-4)
    assert all(b < a for a, b in itertools.pairwise(speeds)) and speeds[-1] < 1e-3
    viscosities = [phi(nu, 1000.0) for nu in (1e-6, 10e-6, 100e-6, 1000e-6)]
    assert all(b < a for a, b in itertools.pairwise(viscosities))
    # K_rs enters the exponent linearly: oil bath (3e-8) is the square root of grease (6e-8)
    oil = replenishment_factor(68e-6, 3000 * RPM, 0.020, 0.021, REPLENISHMENT_OIL)
    assert oil == pytest.approx(math.sqrt(phi(68e-6, 3000.0)), rel=1e-12)


@pytest.mark.parametrize(
    ("args", "field"),
    [
        ((68e-6, -1.0, 0.02, 0.02), "speed"),
        ((-1e-6, 1.0, 0.02, 0.02), "kinematic_viscosity"),
        ((68e-6, 1.0, 0.0, 0.02), "mean_diameter"),
        ((68e-6, 1.0, 0.02, 0.0), "section"),
    ],
)
def test_bad_replenishment_input_is_refused(args, field):
    with pytest.raises(InputError, match=rf"^{field} = "):
        replenishment_factor(*args)


@pytest.mark.parametrize("central", [True, False])
def test_equivalent_inlet_ratio_inverts_the_starvation_law(central):
    m_star = 1.8
    for phi in (0.05, 0.3, 0.9, 1.0):
        m = equivalent_inlet_ratio(phi, m_star, central)
        assert 1.0 < m <= m_star
        assert starvation_factor(m, m_star, central) == pytest.approx(phi, rel=1e-9)
    assert equivalent_inlet_ratio(1.0, m_star, central) == m_star
    with pytest.raises(InputError, match=r"^starvation_factor = "):
        equivalent_inlet_ratio(1.2, m_star, central)


# thin-layer starvation: Chevalier et al. (1998), Damiens et al. (2004)


def test_dowson_higginson_density_closed_form_and_limits():
    assert dowson_higginson_density(0.0) == 1.0
    assert dowson_higginson_density(1e9) == pytest.approx(1.0 + 0.6 / 2.7, rel=1e-12)  # 1.222
    assert dowson_higginson_density(1e18) == pytest.approx(1.0 + 0.6 / 1.7, rel=1e-8)
    with pytest.raises(InputError, match="pressure"):
        dowson_higginson_density(-1.0)


@pytest.mark.parametrize("gamma", [1.0, 2.0, 3.0, 15.0])
def test_layer_starvation_at_r_equal_one_is_the_closed_form(gamma):
    # r = h_oil/(ρ̄ h_ff) = 1: h_c/h_ff = 1/2^(1/γ)
    rho, h_ff = 1.25, 200e-9
    phi = layer_starvation_factor(rho * h_ff, h_ff, rho, gamma)
    assert phi == pytest.approx(2.0 ** (-1.0 / gamma), rel=1e-13)


def test_layer_starvation_limits_flooded_and_mass_conservation():
    rho, h_ff = 1.2, 150e-9
    # a thick layer gives the fully flooded film, also far beyond float overflow of r^γ
    r = 1e-3 / (rho * h_ff)
    assert layer_starvation_factor(1e-3, h_ff, rho) == pytest.approx(1.0 - r**-3 / 3, abs=1e-15)
    assert layer_starvation_factor(1e300, 1e-300, 1.0) == 1.0
    # a thin layer: all the oil passes, h_c → h_oil/ρ̄ (to O(r^(γ+1)))
    for h_oil in (1e-9, 1e-10, 1e-12):
        h_c = h_ff * layer_starvation_factor(h_oil, h_ff, rho)
        assert h_c == pytest.approx(h_oil / rho, rel=1e-6)
        assert h_c <= h_oil / rho * (1.0 + 1e-14)  # never more film than oil
    assert layer_starvation_factor(1e-300, 1.0, 1.0) == pytest.approx(1e-300, rel=1e-12)
    assert layer_starvation_factor(0.0, h_ff, rho) == 0.0
    assert layer_starvation_factor(1e-7, 0.0, rho) == 1.0  # no film to starve


def test_layer_starvation_is_monotone_and_sharpens_to_min_r_1_as_gamma_grows():
    rho, h_ff = 1.2, 150e-9
    layers = np.geomspace(1e-10, 1e-4, 200)
    phi = np.array([layer_starvation_factor(h, h_ff, rho) for h in layers])
    assert np.all(np.diff(phi) > 0.0) and np.all((phi > 0.0) & (phi < 1.0))
    r = layers / (rho * h_ff)
    assert np.all(phi < np.minimum(r, 1.0))  # below both bounds: the oil and the flooded film
    sharp = np.array([layer_starvation_factor(h, h_ff, rho, 1e4) for h in layers])
    np.testing.assert_allclose(sharp, np.minimum(r, 1.0), rtol=1e-3)


@pytest.mark.parametrize(
    ("args", "field"),
    [
        ((-1e-9, 1e-7, 1.2), "inlet_layer"),
        ((float("nan"), 1e-7, 1.2), "inlet_layer"),
        ((1e-7, -1e-7, 1.2), "film"),
        ((1e-7, 1e-7, 0.0), "density_ratio"),
        ((1e-7, 1e-7, 1.2, 0.0), "starvation_exponent"),
    ],
)
def test_layer_starvation_bad_input_is_a_one_line_error(args, field):
    with pytest.raises(InputError) as err:
        layer_starvation_factor(*args)
    assert str(err.value).startswith(field) and "\n" not in str(err.value)
