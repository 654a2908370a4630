"""The design check of a guided and a free nut (``loads.nut_support``): the balls' radial force
and tilting moment the housing takes, the free nut's shift and tilt, its lift-off, its figures.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from tests.quick_cases import dump_toml
from typer.testing import CliRunner

import ballscrew
from ballscrew.analyses.ball_loads import elastic_distribution
from ballscrew.analyses.design_check import DesignCheck, design_check
from ballscrew.analyses.parameters import ScrewParameters
from ballscrew.case import case_from_dict
from ballscrew.cli import app

from .test_design_check import raw_case


def raw_supported(support: str, **loads: object) -> dict:
    raw = raw_case()
    raw["loads"] = {"distribution": "elastic", "nut_support": support, **loads}
    return raw


def check(support: str) -> DesignCheck:
    return design_check(case_from_dict(raw_supported(support)))


def value_rows(result: DesignCheck) -> dict:
    return dict(next(s for s in result.report() if s.title == "Design values").tables[0].rows)


def test_a_guided_nut_reports_what_its_housing_takes() -> None:
    """|F_r| and |M| of the balls on the nut under the largest load are ball_loads' (the helix's
    part turn leaves them; a guided nut neither shifts nor tilts)."""
    result = check("guided")
    balls = ballscrew.ball_loads(result.case, axial_load=result.spectrum.max_load)
    force, moment = np.hypot(*balls.radial_force), np.hypot(*balls.tilting_moment)
    assert result.nut_radial_force == pytest.approx(force, rel=1e-9)
    assert result.nut_tilting_moment == pytest.approx(moment, rel=1e-9)
    assert force > 10.0 and moment > 0.1  # a real load on the housing, not rounding
    assert result.nut_radial_displacement is None and result.nut_tilt is None
    summary = result.summary()
    assert summary["nut_support"] == "guided"
    assert summary["nut_radial_force"] == {"value": pytest.approx(force, rel=1e-9), "unit": "N"}
    assert summary["nut_tilting_moment"]["unit"] == "N*m"
    assert "nut_tilt" not in summary and "nut_radial_displacement" not in summary
    rows = value_rows(result)
    assert rows["radial force on the guided nut at the largest load [N]"] == pytest.approx(force)
    assert rows["tilting moment on the guided nut, same load [N·m]"] == pytest.approx(moment)
    values = next(s for s in result.report() if s.title == "Design values")
    assert "housing takes their net radial force" in values.paragraphs[0]


def test_a_free_nut_reports_its_shift_and_tilt() -> None:
    """|u| and |γ| are ball_loads' (µm and µrad in the report, SI in the summary); the balls'
    net radial force on a free nut without external load balances to zero."""
    result = check("free")
    balls = ballscrew.ball_loads(result.case, axial_load=result.spectrum.max_load)
    shift, tilt = np.hypot(*balls.radial_displacement), np.hypot(*balls.tilt)
    assert result.nut_radial_displacement == pytest.approx(shift, rel=1e-9)
    assert result.nut_tilt == pytest.approx(tilt, rel=1e-9)
    assert shift > 1e-8 and tilt > 1e-6
    assert np.hypot(*balls.radial_force) < 1e-9 * result.spectrum.max_load
    assert result.nut_radial_force is None and result.nut_tilting_moment is None
    summary = result.summary()
    assert summary["nut_support"] == "free"
    assert summary["nut_tilt"] == {"value": pytest.approx(tilt, rel=1e-9), "unit": "rad"}
    assert summary["nut_radial_displacement"]["unit"] == "m"
    rows = value_rows(result)
    assert rows["radial shift of the free nut at the largest load [µm]"] == pytest.approx(
        1e6 * shift
    )
    assert rows["tilt of the free nut, same load [µrad]"] == pytest.approx(1e6 * tilt)


def test_the_lift_off_with_bodies_is_that_of_the_free_nut() -> None:
    """The free nut's tilt keeps balls of nut 2 loaded beyond the guided nut's lift-off: the
    curve's lift-off is where the free distribution's nut 2 force vanishes (the bisection's
    tolerance 1e-4), well above the guided one."""
    guided = check("guided").to_xarray().attrs["lift_off_load_bodies_N"]
    free = check("free")
    curve = free.to_xarray()
    lift = curve.attrs["lift_off_load_bodies_N"]
    assert curve.attrs["nut_support"] == "free"
    assert lift > 1.2 * guided
    params = ScrewParameters.from_case(free.case)
    spec, root = free.case.loads, free.root_diameter
    g = elastic_distribution(params, spec, root, 0.0, errors=False).interference
    nut_2 = [
        elastic_distribution(params, spec, root, f, g, errors=False).nut_forces[1]
        for f in (0.998 * lift, lift)
    ]
    assert nut_2[0] > 0.0 and nut_2[1] <= 0.0


def test_the_check_folder_of_a_free_nut_under_a_reverse_load(tmp_path: Path) -> None:
    """A reverse largest load (nut 2, mirror image ASSUMED): the same shift and tilt as the
    forward one, and the per-ball figure with the case's and the largest load."""
    raw = raw_supported("free")
    raw["operating"]["axial_load"] = "0 N"
    raw["duty"] = [
        {"speed": "1000 rpm", "axial_load": load, "duration": "10 min"}
        for load in ("1 kN", "-2 kN")
    ]
    case_file = tmp_path / "case.toml"
    case_file.write_text(dump_toml(raw))
    out = tmp_path / "o"
    run = CliRunner().invoke(app, ["check", str(case_file), "--out", str(out), "-q"])
    assert run.exit_code == 0, run.output
    summary = json.loads((out / "summary.json").read_text())
    balls = ballscrew.ball_loads(case_from_dict(raw), axial_load=2000.0)
    assert summary["nut_tilt"]["value"] == pytest.approx(np.hypot(*balls.tilt), rel=1e-9)
    assert (out / "ball_loads.png").stat().st_size > 0
    assert "radial shift of the free nut" in (out / "report.html").read_text()


