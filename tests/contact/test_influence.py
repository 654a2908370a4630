"""Love's rectangular-cell coefficients (K4) against a six-digit reference table, the closed-form
self-coefficient, the Boussinesq far field (K2) and a numerical quadrature of (K2) over the cell."""

import numpy as np
import pytest
from scipy.integrate import dblquad

from ballscrew.contact import love_coefficient, love_coefficients

E_STAR = 113.19e9


def test_square_cell_table_matches_t_k1():
    """K·E*/Δ of a square cell at the listed offsets, 6 digits."""
    delta = 10e-6
    table = love_coefficients(11, 11, delta, delta, E_STAR) * E_STAR / delta
    expected = {(0, 0): 1.122200, (1, 0): 0.330421, (1, 1): 0.230678, (2, 0): 0.160776,
                (5, 0): 0.063768, (10, 0): 0.031844}  # fmt: skip
    for (i, j), value in expected.items():
        assert table[i, j] == pytest.approx(value, abs=6e-7), (i, j)
        assert table[j, i] == pytest.approx(value, abs=6e-7), "K must be symmetric in x and y"


def test_self_coefficient_closed_form():
    """K(0, 0) of a square cell = 4 ln(1 + √2)/π · Δ/E* (K4)."""
    delta = 3.7e-6
    k00 = love_coefficient(0.0, 0.0, delta, delta, E_STAR)
    assert k00 == pytest.approx(4.0 * np.log(1.0 + np.sqrt(2.0)) / np.pi * delta / E_STAR, 1e-14)


@pytest.mark.parametrize("r_cells", [20, 50, 200])
def test_far_field_tends_to_point_load(r_cells):
    """Far away the cell acts as a point force p·dx·dy: K → dx·dy/(π E* r) (K2), error O((Δ/r)²)."""
    dx, dy = 4e-6, 9e-6
    x = y = r_cells * dy / np.sqrt(2.0)
    point = dx * dy / (np.pi * E_STAR * np.hypot(x, y))
    assert float(love_coefficient(x, y, dx, dy, E_STAR)) == pytest.approx(
        point, rel=0.2 / r_cells**2
    )


@pytest.mark.parametrize(("x", "y"), [(1.0, 0.0), (2.0, 3.0), (0.0, -4.0), (-7.0, 5.0)])
def test_rectangular_cell_against_quadrature_of_boussinesq(x, y):
    """(K4) equals ∬ dξ dη / (π E* √((x−ξ)² + (y−η)²)) over the cell, by adaptive quadrature."""
    dx, dy = 1.0, 2.5  # offsets in cell units
    x, y = x * dx, y * dy

    def integrand(eta, xi):
        return 1.0 / (np.pi * E_STAR * np.hypot(x - xi, y - eta))

    reference, _ = dblquad(integrand, -dx / 2, dx / 2, -dy / 2, dy / 2, epsabs=0, epsrel=1e-12)
    assert float(love_coefficient(x, y, dx, dy, E_STAR)) == pytest.approx(reference, rel=1e-10)


def test_table_is_the_pointwise_formula_on_the_grid():
    """The corner-lattice table equals (K4) evaluated cell by cell on a rectangular grid."""
    dx, dy = 6.1e-6, 9.9e-6
    table = love_coefficients(9, 14, dx, dy, E_STAR)
    x, y = dx * np.arange(9)[:, None], dy * np.arange(14)[None, :]
    np.testing.assert_allclose(table, love_coefficient(x, y, dx, dy, E_STAR), rtol=1e-13)
