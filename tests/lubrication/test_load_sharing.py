"""JGP load sharing between the EHL film and fractal asperities (load sharing, (E6.1)–(E6.5))."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew.contact import hertz, solve_normal
from ballscrew.errors import InputError
from ballscrew.geometry import ScrewGeometry, gap_function
from ballscrew.lubrication import (
    AsperitySurface,
    asperity_pressure,
    load_sharing_residual,
    share_load,
)

from .test_film import ALPHA, ETA, RX, RY, U_E

E_STAR, H = 1.1319e11, 7.0e9
SURFACE = AsperitySurface(Ds=2.4, G=1e-10, e_star=E_STAR, hardness=H, cell_area=100e-12)


def hertz_area(load: float) -> float:
    c = hertz(RX, RY, E_STAR, load)
    return math.pi * c.a * c.b


def test_sigma_of_the_cell():
    assert SURFACE.rms_height == pytest.approx(7.254e-8, rel=5e-4)


@pytest.mark.parametrize(
    ("load", "psi", "h", "f_asp", "f_film"),
    [
        (39.41, 0.767, 58.76e-9, 30.21, 9.19),
        (68.69, 0.672, 55.34e-9, 46.18, 22.51),
        (105.79, 0.603, 53.07e-9, 63.77, 42.02),
    ],
)
def test_ref_sharing(load, psi, h, f_asp, f_film):
    r = share_load(load, RX, RY, ETA, ALPHA, U_E, hertz_area(load), SURFACE)
    assert r.psi == pytest.approx(psi, abs=5e-4)
    assert r.separation == pytest.approx(h, rel=5e-4)
    assert r.asperity_force == pytest.approx(f_asp, rel=5e-4)
    assert r.film_force == pytest.approx(f_film, rel=1e-3)
    # E6.2: the film is as thick as the film-borne load alone makes it
    assert r.film.central == r.separation
    assert r.asperity_force + r.film_force == pytest.approx(load, rel=1e-14)


def test_t6_7_pipeline_grid():
    # 32 × 128 cells over ±1.4 b_max × ±1.4 a_max (Hertz, 105.79 N), exact gap, A_n = loaded cells
    g = ScrewGeometry(0.040, 0.010, 6.35e-3, 0.55, 0.55, math.pi / 4)
    big = hertz(RX, RY, E_STAR, 105.79)
    nx, ny = 32, 128
    dx, dy = 2.8 * big.a / nx, 2.8 * big.b / ny
    x = (np.arange(nx) - (nx - 1) / 2) * dx
    y = (np.arange(ny) - (ny - 1) / 2) * dy
    gap = gap_function(g, "screw", 1, "exact")(x[:, None], y[None, :])
    surface = AsperitySurface(2.4, 1e-10, E_STAR, H, dx * dy)
    assert dx * dy == pytest.approx(59.91e-12, rel=5e-4)
    for load, psi in ((68.69, 0.643), (16.15, 0.863)):
        sol = solve_normal(gap, dx, dy, E_STAR, load, 1e-8)
        area = float((sol.pressure > 0).sum()) * dx * dy
        r = share_load(load, RX, RY, ETA, ALPHA, U_E, area, surface)
        assert r.psi == pytest.approx(psi, rel=6e-3)  # grid details differ slightly


def test_residual_is_monotone_with_the_right_end_values():
    load = 39.41
    psi = np.concatenate([np.linspace(0.0, 0.999, 200), 1.0 - np.logspace(-4, -15, 40)])
    r = load_sharing_residual(psi, load, RX, RY, ETA, ALPHA, U_E, hertz_area(load), SURFACE)
    assert r[0] > 0.0
    assert r[-1] == pytest.approx(-load, rel=1e-6)  # r → −Q as ψ → 1 (film ≫ σ)
    assert np.all(np.diff(r) < 0.0)


def test_residual_is_still_positive_at_the_documents_bracket_end_on_rough_surfaces():
    # A bracket of ψ on [0, 1 − 1e-12] claiming r(1⁻) = −Q < 0. h_c only
    # grows as W^−0.067, so at 1 − 1e-12 the film is 6.4× thicker, not infinite: on a rough
    # surface (σ = 0.46 µm ≫ h_c) the residual there is still +42 N and that bracket fails.
    rough = AsperitySurface(2.4, 1e-8, E_STAR, H, 100e-12)
    area = hertz_area(39.41)
    end = load_sharing_residual(1.0 - 1e-12, 39.41, RX, RY, ETA, ALPHA, U_E, area, rough)
    assert end > 0.0
    r = share_load(39.41, RX, RY, ETA, ALPHA, U_E, area, rough)
    assert 1.0 - 1e-12 < r.psi <= 1.0


def test_rough_surfaces_are_dry_and_smooth_ones_are_film_borne():
    area = hertz_area(39.41)
    psis = []
    for G in (1e-13, 1e-12, 1e-11, 1e-10, 1e-9, 1e-8):
        s = AsperitySurface(2.4, G, E_STAR, H, 100e-12)
        psis.append(share_load(39.41, RX, RY, ETA, ALPHA, U_E, area, s).psi)
    assert np.all(np.diff(psis) > 0.0)
    assert psis[0] < 1e-6  # smooth: σ ≪ h_c, the film carries the load
    assert psis[-1] > 0.99  # rough: σ ≫ h_c, asperity contact


def test_faster_means_more_film():
    area = hertz_area(39.41)
    psis = [share_load(39.41, RX, RY, ETA, ALPHA, u, area, SURFACE).psi for u in (0.01, 0.1, 1.0)]
    assert psis[0] > psis[1] > psis[2]


def test_no_entrainment_is_a_dry_contact():
    r = share_load(39.41, RX, RY, ETA, ALPHA, 0.0, hertz_area(39.41), SURFACE)
    assert r.psi == 1.0 and r.separation == 0.0 and r.film is None


def test_asperity_pressure_field():
    p = np.array([[0.0, 1e9], [5e8, 2e9]])
    np.testing.assert_array_equal(asperity_pressure(p, 0.25), 0.25 * p)
    with pytest.raises(InputError, match="psi"):
        asperity_pressure(p, 1.5)


def test_bad_input():
    with pytest.raises(InputError, match="viscosity"):
        share_load(39.41, RX, RY, 0.0, ALPHA, U_E, hertz_area(39.41), SURFACE)
    with pytest.raises(InputError, match="load"):
        share_load(-1.0, RX, RY, ETA, ALPHA, U_E, 1e-8, SURFACE)
