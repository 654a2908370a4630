"""Friction heat of bearings and ball screw against worked examples (Q2)–(Q4)."""

from __future__ import annotations

import math

import pytest

from ballscrew.errors import InputError
from ballscrew.loads import preload_drag_torque
from ballscrew.thermal.heat_sources import friction_heat, nut_heat_shares, palmgren_torque

RPM = 2 * math.pi / 60


def test_palmgren_worked_example():
    """(Q3) f0 = 2, ν0 = 20 mm²/s, 1000 r/min, d_m = 46 mm, F_a = 2000 N, C0 = 12000 N:
    M0 = 14.34 N·mm, M1 = 50.93 N·mm, M = 0.06528 N·m, Q = 6.84 W."""
    m = palmgren_torque(1000 * RPM, 2.0, 20e-6, 0.046, 2000.0, 12000.0)
    assert m.load_independent == pytest.approx(14.34e-3, rel=5e-4)
    assert m.load_dependent == pytest.approx(50.93e-3, rel=5e-4)
    assert m.total == pytest.approx(0.06528, rel=5e-4)
    assert friction_heat(m.total, 1000 * RPM) == pytest.approx(6.84, rel=1e-3)


def test_palmgren_low_speed_branch_and_radial_load():
    """ν0·n < 2000 → M0 = 160e-7 f0 d_m³ [N·mm]; P1 = F_a − 0.1 F_r (Harris)."""
    m = palmgren_torque(50 * RPM, 1.5, 20e-6, 0.046, 2000.0, 12000.0, radial_load=1000.0)
    assert m.load_independent == pytest.approx(160e-7 * 1.5 * 46.0**3 * 1e-3, rel=1e-12)
    f1 = 0.001 * (2000.0 / 12000.0) ** 0.33
    assert m.load_dependent == pytest.approx(f1 * (2000.0 - 100.0) * 46.0 * 1e-3, rel=1e-12)


def test_given_f1_overrides_the_estimate():
    m = palmgren_torque(1000 * RPM, 2.0, 20e-6, 0.046, 2000.0, 12000.0, f1=1e-3)
    assert m.load_dependent == pytest.approx(1e-3 * 2000.0 * 0.046, rel=1e-12)


@pytest.mark.parametrize(("rpm", "heat"), [(1000, 44.31), (800, 35.45)])
def test_drag_torque_heat_worked_example(rpm, heat):
    """(Q4) F_p = 1500 N, L = 10 mm, d_m = 40 mm: T_p = 0.42314 N·m → 44.31 W / 35.45 W."""
    lead_angle = math.atan(0.010 / (math.pi * 0.040))
    torque = preload_drag_torque(1500.0, 0.010, lead_angle)
    assert torque == pytest.approx(0.42314, rel=1e-4)
    assert friction_heat(torque, rpm * RPM) == pytest.approx(heat, abs=0.006)


def test_heat_split_between_nuts_follows_their_forces():
    assert nut_heat_shares(40.0, (1500.0, 1500.0)) == pytest.approx((20.0, 20.0))
    assert nut_heat_shares(40.0, (3000.0, 1000.0)) == pytest.approx((30.0, 10.0))
    assert nut_heat_shares(40.0, (5000.0, 0.0)) == pytest.approx((40.0, 0.0))
    assert sum(nut_heat_shares(7.0, (0.3, 0.9, 1.1))) == pytest.approx(7.0)


def test_bad_inputs_raise():
    with pytest.raises(InputError, match="torque"):
        friction_heat(-1.0, 10.0)
    with pytest.raises(InputError, match="mean_diameter"):
        palmgren_torque(100.0, 2.0, 20e-6, 0.0, 1.0, 1.0)
