"""Hardness and accuracy factors of the load ratings (NBS catalogue ch. 4 §2.5.2-2.5.3, §2.7.3)."""

from __future__ import annotations

import pytest
from tests.design.test_design_check import raw_case

from ballscrew import design
from ballscrew.analyses.design_check import design_check
from ballscrew.case import case_from_dict
from ballscrew.errors import BallscrewError, InputError

KGF_MM2 = 9.80665e6


@pytest.mark.parametrize(
    ("hv", "expected"),
    [
        (700.0, 1.0),  # the catalogue's reference, 700 HV10 ≈ 60 HRC
        (746.0, 1.0),  # HRC 62: capped at 1
        (697.0, 0.98720),  # HRC 60 (ASTM E140): inside the catalogue's 0.98-1.0
        (653.0, 0.81179),  # HRC 58
        (500.0, (500.0 / 700.0) ** 3),
    ],
)
def test_hardness_factor_is_the_cube_of_hv_over_700(hv: float, expected: float) -> None:
    assert design.hardness_factor(hv * KGF_MM2) == pytest.approx(expected, rel=1e-4)


@pytest.mark.parametrize(("grade", "expected"), [(1, 1.0), (3, 1.0), (5, 1.0), (7, 0.9), (10, 0.7)])
def test_accuracy_factor_table(grade: int, expected: float) -> None:
    assert design.accuracy_factor(grade) == expected


def test_unknown_accuracy_grade_names_the_field() -> None:
    with pytest.raises(InputError, match=r"design\.accuracy_grade = 6"):
        design.accuracy_factor(6)


def _computed(**overrides: object):
    raw = raw_case(**overrides)
    del raw["design"]["static_load_rating"], raw["design"]["dynamic_load_rating"]
    with pytest.warns(UserWarning, match="computed from the geometry"):
        return design_check(case_from_dict(raw))


@pytest.mark.parametrize("rating", ["dynamic_load_rating", "static_load_rating"])
def test_grade_and_hardness_scale_the_computed_ratings(rating: str) -> None:
    """Class 7 takes 0.9 of the class-5 rating; class 10 with a softer screw raceway (HV 500
    against the example's 6.5 GPa) takes 0.7 (500/700)^3 / f_H(6.5 GPa) of it."""
    c5 = getattr(_computed(), rating)
    assert getattr(_computed(accuracy_grade=7), rating) == pytest.approx(0.9 * c5, rel=1e-12)
    soft_screw = f"{500.0 * KGF_MM2 * 1e-9!r} GPa"
    raw = raw_case(accuracy_grade=10)
    del raw["design"]["static_load_rating"], raw["design"]["dynamic_load_rating"]
    assert raw["materials"]["screw"]["hardness"] == "6.5 GPa"
    raw["materials"]["screw"]["hardness"] = soft_screw
    with pytest.warns(UserWarning, match="computed from the geometry"):
        soft = getattr(design_check(case_from_dict(raw)), rating)
    ratio = (500.0 / 700.0) ** 3 / design.hardness_factor(6.5e9)
    assert soft == pytest.approx(0.7 * ratio * c5, rel=1e-9)


def test_a_maker_rating_is_taken_as_printed() -> None:
    result = design_check(case_from_dict(raw_case(accuracy_grade=10)))
    assert (result.dynamic_load_rating, result.static_load_rating) == (52_700.0, 141_100.0)


def test_bad_grade_in_the_case_is_one_clear_error() -> None:
    with pytest.raises(BallscrewError, match="accuracy_grade"):
        case_from_dict(raw_case(accuracy_grade=6))
