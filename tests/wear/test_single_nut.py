"""Wear life of a preloaded single nut (theory manual, *Wear*: the preloaded single nut).

A four-point nut (oversized balls) wears its two flanks as a double nut's two nuts with all its
balls on each flank; an offset-lead nut as a double nut of half its balls per half. With rigid
bodies and no lead or ball errors (``loads.distribution = "uniform"``) both equal those double
nuts exactly; with the elastic bodies the offset-lead nut still does (same layout, the lead-shift
zone as the spacer), the four-point nut does not (its preload loop is the ring alone).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew.analyses.ball_loads import nut_model
from ballscrew.analyses.parameters import ScrewParameters
from ballscrew.analyses.wear import _preload_loop_compliance, wear_life, wear_setup
from ballscrew.calibration import calibrate, measured_history
from ballscrew.case import with_overrides
from ballscrew.errors import InputError
from ballscrew.loads import preload_after_wear

FOUR_POINT = {"screw.nuts": 1, "screw.preload_method": "oversized_balls"}
OFFSET_LEAD = {"screw.nuts": 1, "screw.preload_method": "offset_lead"}
ELASTIC = {"loads.distribution": "elastic", "wear.load_classes": 3}

# nuts = 2, coarse case, before the single nut was admitted: h_max [m], F_p [N], T [N m]
DOUBLE_NUT = {
    "uniform": (4.917500065146882e-07, 1192.0781622569593, 0.3362790409600643),
    "elastic": (4.9332175337321e-07, 1215.0287847417328, 0.34275329203098737),
}


def _histories_equal(a, b, rtol: float = 1e-9) -> None:
    for name in ("revolutions", "max_wear_depth", "preload", "friction_torque", "nut_forces"):
        np.testing.assert_allclose(getattr(a, name), getattr(b, name), rtol=rtol, err_msg=name)
    np.testing.assert_allclose(a.profiles, b.profiles, rtol=rtol, atol=1e-9 * a.profiles.max())


@pytest.mark.parametrize("distribution", ["uniform", "elastic"])
def test_double_nut_results_do_not_move(coarse_case, distribution) -> None:
    """Admitting the single nut leaves every double-nut number as it was (to 1e-12)."""
    extra = ELASTIC if distribution == "elastic" else {}
    life = wear_life(with_overrides(coarse_case, extra))
    got = (life.max_wear_depth[-1], life.preload[-1], life.friction_torque[-1])
    assert got == pytest.approx(DOUBLE_NUT[distribution], rel=1e-12)
    assert life.steps == 15


def test_rigid_four_point_nut_equals_the_double_nut(coarse_case) -> None:
    """Rigid bodies, no errors: a four-point nut of 54 balls (both contact pairs on all 54) wears,
    loses preload and drags exactly as a double nut of 54 balls per nut: same flank forces (P1),
    same C_a (E1.8) and ball load per flank, no body compliance."""
    double = wear_life(coarse_case)
    four = wear_life(with_overrides(coarse_case, FOUR_POINT))
    assert wear_setup(with_overrides(coarse_case, FOUR_POINT)).balls == 54
    _histories_equal(four, double)


@pytest.mark.parametrize("distribution", ["uniform", "elastic"])
def test_offset_lead_nut_equals_the_double_nut_of_half_the_balls(coarse_case, distribution):
    """An offset-lead nut of 54 balls = a double nut of 27 balls per nut, the lead-shift zone in
    the spacer's place (both one lead by default): rigid, and with the elastic bodies."""
    extra = ELASTIC if distribution == "elastic" else {}
    double = wear_life(with_overrides(coarse_case, extra | {"screw.balls_per_nut": 27}))
    offset = with_overrides(coarse_case, extra | OFFSET_LEAD)
    assert wear_setup(offset).balls == 27
    _histories_equal(wear_life(offset), double)


