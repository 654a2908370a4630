"""Rival traction laws (``friction.traction``): the SKF sliding weighting against the film law."""

from __future__ import annotations

import dataclasses
import math

import pytest

import ballscrew
from ballscrew.analyses.friction import friction_torque
from ballscrew.analyses.kinematics import ball_model
from ballscrew.case import CaseError, with_overrides
from ballscrew.friction.groove_slip import differential_slip_power, heathcote_power
from ballscrew.kinematics.balance import solve_ball
from ballscrew.kinematics.torque import ball_drag
from ballscrew.kinematics.traction_laws import (
    SKF_BOUNDARY_FRICTION,
    SKF_EHL_FRICTION,
    TRACTION_LAWS,
    skf_sliding_friction,
    skf_weighting,
    traction_weights,
)

RPM = 2.0 * math.pi / 60.0


def test_skf_weighting_in_catalogue_units():
    # φ_bl = 1/exp[2.6e-8 (n ν)^1.4 d_m], n [r/min], ν [mm²/s], d_m [mm] (SKF Rolling bearings):
    # n = 100 r/min, ν = 69 mm²/s, d_m = 32 mm: (6900)^1.4 = 2.36804e5, × 32 × 2.6e-8 = 0.197021
    assert skf_weighting(100.0 * RPM, 69e-6, 0.032) == pytest.approx(math.exp(-0.197021), rel=1e-6)
    # the argument is 1 at (n ν)^1.4 d_m = 1/2.6e-8: n ν = 1000 r/min × 100 mm²/s, d_m = 38.46 mm
    d_m = 1.0 / (2.6e-8 * 1e5**1.4)
    assert skf_weighting(1000.0 * RPM, 100e-6, d_m * 1e-3) == pytest.approx(1.0 / math.e, rel=1e-9)


def test_skf_weighting_limits_and_sliding_coefficient():
    assert skf_weighting(0.0, 100e-6, 0.04) == 1.0  # boundary at rest
    assert skf_weighting(3000.0 * RPM, 100e-6, 0.04) < 1e-9  # full film at high n ν
    assert skf_sliding_friction(1.0) == SKF_BOUNDARY_FRICTION == 0.15
    assert skf_sliding_friction(0.0) == SKF_EHL_FRICTION == 0.05
    assert skf_sliding_friction(0.82) == pytest.approx(0.82 * 0.15 + 0.18 * 0.05, rel=1e-12)


@pytest.fixture
def physics_case(wear_case_path):
    return ballscrew.load_case(
        wear_case_path,
        {"friction.model": "ball_model", "operating.axial_load": 0.0, "kinematics.level": 1},
    )


def _law(case, name):
    return case.model_copy(update={"friction": case.friction.model_copy(update={"traction": name})})


def test_registry_and_case_default(wear_case_path):
    assert TRACTION_LAWS.names == ("film", "skf")
    assert ballscrew.load_case(wear_case_path).friction.traction == "film"


def test_unknown_law_is_a_one_line_error(wear_case_path):
    with pytest.raises(CaseError) as err:
        ballscrew.load_case(wear_case_path, {"friction.traction": "stribeck"})
    message = str(err.value).strip()
    assert "traction" in message and "film" in message and "skf" in message and "\n" not in message


@pytest.mark.parametrize(
    ("level", "rpm", "total"),
    # the ball model's torques, default law, at the entrainment speed of the ball-centre speed
    # V: those before the rival law existed (commit 795fb9e; 0.19186, 0.26263, 0.19454 N m)
    # with the JGP share on the asperity heights of σ_Λ (E6.6) instead of the cell's σ (E5.3),
    # the asperities on the 3-D G of the profile G since surface.G_convention (0.29973 N m at
    # 3000 rpm with the profile G read as a surface G)
    [
        (1, 100.0, 0.20083663518246525),
        (1, 3000.0, 0.29758800525071494),
        (2, 100.0, 0.20435820619124825),
    ],
)
def test_default_numbers_are_unchanged(physics_case, level, rpm, total):
    case = physics_case.model_copy(
        update={
            "kinematics": physics_case.kinematics.model_copy(
                update={"level": level, "entrainment": "ball_centre"}
            )
        }
    )
    assert friction_torque(case, speed=rpm * RPM).total == pytest.approx(total, rel=1e-9)
    if level == 1:
        film = friction_torque(_law(case, "film"), speed=rpm * RPM)
        assert film.total == pytest.approx(total, rel=1e-9)


