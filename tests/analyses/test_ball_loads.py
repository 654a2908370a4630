"""Per-ball loads: the uniform (rigid) distribution balances the nut forces."""

from __future__ import annotations

import math

import numpy as np
import pytest

import ballscrew


def test_every_ball_of_a_nut_carries_its_share(gao_case_path):
    case = ballscrew.load_case(gao_case_path, {"operating.axial_load": 3000.0})
    balls = ballscrew.ball_loads(case)
    f1, f2 = ballscrew.nut_forces(1500.0, 3000.0)
    assert balls.loads.shape == (2, 54) and balls.distribution == "uniform"
    np.testing.assert_allclose(balls.axial_forces, [f1, f2], rtol=1e-12)  # force balance
    beta, lead = math.radians(45.0), math.atan(0.01 / (math.pi * 0.04))
    q1 = f1 / (54 * math.sin(beta) * math.cos(lead))
    np.testing.assert_allclose(balls.loads[0], q1, rtol=1e-12)
    np.testing.assert_allclose(balls.angles, beta, rtol=1e-12)


def test_a_lifted_off_nut_carries_nothing(gao_case_path):
    case = ballscrew.load_case(gao_case_path, {"operating.axial_load": 6000.0})  # > 2^1.5 F_p
    balls = ballscrew.ball_loads(case)
    assert np.all(balls.loads[1] == 0.0)
    assert balls.axial_forces[0] == pytest.approx(6000.0, rel=1e-12)
