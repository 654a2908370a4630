"""Duty cycles: the case list, its repetition, the moving share of a segment and bad input."""

from __future__ import annotations

import itertools
import math

import pytest

import ballscrew
from ballscrew.analyses.duty import duty_schedule, moving_fraction
from ballscrew.case import CaseError

RPM = 2 * math.pi / 60

CYCLE = [
    {"speed": "1500 rpm", "axial_load": "2 kN", "stroke": "400 mm", "dwell": "2 s",
     "duration": "40 min"},
    {"speed": 0, "duration": "20 min"},
]  # fmt: skip


def test_schedule_repeats_the_list_back_to_back(gao_case_path):
    case = ballscrew.load_case(gao_case_path, {"duty": CYCLE, "duty_repeat": 8})
    phases = duty_schedule(case)
    assert len(phases) == 16
    assert phases[0].start == 0.0 and phases[-1].end == pytest.approx(8 * 3600.0)
    assert all(a.end == b.start for a, b in itertools.pairwise(phases))
    assert phases[0].speed == pytest.approx(1500 * RPM) and phases[0].axial_load == 2000.0
    assert phases[1].mean_speed == 0.0


def test_moving_fraction_is_stroke_time_over_stroke_and_dwell_time():
    # 1500 rpm, 10 mm lead: 0.25 m/s; a 400 mm stroke takes 1.6 s, then 2 s standstill
    assert moving_fraction(1500 * RPM, 0.01, 0.4, 2.0) == pytest.approx(1.6 / 3.6)
    assert moving_fraction(1500 * RPM, 0.01, 0.4, 0.0) == 1.0
    assert moving_fraction(1500 * RPM, 0.01, 0.0, 2.0) == 1.0
    assert moving_fraction(0.0, 0.01, 0.4, 2.0) == 0.0


def test_no_duty_is_an_empty_schedule(gao_case_path):
    assert duty_schedule(ballscrew.load_case(gao_case_path, {"duty": []})) == ()


@pytest.mark.parametrize(
    ("segment", "field"),
    [
        ({"speed": 10.0, "duration": 0}, "duty.0.duration"),
        ({"speed": 10.0, "duration": "-1 min"}, "duty.0.duration"),
        ({"speed": 10.0, "duration": "1 s", "dwell": "2 s"}, "dwell"),
        ({"speed": "1 %", "duration": "1 s"}, "duty.0.speed"),
    ],
)
def test_bad_segments_are_one_line_errors(gao_case_path, segment, field):
    with pytest.raises(CaseError) as info:
        ballscrew.load_case(gao_case_path, {"duty": [segment]})
    message = str(info.value)
    assert field in message and "\n" not in message
