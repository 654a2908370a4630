"""Efficiency formulas: THK's worked example, limits, self-locking and the load torque."""

from __future__ import annotations

import math

import pytest

from ballscrew.errors import InputError
from ballscrew.friction import (
    backdriving_efficiency,
    driving_efficiency,
    load_friction_torque,
    load_torque,
)

THK_LEAD_ANGLE = math.atan(0.010 / (math.pi * 0.033))  # A-666: d_m 33 mm, lead 10 mm, 5°30'


def test_thk_worked_example_efficiency_and_torque():
    eta = driving_efficiency(THK_LEAD_ANGLE, 0.003)
    assert eta == pytest.approx(0.9695, abs=5e-4)  # THK prints η = 0.96 (chart reading)
    assert load_torque(14.7, 0.010, THK_LEAD_ANGLE, 0.003) * 1e3 == pytest.approx(24.0, abs=0.5)


def test_textbook_identities():
    lam, mu = 0.0794, 0.003
    rho = math.atan(mu)
    assert driving_efficiency(lam, mu) == pytest.approx(
        (1 - mu * math.tan(lam)) / (1 + mu / math.tan(lam))  # THK's η₁ form
    )
    assert backdriving_efficiency(lam, mu) == pytest.approx(math.tan(lam - rho) / math.tan(lam))
    assert driving_efficiency(lam, 0.0) == 1.0 and backdriving_efficiency(lam, 0.0) == 1.0


def test_self_locking_when_the_friction_angle_exceeds_the_lead_angle():
    lam = math.radians(3.0)
    locking = math.tan(lam) * 1.01
    free = math.tan(lam) * 0.99
    assert backdriving_efficiency(lam, locking) < 0.0 < backdriving_efficiency(lam, free)
    assert 0.0 < driving_efficiency(lam, locking) < 0.5


@pytest.mark.parametrize("mu", [0.0, 0.003, 0.01, 0.1])
def test_load_torque_splits_into_work_and_heat(mu):
    lam, force, lead = 0.0794, 2000.0, 0.01
    work = force * lead / (2 * math.pi)
    total = load_torque(force, lead, lam, mu)
    assert total == pytest.approx(work / driving_efficiency(lam, mu))
    assert load_friction_torque(force, lead, lam, mu) == pytest.approx(total - work)
    assert load_friction_torque(force, lead, lam, mu) >= 0.0


def test_no_load_no_load_torque():
    assert load_torque(0.0, 0.01, 0.0794, 0.003) == 0.0
    assert load_friction_torque(0.0, 0.01, 0.0794, 0.003) == 0.0


@pytest.mark.parametrize(("lam", "mu"), [(0.0, 0.003), (math.pi / 2, 0.003), (0.08, -0.1)])
def test_bad_efficiency_inputs(lam, mu):
    with pytest.raises(InputError):
        driving_efficiency(lam, mu)
