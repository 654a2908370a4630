"""The operating point's film, film parameter Λ and viscosity, whatever the friction model."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

import ballscrew
from ballscrew.analyses.kinematics import ball_model
from ballscrew.analyses.operating_point import operating_point
from ballscrew.analyses.parameters import ScrewParameters, library_entry
from ballscrew.kinematics.motion import entrainment_speed

RPM = 2 * math.pi / 60
pytestmark = pytest.mark.filterwarnings("ignore::UserWarning")
EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "gao2019_tcr.toml"
NAMED = {"medium.lubricant": "iso_vg_68"}


@pytest.fixture(scope="module")
def case():
    return ballscrew.load_case(EXAMPLE, {"numerics.cells_across": 16})


@pytest.fixture(scope="module")
def slow(case):
    return operating_point(case, speed=100 * RPM)


def test_boundary_lubrication_warning_fires_with_the_default_friction_model(case, slow):
    """At 100 rpm the EHL film is 58 nm against the raceway's σ = 0.30 µm: Λ ≈ 0.19. The
    catalogue friction model has no film of its own, yet the point warns."""
    assert case.friction.model == "catalogue"
    assert slow.film_thickness < 0.1e-6
    assert slow.film_parameter == pytest.approx(slow.film_thickness / 302.0e-9, rel=2e-3)
    assert any("boundary lubrication" in w for w in slow.warnings), slow.warnings
    summary = slow.summary()
    assert summary["lubrication_regime"] == "boundary"
    assert summary["film_parameter"]["value"] == pytest.approx(slow.film_parameter)


def test_film_parameter_does_not_depend_on_the_friction_model(case, slow):
    ball = ballscrew.case.with_overrides(case, {"friction.model": "ball_model"})
    point = operating_point(ball, speed=100 * RPM)
    assert point.film_parameter == pytest.approx(slow.film_parameter, rel=1e-9)
    # the ball model's own Λ (JGP separation over the same σ) agrees within its film share
    assert point.friction.film_parameter == pytest.approx(point.film_parameter, rel=0.05)


def test_films_are_named_and_contact_b_is_reported(case, slow):
    """h_c and h_min at the screw contact A, h_c at the nut contact B, each by hand from the
    ball model at the rolling entrainment speed of that contact."""
    model = ball_model(case)
    params = ScrewParameters.from_case(case)
    load = params.loaded_nut.ball_load
    films = {
        side: model.film(load, entrainment_speed(params.geometry, 100 * RPM, contact=side), side)
        for side in ("screw", "nut")
    }
    assert slow.film_thickness == pytest.approx(films["screw"].central, rel=1e-9)
    assert slow.film_thickness_minimum == pytest.approx(films["screw"].minimum, rel=1e-9)
    assert slow.film_thickness_nut == pytest.approx(films["nut"].central, rel=1e-9)
    summary = slow.summary()
    assert summary["film_thickness_nut"]["value"] == pytest.approx(slow.film_thickness_nut)
    assert summary["film_thickness_minimum"]["unit"] == "m"


def test_an_explicit_viscosity_beside_a_lubricant_is_warned_once(case):
    both = ballscrew.case.with_overrides(case, NAMED)
    point = operating_point(both, speed=100 * RPM)
    notes = [w for w in point.warnings if "medium.viscosity" in w]
    assert len(notes) == 1 and "iso_vg_68" in notes[0]
    assert point.viscosity == 0.06
    assert "fixed" in point.summary()["viscosity_source"]


def test_a_named_lubricant_follows_its_law_at_the_contact_temperature(case):
    named = ballscrew.case.with_overrides(
        case, {**NAMED, "medium.viscosity": None, "medium.pressure_viscosity": None}
    )
    point = operating_point(named, speed=100 * RPM)
    law = library_entry(named).at(point.contact_temperature)
    assert point.viscosity == pytest.approx(law.viscosity, rel=1e-9)
    assert not [w for w in point.warnings if "medium.viscosity" in w]
    summary = point.summary()
    assert "iso_vg_68" in summary["viscosity_source"]
    assert summary["viscosity_temperature"]["value"] == pytest.approx(point.contact_temperature)


def test_film_follows_the_entrainment_rule_as_hamrock_dowsons_speed_power(case, slow):
    """Only u_e differs between the two rules, so h_c(rolling)/h_c(ball centre) =
    (u_roll/V)^0.67 at A and B (Hamrock & Dowson 1977: H_c ∝ U^0.67), with u_roll/V ≈ 1 + γ,
    γ = D cosβ/d_m (1 + γ ≈ 1.11 here)."""
    centre = operating_point(
        ballscrew.case.with_overrides(case, {"kinematics.entrainment": "ball_centre"}),
        speed=100 * RPM,
    )
    g = ScrewParameters.from_case(case).geometry
    gamma = 2 * g.ball_radius * math.cos(g.contact_angle) / (2 * g.pitch_radius)
    v = entrainment_speed(g, 100 * RPM, "ball_centre")
    for side, rolling, at_centre in (
        ("screw", slow.film_thickness, centre.film_thickness),
        ("nut", slow.film_thickness_nut, centre.film_thickness_nut),
    ):
        ratio = entrainment_speed(g, 100 * RPM, contact=side) / v
        assert ratio == pytest.approx(1 + gamma, rel=0.02)
        assert rolling / at_centre == pytest.approx(ratio**0.67, rel=1e-9)
    assert slow.film_roughness == centre.film_roughness