def test_four_point_preload_interference_law(ref_case) -> None:
    """The four-point nut's preload loop: at F_a = 0 both pairs of a ball carry Q_p, the bars
    carry no net force, and the ring (D3) under the line load of both pairs gives the body
    compliance c_b = 2 cos²β c_r n_t / (L n_b s²), n_t = π d_m/(D_b cosα) balls per turn; the
    double nut's c_b (its bars and one pair's ring) is larger."""
    case = with_overrides(ref_case, FOUR_POINT | {"loads.distribution": "elastic"})
    params = ScrewParameters.from_case(case)
    _, bodies = nut_model(params, case.loads)
    g = params.geometry
    s = math.sin(g.contact_angle) * math.cos(g.lead_angle)
    per_turn = math.pi * g.pitch_diameter / (g.ball_diameter * math.cos(g.lead_angle))
    ring = 2.0 * math.cos(g.contact_angle) ** 2 * bodies.ring_compliance * per_turn
    closed = ring / (g.lead * params.balls_per_nut * s * s)
    assert _preload_loop_compliance(case, params) == pytest.approx(closed, rel=1e-9)
    double = with_overrides(ref_case, {"loads.distribution": "elastic"})
    assert _preload_loop_compliance(double, ScrewParameters.from_case(double)) > 1.05 * closed
    setup = wear_setup(case)
    assert setup.body_compliance == pytest.approx(closed, rel=1e-9)
    # the oversize left after a wear depth h: C_a F^(2/3) + c_b F = C_a F_p0^(2/3) + c_b F_p0 − h/s
    h = 1.0e-6
    fp = setup.preload(h)
    c_a, fp0 = setup.compliance, setup.initial_preload
    assert c_a * fp ** (2 / 3) + closed * fp == pytest.approx(
        c_a * fp0 ** (2 / 3) + closed * fp0 - h / s, rel=1e-12
    )
    rigid = preload_after_wear(fp0, c_a, h, g.contact_angle, g.lead_angle)
    assert rigid < fp < fp0  # the ring in series softens the loop: less preload lost per depth


def test_preload_falls_to_zero_and_stays_there(coarse_case) -> None:
    """A four-point nut worn well past its oversize: the depth grows monotonically on every
    cell, the preload falls monotonically to 0 and never below (E1.13), the torque with it; then
    flank 1 carries F_a alone and flank 2 nothing."""
    case = with_overrides(
        coarse_case, FOUR_POINT | {"wear.coefficient": 1.5e-3, "wear.box_factor": 2.0}
    )
    life = wear_life(case)
    setup = wear_setup(case)
    assert np.all(np.diff(life.max_wear_depth) > 0.0)
    assert np.all(np.diff(life.profiles, axis=0) >= 0.0)
    assert np.all(np.diff(life.preload) <= 0.0)
    assert np.all(life.preload >= 0.0) and life.preload[-1] == 0.0
    assert np.all(life.friction_torque >= 0.0) and life.friction_torque[-1] == 0.0
    np.testing.assert_allclose(life.nut_forces[-1], [4000.0, 0.0])
    g = setup.geometry
    s = math.sin(g.contact_angle) * math.cos(g.lead_angle)
    lost = setup.compliance * 1500.0 ** (2 / 3) * s  # the oversize, normal to the flank
    assert life.max_wear_depth[life.preload > 0.0].max() < lost <= life.max_wear_depth[-1]


def test_single_nut_without_preload_is_refused(coarse_case) -> None:
    """One loaded flank: wear would open backlash, not lose preload; refused in one line."""
    case = with_overrides(coarse_case, FOUR_POINT | {"operating.preload": 0.0})
    with pytest.raises(InputError, match=r"^operating\.preload = 0\.0 .*backlash") as err:
        wear_life(case)
    assert "\n" not in str(err.value)


@pytest.mark.filterwarnings("ignore::ballscrew.calibration.CalibrationWarning")
def test_calibration_recovers_k_of_a_four_point_nut(coarse_case) -> None:
    """``calibrate`` runs the single nut's wear model: the torque history of a four-point nut
    at K = 2e-4 gives K back (noise-free data: the residuals' runs test warns, ignored)."""
    case = with_overrides(coarse_case, FOUR_POINT)
    life = wear_life(with_overrides(case, {"wear.coefficient": 2.0e-4}))
    at = life.sampled
    data = measured_history(life.revolutions[at], life.friction_torque[at], "friction_torque")
    result = calibrate(case, data, fit="wear_coefficient")
    assert result.wear_coefficient == pytest.approx(2.0e-4, rel=1e-3)
