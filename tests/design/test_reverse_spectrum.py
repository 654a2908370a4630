"""Load spectra in both directions: signed ``[[duty]]`` loads in the design check.

Closed forms: HIWIN F 3.5–3.7 for the preloaded halves, the cube mean per direction (THK A-706)
and the system life (P5) L = (L₁^(−10/9) + L₂^(−10/9))^(−9/10).
"""

from __future__ import annotations

from pathlib import Path

import pytest
from tests.quick_cases import dump_toml
from typer.testing import CliRunner

from ballscrew.analyses.design_check import DesignWarning, design_check, load_spectrum
from ballscrew.case import CaseError, case_from_dict
from ballscrew.cli import app

from .test_design_check import raw_case

CA, FW = 52_700.0, 1.2  # DESIGN's C_a and the example's load factor
FP = 1500.0  # the example's preload


def duty(*loads: str) -> list[dict]:
    """Segments of equal speed and duration, one per load."""
    return [{"speed": "1000 rpm", "axial_load": f, "duration": "10 min"} for f in loads]


def check_of(loads: tuple[str, ...], **operating: object):
    raw = raw_case()
    raw["operating"].update(operating)
    raw["duty"] = duty(*loads)
    return design_check(case_from_dict(raw))


def half_loads(f: float) -> tuple[float, float]:
    """(F_b1, F_b2) of |f| below lift-off, HIWIN F 3.5–3.7."""
    fb1 = (1.0 + f / (2.0**1.5 * FP)) ** 1.5 * FP
    return fb1, fb1 - f


def life(mean_load: float) -> float:
    return (CA / (FW * mean_load)) ** 3 * 1e6


def test_plus_minus_spectrum_loads_both_nuts_equally() -> None:
    result = check_of(("2 kN", "-2 kN"))
    fb1, fb2 = half_loads(2000.0)
    mean = ((fb1**3 + fb2**3) / 2.0) ** (1.0 / 3.0)
    assert result.equivalent_loads == pytest.approx((mean, mean), rel=1e-12)
    assert result.rating_life == pytest.approx(2.0 ** (-0.9) * life(mean), rel=1e-12)


def test_single_nut_without_preload_carries_reverse_loads_on_its_other_flank() -> None:
    raw = raw_case()
    raw["screw"].update(nuts=1, preload_method="oversized_balls")
    raw["operating"].update(preload=0.0)
    raw["duty"] = duty("2 kN", "-2 kN")
    result = design_check(case_from_dict(raw))
    mean = 2000.0 / 2.0 ** (1.0 / 3.0)  # each direction: half the revolutions at 2 kN
    assert result.flanks == 1
    assert result.equivalent_loads == pytest.approx((mean, mean), rel=1e-12)
    assert result.rating_life == pytest.approx(2.0 ** (-0.9) * life(mean), rel=1e-12)


def test_one_direction_spectrum_keeps_the_half_loads_of_hiwin() -> None:
    result = check_of(("3 kN", "1 kN"))
    halves = [half_loads(f) for f in (3000.0, 1000.0)]
    means = [(sum(h[k] ** 3 for h in halves) / 2.0) ** (1.0 / 3.0) for k in (0, 1)]
    assert result.equivalent_loads == pytest.approx(tuple(means), rel=1e-12)
    combined = (life(means[0]) ** (-10 / 9) + life(means[1]) ** (-10 / 9)) ** (-0.9)
    assert result.rating_life == pytest.approx(combined, rel=1e-12)


def test_reverse_only_equals_forward_with_the_nuts_swapped() -> None:
    forward, reverse = check_of(("3 kN", "1 kN")), check_of(("-3 kN", "-1 kN"))
    assert reverse.equivalent_loads == forward.equivalent_loads[::-1]
    assert reverse.rating_life == forward.rating_life
    assert reverse.static_safety_factor == forward.static_safety_factor
    assert reverse.lost_motion == forward.lost_motion
    assert reverse.nut_radial_force == forward.nut_radial_force  # mirror image, ASSUMED
    margins = {m.name: (m.demand, m.capacity) for m in forward.margins}
    assert {m.name: (m.demand, m.capacity) for m in reverse.margins} == margins


def test_the_largest_load_of_either_direction_sets_safety_and_lift_off() -> None:
    with pytest.warns(DesignWarning, match="lift-off load"):
        result = check_of(("1 kN", "-5 kN"))
    assert load_spectrum(result.case).loads == (1000.0, -5000.0)
    assert result.spectrum.max_load == 5000.0
    assert result.static_safety_factor == pytest.approx(141_100.0 / 5000.0)
    lift = next(m for m in result.margins if m.name == "lift_off")
    assert lift.demand == 5000.0 and lift.capacity == pytest.approx(2.0**1.5 * FP)
    assert lift.status == "red"  # 5 kN in reverse lifts nut 1 off, as 5 kN forward lifts nut 2
    assert any("lift-off load" in w for w in result.warnings)


def test_a_load_beyond_the_range_is_one_line_exit_2(tmp_path: Path) -> None:
    raw = raw_case()
    raw["duty"] = duty("2 kN", "-200000 kN")
    with pytest.raises(CaseError) as info:
        case_from_dict(raw)
    message = str(info.value)
    assert "\n" not in message and "duty.1.axial_load" in message
    assert "[-1e+08, 1e+08] N" in message
    case_file = tmp_path / "case.toml"
    case_file.write_text(dump_toml(raw))
    out = tmp_path / "o"
    result = CliRunner().invoke(app, ["check", str(case_file), "--out", str(out)])
    assert result.exit_code == 2 and "duty.1.axial_load" in result.output
    assert len(result.output.strip().splitlines()) == 1 and not out.exists()


def test_the_range_is_symmetric() -> None:
    raw = raw_case()
    raw["duty"] = duty("-1e5 kN", "1e5 kN")
    assert [s.axial_load for s in case_from_dict(raw).duty] == [-1e8, 1e8]


def test_an_operating_point_beyond_the_duty_is_said_to_be_unchecked() -> None:
    """[operating] above every [[duty]] level (3 kN against 2 kN): the margins keep the duty's
    2 kN (static safety C_0a/2 kN), and a warning says the point is not checked."""
    with pytest.warns(DesignWarning, match=r"axial_load = 3 kN above the duty's largest 2 kN"):
        check = check_of(("2 kN", "1 kN"), axial_load="3 kN")
    assert check.spectrum.max_load == 2000.0
    assert check.static_safety_factor == pytest.approx(check.static_load_rating / 2000.0)
    assert any("not this point" in w for w in check.warnings)


def test_an_operating_point_inside_the_duty_is_not_warned_about() -> None:
    check = check_of(("2 kN", "1 kN"), axial_load="2 kN", speed="1000 rpm")
    assert not any("not this point" in w for w in check.warnings)
