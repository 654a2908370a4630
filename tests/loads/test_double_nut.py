"""Double-nut preload (P1)–(P3), stiffness (P4) and wear (E1.7)–(E1.13).

Against the load-split table of the preloaded double nut and worked examples of the TCR and the
wear reference screws.
"""

import math

import numpy as np
import pytest

from ballscrew.errors import InputError
from ballscrew.loads import (
    axial_deflection_from_approaches,
    nut_axial_compliance,
    nut_axial_deflection,
    nut_forces,
    preload_after_wear,
    preloaded_axial_stiffness,
)

BETA = math.radians(45.0)
ALPHA = math.atan(10e-3 / (math.pi * 40e-3))
LIFT_OFF = 2**1.5  # F_a/F_p at lift-off (P2)


@pytest.mark.parametrize(
    ("ratio", "f1", "f2"),
    [
        (0.5, 1.26046, 0.76046),
        (1.0, 1.54237, 0.54237),
        (2.0, 2.17996, 0.17996),
        (2.5, 2.54904, 0.04904),
    ],
)
def test_load_split_table(ratio: float, f1: float, f2: float) -> None:
    forces = nut_forces(1.0, ratio)
    assert forces.f1 == pytest.approx(f1, abs=1e-5)
    assert forces.f2 == pytest.approx(f2, abs=1e-5)
    scaled = nut_forces(1500.0, 1500.0 * ratio)  # homogeneous of degree 1
    assert scaled.f1 / 1500.0 == pytest.approx(forces.f1, rel=1e-12)


@pytest.mark.parametrize(
    ("f_a", "f1", "f2"),
    [(2000.0, 2614.6, 614.6), (3000.0, 3269.9, 269.9), (4000.0, 4026.8, 26.84)],
)
def test_t1_10(f_a: float, f1: float, f2: float) -> None:
    forces = nut_forces(1500.0, f_a)
    assert forces.f1 == pytest.approx(f1, abs=0.05)
    assert forces.f2 == pytest.approx(f2, abs=0.005 if f2 < 100 else 0.05)


def test_lift_off_at_4242_6_n() -> None:
    f_p = 1500.0
    assert LIFT_OFF * f_p == pytest.approx(4242.6, abs=0.05)
    assert nut_forces(f_p, 4242.6).f2 > 0.0
    assert nut_forces(f_p, 4242.7).f2 == 0.0
    assert nut_forces(f_p, LIFT_OFF * f_p * (1 + 1e-12)).f2 == 0.0


def test_no_axial_load_keeps_preload() -> None:
    assert tuple(nut_forces(1500.0, 0.0)) == pytest.approx((1500.0, 1500.0), rel=1e-14)


def test_continuity_monotonicity_and_balance_across_lift_off() -> None:
    f_p = 1500.0
    f_a = np.concatenate(
        [
            np.linspace(0.0, 6 * f_p, 601),
            LIFT_OFF * f_p * (1 + np.linspace(-1e-6, 1e-6, 41)),
        ]
    )
    f_a.sort()
    forces = np.array([tuple(nut_forces(f_p, x)) for x in f_a])
    f1, f2 = forces[:, 0], forces[:, 1]
    np.testing.assert_allclose(f1 - f2, f_a, rtol=1e-13, atol=1e-9)
    assert np.all(np.diff(f1) > 0.0)
    assert np.all(np.diff(f2) <= 0.0)
    assert np.all(f2 >= 0.0)
    beyond = f_a > LIFT_OFF * f_p
    assert np.all(f2[beyond] == 0.0)
    np.testing.assert_array_equal(f1[beyond], f_a[beyond])
    assert np.all(f2[~beyond & (f_a < LIFT_OFF * f_p * (1 - 1e-12))] > 0.0)
    # while both nuts touch, the axial interference is conserved (P1)
    both = f_a < LIFT_OFF * f_p * (1 - 1e-9)
    np.testing.assert_allclose(
        f1[both] ** (2 / 3) + f2[both] ** (2 / 3), 2 * f_p ** (2 / 3), rtol=1e-12
    )
    # continuity: no jump at lift-off (F2 ∝ (1−u)^(3/2) → 0 smoothly)
    steps = np.abs(np.diff(forces, axis=0)).max(axis=1)
    assert steps.max() <= 1.01 * np.diff(f_a).max() + 1e-9


