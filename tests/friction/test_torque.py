"""Total friction torque: energy balance, limits, monotonicity, heat split and the registry."""

from __future__ import annotations

import dataclasses
import math
import warnings

import pytest

import ballscrew
from ballscrew.analyses.friction import FourPointContactWarning, friction_torque, seal_torque
from ballscrew.analyses.kinematics import ball_model, computed_drag_torque
from ballscrew.analyses.parameters import ScrewParameters
from ballscrew.case import CaseError, with_overrides
from ballscrew.contact import hertz
from ballscrew.errors import InputError
from ballscrew.friction import (
    FRICTION_MODELS,
    BallLosses,
    FrictionInputs,
    ball_losses,
    hysteresis_force,
    nut_friction_torque,
)
from ballscrew.kinematics.balance import solve_ball
from ballscrew.loads import preload_drag_torque
from ballscrew.lubrication import regime

LEAD, LAMBDA = 0.01, math.atan(0.01 / (math.pi * 0.04))


def _losses(speed: float) -> BallLosses:
    return BallLosses(0.05, 0.02 * (speed > 0), 0.003, 0.03, 2.0 if speed else 0.0)


def _inputs(**kw: float) -> FrictionInputs:
    base = dict(lead=LEAD, lead_angle=LAMBDA, preload=1500.0, axial_load=1000.0, speed=100.0)
    return FrictionInputs(**{**base, **kw}, ball_losses=_losses)


@pytest.mark.parametrize("model", FRICTION_MODELS.names)
@pytest.mark.parametrize(("load", "seals"), [(0.0, 0), (1000.0, 2), (5000.0, 1)])
def test_heat_is_torque_times_speed_less_the_work(model, load, seals):
    inputs = _inputs(axial_load=load, seals=seals, seal_torque=0.1, recirculation_torque=0.01)
    r = nut_friction_torque(inputs, model)
    velocity = inputs.lead * inputs.speed / (2 * math.pi)
    assert r.heat == pytest.approx(r.total * inputs.speed - load * velocity)
    assert r.heat == pytest.approx(r.friction * inputs.speed)
    assert r.heat >= 0.0 and r.total == pytest.approx(sum(r.parts.values()))
    assert r.heat_to_screw + r.heat_to_nut == pytest.approx(r.heat)
    assert 0.0 < r.heat_to_screw < r.heat
    assert r.parts["seals"] == pytest.approx(0.1 * seals)


@pytest.mark.parametrize("model", FRICTION_MODELS.names)
def test_limits(model):
    free = nut_friction_torque(_inputs(axial_load=0.0), model)
    assert free.parts["work"] == 0.0 and free.parts["load"] == 0.0
    assert free.parts["seals"] == 0.0 and free.parts["recirculation"] == 0.0
    still = nut_friction_torque(_inputs(speed=0.0), model)
    assert still.heat == 0.0 and still.total > still.parts["work"] > 0.0


def test_catalogue_preload_part_is_the_catalogue_formula():
    r = nut_friction_torque(_inputs(), "catalogue")
    assert r.parts["preload"] == pytest.approx(preload_drag_torque(1500.0, LEAD, LAMBDA))
    assert r.efficiency_driving == pytest.approx(0.9634, abs=1e-4)


def test_ball_model_parts_and_regime():
    r = nut_friction_torque(_inputs(), "ball_model")
    assert (r.parts["sliding"], r.parts["ehl_rolling"], r.parts["hysteresis"]) == (
        0.05,
        0.02,
        0.003,
    )
    assert r.film_parameter == 2.0 and r.regime == "mixed"
    assert [regime(x) for x in (0.5, 2.0, 4.0)] == ["boundary", "mixed", "EHL"]


def test_hysteresis_force_closed_form():
    assert hysteresis_force(100.0, 2e-4, 3e-3, 0.01) == pytest.approx(
        0.01 * 3 / 16 * 100 * 2e-4 / 3e-3
    )
    assert hysteresis_force(0.0, 2e-4, 3e-3, 0.01) == 0.0


@pytest.mark.parametrize(
    ("changes", "field"),
    [
        ({"speed": -1.0}, "speed"),
        ({"axial_load": math.nan}, "axial_load"),
        ({"seal_torque": -0.1}, "friction.seal_torque"),
    ],
)
def test_bad_inputs_name_the_field(changes, field):
    with pytest.raises(InputError, match=rf"^{field} = "):
        nut_friction_torque(_inputs(**changes))


def test_ball_model_needs_its_losses():
    bare = FrictionInputs(lead=LEAD, lead_angle=LAMBDA, preload=1500.0)
    with pytest.raises(InputError, match=r"friction\.model"):
        nut_friction_torque(bare, "ball_model")


# --- the composer on the example case --------------------------------------------------------


@pytest.fixture
def ball_case(wear_case_path):
    return ballscrew.load_case(wear_case_path, {"friction.model": "ball_model"})


