"""Reverse duty segments in the wear chain: the sign says which nut carries the larger force.

Under the engine's reciprocation (E8.4) each screw flank spends half of a level under each nut,
so a reverse level (nut 2 loaded) wears as its mirror image; the nut forces of the history
swap. Closed form of the forces: (P1)–(P3), F_p = 1500 N, F_a = 2000 N → (2614.586, 614.586) N.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import ballscrew
from ballscrew.analyses.wear_duty import duty_programme, range_messages
from ballscrew.calibration.api import programme_range
from ballscrew.case import Case
from ballscrew.loads import nut_forces
from ballscrew.wear.setup import nut_force_pair

from .conftest import REF_PATH

RPM = math.pi / 30.0
pytestmark = pytest.mark.filterwarnings(  # the reference screw at 100 rpm: boundary film
    "ignore::ballscrew.analyses.operating_point.OperatingPointWarning"
)


def test_a_reverse_load_puts_the_larger_force_on_nut_2() -> None:
    assert nut_force_pair(1500.0, 2000.0) == pytest.approx((2614.586, 614.586), abs=1e-3)
    assert nut_force_pair(1500.0, -2000.0) == nut_force_pair(1500.0, 2000.0)[::-1]
    assert nut_force_pair(1500.0, -5000.0) == (0.0, 5000.0)  # beyond lift-off of nut 1
    assert nut_force_pair(0.0, -2000.0) == (0.0, 2000.0)


@pytest.mark.parametrize("load", [0.0, 1.0, 2000.0, 4242.6, 5000.0, 3.7e4])
def test_forward_forces_are_those_of_the_double_nut_bit_for_bit(load: float) -> None:
    assert nut_force_pair(1500.0, load) == tuple(nut_forces(1500.0, load))


def duty_case(*loads: float) -> Case:
    """The wear reference screw (elastic distribution, ISO VG 68 at its operating point) with
    one 100 rpm segment of 10 min per load."""
    raw = ballscrew.load_case(REF_PATH).model_dump()
    raw["wear"].pop("programme")
    raw["wear"].update({"grid": [12, 48], "torque_sampling": 2.0e4})
    raw["medium"].update({"viscosity": None, "pressure_viscosity": None})
    raw["kinematics"]["lubricant"] = "iso_vg_68"
    raw["loads"]["distribution"] = "elastic"
    raw["duty"] = [
        {"speed": 100 * RPM, "axial_load": f, "stroke": 0.3, "duration": 600.0} for f in loads
    ]
    return type(ballscrew.load_case(REF_PATH)).model_validate(raw)


@pytest.fixture(scope="module")
def lives() -> dict[tuple[float, ...], object]:
    runs = [(2000.0,), (-2000.0,), (2000.0, 2000.0), (2000.0, -2000.0)]
    return {loads: ballscrew.wear_life(duty_case(*loads)).life for loads in runs}


def test_a_reverse_segment_keeps_its_sign_at_the_operating_point_of_its_size() -> None:
    (forward,), (reverse,) = duty_programme(duty_case(2000.0)), duty_programme(duty_case(-2000.0))
    assert (forward.axial_load, reverse.axial_load) == (2000.0, -2000.0)
    assert reverse.viscosity == forward.viscosity
    assert reverse.temperature == forward.temperature


def test_reverse_only_wears_as_forward_with_the_nuts_swapped(lives) -> None:
    forward, reverse = lives[(2000.0,)], lives[(-2000.0,)]
    np.testing.assert_allclose(reverse.profiles, forward.profiles, rtol=1e-12, atol=0.0)
    np.testing.assert_allclose(reverse.preload, forward.preload, rtol=1e-12)
    np.testing.assert_allclose(reverse.nut_forces, forward.nut_forces[:, ::-1], rtol=1e-12)
    assert reverse.nut_forces[0, 1] > reverse.nut_forces[0, 0]  # nut 2 carries the load
    assert reverse.ellipse_major_axis == forward.ellipse_major_axis


def test_a_plus_minus_programme_wears_both_flanks_equally(lives) -> None:
    both, forward = lives[(2000.0, -2000.0)], lives[(2000.0, 2000.0)]
    worn = both.profiles[-1]
    assert worn.max() > 0.0
    np.testing.assert_allclose(worn[0], worn[1][::-1], rtol=0.0, atol=1e-9 * worn.max())
    assert worn[0].max() == pytest.approx(worn[1].max(), rel=1e-9)
    # (E8.4) already sends each flank half the time under each nut: ± equals + + of the same
    # |F|, to the contact solver's tolerance (the second level's warm starts differ)
    np.testing.assert_allclose(both.profiles, forward.profiles, rtol=1e-7, atol=0.0)
    np.testing.assert_allclose(both.preload, forward.preload, rtol=1e-9)


def test_the_calibrated_range_reads_the_size_of_a_reverse_load() -> None:
    case = duty_case(-2000.0, 3000.0)
    assert range_messages(case.wear, duty_programme(case)) == []  # 2000–4000 N at 100 rpm
    span = programme_range(case)
    assert (span["load_min"], span["load_max"]) == (2000.0, 3000.0)