@pytest.mark.parametrize(("preload", "axial"), [(0.0, 1.0), (-1.0, 1.0), (math.nan, 1.0)])
def test_rejects_bad_preload(preload: float, axial: float) -> None:
    with pytest.raises(InputError, match="preload"):
        nut_forces(preload, axial)


@pytest.mark.parametrize("axial", [-1.0, math.inf, math.nan])
def test_rejects_bad_axial_load_and_states_sign_convention(axial: float) -> None:
    with pytest.raises(InputError, match="loads nut 1"):
        nut_forces(1500.0, axial)


# ---------------------------------------------------------------------------------- stiffness


def test_preloaded_axial_stiffness_of_the_tcr_reference_screw() -> None:
    # TCR reference screw: δ_a = 4.0217 µm at 1500 N → 559 N/µm per nut
    assert float(preloaded_axial_stiffness(1500.0, 4.0217e-6)) == pytest.approx(559e6, rel=1e-3)
    # wear reference screw: 1.5 F^(1/3)/C_a = 4.58e8 N/m at 1500 N, C_a = 3.749e-8
    delta = nut_axial_deflection(1500.0, 3.749e-8)
    assert float(preloaded_axial_stiffness(1500.0, delta)) == pytest.approx(4.58e8, rel=1e-3)
    with pytest.raises(InputError):
        preloaded_axial_stiffness(1500.0, 0.0)


def test_axial_deflection_from_normal_approaches() -> None:
    # Hertz approaches at the screw and nut contacts of the TCR reference screw:
    # (1.432304 + 1.402484) µm / (sinβ cosα) = 4.0217 µm
    d = axial_deflection_from_approaches(1.432304e-6, 1.402484e-6, BETA, ALPHA)
    assert float(d) == pytest.approx(4.0217e-6, rel=1e-4)
    # wear reference screw: δ_A = 1.752, δ_B = 1.710 µm → δ_a0 = 4.912 µm
    d = axial_deflection_from_approaches(1.752e-6, 1.710e-6, BETA, ALPHA)
    assert float(d) == pytest.approx(4.912e-6, rel=2e-4)


def test_compliance_constant_t1_8() -> None:
    # Hertz constants → C_a (exact and Hamrock–Brewe)
    assert nut_axial_compliance(1.513e-7, 1.477e-7, 54, BETA, ALPHA) == pytest.approx(
        3.749e-8, rel=1e-3
    )
    assert nut_axial_compliance(1.517e-7, 1.483e-7, 54, BETA, ALPHA) == pytest.approx(
        3.762e-8, rel=1e-3
    )
    # δ_a0 = C_a F_p^(2/3) = 4.912 µm at 1500 N
    assert float(nut_axial_deflection(1500.0, 3.749e-8)) == pytest.approx(4.912e-6, rel=2e-4)


# ---------------------------------------------------------------------------------- wear


def test_preload_after_wear_t1_12() -> None:
    h = np.array([0.1e-6, 1.0e-6, 2.43e-6])
    f_p = preload_after_wear(1500.0, 3.749e-8, h, BETA, ALPHA)
    np.testing.assert_allclose(f_p, [1435.5, 899.6, 244.3], rtol=1e-3)
    # Hamrock–Brewe constants (C_a = 3.762e-8) → 1435.7 / 901.5 / 247.2 N
    f_hb = preload_after_wear(1500.0, 3.762e-8, h, BETA, ALPHA)
    np.testing.assert_allclose(f_hb, [1435.7, 901.5, 247.2], rtol=1e-3)


def test_preload_after_wear_limits() -> None:
    f_p = preload_after_wear(1500.0, 3.749e-8, [0.0, 1e-5], BETA, ALPHA)
    assert f_p[0] == pytest.approx(1500.0, rel=1e-14)
    assert f_p[1] == 0.0  # interference worn away
    with pytest.raises(InputError, match="max_wear_depth"):
        preload_after_wear(1500.0, 3.749e-8, -1e-7, BETA, ALPHA)
    with pytest.raises(InputError, match="initial_preload"):
        preload_after_wear(0.0, 3.749e-8, 1e-7, BETA, ALPHA)
