"""The speed-spread ball train: closed forms, balances, saturation, invariances, a brute-force
optimisation, the creep stiffness by quadrature, the kinematics and the model in the torque."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import minimize

import ballscrew
from ballscrew.analyses.ball_loads import nut_model
from ballscrew.analyses.friction import friction_torque
from ballscrew.analyses.parameters import ScrewParameters
from ballscrew.errors import InputError
from ballscrew.friction.ball_train import BallTrain, ball_ball_force, return_resistance
from ballscrew.friction.speed_spread import (
    TrainSpread,
    circuit_trains,
    creep_stiffness,
    free_speed,
    group_speed,
    spread_forces,
    traction_capacity,
)
from ballscrew.geometry import ScrewGeometry
from ballscrew.kinematics.motion import ball_motion


def _train(v, k, c=None) -> TrainSpread:
    v = np.asarray(v, dtype=float)
    k = np.broadcast_to(np.asarray(k, dtype=float), v.shape).copy()
    c = np.full(v.shape, 1e9) if c is None else np.broadcast_to(np.asarray(c, float), v.shape)
    return TrainSpread(v, k, np.array(c, dtype=float))


def test_identical_balls_do_not_push_each_other():
    forces, speeds = spread_forces(_train(np.full(12, 0.1), 800.0, 3.0))
    assert np.all(forces == 0.0) and speeds == pytest.approx(np.full(12, 0.1))


def test_two_balls_closed_form():
    # the faster ball behind closes up: u = k-weighted mean, C = k1 k2 (v1 − v2)/(k1 + k2)
    k1, k2, v1, v2 = 1000.0, 3000.0, 0.102, 0.100
    forces, speeds = spread_forces(_train([v1, v2], [k1, k2]))
    assert speeds == pytest.approx(np.full(2, (k1 * v1 + k2 * v2) / (k1 + k2)), rel=1e-14)
    assert forces[0] == pytest.approx(k1 * k2 * (v1 - v2) / (k1 + k2), rel=1e-12)
    assert forces[1] == 0.0
    # the faster ball ahead separates
    apart, speeds = spread_forces(_train([v2, v1], [k1, k2]))
    assert np.all(apart == 0.0) and speeds == pytest.approx([v2, v1])


def test_saturation_at_the_weaker_traction_capacity():
    # 10 m/s of mismatch: both creep laws saturate; the push is the smaller capacity
    forces, _ = spread_forces(_train([10.0, 0.0], [1000.0, 1000.0], [2.0, 5.0]))
    assert forces[0] == pytest.approx(2.0, rel=1e-12)
    forces, _ = spread_forces(_train([10.0, 0.0], [1000.0, 1000.0], [5.0, 2.0]))
    assert forces[0] == pytest.approx(2.0, rel=1e-12)
    # two fast balls behind a slow one: it holds 1.5 N, shared by the two (0.75 N each)
    forces, _ = spread_forces(_train([5.0, 5.0, 0.0], 1000.0, 1.5))
    assert forces == pytest.approx([0.75, 1.5, 0.0], rel=1e-12)


def _complementarity(train: TrainSpread, push: float, forces, speeds) -> None:
    """C ≥ 0, u non-decreasing, C_i (u_(i+1) − u_i) = 0, each ball in balance."""
    drives = np.clip(train.stiffness * (train.speeds - speeds), -train.capacity, train.capacity)
    behind = np.concatenate([[0.0], forces[:-1]])
    scale = float(np.max(train.capacity))
    assert behind + drives - forces == pytest.approx(np.zeros_like(forces), abs=1e-9 * scale)
    assert np.all(forces >= 0.0) and np.all(np.diff(speeds) >= -1e-15)
    assert forces[:-1] * np.diff(speeds) == pytest.approx(np.zeros(forces.size - 1), abs=1e-12)
    assert forces[-1] == pytest.approx(push)


@pytest.mark.parametrize("seed", range(6))
def test_groups_balance_and_contacts_are_complementary(seed):
    rng = np.random.default_rng(seed)
    train = _train(rng.normal(0.1, 1e-3, 40), rng.uniform(500, 5000, 40), rng.uniform(0.5, 4, 40))
    forces, speeds = spread_forces(train, push=0.05)
    _complementarity(train, 0.05, forces, speeds)
    # Σ T over each group of touching balls is 0 (R for the leading group)
    edges = np.flatnonzero(np.diff(speeds) > 0.0) + 1
    drives = np.clip(train.stiffness * (train.speeds - speeds), -train.capacity, train.capacity)
    sums = [float(np.sum(g)) for g in np.split(drives, edges)]
    assert sums[:-1] == pytest.approx([0.0] * (len(sums) - 1), abs=1e-10)
    assert sums[-1] == pytest.approx(0.05, rel=1e-9)


def test_forces_depend_only_on_speed_differences_and_the_order():
    rng = np.random.default_rng(7)
    v, k, c = rng.normal(1.0, 0.01, 25), rng.uniform(1e3, 1e4, 25), rng.uniform(1, 3, 25)
    forces, _ = spread_forces(_train(v, k, c))
    # a common speed, or speeds in other units (stiffness rescaled): the same forces
    assert spread_forces(_train(v + 3.7, k, c))[0] == pytest.approx(forces, rel=1e-9, abs=1e-10)
    assert spread_forces(_train(v / 9.55, k * 9.55, c))[0] == pytest.approx(
        forces, rel=1e-9, abs=1e-10
    )
    # balls already ordered slowest first never touch, whatever their stiffness and capacity
    assert np.all(spread_forces(_train(np.sort(v), k, c))[0] == 0.0)
    assert np.all(spread_forces(_train(np.sort(v), k[::-1], c * 0.01))[0] == 0.0)


@pytest.mark.parametrize("seed", range(4))
def test_pool_adjacent_violators_equals_a_brute_force_optimisation(seed):
    """min Σ φ_i(u_i) + R u_n, u non-decreasing (φ_i' = −T_i, the clipped creep law): SLSQP."""
    rng = np.random.default_rng(100 + seed)
    n, push = 6, 0.02
    v, k, c = rng.normal(0.0, 1e-3, n), rng.uniform(1e3, 5e3, n), rng.uniform(0.5, 2.0, n)
    corner = c / k  # where the creep law saturates (Huber potential)

    def energy(u):
        d = u - v
        quad = 0.5 * k * d**2
        lin = c * np.abs(d) - 0.5 * c * corner
        return float(np.sum(np.where(np.abs(d) <= corner, quad, lin)) + push * u[-1])

    def gradient(u):
        g = -np.clip(k * (v - u), -c, c)
        g[-1] += push
        return g

    order = [{"type": "ineq", "fun": lambda u, i=i: u[i + 1] - u[i]} for i in range(n - 1)]
    best = minimize(
        energy,
        np.full(n, v.mean()),
        jac=gradient,
        constraints=order,
        method="SLSQP",
        options={"ftol": 1e-16, "maxiter": 500},
    )
    train = _train(v, k, c)
    forces, speeds = spread_forces(train, push)
    assert speeds == pytest.approx(best.x, abs=1e-7)
    brute = np.cumsum(np.clip(k * (v - best.x), -c, c))
    assert forces == pytest.approx(brute, abs=1e-3 * float(c.max()))


def test_return_push_of_identical_balls_is_the_ramp_of_the_return_push_model():
    push, n = 0.3, 17
    forces, _ = spread_forces(_train(np.full(n, 0.1), 900.0, 5.0), push)
    assert forces == pytest.approx(push * np.arange(1, n + 1) / n, rel=1e-12)
    train = BallTrain(load=40.0, mass=1e-3, speed=1.0, loaded_balls=n, return_fraction=3.0 / n)
    spread = (_train(np.full(n, 0.1), 900.0, 5.0),)
    with_spread = ball_ball_force("speed_spread", BallTrain(**{**train.__dict__, "spread": spread}))
    same = ball_ball_force("return_push", train)
    assert with_spread.contact == pytest.approx(same.contact, rel=1e-12)
    assert ball_ball_force("speed_spread", train) == same  # no per-ball states: identical balls
    assert with_spread.return_push == pytest.approx(3 * return_resistance(train), rel=1e-12)


def test_a_return_heavier_than_the_traction_is_refused():
    with pytest.raises(InputError, match=r"^friction\.return_fraction = "):
        spread_forces(_train(np.full(3, 0.1), 900.0, 0.1), push=1.0)
    with pytest.raises(InputError, match=r"^spin = 0\.0 .*needs spin"):
        creep_stiffness(0.1, [40.0], 0.0, [1e-3])


def test_unloaded_balls_carry_the_push_through():
    train = _train([0.101, 0.1, 0.1], [1000.0, 0.0, 1000.0], [5.0, 0.0, 5.0])
    forces, speeds = spread_forces(train)
    assert forces[:2] == pytest.approx([0.5, 0.5]) and speeds == pytest.approx([0.1005] * 3)
    assert group_speed(np.array([0.2, 0.4]), np.zeros(2), np.zeros(2)) == pytest.approx(0.3)


def test_free_speed_is_the_rolling_closure_of_the_kinematics():
    g = ScrewGeometry(
        pitch_diameter=0.04175,
        lead=0.01,
        ball_diameter=0.00635,
        contact_angle=math.radians(45.0),
        screw_conformity=0.52,
        nut_conformity=0.52,
    )
    omega = 10.0
    for beta in np.radians([40.0, 45.0, 47.5]):
        motion = ball_motion(g, omega, 1, angle_screw=beta, angle_nut=beta)
        v = free_speed(0.5 * g.pitch_diameter, g.lead_angle, g.ball_radius, beta, omega)
        assert float(v) == pytest.approx(motion.ball_speed, rel=1e-12)
    # a larger contact angle or a smaller ball runs faster
    assert free_speed(0.02, 0.07, 0.003, math.radians(46.0)) > free_speed(0.02, 0.07, 0.003, 0.8)
    assert free_speed(0.02, 0.07, 0.0029, 0.8) > free_speed(0.02, 0.07, 0.003, 0.8)


def test_creep_stiffness_against_a_quadrature_of_coulomb_traction():
    """F = μ ∫ p (u − ω y)/|s| dA over a Hertz ellipse spinning at ω about its centre and creeping
    at u along x: → (3/2) μ Q u/(ω b) for an ellipse long across the track (b/a = 8: 2 %)."""
    a, b, omega, mu, load = 0.1e-3, 0.8e-3, 12.0, 0.08, 40.0
    u = 1e-3 * omega * b
    n = 800
    x = ((np.arange(n) + 0.5) / n * 2 - 1)[:, None] * a
    y = ((np.arange(n) + 0.5) / n * 2 - 1)[None, :] * b
    rho = np.maximum(1 - (x / a) ** 2 - (y / b) ** 2, 0.0)
    p = 3 * load / (2 * math.pi * a * b) * np.sqrt(rho)
    force = mu * np.sum(p * (u - omega * y) / np.hypot(u - omega * y, omega * x)) * 4 * a * b / n**2
    k_contact = float(creep_stiffness(mu, load, omega, b)) / 4.0  # per contact, per creep at A
    assert force / (k_contact * u) == pytest.approx(1.0, abs=0.025)
    assert traction_capacity(mu, [load, -1.0]) == pytest.approx([2 * mu * load, 0.0])


def test_circuits_run_both_ways():
    trains = circuit_trains(np.arange(5.0), np.ones(5), np.ones(5), 2)
    assert [t.speeds.tolist() for t in trains] == [[0, 1, 2], [2, 1, 0], [3, 4], [4, 3]]


@pytest.fixture
def spread_case(wear_case_path):
    return ballscrew.load_case(
        wear_case_path,
        {"friction.model": "ball_model", "operating.axial_load": 0.0, "kinematics.level": 0},
    )


def _with(case, loads=None, **friction):
    update = {"friction": case.friction.model_copy(update=friction)}
    if loads is not None:
        update["loads"] = case.loads.model_copy(update=loads)
    return case.model_copy(update=update)


def test_identical_balls_in_the_torque_are_the_return_push(spread_case):
    spread = friction_torque(_with(spread_case, ball_train="speed_spread"), speed=100.0)
    push = friction_torque(_with(spread_case, ball_train="return_push"), speed=100.0)
    assert spread.parts == pytest.approx(push.parts, rel=1e-12)


def test_elastic_ball_states_push_the_balls_and_errors_push_harder(spread_case):
    elastic = {"distribution": "elastic"}
    ratio = friction_torque(_with(spread_case, elastic), speed=100.0)
    even = friction_torque(_with(spread_case, elastic, ball_train="speed_spread"), speed=100.0)
    push = friction_torque(_with(spread_case, ball_train="return_push"), speed=100.0)
    for part in ("sliding", "groove_slip", "ehl_rolling", "hysteresis", "drag"):
        assert even.parts[part] == ratio.parts[part]  # the ball train acts on F_B alone
    assert even.parts["ball_ball"] > push.parts["ball_ball"]  # the elastic spread adds force
    layout, _ = nut_model(ScrewParameters.from_case(spread_case), spread_case.loads)
    slope = 2e-6 * (layout.z - layout.z.mean()) / float(np.ptp(layout.z))  # 2 µm over the nuts
    errors = {**elastic, "lead_error": slope.tolist()}
    worse = friction_torque(_with(spread_case, errors, ball_train="speed_spread"), speed=100.0)
    assert worse.parts["ball_ball"] > even.parts["ball_ball"]
    rest = friction_torque(_with(spread_case, errors, ball_train="speed_spread"), speed=0.0)
    assert 0.0 < rest.parts["ball_ball"]  # the forces per unit speed: finite at breakaway


def test_the_ball_states_are_solved_once_per_case(spread_case, monkeypatch):
    """A coupled operating point asks for the torque of one case at many viscosities: the
    elastic distribution behind the ball states is solved once, and again for another preload."""
    from ballscrew.analyses import friction as module

    calls = []
    original = module.ball_loads
    monkeypatch.setattr(module, "ball_loads", lambda *a, **k: calls.append(1) or original(*a, **k))
    module._NUT_BALLS.clear()
    case = _with(spread_case, {"distribution": "elastic"}, ball_train="speed_spread")
    first = friction_torque(case, speed=100.0, viscosity=0.05)
    friction_torque(case, speed=100.0, viscosity=0.02)
    assert len(calls) == 1
    other = case.model_copy(
        update={
            "operating": case.operating.model_copy(update={"preload": 1.5 * case.operating.preload})
        }
    )
    assert friction_torque(other, speed=100.0, viscosity=0.05).total != first.total
    assert len(calls) == 2
