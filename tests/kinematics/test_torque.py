"""Drag torque: catalogue (E9.1), efficiency form (E9.2) and the ball model."""

from __future__ import annotations

import math

import pytest

import ballscrew
from ballscrew.analyses.friction import friction_torque
from ballscrew.analyses.kinematics import computed_drag_torque, speed_sweep
from ballscrew.kinematics.torque import efficiency_drag_torque

from .conftest import OMEGA, RPM, updated


def test_t9_1_t9_2_catalogue(ref_case, ref_geometry):
    assert 0.05 / math.sqrt(math.tan(ref_geometry.lead_angle)) == pytest.approx(0.1772, rel=5e-4)
    assert ballscrew.drag_torque(ref_case) == pytest.approx(0.4231, rel=5e-4)
    assert ballscrew.drag_torque(ref_case, preload=1000.0) == pytest.approx(0.2821, rel=5e-4)


def test_t9_3_efficiency_formula(ref_geometry):
    torque, eta = efficiency_drag_torque(1500.0, 0.010, ref_geometry.lead_angle, 0.003)
    assert eta == pytest.approx(0.9634, rel=5e-4)
    assert torque == pytest.approx(0.1779, rel=5e-3)


def test_ball_model_torque_at_every_level(ref_case):
    torques = [computed_drag_torque(ref_case, OMEGA, level=lvl) for lvl in (0, 1, 2)]
    assert all(0.02 < t < ballscrew.drag_torque(ref_case) for t in torques)
    # Levels 0 and 1 differ only through the small groove-angle change (45° → 45.31° at 100 rpm).
    assert torques[1] == pytest.approx(torques[0], rel=0.02)


def test_ball_model_torque_grows_with_preload(ref_case):
    t = [computed_drag_torque(ref_case, OMEGA, preload=f) for f in (500.0, 1000.0, 2000.0)]
    assert t[0] < t[1] < t[2]
    # Dry: traction ∝ Q, spin moments ∝ Q a ∝ Q^(4/3), so between linear and the 4/3 power.
    # Lubricated it grows less than linearly: the asperity share ψ falls with load.
    assert t[2] / t[1] < 2.0
    dry = updated(ref_case, medium={"viscosity": None, "pressure_viscosity": None})
    d = [computed_drag_torque(dry, OMEGA, preload=f) for f in (1000.0, 2000.0)]
    assert 2.0 < d[1] / d[0] < 2.0 ** (4 / 3)


def test_dry_case_uses_boundary_friction_only(ref_case):
    dry = updated(ref_case, medium={"viscosity": None, "pressure_viscosity": None})
    # a raceway of σ_Λ = 50 nm runs mixed (Λ ≈ 1.1): less than μ_b = 0.1 on all of the load
    smooth = updated(ref_case, tcr={"rms_roughness": 50e-9, "rms_slope": 0.05})
    assert computed_drag_torque(dry, OMEGA) > computed_drag_torque(smooth, OMEGA)
    assert computed_drag_torque(dry, 0.0) == pytest.approx(
        computed_drag_torque(dry, OMEGA), rel=1e-9
    )


def test_boundary_film_gives_the_dry_traction(ref_case):
    """Λ = h_c/σ_Λ ≈ 0.04 on the reference raceway: the JGP share on the same σ_Λ is ψ → 1, so
    the traction at A is the dry contact's boundary friction (the film adds EHL rolling only)."""
    ball = {"model": "ball_model"}
    wet = friction_torque(updated(ref_case, friction=ball), speed=OMEGA)
    dry = updated(ref_case, friction=ball, medium={"viscosity": None, "pressure_viscosity": None})
    assert wet.film_parameter < 0.1 and wet.asperity_share > 1.0 - 1e-9
    assert wet.parts["sliding"] == pytest.approx(
        friction_torque(dry, speed=OMEGA).parts["sliding"], rel=1e-6
    )


def test_torque_scales_with_the_friction_coefficient_when_dry(ref_case):
    dry = updated(ref_case, medium={"viscosity": None, "pressure_viscosity": None})
    half = updated(dry, kinematics={"boundary_friction": 0.05})
    assert computed_drag_torque(half, OMEGA) == pytest.approx(
        0.5 * computed_drag_torque(dry, OMEGA), rel=1e-9
    )


def test_default_speed_is_the_case_speed(ref_case):
    assert computed_drag_torque(ref_case) == computed_drag_torque(
        ref_case, ref_case.operating.speed
    )
    fast = computed_drag_torque(ref_case, 1000 * RPM)
    assert fast > 0


def test_e3_7_at_a_alone_needs_the_balance(ref_case):
    # At Level 0 the traction is not part of the balance: the Heathcote sliding (−k_H y²/2R_d,
    # the ball slower than the screw at the edges) leaves a net +X_A traction on the ball that
    # E3.7 turns into screw torque at the screw's surface speed 2V, although no equilibrium
    # carries it. E3.7 then overstates the dissipation ~2.6×; with the balance (Level 2) the two
    # agree to rounding. Hence computed_drag_torque uses the dissipated power.
    from ballscrew.analyses.kinematics import ball_model
    from ballscrew.kinematics import ball_drag, solve_ball

    model = ball_model(ref_case)
    level0 = ball_drag(model, solve_ball(model, OMEGA, 1500.0, 1, level=0))
    level2 = ball_drag(model, solve_ball(model, OMEGA, 1500.0, 1, level=2))
    assert level0.torque > 2.0 * level0.dissipation_torque
    assert level0.traction.force @ model.frame.t > 0.05  # unbalanced Heathcote traction [N]
    assert level2.torque == pytest.approx(level2.dissipation_torque, rel=1e-7)
    assert level2.dissipation_torque == pytest.approx(level0.dissipation_torque, rel=0.15)


@pytest.mark.parametrize("axial_load", [0.0, 5000.0], ids=["both_nuts", "nut2_lifted_off"])
def test_speed_sweep_torque_is_the_drag_torque_of_every_loaded_nut(ref_case, axial_load):
    """The sweep solves each loaded nut once per speed and reuses nut 1's ball for its row: its
    torque is computed_drag_torque's at each speed, with nut 2 (0 N) and without it (5 kN lifts
    it off, F_a > 2^1.5 F_p)."""
    case = updated(ref_case, operating={"axial_load": axial_load})
    speeds = [100 * RPM, 1000 * RPM]
    sweep = speed_sweep(case, speeds, level=0)
    for omega, torque in zip(speeds, sweep.model_torque, strict=True):
        assert torque == pytest.approx(computed_drag_torque(case, omega, level=0), rel=1e-12)
