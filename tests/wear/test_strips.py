"""Wear strips, L_w, reciprocation and the worn gap: ``docs/theory/wear.md`` (E8.1)–(E8.4)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew.errors import InputError
from ballscrew.geometry import ScrewGeometry, gap_function
from ballscrew.wear import (
    depth_per_revolution,
    raceway_depth_rate,
    reciprocating_rate,
    strip_wear_speed,
    working_raceway_length,
    worn_gap,
    worn_gap_function,
)

OMEGA = 10.472


def test_t8_1_strip_sum() -> None:
    w = np.array([[1.0, 2.0, 1.0], [0.5, 1.0, 0.5]]) * 1e-9
    strips = strip_wear_speed(w, 10e-6)
    np.testing.assert_allclose(strips, [1.5e-14, 3.0e-14, 1.5e-14], rtol=1e-12)
    rate = raceway_depth_rate(strips, 54, 3.3601)
    np.testing.assert_allclose(rate, [2.411e-13, 4.821e-13, 2.411e-13], rtol=1e-3)
    per_rev = depth_per_revolution(rate, OMEGA)
    np.testing.assert_allclose(per_rev, [1.446e-13, 2.893e-13, 1.446e-13], rtol=1e-3)


def test_t8_2_working_raceway_length(ref_case) -> None:
    g = ScrewGeometry.from_spec(ref_case.screw)
    rho = g.pitch_radius - g.ball_radius * math.cos(g.contact_angle)
    assert rho == pytest.approx(17.755e-3, rel=1e-4)
    assert math.hypot(2 * math.pi * rho, g.lead) == pytest.approx(112.00e-3, rel=1e-4)
    length = working_raceway_length(0.3, g.lead, g.pitch_radius, g.ball_radius, g.contact_angle)
    assert length == pytest.approx(3.3601, rel=1e-4)


def test_reciprocation_and_lift_off() -> None:
    loaded, unloaded = np.array([4.0, 2.0]), np.array([1.0, 1.0])
    np.testing.assert_allclose(reciprocating_rate(loaded, unloaded), [2.5, 1.5])
    np.testing.assert_allclose(reciprocating_rate(loaded, None), [2.0, 1.0])  # F_2 = 0


def test_strip_input_checks() -> None:
    with pytest.raises(InputError):
        strip_wear_speed(np.ones(3), 1e-6)
    with pytest.raises(InputError):
        raceway_depth_rate(np.ones(3), 0, 1.0)
    with pytest.raises(InputError):
        working_raceway_length(-0.3, 0.01, 0.02, 0.003, 0.7)


def test_worn_gap_adds_depth_along_the_groove(ref_case) -> None:
    g = ScrewGeometry.from_spec(ref_case.screw)
    nominal = gap_function(g, "screw", flank=1)
    y = np.linspace(-300e-6, 300e-6, 7)
    h = np.array([0.0, 1.0, 2.0, 3.0, 2.0, 1.0, 0.0]) * 1e-6
    worn = worn_gap_function(nominal, y, h)
    xs, ys = np.array([[0.0], [20e-6]]), np.array([[-400e-6, -150e-6, 0.0, 50e-6, 400e-6]])
    diff = worn(xs, ys) - nominal(xs, ys)
    np.testing.assert_allclose(diff[0], [0.0, 1.5e-6, 3e-6, 2.5e-6, 0.0], atol=1e-15)
    np.testing.assert_allclose(diff[1], diff[0], atol=1e-15)  # h depends on y only
    grid = nominal(xs, y[None, :])
    np.testing.assert_allclose(worn_gap(grid, h) - grid, np.broadcast_to(h, grid.shape))
    with pytest.raises(InputError):
        worn_gap_function(nominal, y, -h)
    with pytest.raises(InputError):
        worn_gap(grid, h[:3])
