"""Quasi-static ball balance, Levels 0/1/2: worked examples of the wear reference screw."""

from __future__ import annotations

import math

import numpy as np
import pytest

import ballscrew
from ballscrew.analyses.kinematics import ball_model
from ballscrew.errors import InputError
from ballscrew.kinematics import ball_drag, solve_ball

from .conftest import RPM, updated

DEG = math.pi / 180.0


def test_contract_attributes(ref_case):
    state = ballscrew.ball_kinematics(ref_case)
    for name in (
        "ball_speed",
        "orbital_speed",
        "spin_screw",
        "spin_nut",
        "load_screw",
        "load_nut",
        "angle_screw",
        "angle_nut",
    ):
        assert isinstance(getattr(state, name), float), name
    assert state.ball_speed == pytest.approx(0.09333, rel=5e-4)  # at the case speed


def test_t1_7_hertz_constants(ref_case):
    model = ball_model(ref_case)
    assert model.hertz_constant("screw") == pytest.approx(1.513e-7, rel=5e-4)
    assert model.hertz_constant("nut") == pytest.approx(1.477e-7, rel=5e-4)


@pytest.mark.parametrize(
    ("axial", "load"), [(0.0, 39.41), (2000.0, 68.69), (3000.0, 85.91), (4000.0, 105.79)]
)
def test_t1_9_t1_11_level0_loads(ref_case, axial, load):
    case = updated(ref_case, operating={"axial_load": axial})
    state = ballscrew.ball_kinematics(case, level=0)
    assert state.load_screw == state.load_nut == pytest.approx(load, rel=5e-4)
    assert state.angle_screw == state.angle_nut == pytest.approx(45 * DEG)


@pytest.mark.parametrize(
    ("rpm", "q_a", "q_b", "b_a", "b_b"),
    [
        (100, 39.197, 39.197, 45.31, 45.31),
        (3000, 39.05, 39.34, 45.52, 45.10),
        (6000, 38.64, 39.79, 46.15, 44.45),
    ],
)
def test_level1_groove_balance(ref_case, rpm, q_a, q_b, b_a, b_b):
    state = solve_ball(ball_model(ref_case), rpm * RPM, 1500.0, 1, level=1)
    assert state.load_screw == pytest.approx(q_a, rel=3e-4)
    assert state.load_nut == pytest.approx(q_b, rel=3e-4)
    assert state.angle_screw / DEG == pytest.approx(b_a, abs=0.011)
    assert state.angle_nut / DEG == pytest.approx(b_b, abs=0.011)
    assert state.residual < 1e-9


def test_level1_flanks_are_mirror_images_in_loads(ref_case):
    model = ball_model(ref_case)
    a, b = (solve_ball(model, 3000 * RPM, 1500.0, s, level=1) for s in (1, -1))
    assert (a.load_screw, a.load_nut, a.angle_screw) == pytest.approx(
        (b.load_screw, b.load_nut, b.angle_screw), rel=1e-9
    )
    assert a.spin_screw == pytest.approx(-b.spin_screw, rel=1e-6)


def test_level1_tends_to_level0_as_speed_goes_to_zero(ref_case):
    model = ball_model(ref_case)
    beta0, lam = model.geometry.contact_angle, model.geometry.lead_angle
    # The centrifugal split of loads and angles vanishes like ω².
    split = []
    for w in (20.0, 40.0, 80.0):
        s = solve_ball(model, w, 1500.0, 1, level=1)
        split.append((s.load_nut - s.load_screw, s.angle_screw - s.angle_nut))
    split = np.array(split)
    np.testing.assert_allclose(split[1:] / split[:-1], 4.0, rtol=2e-3)
    # At ω = 0 the ball is symmetric and carries the nut force exactly as Level 0 does.
    s0 = solve_ball(model, 0.0, 1500.0, 1, level=1)
    assert s0.load_screw == pytest.approx(s0.load_nut, rel=1e-9)
    assert s0.angle_screw == pytest.approx(s0.angle_nut, rel=1e-9)
    axial = model.balls * s0.load_nut * math.sin(s0.angle_nut) * math.cos(lam)
    assert axial == pytest.approx(1500.0, rel=1e-9)
    # What is left, the conformal groove turning the load line (β 45° → 45.31° at 100 rpm), is an
    # elastic effect that vanishes like δ ∝ F^(2/3) as the load goes to zero.
    for force in (1500.0, 1.0):
        s0 = solve_ball(model, 0.0, force, 1, level=1)
        l0 = solve_ball(model, 0.0, force, 1, level=0)
        assert s0.angle_screw - beta0 == pytest.approx(
            0.31 * DEG * (force / 1500) ** (2 / 3), rel=0.05
        )
        assert s0.load_screw / l0.load_screw == pytest.approx(
            1.0, abs=0.006 * (force / 1500) ** (2 / 3)
        )
    assert s0.ball_speed == pytest.approx(l0.ball_speed, abs=1e-12)


def test_level2_needs_lubricant(ref_case):
    dry = updated(ref_case, medium={"viscosity": None, "pressure_viscosity": None})
    with pytest.raises(InputError, match="level 2"):
        ballscrew.ball_kinematics(dry, level=2)
    ballscrew.ball_kinematics(dry, level=1)  # fine without lubricant


