"""Preload after wear (E1.13) and drag torque (E9.1) of the wear set-up."""

from __future__ import annotations

import math

import pytest

from ballscrew.analyses.wear import wear_setup
from ballscrew.case import with_overrides
from ballscrew.errors import InputError


def test_t1_8_compliance_and_t1_12_preload_after_wear(ref_case) -> None:
    s = wear_setup(ref_case)
    assert s.compliance == pytest.approx(3.749e-8, rel=1e-3)
    assert s.preload(0.0) == pytest.approx(1500.0, rel=1e-12)
    assert s.preload(0.1e-6) == pytest.approx(1435.5, rel=1e-3)
    assert s.preload(1.0e-6) == pytest.approx(899.6, rel=1e-3)
    assert s.preload(2.43e-6) == pytest.approx(244.3, rel=2e-3)
    assert s.preload(10e-6) == 0.0


def test_t9_1_t9_2_catalogue_torque(ref_case) -> None:
    s = wear_setup(ref_case)
    g = s.geometry
    assert 0.05 / math.sqrt(math.tan(g.lead_angle)) == pytest.approx(0.1772, rel=1e-3)
    assert s.torque(1500.0) == pytest.approx(0.4231, rel=1e-3)
    assert s.torque(1000.0) == pytest.approx(0.2821, rel=1e-3)


def test_torque_scale_and_initial_torque(ref_case) -> None:
    scaled = wear_setup(with_overrides(ref_case, {"wear.torque_scale": 1.5}))
    assert scaled.torque(1000.0) == pytest.approx(1.5 * 0.2821, rel=1e-3)
    fitted = wear_setup(with_overrides(ref_case, {"wear.initial_torque": "0.6 N*m"}))
    assert fitted.torque(1500.0) == pytest.approx(0.6, rel=1e-12)
    assert fitted.torque(1000.0) == pytest.approx(0.4, rel=1e-12)  # linear in F_p


def test_grid_of_the_reference_case(ref_case) -> None:
    """32 × 128 over ±1.4 b_max × ±1.4 a_max: Δx = 6.823 µm, Δy = 8.780 µm, ΔA = 59.91 µm²."""
    s = wear_setup(ref_case)
    assert s.dx == pytest.approx(6.823e-6, rel=1e-3)
    assert s.dy == pytest.approx(8.780e-6, rel=1e-3)
    assert s.cell_area == pytest.approx(59.91e-12, rel=1e-3)
    assert s.surface.rms_height == pytest.approx(6.221e-8, rel=1e-3)


def test_torque_offset_e9_4(ref_case) -> None:
    """T = m K_T F_p L/2π + T_0: the offset is added at every preload, and with an initial
    torque only the preload part is rescaled (T(0) still the given torque)."""
    offset = wear_setup(with_overrides(ref_case, {"wear.torque_offset": "0.1 N*m"}))
    assert offset.torque(1500.0) == pytest.approx(0.4231 + 0.1, rel=1e-3)
    assert offset.torque(0.0) == pytest.approx(0.1, rel=1e-12)
    both = with_overrides(ref_case, {"wear.torque_offset": 0.1, "wear.initial_torque": 0.6})
    fitted = wear_setup(both)
    assert fitted.torque(1500.0) == pytest.approx(0.6, rel=1e-12)
    assert fitted.torque(1000.0) == pytest.approx(0.1 + 0.5 * 1000.0 / 1500.0, rel=1e-12)


def test_initial_torque_below_the_offset_is_refused(ref_case) -> None:
    case = with_overrides(ref_case, {"wear.torque_offset": 0.7, "wear.initial_torque": 0.6})
    with pytest.raises(InputError, match=r"wear\.initial_torque"):
        wear_setup(case)
