"""A preloaded single nut in the TCR, thermal-interface and kinematics chains: both loaded
flanks count, each with ``params.flanks.balls`` balls, compared with the double nut that has the
same balls per flank and with hand numbers."""

from __future__ import annotations

import pytest
from tests.quick_cases import EXAMPLES

from ballscrew.analyses.kinematics import (
    ball_kinematics,
    ball_model,
    computed_drag_torque,
    run_kinematics,
)
from ballscrew.analyses.parameters import ScrewParameters
from ballscrew.analyses.screw_tcr import screw_tcr
from ballscrew.analyses.thermal_setup import build_problem
from ballscrew.case import load_case, with_overrides
from ballscrew.contact_resistance import parallel_resistance
from ballscrew.kinematics.torque import ball_drag

FOUR = {"screw.nuts": 1}
OFFSET = {"screw.nuts": 1, "screw.preload_method": "offset_lead"}
LOAD = {"operating.axial_load": "2000 N"}
SPEED = 104.72


@pytest.fixture(scope="module")
def case():
    base = load_case(EXAMPLES / "gao2019_tcr.toml")
    return lambda **overrides: with_overrides(base, overrides)


@pytest.fixture(scope="module")
def double(case):
    return screw_tcr(case())


def test_four_point_tcr_is_the_double_nuts_at_zero_axial_load(case, double):
    """Each four-point ball carries F_p on two contact pairs: the 54 balls × 2 pairs make the
    same parallel paths as the double nut's 54 + 54 balls (R = 0.01948 K/W)."""
    four = screw_tcr(case(**FOUR))
    assert [(n.index, n.balls) for n in four.nuts] == [(1, 54), (2, 54)]
    assert four.nut_forces == pytest.approx(double.nut_forces, rel=1e-12)
    assert four.resistance == pytest.approx(double.resistance, rel=1e-12)
    assert four.resistance == pytest.approx(0.5 * double.nuts[0].resistance, rel=1e-12)


def test_offset_lead_halves_carry_their_own_flank_load(case):
    """27 balls per half: Q = F/(Z sinβ cosα) is twice the 54-ball double nut's at the same
    flank force, and R is above the double nut's under axial load (fewer, not more, balls)."""
    double = screw_tcr(case(**LOAD))
    offset = screw_tcr(case(**OFFSET, **LOAD))
    assert [n.balls for n in offset.nuts] == [27, 27]
    assert offset.nut_forces == pytest.approx(double.nut_forces, rel=1e-12)
    for half, nut in zip(offset.nuts, double.nuts, strict=True):
        assert half.ball_load == pytest.approx(2.0 * nut.ball_load, rel=1e-12)
    assert offset.resistance > double.resistance


def test_single_nut_thermal_interface_takes_both_flanks_in_parallel(case):
    """The one nut body of a four-point nut gets both contact pairs' paths in parallel: the
    double nut's two interfaces in parallel."""
    torque = {"thermal.drag_torque.source": "catalogue", "thermal.sensors": []}
    two = build_problem(case(**torque))[3]
    single = build_problem(case(**FOUR, **torque))[3]
    assert len(single) == 1
    both = parallel_resistance([i.resistance for i in two])
    assert single[0].resistance == pytest.approx(float(both), rel=1e-12)
    micro = parallel_resistance([i.micro_resistance for i in two])
    assert single[0].micro_resistance == pytest.approx(float(micro), rel=1e-12)


def test_four_point_drag_is_the_double_nuts(case):
    """At F_a = 0 both contact pairs of a four-point ball carry F_p: the same contact losses as
    the double nut with 54 balls per flank (0.1213 N m)."""
    double = computed_drag_torque(case(), SPEED)
    assert computed_drag_torque(case(**FOUR), SPEED) == pytest.approx(double, rel=1e-12)


def test_offset_lead_drag_is_both_halves_by_hand(case):
    """T = Σ over the two flanks of 27 × one ball's dissipation torque at that flank's load."""
    offset = case(**OFFSET, **LOAD)
    model_balls = ScrewParameters.from_case(offset).flanks.balls
    model = ball_model(offset)
    by_hand = sum(
        model_balls * ball_drag(model, ball_kinematics(offset, SPEED, nut=k)).dissipation_torque
        for k in (1, 2)
    )
    assert model_balls == 27
    assert computed_drag_torque(offset, SPEED) == pytest.approx(by_hand, rel=1e-12)


def test_kinematics_report_entries_add_up_to_the_contact_losses(case):
    """The per-flank contact-loss entries use the balls of a flank (27 for an offset-lead half)."""
    run = run_kinematics(case(**OFFSET, **{"kinematics.speed_points": 3}), SPEED, level=0)
    summary = run.summary()
    parts = [entry["contact_losses"]["value"] for entry in summary["nuts"].values()]
    total = summary["drag_torque"]["contact_losses"]["value"]
    assert len(parts) == 2
    assert sum(parts) == pytest.approx(total, rel=1e-12)


def test_the_tcr_report_says_nut_1_and_2_are_the_flanks_of_a_single_nut(case, double):
    from ballscrew.analyses.tcr_report import sections

    def text(result) -> str:
        return " ".join(sections(result)[0].paragraphs)

    assert "four-point contact" in text(screw_tcr(case(**FOUR)))
    assert "two halves" in text(screw_tcr(case(**OFFSET)))
    assert "loaded flanks" not in text(double)


def test_screw_parameters_nut_forces_are_the_flanks_of_a_preloaded_single_nut(case):
    """(F1, F2) of (P1)–(P3) for either preload method, as for the double nut; (F_a, 0) for a
    single nut without preload (F2 was 0 for every single nut, its second flank left out)."""
    from ballscrew.loads import nut_forces

    expected = tuple(nut_forces(1500.0, 2000.0))
    for overrides in ({}, FOUR, OFFSET):
        params = ScrewParameters.from_case(case(**overrides, **LOAD))
        assert params.preload == 1500.0
        assert params.nut_forces == pytest.approx(expected, rel=1e-12)
    bare = ScrewParameters.from_case(case(**OFFSET, **LOAD, **{"operating.preload": 0.0}))
    assert bare.nut_forces == (2000.0, 0.0)


def test_the_operating_point_report_names_a_lifted_flank(case):
    """A four-point nut at F_a = 5 kN > 2^1.5 F_p = 4243 N: flank 2 is lifted off, and the
    report says so instead of printing 'nan nm' for 'nut 2'."""
    from ballscrew.analyses.operating_point import operating_point
    from ballscrew.analyses.operating_point_report import sections

    point = operating_point(case(**FOUR, **{"thermal.sensors": []}), axial_load=5000.0)
    rows = {row[0]: row[1] for s in sections(point) for t in s.tables for row in t.rows}
    label = "central film h_c, screw contact A of flank 2 at its ball load [nm]"
    assert rows[label] == "— (lifted off or dry)"
    assert rows["central film h_c, screw contact A of nut 1 [nm]"] > 0.0