@pytest.mark.parametrize("flank", [1, -1])
def test_level2_balance_holds_and_conserves_energy(ref_case, flank):
    model = ball_model(ref_case)
    state = solve_ball(model, 1000 * RPM, 1500.0, flank, level=2)
    assert state.residual < 1e-9
    m = state.motion
    # nut-raceway control: no slip and no spin at B
    np.testing.assert_allclose(m.ball_velocity(m.nut_contact.origin), 0.0, atol=1e-12)
    assert state.spin_nut == pytest.approx(0.0, abs=1e-9)
    # E3.7 torque (power the screw delivers) = dissipated power, because the balance holds
    drag = ball_drag(model, state)
    assert drag.torque == pytest.approx(drag.dissipation_torque, rel=1e-7)
    assert drag.dissipation_torque > 0.0
    # the nut force is carried: Z × axial component of the ball's force on the nut
    on_nut = (
        state.load_nut * m.nut_contact.direction - state.traction_nut - state.rolling_resistance_nut
    )
    assert -flank * model.balls * on_nut @ m.frame.axis == pytest.approx(1500.0, rel=1e-8)


def test_level2_without_friction_is_level1(ref_case):
    # μ_b = Λ → 0 and low speed: no traction, negligible inertia and rolling force, so Level 2
    # gives the groove balance of Level 1. Exactly zero friction leaves V undetermined
    # (F_R,A = F_R,B fixes nothing), hence 1e-4.
    frictionless = updated(ref_case, kinematics={"boundary_friction": 1e-4, "limiting_shear": 1e-4})
    s2 = solve_ball(ball_model(frictionless), 100 * RPM, 1500.0, 1, level=2)
    assert s2.load_screw == pytest.approx(39.197, rel=2e-4)
    assert s2.load_nut == pytest.approx(39.197, rel=2e-4)
    assert s2.angle_screw / DEG == pytest.approx(45.31, abs=0.011)
    assert s2.angle_nut / DEG == pytest.approx(45.31, abs=0.011)


def test_level2_nut_reaction_holds_the_gyroscopic_moment(ref_case):
    # Without friction at A the t-component of M_g (E3.2: s J ω_B ω_c cosλ sinβ) can only be
    # held by the traction at B: |F_TB,Y| r_b = M_g·t (3000 rpm: |M_g| = 3.705e-4 N m),
    # up to what the weak friction at A can carry, μ Q_A r_b.
    mu = 1e-4
    frictionless = updated(ref_case, kinematics={"boundary_friction": mu, "limiting_shear": mu})
    model = ball_model(frictionless)
    s2 = solve_ball(model, 3000 * RPM, 1500.0, 1, level=2)
    assert s2.ball_speed == pytest.approx(2.800, rel=0.02)
    assert np.linalg.norm(s2.gyroscopic_moment) == pytest.approx(3.705e-4, rel=0.03)
    m_t = s2.gyroscopic_moment @ s2.motion.frame.t
    f_y = s2.traction_nut @ s2.motion.nut_contact.y
    r_b = model.geometry.ball_radius
    assert abs(abs(f_y) * r_b - abs(m_t)) <= mu * s2.load_screw * r_b


def test_level2_load_at_a_falls_with_speed(ref_case):
    model = ball_model(ref_case)
    loads = [
        solve_ball(model, rpm * RPM, 1500.0, 1, level=2).load_screw for rpm in (100, 1000, 3000)
    ]
    assert loads[0] > loads[1] > loads[2]


def test_level2_standstill_is_the_slow_limit(ref_case):
    model = ball_model(ref_case)
    s0 = solve_ball(model, 0.0, 1500.0, 1, level=2)
    slow = solve_ball(model, 1e-4, 1500.0, 1, level=2)
    assert s0.ball_speed == 0.0 and s0.spin_screw == 0.0
    assert s0.angle_screw == pytest.approx(slow.angle_screw, rel=1e-3)
    assert s0.load_screw == pytest.approx(slow.load_screw, rel=1e-5)


def test_bad_input_before_any_work(ref_case, monkeypatch):
    import ballscrew.analyses.kinematics as api

    def forbidden(*args, **kwargs):
        raise AssertionError("work started before the input was checked")

    monkeypatch.setattr(api, "solve_ball", forbidden)
    with pytest.raises(InputError, match="speed"):
        ballscrew.ball_kinematics(ref_case, speed=-1.0)
    with pytest.raises(InputError, match="level"):
        ballscrew.ball_kinematics(ref_case, level=3)
    dry = updated(ref_case, medium={"viscosity": None, "pressure_viscosity": None})
    with pytest.raises(InputError, match="viscosity"):
        ballscrew.ball_kinematics(dry, level=2)
    single = updated(ref_case, screw={"nuts": 1}, operating={"preload": 0.0, "axial_load": 500.0})
    with pytest.raises(InputError, match="nut"):  # one loaded flank (a preloaded one has two)
        ballscrew.ball_kinematics(single, nut=2)
