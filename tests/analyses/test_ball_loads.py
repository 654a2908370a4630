"""Per-ball loads: the uniform (rigid) distribution balances the nut forces."""

from __future__ import annotations

import math
from pathlib import Path

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


@pytest.mark.parametrize("distribution", ["uniform", "elastic"])
def test_another_axial_load_is_the_case_at_that_load(gao_case_path, distribution):
    loaded = ballscrew.load_case(
        gao_case_path, {"operating.axial_load": 2000.0, "loads.distribution": distribution}
    )
    bare = ballscrew.load_case(
        gao_case_path, {"operating.axial_load": 0.0, "loads.distribution": distribution}
    )
    at_zero = ballscrew.ball_loads(loaded, axial_load=0.0)
    np.testing.assert_allclose(at_zero.loads, ballscrew.ball_loads(bare).loads, rtol=1e-10)
    assert not np.allclose(at_zero.loads, ballscrew.ball_loads(loaded).loads)


ELASTIC = {"loads.distribution": "elastic", "operating.axial_load": 2000.0}


def test_the_elastic_distribution_balances_the_load_and_spreads_it(gao_case_path):
    case = ballscrew.load_case(gao_case_path, ELASTIC)
    balls = ballscrew.ball_loads(case)
    assert balls.distribution == "elastic" and balls.loads.shape == (2, 54)
    assert balls.axial_forces[0] - balls.axial_forces[1] == pytest.approx(2000.0, rel=1e-10)
    assert balls.spread > 1.01 and np.all(balls.loads > 0)
    assert np.all(balls.angles > math.radians(45.0))  # the loaded balls ride up the groove
    assert balls.positions.shape == balls.loads.shape


def test_the_contact_chain_takes_the_most_loaded_ball(gao_case_path):
    from ballscrew.analyses.ball_contact import solve_ball_contacts

    overrides = ELASTIC | {"numerics.cells_across": 16}
    case = ballscrew.load_case(gao_case_path, overrides)
    result = solve_ball_contacts(case)
    balls = ballscrew.ball_loads(case)
    assert result.ball_load == pytest.approx(balls.max_load, rel=1e-12)
    assert result.load_spread == pytest.approx(balls.spread, rel=1e-12)
    assert result.nut_force == pytest.approx(balls.axial_forces[0], rel=1e-12)
    uniform = solve_ball_contacts(
        ballscrew.load_case(gao_case_path, overrides | {"loads.distribution": "uniform"})
    )
    f1 = ballscrew.nut_forces(1500.0, 2000.0)[0]
    assert uniform.nut_force == f1 and uniform.load_spread == 1.0


def test_a_nut_thinner_than_its_groove_is_refused_by_its_case_field(gao_case_path):
    thin = ELASTIC | {"loads.nut_outer_diameter": "44 mm"}
    with pytest.raises(ValueError, match=r"loads\.nut_outer_diameter"):  # now at case load
        ballscrew.ball_loads(ballscrew.load_case(gao_case_path, thin))


def test_the_wear_preload_update_puts_the_bodies_in_series():
    from ballscrew.analyses.wear import wear_setup

    path = Path(__file__).resolve().parents[2] / "examples" / "wear_step_stress.toml"
    uniform = wear_setup(ballscrew.load_case(path))
    elastic = wear_setup(ballscrew.load_case(path, {"loads.distribution": "elastic"}))
    assert uniform.body_compliance == 0.0 and elastic.body_compliance > 0.0
    assert uniform.preload(1e-6) == pytest.approx(899.7, rel=1e-4)  # (E1.13), unchanged
    assert elastic.preload(1e-6) > uniform.preload(1e-6)


def test_a_free_nut_reports_its_tilt_and_balances_the_external_loads(gao_case_path):
    free = ELASTIC | {
        "loads.nut_support": "free",
        "loads.nut_radial_load": "200 N",
        "loads.nut_tilting_moment": "3 N*m",
    }
    balls = ballscrew.ball_loads(ballscrew.load_case(gao_case_path, free))
    np.testing.assert_allclose(balls.radial_force, [-200.0, 0.0], atol=1e-9)
    np.testing.assert_allclose(balls.tilting_moment, [0.0, -3.0], atol=1e-11)
    assert np.hypot(*balls.tilt) > 1e-6 and np.hypot(*balls.radial_displacement) > 1e-8
    assert balls.axial_forces[0] - balls.axial_forces[1] == pytest.approx(2000.0, rel=1e-10)
    guided = ballscrew.ball_loads(ballscrew.load_case(gao_case_path, ELASTIC))
    assert np.all(guided.tilt == 0.0) and np.hypot(*guided.radial_force) > 10.0


@pytest.mark.parametrize(
    "overrides",
    [
        {"loads.nut_support": "free"},  # the uniform distribution has no ball positions
        ELASTIC | {"loads.nut_radial_load": "100 N"},  # a guided nut's housing takes it
    ],
)
def test_free_nut_options_are_refused_where_they_mean_nothing(gao_case_path, overrides):
    with pytest.raises(ValueError, match="nut_support"):
        ballscrew.load_case(gao_case_path, overrides)
