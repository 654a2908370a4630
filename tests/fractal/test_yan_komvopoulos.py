"""3-D fractal micro-contact (Yan & Komvopoulos 1998) against worked examples ((E5.1)–(E5.16)).

E* = 1.1319e11 Pa, H = 7.0 GPa, γ = 1.5; Ds is the surface dimension (profile D + 1).
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from ballscrew.errors import InputError
from ballscrew.fractal import yan_komvopoulos as yk

E_STAR, H = 1.1319e11, 7.0e9
CELL = 100e-12  # ΔA = 100 µm²


@pytest.mark.parametrize(
    ("Ds", "G", "a_c", "delta_c"),
    [
        (2.3, 1e-10, 1.497e-13, 4.498e-8),
        (2.4, 1e-10, 2.265e-15, 5.534e-9),
        (2.5, 1e-10, 1.833e-16, None),
        (2.4, 1e-9, 2.265e-13, None),
    ],
)
def test_critical_area(Ds, G, a_c, delta_c):
    got = yk.critical_area(Ds, G, E_STAR, H)
    assert got == pytest.approx(a_c, rel=5e-4)
    if delta_c is not None:
        assert yk.asperity_interference(got, Ds, G) == pytest.approx(delta_c, rel=5e-4)


def test_t5_2_radius_and_elastic_coefficient():
    a_c = yk.critical_area(2.4, 1e-10, E_STAR, H)
    assert math.sqrt(a_c / math.pi) == pytest.approx(2.685e-8, rel=5e-4)
    assert yk.elastic_coefficient(2.4, 1e-10, E_STAR) == pytest.approx(8.244e6, rel=5e-4)


def test_t5_5_elastic_and_plastic_forces_meet_at_the_critical_area():
    a_c = yk.critical_area(2.4, 1e-10, E_STAR, H)
    assert yk.asperity_elastic_force(a_c, 2.4, 1e-10, E_STAR) / (H * a_c) == pytest.approx(
        1.0, rel=1e-12
    )
    assert float(yk.asperity_plastic_force(a_c, H)) == pytest.approx(H * a_c, rel=1e-15)


def test_hertz_force_of_the_cap_equals_the_closed_form():
    # f_e = (4/3) E* R^½ δ^(3/2) with R = r'²/(2δ) (E5.6) must equal C_e a'^((4−Ds)/2) (E5.7).
    a = np.array([1e-16, 1e-14, 1e-12])
    delta = yk.asperity_interference(a, 2.4, 1e-10)
    radius = yk.asperity_tip_radius(a, 2.4, 1e-10)
    hertz = 4.0 / 3.0 * E_STAR * np.sqrt(radius) * delta**1.5
    np.testing.assert_allclose(yk.asperity_elastic_force(a, 2.4, 1e-10, E_STAR), hertz, rtol=1e-12)


@pytest.mark.parametrize(
    ("a_l", "total", "f_e", "f_p"),
    [(1e-12, 9.239e-3, 6.611e-3, 2.628e-3), (1e-11, 6.512e-2, 5.195e-2, 1.317e-2)],
)
def test_forward_cell_forces(a_l, total, f_e, f_p):
    e, p = yk.cell_forces(a_l, 2.4, 1e-10, E_STAR, H)
    assert float(e) == pytest.approx(f_e, rel=5e-4)
    assert float(p) == pytest.approx(f_p, rel=5e-4)
    assert float(yk.total_force(a_l, 2.4, 1e-10, E_STAR, H)) == pytest.approx(total, rel=5e-4)


def test_forces_equal_the_integral_over_the_size_distribution():
    # E5.12 integrates f_e (a' > a_c) and f_p (a' ≤ a_c) over n(a') (E5.10): check numerically.
    Ds, G, a_l = 2.4, 1e-10, 1e-11
    a_c = yk.critical_area(Ds, G, E_STAR, H)
    u = np.linspace(np.log(a_c), np.log(a_l), 200_001)
    a = np.exp(u)
    integrand = yk.asperity_elastic_force(a, Ds, G, E_STAR) * yk.size_distribution(a, a_l, Ds) * a
    f_e = np.trapezoid(integrand, u)
    e, _ = yk.cell_forces(a_l, Ds, G, E_STAR, H)
    assert f_e == pytest.approx(float(e), rel=1e-6)


def test_t5_8_inversion_at_500_mpa():
    a_l = float(yk.largest_area_from_force(500e6 * CELL, CELL, 2.4, 1e-10, E_STAR, H))
    assert a_l == pytest.approx(7.306e-12, rel=5e-4)
    assert float(yk.truncated_area(a_l, 2.4)) / CELL == pytest.approx(0.1705, rel=5e-4)
    assert float(yk.real_contact_area(a_l, 2.4, 1e-10, E_STAR, H)) / CELL == pytest.approx(
        0.0928, rel=5e-4
    )
    f_e, f_p = yk.cell_forces(a_l, 2.4, 1e-10, E_STAR, H)
    assert float(f_e) == pytest.approx(3.943e-2, rel=5e-4)
    assert float(f_p) == pytest.approx(1.057e-2, rel=5e-4)
    assert float(f_p / (f_e + f_p)) == pytest.approx(0.211, abs=5e-4)
    assert float(yk.asperity_interference(a_l, 2.4, 1e-10)) == pytest.approx(6.246e-8, rel=5e-4)


def test_t5_9_inversion_is_vectorised_over_cells():
    forces = np.array([100e6, 1000e6]) * CELL
    a_l = yk.largest_area_from_force(forces, CELL, 2.4, 1e-10, E_STAR, H)
    np.testing.assert_allclose(a_l, [1.097e-12, 1.667e-11], rtol=5e-4)
    f_e, f_p = yk.cell_forces(a_l, 2.4, 1e-10, E_STAR, H)
    np.testing.assert_allclose(f_p / (f_e + f_p), [0.280, 0.188], atol=5e-4)
    np.testing.assert_allclose(yk.total_force(a_l, 2.4, 1e-10, E_STAR, H), forces, rtol=1e-10)


def test_t5_10_fully_plastic_limit():
    a_c = yk.critical_area(2.4, 1e-8, E_STAR, H)
    assert a_c == pytest.approx(2.265e-11, rel=5e-4)
    a_l = float(yk.largest_area_from_force(500e6 * CELL, CELL, 2.4, 1e-8, E_STAR, H))
    assert a_l == pytest.approx(3.061e-12, rel=5e-4)
    f_e, f_p = yk.cell_forces(a_l, 2.4, 1e-8, E_STAR, H)
    assert float(f_e) == 0.0
    assert float(f_p) == pytest.approx(500e6 * CELL, rel=1e-10)  # F = H A'


def test_t5_11_logarithmic_branch_and_its_continuity():
    e, p = yk.cell_forces(1e-11, 2.5, 1e-10, E_STAR, H)
    assert float(e) == pytest.approx(3.747e-2, rel=5e-4)
    assert float(p) == pytest.approx(1.374e-2, rel=5e-4)
    assert float(e + p) == pytest.approx(5.121e-2, rel=5e-4)
    near = [float(yk.total_force(1e-11, 2.5 + d, 1e-10, E_STAR, H)) for d in (-1e-7, 1e-7)]
    assert near == pytest.approx([float(e + p)] * 2, rel=1e-5)


def test_t5_12_rms_height_closed_form_and_sampled():
    sigma = yk.rms_height(2.4, 1e-10, 10e-6)
    assert sigma == pytest.approx(7.254e-8, rel=5e-4)
    # 8 realisations of E5.1 with M = 10, n = 0..17 (reference: 7.42e-8 ± 0.77e-8).
    x = np.linspace(0.0, 10e-6, 96)
    xx, yy = np.meshgrid(x, x, indexing="ij")
    samples = [
        np.std(yk.weierstrass_mandelbrot_surface(xx, yy, 2.4, 1e-10, 10e-6, rng=seed))
        for seed in range(8)
    ]
    assert np.mean(samples) == pytest.approx(sigma, rel=0.25)


def test_t5_13_structure_function():
    assert yk.structure_function_constant(1.4, 1e-10) == pytest.approx(3.697e-8, rel=5e-4)
    assert float(yk.structure_function(1e-6, 1.4, 1e-10)) == pytest.approx(2.333e-15, rel=5e-4)


def test_saturated_cells_are_clamped_with_a_warning():
    limit = yk.max_largest_area(CELL, 2.4)
    with pytest.warns(yk.SaturatedCellWarning):
        a_l = yk.largest_area_from_force([1e-2, 1e3], CELL, 2.4, 1e-10, E_STAR, H)
    assert a_l[1] == limit and a_l[0] < limit
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert float(yk.largest_area_from_force(0.0, CELL, 2.4, 1e-10, E_STAR, H)) == 0.0


def test_dimension_conversion_and_bad_input():
    assert yk.surface_dimension(1.4) == pytest.approx(2.4)
    with pytest.raises(InputError, match="Ds"):
        yk.critical_area(1.4, 1e-10, E_STAR, H)  # a profile D passed by mistake
    with pytest.raises(InputError, match="D"):
        yk.surface_dimension(2.4)
    with pytest.raises(InputError, match="G"):
        yk.rms_height(2.4, -1.0, 1e-5)
