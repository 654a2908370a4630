"""Per-ball wear with the elastic distribution: load classes, conservation, convergence."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

import ballscrew
from ballscrew.analyses.wear import wear_life, wear_setup
from ballscrew.case import with_overrides
from ballscrew.loads import nut_forces
from ballscrew.wear import flank_rate
from ballscrew.wear.life import integrate_wear
from ballscrew.wear.load_classes import UNIFORM, LoadClasses, load_classes

from .conftest import REF_PATH, SPEED, short_programme

SPREAD = np.linspace(0.6, 1.4, 54)
"""Per-ball load ratios of a nut with a strong lead error (±40 %), 54 balls."""


def _classes(setup, classes: LoadClasses):
    loads = {part.axial_load for lv in setup.spec.programme for _, part in lv.parts()}
    return replace(setup, ball_classes=tuple((a, (classes, classes)) for a in sorted(loads)))


def test_equal_count_classes_keep_the_nut_force():
    c = load_classes(SPREAD * 70.0, 3)
    assert len(c.ratios) == 3 and sum(c.weights) == pytest.approx(1.0, rel=1e-14)
    assert sum(w * r for r, w in zip(c.ratios, c.weights, strict=True)) == pytest.approx(1.0)
    assert c.ratios == pytest.approx(
        (0.6 + 8.5 * 0.8 / 53, 1.0, 1.4 - 8.5 * 0.8 / 53)
    )  # class means
    assert load_classes(np.full(54, 70.0), 5) == UNIFORM
    assert load_classes(np.zeros(54), 3) == UNIFORM  # a lifted-off nut
    assert load_classes(SPREAD, 99).ratios == pytest.approx(tuple(SPREAD))  # per ball


def test_uniform_classes_give_todays_numbers(coarse_case):
    """Three classes all at the mean load reproduce the uniform run to 1e-10."""
    setup = wear_setup(with_overrides(coarse_case, {"wear.programme": short_programme(3.0e4)}))
    today = integrate_wear(setup, "u")
    split = integrate_wear(_classes(setup, LoadClasses((1.0, 1.0, 1.0), (0.25, 0.5, 0.25))), "s")
    np.testing.assert_allclose(split.profiles, today.profiles, rtol=1e-10, atol=1e-22)
    np.testing.assert_allclose(split.preload, today.preload, rtol=1e-10)
    assert split.contact_solves > today.contact_solves


@pytest.fixture(scope="module")
def elastic_life(coarse_case):
    case = with_overrides(
        coarse_case,
        {"loads.distribution": "elastic", "wear.programme": short_programme(5.0e4)},
    )
    setup = _classes(wear_setup(case), load_classes(SPREAD, 3))
    return setup, integrate_wear(setup, "e")


def test_per_ball_wear_conserves_volume_and_stays_physical(elastic_life):
    """Worn volume L_w ∫ h dy = ∫ Σ_k w_k Z ∫∫ w_k dA dt; depth monotone, F_p ≥ 0."""
    s, life = elastic_life
    assert np.all(np.diff(life.profiles, axis=0) >= 0.0)
    assert np.all(np.diff(life.preload) <= 0.0) and np.all(life.preload >= 0.0)
    removed = np.zeros(2)
    for k in range(life.revolutions.size - 1):
        level = s.spec.programme[int(life.level[k + 1])]
        dn = life.revolutions[k + 1] - life.revolutions[k]
        forces = nut_forces(life.preload[k], level.axial_load)
        for j, flank in enumerate((1, -1)):
            for nut, force in enumerate(forces, start=1):
                if force <= 0.0:
                    continue
                c = s.load_classes(level.axial_load, nut)
                for r, w in zip(c.ratios, c.weights, strict=True):
                    out = flank_rate(
                        s, flank, force, level.speed, life.profiles[k, j], None, None, r
                    )
                    volume_rate = s.balls * out.cell_rate.sum() * s.cell_area
                    removed[j] += 0.5 * w * volume_rate * dn * 2 * math.pi / level.speed
    worn = s.raceway_length * life.profiles[-1].sum(axis=1) * s.dy
    np.testing.assert_allclose(worn, removed, rtol=1e-5)


def test_an_uneven_nut_wears_less_than_its_mean_load_and_three_classes_converge():
    """The wear law is sublinear in the ball load (ḣ ∝ Q^0.7–0.8 on the reference screw), so by
    Jensen's inequality the per-ball mean of ±40 % loads wears less than the mean load would;
    three equal-count classes come within 0.5 % of the 54-ball sum, one class is 1.5 % off."""
    case = ballscrew.load_case(REF_PATH, {"wear.grid": [24, 96], "wear.box_factor": 1.8})
    s = wear_setup(case)
    f1 = nut_forces(s.initial_preload, 2000.0)[0]
    zero = np.zeros_like(s.y)

    def rate(c: LoadClasses) -> float:
        return sum(
            w * flank_rate(s, 1, f1, SPEED, zero, load_ratio=r).depth_per_revolution.sum()
            for r, w in zip(c.ratios, c.weights, strict=True)
        )

    low, mid, high = (rate(LoadClasses((r,), (1.0,))) for r in (0.5, 1.0, 2.0))
    assert math.log2(mid / low) < 0.9 and math.log2(high / mid) < 0.9  # sublinear
    per_ball = rate(load_classes(SPREAD, 54))
    assert mid > 1.01 * per_ball
    assert rate(load_classes(SPREAD, 3)) == pytest.approx(per_ball, rel=5e-3)


def test_the_elastic_case_wears_per_ball(coarse_case):
    """loads.distribution = "elastic": each nut's classes come from the distribution."""
    case = with_overrides(
        coarse_case,
        {"loads.distribution": "elastic", "wear.programme": short_programme(2.0e4)},
    )
    s = wear_setup(case)
    assert [a for a, _ in s.ball_classes] == [2000.0, 3000.0, 4000.0]
    for _, pair in s.ball_classes:
        for c in pair:
            assert len(c.ratios) == 3 and c.ratios[0] < 1.0 < c.ratios[-1]
    life = wear_life(case)
    assert np.all(life.preload >= 0.0) and life.max_wear_depth[-1] > 0.0
    uniform = wear_setup(coarse_case)
    assert uniform.ball_classes == () and uniform.load_classes(2000.0, 1) == UNIFORM