def test_skf_law_raises_the_torque_in_mixed_and_lowers_it_in_full_film(physics_case):
    """On a raceway of σ_Λ = 50 nm: mixed at 100 rpm, full film at 3000 rpm."""
    smooth = with_overrides(physics_case, {"tcr.rms_roughness": 50e-9, "tcr.rms_slope": 0.05})
    mixed = [friction_torque(_law(smooth, n), speed=100.0 * RPM) for n in ("film", "skf")]
    assert mixed[0].regime == "mixed"
    # μ_sl ≈ 0.132 at φ_bl ≈ 0.82 against the film law's ≈ 0.08: sliding and slip at B rise
    assert mixed[1].parts["sliding"] > 1.3 * mixed[0].parts["sliding"]
    assert mixed[1].parts["groove_slip"] > mixed[0].parts["groove_slip"]
    assert mixed[1].total > mixed[0].total
    full = [friction_torque(_law(smooth, n), speed=3000.0 * RPM) for n in ("film", "skf")]
    assert full[0].regime == "EHL"
    # μ_EHL = 0.05 < Λ_L = 0.07 once φ_bl → 0
    assert full[1].parts["sliding"] < full[0].parts["sliding"]


def test_skf_law_acts_in_the_level_2_balance_and_keeps_its_energy_balance(physics_case):
    model = ball_model(_law(physics_case, "skf"), None)
    film = dataclasses.replace(model, traction_law="film")
    omega = 100.0 * RPM
    states = [solve_ball(m, omega, 1500.0, 1, 2) for m in (film, model)]
    # the balance's traction at A follows the law (the state carries the balanced traction)
    assert states[1].traction_screw.power_loss > 1.3 * states[0].traction_screw.power_loss
    for m, state in zip((film, model), states, strict=True):
        drag = ball_drag(m, state)  # at Level 2, T ω_s = dissipated power (E3.7)
        assert drag.torque == pytest.approx(drag.dissipation_torque, rel=1e-6)


def test_skf_cell_shear_is_mu_sl_p_where_the_film_is_at_its_cap(physics_case):
    """Grid integral of the Heathcote slip with the SKF weights and a saturated film equals the
    closed form (F3b) with μ = μ_sl: the SKF weighting of μ_bl and μ_EHL, cell by cell."""
    model = ball_model(_law(physics_case, "skf"), None)
    omega = 100.0 * RPM
    weights = traction_weights(model, 0.3, omega)
    nu = model.viscosity / model.lubricant_density
    assert weights.share == pytest.approx(skf_weighting(omega, nu, 0.040), rel=1e-12)
    load, a, b, radius, rate = 35.0, 4.1e-5, 3.6e-4, 2.43e-3, 20.0
    mu_sl = skf_sliding_friction(weights.share)
    # thin: the Barus film shear exceeds μ_EHL p on every cell; and a film that carries nothing
    # (h = 0, ψ = 1 of a starved contact), the limit h → 0: the film part at its cap, not a
    # contact without friction
    weighted = {
        "psi": weights.share,
        "boundary_friction": weights.boundary_friction,
        "limiting_shear": weights.film_friction,
    }
    oil = {"viscosity": model.viscosity, "pressure_viscosity": model.pressure_viscosity}
    for film in (1e-9, 0.0):
        grid = differential_slip_power(
            load, a, b, radius, rate, film_thickness=film, cells=64, **weighted, **oil
        )
        assert grid == pytest.approx(heathcote_power(load, b, radius, rate, mu_sl), rel=3e-3)
    # dry or at rest the law is pure boundary friction μ_bl
    assert traction_weights(model, 0.3, 0.0).share == 1.0