def test_ball_model_rises_with_preload_and_load(wear_case_path):
    torques = []
    for preload in (1000.0, 2000.0):
        case = ballscrew.load_case(
            wear_case_path, {"friction.model": "ball_model", "operating.preload": preload}
        )
        torques.append([friction_torque(case, 50.0, fa).total for fa in (0.0, 1000.0)])
    (low_0, low_1), (high_0, high_1) = torques
    assert high_0 > low_0 and low_1 > low_0 and high_1 > high_0


def test_ball_model_at_zero_speed_is_the_dry_breakaway_value(ball_case):
    still = friction_torque(ball_case, speed=0.0, axial_load=0.0)
    turning = friction_torque(ball_case, speed=100.0, axial_load=0.0)
    assert still.heat == 0.0 and still.parts["ehl_rolling"] == 0.0 and still.regime == "boundary"
    assert still.parts["sliding"] > turning.parts["sliding"] > 0.0
    assert turning.film_parameter > 0.0 and turning.parts["ehl_rolling"] > 0.0


def test_thinner_oil_thins_the_film(ball_case):
    thick = friction_torque(ball_case, 100.0, viscosity=0.06)
    thin = friction_torque(ball_case, 100.0, viscosity=0.01)
    assert thin.film_parameter < thick.film_parameter
    assert thin.parts["ehl_rolling"] < thick.parts["ehl_rolling"]
    with pytest.raises(InputError, match=r"^viscosity = "):
        friction_torque(ball_case, 100.0, viscosity=-1.0)


def test_seal_defaults_and_overrides(wear_case_path):
    sealed = ballscrew.load_case(wear_case_path, {"friction.seals": 2})
    assert seal_torque(sealed) == pytest.approx(5.0 * 0.5 * sealed.screw.pitch_diameter)
    given = ballscrew.load_case(wear_case_path, {"friction.seals": 2, "friction.seal_torque": 0.07})
    assert friction_torque(given).parts["seals"] == pytest.approx(0.14)
    assert friction_torque(ballscrew.load_case(wear_case_path)).parts["seals"] == 0.0


def test_case_names_come_from_the_registry(wear_case_path):
    assert FRICTION_MODELS.names == ("catalogue", "ball_model")
    with pytest.raises(
        CaseError,
        match=r"friction\.model = 'nonsense' is not allowed: .*"
        r"one of catalogue, ball_model",
    ):
        ballscrew.load_case(wear_case_path, {"friction.model": "nonsense"})
    with pytest.raises(CaseError, match=r"friction\.seals"):
        ballscrew.load_case(wear_case_path, {"friction.seals": -1})


@pytest.mark.parametrize(
    "single",
    [
        {},
        {"screw.nuts": 1, "screw.preload_method": "oversized_balls"},
        {"screw.nuts": 1, "screw.preload_method": "offset_lead"},
    ],
    ids=["double", "four_point", "offset_lead"],
)
@pytest.mark.filterwarnings("ignore:screw.preload_method = oversized_balls")
def test_ball_parts_are_the_kinematics_drag_plus_hysteresis(wear_case_path, single):
    """Double nut and preloaded single nuts: the kinematics drag counts the same flanks and balls
    per flank as the friction ball model."""
    case = ballscrew.load_case(
        wear_case_path, {"friction.model": "ball_model", "operating.axial_load": 0.0, **single}
    )
    r = friction_torque(case, speed=100.0)
    drag = computed_drag_torque(case, speed=100.0)
    assert r.parts["sliding"] + r.parts["ehl_rolling"] == pytest.approx(drag, rel=1e-12)
    assert 0.0 < r.parts["hysteresis"] < 0.1 * drag
    assert 0.0 < r.heat_to_screw < 0.5 * r.heat


@pytest.mark.parametrize("level", [0, 2])
def test_film_parameter_is_the_screw_contacts_whole_load_film_over_the_roughness(ball_case, level):
    """Λ is h_c/σ_Λ of the whole ball load at A of the first loaded nut, at the state's load and
    rolling speed (the operating point's definition; the nut contact B has another load and
    film and must not be read), and ψ is the JGP share at A."""
    model = ball_model(ball_case)
    force, flank = next(
        (n.force, n.flank)
        for n in ScrewParameters.from_case(ball_case).with_loads(axial_load=0.0).nuts
        if n.force > 0.0
    )
    state = solve_ball(model, 100.0, force, flank, level)
    u_a = model.entrainment_speed(state.motion)
    expected = model.film(state.load_screw, u_a).central / model.surface.film_roughness
    losses = ball_losses(model, 100.0, ((force, flank),), level=level)
    assert losses.film_parameter == pytest.approx(expected, rel=1e-9)
    assert losses.asperity_share == pytest.approx(model.sharing(state.load_screw, u_a).psi)
    u_b = model.entrainment_speed(state.motion, "nut")
    nut_side = model.film(state.load_nut, u_b, "nut").central / model.surface.film_roughness
    assert nut_side != pytest.approx(expected, rel=1e-3)


