"""A reverse ``[[duty]]`` segment (F_a < 0) in the duty schedule and the working day.

ASSUMED mirror symmetry: the nut under −F_a is the nut under +F_a with nut 1 and nut 2 swapped,
so a reverse segment makes the friction heat of |F_a| (theory manual, *Operating point*).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import ballscrew
from ballscrew.analyses.duty import duty_schedule
from ballscrew.analyses.duty_thermal import thermal_duty
from ballscrew.analyses.operating_point import operating_point

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "gao2019_tcr.toml"


def cycle(load: str) -> list[dict]:
    return [
        {"speed": "1500 rpm", "axial_load": load, "stroke": "400 mm", "dwell": "2 s",
         "duration": "40 min"},
        {"speed": 0, "duration": "20 min"},
    ]  # fmt: skip


def day(*loads: str):
    segments = [seg for load in loads for seg in cycle(load)]
    return thermal_duty(ballscrew.load_case(EXAMPLE, {"duty": segments}), "network")


def test_the_schedule_keeps_the_sign() -> None:
    case = ballscrew.load_case(EXAMPLE, {"duty": cycle("-2 kN")})
    assert [p.axial_load for p in duty_schedule(case)] == [-2000.0, 0.0] * case.duty_repeat


def test_a_reverse_day_heats_as_the_forward_day() -> None:
    forward, reverse = day("2 kN"), day("-2 kN")
    assert reverse.segment_heat == forward.segment_heat
    np.testing.assert_array_equal(reverse.friction_heat, forward.friction_heat)
    # the heat sits on the other nut of an assembly not centred on the shaft: nearly the same
    np.testing.assert_allclose(reverse.elongation, forward.elongation, rtol=1e-4, atol=1e-12)


def test_a_reverse_load_heats_nut_2() -> None:
    """Under −F_a nut 2 carries the load and the larger share of the heat (F₁ = 3270 N,
    F₂ = 270 N at 3 kN, 1.5 kN preload): the nuts' sensors are the forward day's swapped, the
    loaded nut the hot one. The reverse day once heated nut 1, as the forward day (8 K off)."""
    forward, reverse = (thermal_duty(ballscrew.load_case(EXAMPLE, {"duty": [
        {"speed": "1500 rpm", "axial_load": load, "duration": "40 min"},
        {"speed": 0, "duration": "20 min"},
    ]}), "network") for load in ("3 kN", "-3 kN"))  # fmt: skip
    nut1, nut2 = (forward.sensor_names.index(n) for n in ("nut 1", "nut 2"))
    rise_f, rise_r = forward.sensors - 293.15, reverse.sensors - 293.15
    hot = int(np.argmax(rise_f[:, nut1]))  # the end of the working segment
    assert rise_f[hot, nut1] > 2.0 * rise_f[hot, nut2] > 0.0
    np.testing.assert_allclose(rise_r[:, nut2], rise_f[:, nut1], rtol=1e-3, atol=1e-6)
    np.testing.assert_allclose(rise_r[:, nut1], rise_f[:, nut2], rtol=1e-3, atol=1e-6)


def test_a_push_pull_day_heats_each_segment_at_its_size() -> None:
    both = day("2 kN", "-1 kN")
    case = ballscrew.case.with_overrides(both.case, {"operating.axial_load": 1000.0})
    point = operating_point(case, speed=1500 * 2 * np.pi / 60)
    # 1500 rpm, 10 mm lead: a 400 mm stroke takes 1.6 s, then 2 s standstill
    assert both.segment_heat[2] == pytest.approx(point.heat * 1.6 / 3.6, rel=1e-6)
    assert both.segment_heat[0] > both.segment_heat[2] > 0.0
    assert both.heat_balance_error < 1e-10
