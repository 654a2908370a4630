"""The preload update through the worn groove's own contact (``wear.preload_contact = "worn"``):
the closed-form limits of (E1.13) and the sign of the conforming groove's effect."""

from __future__ import annotations

import math

import numpy as np
import pytest

import ballscrew
from ballscrew.analyses.wear import wear_setup
from ballscrew.case import Case, with_overrides
from ballscrew.errors import InputError
from ballscrew.wear import preload_after

from .conftest import REF_PATH

LOADS = {"wear.grid": [16, 64]}


@pytest.fixture(scope="module")
def case() -> Case:
    return ballscrew.load_case(REF_PATH, {**LOADS, "wear.preload_contact": "worn"})


def test_a_uniformly_lowered_groove_is_the_hertz_law(case: Case) -> None:
    """A depth h over the whole groove shifts the contact rigidly: δ_worn − δ_unworn = h, so the
    worn contact's preload is (E1.13) with h_max = h (to the solver's tolerance)."""
    setup = wear_setup(case)
    for h in (0.3e-6, 1.0e-6, 2.0e-6):
        depth = np.full((2, setup.y.size), h)
        preload, solves = preload_after(setup, depth)
        assert solves >= 2
        assert preload == pytest.approx(setup.preload(h), rel=1e-4)


def test_no_wear_keeps_the_initial_preload_without_a_solve(case: Case) -> None:
    setup = wear_setup(case)
    preload, solves = preload_after(setup, np.zeros((2, setup.y.size)))
    assert solves == 0 and preload == pytest.approx(setup.initial_preload, rel=1e-12)


def test_a_conforming_groove_keeps_more_preload_than_its_deepest_point_says(case: Case) -> None:
    """A groove worn deepest at the contact's centre and less towards its edges (the worn shape)
    carries the ball over a wider, more conforming contact: it loses less interference than
    h_max, so more preload is left than (E1.13) with h_max gives, and less than none worn."""
    setup = wear_setup(case)
    b = 0.6 * float(np.max(np.abs(setup.y)))
    shape = np.clip(1.0 - (setup.y / b) ** 2, 0.0, None)
    for h in (0.5e-6, 1.5e-6):
        depth = np.vstack([h * shape, 0.9 * h * shape])
        preload, _ = preload_after(setup, depth)
        hertz = setup.preload(h)
        assert hertz < preload < setup.initial_preload
        assert preload > 1.02 * hertz


def test_the_default_is_the_hertz_law_of_the_largest_depth() -> None:
    """The default (``"hertz"``) history: F_p of (E1.13) at every recorded h_max,
    (F_p0^(2/3) − h_max/(sinβ cosλ C_a))^(3/2)."""
    case = ballscrew.load_case(REF_PATH, {**LOADS, "wear.max_depth_step": 3e-7})
    life = ballscrew.wear_life(case)
    setup = wear_setup(case)
    g = setup.geometry
    s = math.sin(g.contact_angle) * math.cos(g.lead_angle)
    assert setup.body_compliance == 0.0  # the uniform distribution: contacts only
    left = setup.initial_preload ** (2 / 3) - life.max_wear_depth / (s * setup.compliance)
    expected = np.clip(left, 0.0, None) ** 1.5  # (E1.13) written out
    np.testing.assert_allclose(life.preload, expected, rtol=1e-12)


def test_a_life_with_the_worn_contact(case: Case) -> None:
    """Monotone depth, preload ≥ 0 and falling; more preload left than the Hertz update
    (about +10 % on the step-stress test), the same wear to a few per cent."""
    coarse = with_overrides(case, {"wear.max_depth_step": 3e-7})
    worn = ballscrew.wear_life(coarse)
    hertz = ballscrew.wear_life(with_overrides(coarse, {"wear.preload_contact": "hertz"}))
    assert np.all(np.diff(worn.max_wear_depth) >= 0.0)
    assert np.all(worn.preload >= 0.0) and np.all(np.diff(worn.preload) <= 1e-9)
    ratio = worn.preload[-1] / hertz.preload[-1]
    assert 1.04 < ratio < 1.25, ratio
    assert worn.max_wear_depth[-1] == pytest.approx(hertz.max_wear_depth[-1], rel=0.05)
    assert worn.contact_solves > hertz.contact_solves
    assert math.isclose(worn.revolutions[-1], hertz.revolutions[-1])


def test_an_unknown_preload_contact_is_refused() -> None:
    with pytest.raises((InputError, ValueError), match="preload_contact"):
        ballscrew.load_case(REF_PATH, {"wear.preload_contact": "exact"})