def test_external_radial_loads_are_named_as_outside_the_makers_life_and_safety() -> None:
    """A free nut's external radial force or moment raises its largest ball load, but C_a and
    C_0a and the makers' life and static safety take the axial load alone: the check says so,
    with the largest ball load, the distribution's (which balances them); none without them."""
    assert not any("nut_radial_load" in w for w in check("free").warnings)
    raw = raw_supported("free", nut_radial_load="3 kN", nut_tilting_moment="20 N*m")
    case = case_from_dict(raw)
    with pytest.warns(ballscrew.analyses.design_check.DesignWarning, match="axial load alone"):
        result = design_check(case)
    [warning] = [w for w in result.warnings if "axial load alone" in w]
    params = ScrewParameters.from_case(case)
    dist = elastic_distribution(params, case.loads, result.root_diameter, 2000.0)
    largest = float(dist.loads.max())
    assert f"{largest:.4g} N" in warning
    assert np.allclose(dist.resultant[1:], [-3000.0, 0.0, 0.0, -20.0], atol=1e-6)
    assert "\n" not in warning


def test_the_lift_off_with_bodies_has_the_cases_radial_load_and_errors() -> None:
    """The report's lift-off with bodies is that of the distribution the case solves: with a
    free nut's radial load and a lead error nut 2 still carries 0.1 % below it and not 0.1 %
    above; it moves from the one without them, and the check warns that the margin's
    2^1.5 F_p leaves them out, naming that lift-off (none without them)."""
    assert not any("lift-off margin" in w for w in check("free").warnings)
    lead_error = [0.0, 2e-6, 0.0] * 2  # per turn (3 turns per nut), both nuts
    raw = raw_supported("free", nut_radial_load="500 N", lead_error=lead_error)
    case = case_from_dict(raw)
    with pytest.warns(ballscrew.analyses.design_check.DesignWarning, match="lift-off margin"):
        result = design_check(case)
    lift = result.stiffness_curve.attrs["lift_off_load_bodies_N"]
    [warning] = [w for w in result.warnings if "lift-off margin" in w]
    assert "loads.lead_error, loads.nut_radial_load" in warning
    assert warning.endswith(f"at {lift * 1e-3:.4g} kN")
    params = ScrewParameters.from_case(case)
    spec, root = case.loads, result.root_diameter
    g = elastic_distribution(params, spec, root, 0.0).interference
    nut_2 = [
        elastic_distribution(params, spec, root, f, g).nut_forces[1]
        for f in (0.999 * lift, 1.001 * lift)
    ]
    assert nut_2[0] > 0.0 and nut_2[1] == 0.0
    plain = check("free").stiffness_curve.attrs["lift_off_load_bodies_N"]
    assert abs(lift / plain - 1.0) > 0.02
