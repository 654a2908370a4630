"""The ``[wear]`` case section: defaults, units and the contract keys used by calibration."""

from __future__ import annotations

import math

import pytest
from pydantic import ValidationError

import ballscrew
from ballscrew.case import CaseError, with_overrides
from ballscrew.case.wear_spec import WearSpec

from .conftest import REF_PATH


def test_example_programme_is_the_step_stress_test(ref_case) -> None:
    w = ref_case.wear
    assert w.model == "A"
    assert w.coefficient == pytest.approx(1.304e-4)
    assert w.stroke == pytest.approx(0.30)
    assert w.max_depth_step == pytest.approx(1e-7)
    assert w.torque_sampling == pytest.approx(4.8e4)
    assert [lv.axial_load for lv in w.programme] == [2000.0, 3000.0, 4000.0]
    assert all(lv.speed == pytest.approx(10 * math.pi / 3) for lv in w.programme)
    assert all(lv.revolutions == pytest.approx(4.8e5) for lv in w.programme)


def test_defaults_equal_the_example() -> None:
    spec = WearSpec()
    assert spec.coefficient is None  # the reference calibration of the asperity roughness
    assert spec.torque_scale == 1.0 and spec.initial_torque is None
    assert [lv.axial_load for lv in spec.programme] == [2000.0, 3000.0, 4000.0]


def test_contract_keys_accept_overrides(ref_case) -> None:
    case = with_overrides(
        ref_case,
        {"wear.coefficient": 2e-4, "wear.torque_scale": 1.2, "wear.initial_torque": "0.5 N*m"},
    )
    assert case.wear.coefficient == 2e-4
    assert case.wear.torque_scale == 1.2
    assert case.wear.initial_torque == pytest.approx(0.5)


def test_bad_values_rejected(ref_case) -> None:
    with pytest.raises(CaseError):
        with_overrides(ref_case, {"wear.coefficient": -1.0})
    with pytest.raises(CaseError):
        with_overrides(ref_case, {"wear.model": "B"})
    with pytest.raises(ValidationError):
        WearSpec(programme=[])


def test_case_without_wear_section_uses_defaults(tmp_path) -> None:
    body = REF_PATH.read_text()
    path = tmp_path / "c.toml"
    path.write_text(body[: body.index("[wear]")])
    case = ballscrew.load_case(path)
    assert case.wear is None
    from ballscrew.analyses.wear import wear_setup

    assert wear_setup(case).spec.coefficient == pytest.approx(9.607e-5)  # 'film' reference


@pytest.mark.parametrize(("roughness", "k"), [("film", 9.607e-5), ("cell", 1.304e-4)])
def test_the_default_coefficient_follows_the_asperity_roughness(ref_case, roughness, k) -> None:
    """Without a coefficient of its own a case runs with the K that gives the reference screw
    its 2.43 µm under the chosen roughness, also when an override changes the roughness."""
    case = with_overrides(ref_case, {"wear.coefficient": None})
    case = with_overrides(case, {"wear.asperity_roughness": roughness})
    assert case.wear.coefficient is None
    assert case.wear.wear_coefficient == k
    given = with_overrides(case, {"wear.coefficient": 2e-4})
    assert given.wear.wear_coefficient == 2e-4


def test_a_written_reference_value_is_the_reference_calibration(ref_case) -> None:
    """The example writes the 'cell' reference K: it keeps the reference test's range; the same
    K under 'film' is a coefficient of the case's own."""
    assert ref_case.wear.asperity_roughness == "cell" and ref_case.wear.reference_calibration
    film = with_overrides(ref_case, {"wear.asperity_roughness": "film"})
    assert not film.wear.reference_calibration
