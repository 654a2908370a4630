"""Single nut preloaded by oversized balls (four-point contact) or an offset lead: its limits."""

from __future__ import annotations

import numpy as np
import pytest
from tests.loads.test_distribution import ALPHA, BALL, BETA, BODIES, D_M, LEAD, K

from ballscrew.errors import InputError
from ballscrew.loads import Flanks, flank_forces, nut_forces, preload_flanks, preload_methods
from ballscrew.loads.distribution import (
    NutBodies,
    ball_layout,
    expand_errors,
    lift_off_load,
    solve_distribution,
)

FP = 1500.0


def four_point(balls: int = 54):
    return ball_layout(balls, 2, LEAD, D_M, BALL, ALPHA, LEAD, shared=True)


def solve(layout, fa: float, bodies=BODIES, **kw):
    return solve_distribution(layout, K, BETA, ALPHA, fa, FP, bodies, **kw)


def test_flanks_of_each_method() -> None:
    assert preload_flanks("spacer", 2, 54, FP) == Flanks(2, 54, False)
    assert preload_flanks("oversized_balls", 1, 54, FP) == Flanks(2, 54, True)
    assert preload_flanks("offset_lead", 1, 54, FP) == Flanks(2, 27, False)
    assert preload_flanks("oversized_balls", 1, 54, 0.0) == Flanks(1, 54, False)
    with pytest.raises(InputError, match=r"preload_method.*spacer for nuts = 2"):
        preload_flanks("oversized_balls", 2, 54, FP)
    with pytest.raises(InputError, match=r"balls_per_nut = 53.*even"):
        preload_flanks("offset_lead", 1, 53, FP)


def test_methods_per_nut_count_default_first() -> None:
    assert preload_methods(2) == ("spacer",)
    assert preload_methods(1) == ("oversized_balls", "offset_lead")
    assert preload_methods(3) == ()
    with pytest.raises(InputError, match=r"nuts = 3.*1 or 2"):
        preload_flanks("spacer", 3, 54, FP)


def test_four_point_layout_puts_both_flanks_on_the_same_balls() -> None:
    lay = four_point()
    assert lay.z.size == 108 and lay.balls == 54
    assert np.array_equal(lay.z[:54], lay.z[54:])
    assert np.array_equal(lay.flank, np.repeat([1.0, -1.0], 54))
    # one value per ball (or per turn) of the one nut, on both flanks
    per_ball = np.arange(54.0)
    assert np.array_equal(expand_errors("e", per_ball, lay), np.tile(per_ball, 2))
    per_turn = expand_errors("e", [1.0, 2.0, 3.0], lay)
    assert np.array_equal(per_turn[:54], per_turn[54:]) and per_turn[0] == 1.0
    with pytest.raises(InputError, match="54 \\(one per ball\\) or 3 \\(one per turn\\)"):
        expand_errors("e", np.zeros(108), lay)


@pytest.mark.parametrize("fa", [0.0, 1000.0, 2.0**1.5 * FP, 6000.0])
def test_rigid_four_point_nut_is_the_double_nut_of_all_its_balls(fa: float) -> None:
    """Contacts only: each flank carries F1, F2 of (P1)–(P3), every ball the same load."""
    four = solve(four_point(), fa, NutBodies())
    double = solve(ball_layout(54, 2, LEAD, D_M, BALL, ALPHA, LEAD), fa, NutBodies())
    f1, f2 = nut_forces(FP, fa)
    assert four.nut_forces == pytest.approx([f1, f2], rel=1e-10, abs=1e-9 * FP)
    assert four.loads == pytest.approx(double.loads, rel=1e-10, abs=1e-12)
    assert four.stiffness == pytest.approx(double.stiffness, rel=1e-10)


@pytest.mark.parametrize("fa", [0.0, 1500.0, 4000.0, 9000.0])
def test_force_balance_to_1e_10_with_bodies_and_errors(fa: float) -> None:
    rng = np.random.default_rng(2)
    d = solve(
        four_point(), fa, lead_error=rng.normal(0, 1e-6, 54), ball_excess=rng.normal(0, 5e-7, 54)
    )
    assert d.axial_share * np.sum(d.layout.flank * d.loads) == pytest.approx(
        fa, abs=1e-10 * max(fa, FP)
    )
    assert np.all(d.loads >= 0.0)


def test_lift_off_at_two_to_the_three_halves_preload_contact_only() -> None:
    assert lift_off_load(four_point(), K, BETA, ALPHA, FP, NutBodies(), 1e-9) == pytest.approx(
        2.0**1.5 * FP, rel=1e-8
    )


def test_stiffness_is_the_derivative_of_the_load_deflection_curve() -> None:
    lay = four_point()
    g = solve(lay, 0.0).interference
    h = 1.0
    x = [solve(lay, f, interference=g).displacement for f in (2000.0 - h, 2000.0 + h)]
    assert solve(lay, 2000.0, interference=g).stiffness == pytest.approx(
        2.0 * h / (x[1] - x[0]), rel=1e-6
    )


def test_both_contact_pairs_widen_one_ring() -> None:
    """The radial line load of a four-point nut is that of both pairs, Q₁ + Q₂, which is even in
    F_a (swap the flanks): at F_a = 0 the ring's widening leaves the stiffness as it is, while
    each half of a double nut widens its own ring and softens; under load both soften."""
    ring = NutBodies(ring_compliance=BODIES.ring_compliance)
    double_layout = ball_layout(54, 2, LEAD, D_M, BALL, ALPHA, LEAD)
    for fa, four_drop in ((0.0, False), (3000.0, True)):
        four = [solve(four_point(), fa, b).stiffness for b in (NutBodies(), ring)]
        double = [solve(double_layout, fa, b).stiffness for b in (NutBodies(), ring)]
        assert double[1] < 0.99 * double[0]
        if four_drop:
            assert four[1] < 0.99 * four[0]
        else:
            assert four[1] == pytest.approx(four[0], rel=1e-9)


def test_flank_forces_of_one_and_two_flanks() -> None:
    assert flank_forces(FP, 500.0, 1) == (2000.0, 0.0)
    # two flanks: the contact-only double-nut law, F1 − F2 = F_a and equal and opposite
    # Hertz approaches, F1^(2/3) + F2^(2/3) = 2 F_p^(2/3) (below lift-off)
    f1, f2 = flank_forces(FP, 500.0, 2)
    assert f1 - f2 == pytest.approx(500.0, rel=1e-12)
    assert f1 ** (2 / 3) + f2 ** (2 / 3) == pytest.approx(2 * FP ** (2 / 3), rel=1e-9)
    with pytest.raises(InputError, match="flanks"):
        flank_forces(FP, 500.0, 3)
