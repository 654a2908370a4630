"""Load ratings from the geometry: the limits and scalings of the Lundberg–Palmgren and ISO 76
forms (the comparison with makers' tables is in tests/validation/test_load_ratings.py)."""

from __future__ import annotations

import math

import pytest

from ballscrew import design
from ballscrew.contact.elastic import composite_modulus
from ballscrew.contact.hertz import hertz
from ballscrew.errors import InputError
from ballscrew.geometry import RacewayCurvature, ScrewGeometry, raceway_curvature

E_STAR = composite_modulus(206e9, 0.3, 206e9, 0.3)


def geometry(conformity: float = 0.53) -> ScrewGeometry:
    return ScrewGeometry(0.040, 0.010, 0.00635, conformity, conformity, math.pi / 4)


def test_more_turns_raise_the_dynamic_rating_by_the_power_0_7() -> None:
    g = geometry()
    z = design.balls_per_turn(0.040, 0.00635, 0.010)
    one = design.dynamic_load_rating(g, z)
    assert design.dynamic_load_rating(g, 4 * z) == pytest.approx(one * 4**0.7, rel=1e-12)


def test_a_closer_conformity_raises_the_dynamic_rating_by_the_lundberg_palmgren_power() -> None:
    """Both raceways of equal f: C_a ∝ (2f/(2f − 1))^0.41."""
    ratio = design.dynamic_load_rating(geometry(0.52), 90) / design.dynamic_load_rating(
        geometry(0.55), 90
    )
    assert ratio == pytest.approx((1.04 / 0.04 / (1.1 / 0.1)) ** 0.41, rel=1e-12)


def test_static_rating_puts_4200_mpa_on_the_more_stressed_contact() -> None:
    g, balls = geometry(), 90
    c0a = design.static_load_rating(g, balls, (E_STAR, E_STAR))
    ball_load = c0a / (balls * math.sin(g.contact_angle) * math.cos(g.lead_angle))
    peaks = []
    for side in ("screw", "nut"):
        c = raceway_curvature(g, side)
        peaks.append(hertz(c.rx, c.ry, E_STAR, ball_load).p0)
    assert max(peaks) == pytest.approx(4.2e9, rel=1e-9)
    assert peaks[0] > peaks[1]  # the convex screw groove is the more stressed


def test_ball_count_of_a_circuit() -> None:
    per_turn = math.pi * 40.0 / (6.35 * math.cos(math.atan(10.0 / (math.pi * 40.0))))
    assert design.circuit_ball_count(0.040, 0.00635, 0.010, 2.5) == math.floor(2.5 * per_turn) - 1
    with pytest.raises(InputError, match=r"^turns = 0\.05"):
        design.circuit_ball_count(0.040, 0.00635, 0.010, 0.05)


def test_palmgren_rating_leaves_a_permanent_deformation_of_1e_4_ball_diameters() -> None:
    """Palmgren in its own units: δ_s = 1.3e-7 Q² (Σρ_I)(Σρ_II)/D_w [mm, N, 1/mm] = 1e-4 D_w at
    the more deformed (screw) contact, whatever E*."""
    g, balls = geometry(), 90
    c0a = design.static_load_rating(g, balls, (E_STAR, E_STAR), model="palmgren")
    ball_load = c0a / (balls * math.sin(g.contact_angle) * math.cos(g.lead_angle))
    d_mm = g.ball_diameter * 1e3
    deformations = []
    for side in ("screw", "nut"):
        c = raceway_curvature(g, side)
        deformations.append(1.3e-7 * ball_load**2 * (c.h_xx * 1e-3) * (c.h_yy * 1e-3) / d_mm)
    assert max(deformations) == pytest.approx(1e-4 * d_mm, rel=1e-9)
    assert deformations[0] > deformations[1]
    softer = design.static_load_rating(g, balls, (0.5 * E_STAR, E_STAR), model="palmgren")
    assert softer == c0a


def test_palmgren_limit_is_near_the_iso_76_pressure_at_a_bearing_inner_ring() -> None:
    """At the geometry ISO 76 was set for (inner ring, f = 0.52, γ = 0.2) Palmgren's 1e-4 D_w
    falls at a Hertz peak pressure a few per cent below 4200 MPa; at a screw groove (f = 0.53,
    γ ≈ 0.1) about 4000 MPa, so C_0a is 12–19 % lower."""
    d_w, gamma, f = 0.010, 0.2, 0.52
    k_x = 2.0 / d_w * gamma / (1.0 - gamma)
    inner = RacewayCurvature("screw", k_x, 2.0 / d_w + k_x, 2.0 / d_w - 1.0 / (f * d_w), 0.0)
    load = design.STATIC_RATING_MODELS["palmgren"](inner, d_w, E_STAR, 4.2e9)
    assert 3.9e9 < hertz(inner.rx, inner.ry, E_STAR, load).p0 < 4.2e9
    g = geometry()
    ratio = design.static_load_rating(g, 90, (E_STAR,) * 2, model="palmgren") / (
        design.static_load_rating(g, 90, (E_STAR,) * 2)
    )
    assert 0.80 < ratio < 0.90


def test_static_rating_models_are_a_registry() -> None:
    assert design.STATIC_RATING_MODELS.names == ("iso76", "palmgren")
    with pytest.raises(InputError, match=r"^design\.static_rating_model = 'hertz'"):
        design.static_load_rating(geometry(), 90, (E_STAR, E_STAR), model="hertz")