def test_hysteresis_rolls_at_the_contacts_rolling_speed_without_lead(ball_case):
    """(F4) at Level 0 without lead: both contacts roll at u_e = ω_s d_m (1 − γ²)/4 (E2.8), so
    T_hyst = Z Σ_{A,B} α (3/16) Q a/R_x · d_m (1 − γ²)/4 by hand, (1 + γ) times the loss at the
    ball-centre speed V = ω_s d_m (1 − γ)/4 that the ``ball_centre`` rule keeps; the heat is
    T ω_s, half of A's into the screw."""
    model = ball_model(ball_case)
    g = dataclasses.replace(model.geometry, lead=1e-9)
    flat = dataclasses.replace(model, geometry=g)
    alpha, force = 0.01, 1500.0
    losses = ball_losses(flat, 100.0, ((force, 1),), hysteresis=alpha)
    load = force / (model.balls * math.sin(g.contact_angle))  # (Q1) at λ = 0
    gamma = g.ball_diameter * math.cos(g.contact_angle) / g.pitch_diameter
    per_contact = []
    for contact in ("screw", "nut"):
        c = flat.curvature(contact)
        a = hertz(c.rx, c.ry, flat.e_star(contact), load).a
        per_contact.append(model.balls * alpha * 3 / 16 * load * a / c.rx)
    at_a, hand = (
        g.pitch_diameter * (1 - gamma**2) / 4 * t for t in (per_contact[0], sum(per_contact))
    )
    assert losses.hysteresis == pytest.approx(hand, rel=1e-6)
    free = ball_losses(flat, 100.0, ((force, 1),), hysteresis=0.0)
    assert losses.total - free.total == pytest.approx(hand, rel=1e-9)
    assert losses.screw_share - free.screw_share == pytest.approx(0.5 * at_a, rel=1e-6)
    centre = dataclasses.replace(flat, entrainment="ball_centre")
    old = ball_losses(centre, 100.0, ((force, 1),), hysteresis=alpha).hysteresis
    assert losses.hysteresis / old == pytest.approx(1 + gamma, rel=1e-6)
    still = ball_losses(flat, 0.0, ((force, 1),), hysteresis=alpha)
    assert still.hysteresis == pytest.approx(hand, rel=1e-6)  # the limit ω_s → 0⁺


def test_four_point_balls_count_their_train_once(ball_case):
    """A single nut preloaded by oversized balls has Z balls touching both flanks: the contact
    losses add over the two flanks, the ball train's (ball–ball, drag, return) are those of one
    flank's Z balls, not of 2Z."""
    model = ball_model(ball_case)
    fp = 1500.0
    both = ((fp, 1), (fp, -1))
    apart = ball_losses(model, 100.0, both)
    shared = ball_losses(model, 100.0, both, shared=True)
    one = ball_losses(model, 100.0, both[:1])
    for part in ("sliding", "ehl_rolling", "hysteresis", "groove_slip"):
        assert getattr(shared, part) == pytest.approx(getattr(apart, part), rel=1e-12)
    for part in ("ball_ball", "drag", "recirculation"):
        assert getattr(shared, part) == pytest.approx(getattr(one, part), rel=1e-12)
        assert getattr(one, part) > 0.0
    assert shared.total < apart.total


def test_oversized_ball_nut_friction_is_below_the_double_nut(wear_case_path):
    """Same balls per flank and preload: the four-point single nut has the double nut's contact
    losses but half its ball train (Z balls, not 2Z)."""
    base = {"friction.model": "ball_model", "operating.axial_load": 0.0}
    double = ballscrew.load_case(wear_case_path, base)
    single = ballscrew.load_case(
        wear_case_path, {**base, "screw.nuts": 1, "screw.preload_method": "oversized_balls"}
    )
    rd = friction_torque(double, speed=100.0)
    with pytest.warns(FourPointContactWarning, match="lower estimate"):
        rs = friction_torque(single, speed=100.0)
    assert rs.parts["sliding"] == pytest.approx(rd.parts["sliding"], rel=1e-9)
    assert rs.parts["drag"] == pytest.approx(0.5 * rd.parts["drag"], rel=1e-9)


def test_offset_lead_halves_share_the_nut_circuits(wear_case_path):
    """An offset-lead nut is one body with ``friction.circuits`` circuits, half of them in each
    half: its return loss is the four-point nut's (same body and balls, same ball speed), not
    twice it, and an odd circuit count cannot be split."""
    base = {
        "friction.model": "ball_model",
        "operating.axial_load": 0.0,
        "operating.speed": "1000 rpm",
        "screw.nuts": 1,
    }
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FourPointContactWarning)
        four = friction_torque(ballscrew.load_case(wear_case_path, base))
    offset_case = ballscrew.load_case(
        wear_case_path, {**base, "screw.preload_method": "offset_lead"}
    )
    offset = friction_torque(offset_case)
    assert offset.parts["recirculation"] == pytest.approx(four.parts["recirculation"], rel=0.05)
    odd = with_overrides(offset_case, {"friction.circuits": 3})
    with pytest.raises(InputError, match=r"friction\.circuits = 3 .*even number"):
        friction_torque(odd)
