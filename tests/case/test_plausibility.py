"""Bare numbers are SI; a physically implausible magnitude is warned about with the likely unit."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

import ballscrew
from ballscrew.case import CaseError, case_from_dict
from ballscrew.case.plausibility import ImplausibleValueWarning, implausible_values
from quick_cases import write_case

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def warnings_of(tmp_path, overrides):
    with pytest.warns(ImplausibleValueWarning) as caught:
        case = ballscrew.load_case(write_case(tmp_path, "gao2019_tcr.toml", overrides))
    assert [str(w.message).split(": ", 1)[1] for w in caught] == implausible_values(case)
    return implausible_values(case)


def test_a_lead_longer_than_the_pitch_circle_suggests_millimetres(tmp_path):
    (message,) = warnings_of(tmp_path, {"screw.lead": 0.5})
    assert message == (
        "screw.lead = 0.5 m is longer than the pitch circle (π·d_m = 125.7 mm); "
        "did you mean '0.5 mm'?"
    )


def test_a_lead_beyond_its_range_names_the_unit_in_the_error(tmp_path):
    with pytest.raises(
        CaseError, match=r"screw\.lead = 10 is not allowed: .*did you mean '10 mm'\?"
    ):
        ballscrew.load_case(write_case(tmp_path, "gao2019_tcr.toml", {"screw.lead": 10}))


def test_balls_that_do_not_fit_the_nut(tmp_path):
    (message,) = warnings_of(tmp_path, {"screw.balls_per_nut": 5000})
    assert message.startswith("screw.balls_per_nut = 5000 balls of 6.35 mm do not fit a nut")
    assert "holds about 119" in message  # 60 mm / 10 mm × 126.1 mm of helix / 6.35 mm


def test_a_ball_larger_than_the_lead(tmp_path):
    (message,) = warnings_of(tmp_path, {"screw.ball_diameter": "12 mm"})
    assert "does not fit between the thread turns of screw.lead = 10 mm" in message


def test_a_preload_above_the_static_load_rating(tmp_path):
    (message,) = warnings_of(tmp_path, {"operating.preload": "200 kN"})
    assert message.startswith("operating.preload = 200 kN is above design.static_load_rating")


def test_a_bare_modulus_suggests_gigapascal(tmp_path):
    (message,) = warnings_of(tmp_path, {"materials.nut.youngs_modulus": 206})
    assert message.endswith("did you mean '206 GPa'?")


def test_plausible_values_and_units_raise_nothing(tmp_path):
    case = ballscrew.load_case(
        write_case(tmp_path, "gao2019_tcr.toml", {"screw.lead": "20 mm", "operating.preload": 3e3})
    )
    assert implausible_values(case) == []


def test_a_case_changed_by_overrides_warns_only_about_what_the_overrides_bring(tmp_path):
    """``with_overrides`` (sweeps, coupled runs) re-validates the case: its own implausible
    values were warned about when it was read, and are not repeated for every derived case."""
    import warnings

    from ballscrew.case.loader import with_overrides

    with pytest.warns(ImplausibleValueWarning):
        case = ballscrew.load_case(write_case(tmp_path, "gao2019_tcr.toml", {"screw.lead": 0.5}))
    with warnings.catch_warnings():
        warnings.simplefilter("error", ImplausibleValueWarning)
        with_overrides(case, {"operating.axial_load": 100.0})
    with pytest.warns(ImplausibleValueWarning) as caught:
        with_overrides(case, {"operating.speed": 1500.0})
    assert [str(w.message).split(": ", 1)[1].split(" = ")[0] for w in caught] == ["operating.speed"]


def test_a_fractal_roughness_far_outside_engineering_surfaces_is_warned(tmp_path):
    """G = 9e-4 m (for 9e-10 m) moves Mikic's R″ by ×2000; D = 1.95 is near the degenerate 2."""
    messages = warnings_of(tmp_path, {"surface.G": 9e-4, "surface.D": 1.95})
    assert messages == [
        "surface.D = 1.95 is outside the usual 1.2 to 1.9 of engineering surfaces",
        "surface.G = 9×10⁻⁴ m is outside the usual 1×10⁻¹⁶ to 1×10⁻⁸ m of engineering surfaces "
        "(G sets the asperity heights: the contact resistance changes by orders of magnitude)",
    ]


def test_published_roughness_studies_stay_quiet(tmp_path):
    """Gao et al. (2019), Fig. 11: D from 1.4 to 1.7 and G from 5e-11 to 5e-9 m."""
    for d, g in ((1.4, 5e-11), (1.7, 5e-9), (1.475, 1.38e-10)):
        case = ballscrew.load_case(
            write_case(tmp_path, "gao2019_tcr.toml", {"surface.D": d, "surface.G": g})
        )
        assert implausible_values(case) == []


def test_the_warning_points_at_the_callers_line_not_the_loader(tmp_path):
    from ballscrew.case import with_overrides

    case = ballscrew.load_case(write_case(tmp_path, "gao2019_tcr.toml", {}))
    with pytest.warns(ImplausibleValueWarning) as caught:
        with_overrides(case, {"surface.G": 9e-4})
    assert [w.filename for w in caught] == [__file__]


def test_the_rpm_hint_is_given_only_for_a_whole_number():
    """1500 (rpm typed without a unit) gets the hint; 628.3 rad/s (6000 rpm, converted on
    purpose) only the d·n warning. The reference screw: d_m = 40 mm."""
    from ballscrew.case.plausibility import speed_hint

    assert speed_hint(1500.0, 0.040) == (
        "; if given without a unit (rad/s), did you mean '1500 rpm'?"
    )
    assert speed_hint(628.3, 0.040) == ""
    assert speed_hint(6000 * 3.141592653589793 / 30, 0.040) == ""


def test_a_shaft_between_bearings_shorter_than_the_nut(tmp_path):
    """10 mm between the bearings for a nut of 60 mm: a slip of unit or of meaning (the check
    then gives a speed margin of 10⁴), warned about."""
    (message,) = warnings_of(tmp_path, {"design.unsupported_length": "10 mm"})
    assert message == (
        "design.unsupported_length = 10 mm is shorter than a nut (60 mm); did you mean the "
        "shaft between the bearings?"
    )
    assert not implausible_values(ballscrew.load_case(write_case(tmp_path, "gao2019_tcr.toml", {})))


def test_a_shaft_between_bearings_longer_than_the_whole_shaft(tmp_path):
    """5 m between the bearings on a shaft of 1 m ([thermal] shaft_length): one screw, two
    lengths that cannot both hold; warned about. A [thermal] without shaft_length (its 1 m
    default) is not compared."""
    (message,) = warnings_of(tmp_path, {"design.unsupported_length": "5 m"})
    assert message == (
        "design.unsupported_length = 5 m is longer than the whole shaft, "
        "thermal.shaft_length = 1 m; the span between the bearings lies on the shaft"
    )
    assert not implausible_values(
        ballscrew.load_case(
            write_case(tmp_path, "gao2019_tcr.toml", {"design.unsupported_length": "1 m"})
        )
    )
    raw = tomllib.loads((EXAMPLES / "gao2019_tcr.toml").read_text())
    del raw["thermal"]["shaft_length"]
    raw["design"]["unsupported_length"] = "5 m"
    assert not implausible_values(case_from_dict(raw))
