"""``ballscrew.design_check`` and ``ballscrew check``: values, margins, warnings, the folder."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest
from tests.protocol_check import assert_protocol_folder
from tests.quick_cases import dump_toml
from typer.testing import CliRunner

import ballscrew
from ballscrew import design
from ballscrew.analyses.design_check import design_check, load_spectrum
from ballscrew.case import case_from_dict
from ballscrew.cli import app
from ballscrew.errors import BallscrewError, InputError

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "gao2019_tcr.toml"
DESIGN = {
    "dynamic_load_rating": "52.7 kN",
    "static_load_rating": "141.1 kN",
    "unsupported_length": "1.3 m",
    "catalogue_rigidity": "1000 N/um",
    "bearing_stiffness": "1000 N/um",
    "temperature_rise": "3 K",
    "required_life": "20000 h",
}


def raw_case(**design_overrides: object) -> dict:
    raw = tomllib.loads(EXAMPLE.read_text())
    raw.pop("duty", None)  # the load spectrum of these tests is [operating]
    raw.pop("duty_repeat", None)
    raw["design"] = DESIGN | design_overrides
    # one screw: the bearings at the shaft's ends ([thermal] described a 1 m shaft)
    raw["thermal"]["shaft_length"] = raw["design"]["unsupported_length"]
    raw["operating"].update(axial_load="2000 N", speed="1000 rpm")
    return raw


def test_api_contract_values() -> None:
    result = ballscrew.design_check(case_from_dict(raw_case()))
    assert result.dynamic_load_rating == 52_700.0 and result.static_load_rating == 141_100.0
    assert result.static_safety_factor == pytest.approx(141_100.0 / 2000.0)
    fb1, fb2 = design.preloaded_half_loads(2000.0, 1500.0)
    expected = design.combined_life(
        [float(design.rating_life(52_700.0, f, 1.2)) for f in (float(fb1), float(fb2))]
    )
    assert result.rating_life == pytest.approx(expected)
    assert result.preload_drag_torque == pytest.approx(0.42314, rel=1e-4)
    assert 1.0 / result.axial_stiffness == pytest.approx(
        1.0 / result.nut_stiffness + 1.0 / result.shaft_stiffness
    )
    assert result.drive_stiffness < result.axial_stiffness < result.nut_stiffness
    assert result.critical_speed > 0 and result.buckling_load > 0
    assert {m.status for m in result.margins} <= {"green", "amber", "red"}
    assert result.warnings == ()


def test_duty_spectrum_weights_by_revolutions() -> None:
    raw = raw_case()
    raw["duty"] = [
        {"speed": "1000 rpm", "axial_load": "3 kN", "duration": "1 min"},
        {"speed": "500 rpm", "axial_load": "1 kN", "duration": "2 min"},
        {"speed": 0.0, "duration": "1 min"},
    ]
    spectrum = load_spectrum(case_from_dict(raw))
    assert spectrum.source == "duty" and spectrum.loads == (3000.0, 1000.0, 0.0)
    assert spectrum.shares == pytest.approx((0.5, 0.5, 0.0))
    assert spectrum.mean_speed == pytest.approx(2000.0 * 2 * math.pi / 60 / 4.0)


@pytest.mark.parametrize(
    ("overrides", "operating", "warning"),
    [
        ({"dynamic_load_rating": "10 kN", "required_life": "1 h"}, {}, "preload vs its largest"),
        ({"unsupported_length": "4 m"}, {}, "speed vs 0.8 × critical speed"),
        ({"static_load_rating": "2.5 kN"}, {}, "f_s vs its minimum"),
        ({}, {"speed": "3000 rpm"}, "d·n vs its limit"),
    ],
)
def test_red_margins_warn(overrides, operating, warning) -> None:
    raw = raw_case(**overrides)
    raw["operating"].update(operating)
    with pytest.warns(UserWarning, match=warning):
        result = design_check(case_from_dict(raw))
    assert any(warning in w for w in result.warnings)
    assert any(m.status == "red" for m in result.margins)


def test_missing_ratings_are_computed_and_said_so() -> None:
    """Without catalogue ratings the check computes them from the geometry and says so (the
    check used to leave life and static safety out)."""
    raw = raw_case()
    del raw["design"]["dynamic_load_rating"], raw["design"]["static_load_rating"]
    with pytest.warns(UserWarning, match="computed from the geometry"):
        result = design_check(case_from_dict(raw))
    assert result.computed_ratings == ("dynamic_load_rating", "static_load_rating")
    # 54 balls of 6.35 mm at f = 0.52: of the order of the catalogue's 40 x 10 nuts (45-65 kN)
    assert 40e3 < result.dynamic_load_rating < 70e3
    assert result.static_safety_factor == pytest.approx(result.static_load_rating / 2000.0)
    summary = result.summary()
    assert summary["load_ratings_computed"] == ["dynamic_load_rating", "static_load_rating"]
    assert summary["rating_life"]["value"] > 0
    rows = dict(result.report()[1].tables[0].rows)
    assert any("computed from the geometry" in label for label in rows)


@pytest.mark.filterwarnings("ignore::UserWarning")
def test_static_rating_model_of_the_case_picks_the_rival_limit() -> None:
    """``[design] static_rating_model`` chooses the C_0a limit; a name not registered is refused
    naming the field and the known models."""
    raw = raw_case()
    del raw["design"]["static_load_rating"]
    c0a, said = {}, {}
    for name in ("iso76", "palmgren"):
        raw["design"]["static_rating_model"] = name
        result = design_check(case_from_dict(raw))
        c0a[name] = result.static_load_rating
        said[name] = " ".join(w for w in result.warnings if "static_load_rating" in w)
    assert 0.75 < c0a["palmgren"] / c0a["iso76"] < 0.92
    assert "4200 MPa" in said["iso76"] and "Palmgren's formula" in said["palmgren"]
    raw["design"]["static_rating_model"] = "hertz"
    with pytest.raises(
        BallscrewError, match=r"design\.static_rating_model = 'hertz' .*iso76, palmgren"
    ):
        case_from_dict(raw)


def test_given_ratings_are_not_marked_computed() -> None:
    result = design_check(case_from_dict(raw_case()))
    assert result.computed_ratings == () and result.summary()["load_ratings_computed"] == []


def test_no_design_section_is_a_one_line_error() -> None:
    raw = raw_case()
    del raw["design"]
    with pytest.raises(InputError, match=r"^design = None is not allowed"):
        design_check(case_from_dict(raw))


def test_check_command_writes_the_folder(tmp_path: Path) -> None:
    case_file = tmp_path / "case.toml"
    case_file.write_text(dump_toml(raw_case()))
    out = tmp_path / "out"
    result = CliRunner().invoke(app, ["check", str(case_file), "--out", str(out)])
    assert result.exit_code == 0, result.output
    assert {"stiffness_curve.png", "life_spectrum.png"} <= {p.name for p in out.iterdir()}
    api = design_check(case_from_dict(raw_case()))
    summary = assert_protocol_folder(api, out)
    assert summary["rating_life"]["value"] == pytest.approx(api.rating_life)
    assert summary["margins"]["speed"]["status"] == "green"


def test_the_check_builds_its_stiffness_curve_once(tmp_path: Path, monkeypatch) -> None:
    """One ``ballscrew check`` sweeps the body curve (40+ elastic solves) once, from the
    preloaded nut the check solved (no solve of its own at F_a = 0), and the stiffness figure
    draws exactly the curve of the data file (bit for bit)."""
    import xarray as xr

    from ballscrew.analyses import design_check_report as report

    sweeps, solves, drawn = [], [], []
    body_curve, save_figure, solve = (
        report._body_curve,
        report.save_figure,
        report.elastic_distribution,
    )

    def counted_solve(*args, **kwargs):
        solves.append(kwargs)
        return solve(*args, **kwargs)

    def counted(*args):
        sweeps.append(args)
        return body_curve(*args)

    def kept(fig, path):
        drawn.append((path.name, [[line.get_data() for line in ax.lines] for ax in fig.axes]))
        return save_figure(fig, path)

    monkeypatch.setattr(report, "_body_curve", counted)
    monkeypatch.setattr(report, "save_figure", kept)
    monkeypatch.setattr(report, "elastic_distribution", counted_solve)
    raw = raw_case()
    raw.setdefault("loads", {})["distribution"] = "elastic"
    case_file, out = tmp_path / "case.toml", tmp_path / "out"
    case_file.write_text(dump_toml(raw))
    result = CliRunner().invoke(app, ["check", str(case_file), "--out", str(out), "-q"])
    assert result.exit_code == 0, result.output
    assert len(sweeps) == 1
    assert len(solves) == report._BODY_POINTS  # the case's load is the largest: kept
    assert all(kwargs["interference"] is not None for kwargs in solves)
    (lines,) = (axes for name, axes in drawn if name == "stiffness_curve.png")
    with xr.open_dataset(out / "fields.nc", engine="h5netcdf") as curve:
        loads, body = curve["axial_load"].values * 1e-3, curve["body_load"].values * 1e-3
        shown = [
            (loads, curve["deflection"].values * 1e6),
            (body, curve["deflection_bodies"].values * 1e6),
            (loads, curve["stiffness"].values * 1e-6),
            (body, curve["stiffness_bodies"].values * 1e-6),
        ]
    plotted = [*lines[0][:2], *lines[1][:2]]
    for (x, y), (px, py) in zip(shown, plotted, strict=True):
        np.testing.assert_array_equal(px, x)
        np.testing.assert_array_equal(py, y)


def test_check_command_bad_input_exit_2(tmp_path: Path) -> None:
    raw = raw_case(mounting="clamped")
    case_file = tmp_path / "case.toml"
    case_file.write_text(dump_toml(raw))
    result = CliRunner().invoke(app, ["check", str(case_file), "--out", str(tmp_path / "o")])
    assert result.exit_code == 2 and "design.mounting" in result.output
    assert not (tmp_path / "o").exists()


def test_fixed_fixed_shaft_stiffness_uses_the_span() -> None:
    """Fixed–fixed: nut_distance is measured from one bearing and the span stays the length
    (1.3 m); at mid-span both mountings' formulas meet, 4 A E/l = 2 · A E/(l/2)."""

    def shaft(**over: object) -> float:
        return design_check(case_from_dict(raw_case(**over))).shaft_stiffness

    mid = shaft(mounting="fixed-fixed")
    assert shaft(mounting="fixed-fixed", nut_distance="0.65 m") == pytest.approx(mid)
    assert shaft(mounting="fixed-free", nut_distance="0.65 m") == pytest.approx(mid / 2)


def test_margins_read_in_engineering_units() -> None:
    """The margins table showed the speed in rad/s and the red-life warning as '2e+04 against
    1.137e+04 h'; summary.json keeps SI."""
    raw = raw_case(required_life="1e6 h")
    raw["design"]["unsupported_length"] = "4 m"
    raw["thermal"]["shaft_length"] = "4 m"
    with pytest.warns(UserWarning):
        result = design_check(case_from_dict(raw))
    life = next(w for w in result.warnings if w.startswith("required life"))
    assert life.startswith("required life vs rating life: 1×10⁶ h against ") and "e+" not in life
    speed = next(w for w in result.warnings if w.startswith("speed vs"))
    assert speed.startswith("speed vs 0.8 × critical speed: 1000 rpm against ")
    table = next(s for s in result.report() if s.title == "Margins").tables[0]
    rows = {row[0]: row for row in table.rows}
    _, demand, _, unit = rows["speed vs 0.8 × critical speed"][:4]
    assert unit == "rpm" and demand == pytest.approx(1000.0)
    assert rows["axial load vs 0.5 × buckling load"][3] == "kN"
    assert result.summary()["margins"]["speed"]["demand"]["unit"] == "rad/s"
    values = dict(next(s for s in result.report() if s.title == "Design values").tables[0].rows)
    assert values["preload drag torque [N·m]"] == pytest.approx(result.preload_drag_torque)


def test_the_headlines_give_the_life_in_hours() -> None:
    """The console gave the rating life only in revolutions (3.278×10⁸ rev)."""
    from ballscrew.results.headlines import headline_keys, headline_rows

    summary = design_check(case_from_dict(raw_case())).summary()
    rows = dict(headline_rows(summary, headline_keys("check")))
    assert rows["life hours"].endswith(" h") and rows["rating life"].endswith(" rev")


def test_a_red_margin_reads_demand_and_capacity_in_one_unit() -> None:
    """The warning read '2 kN against 881 N' (each value in its own unit) while the margins
    table showed one unit a row; both now pick the unit by the larger value."""
    raw = raw_case()
    raw["design"]["unsupported_length"] = "12 m"
    raw["thermal"]["shaft_length"] = "12 m"
    with pytest.warns(UserWarning):
        result = design_check(case_from_dict(raw))
    buckling = next(w for w in result.warnings if w.startswith("axial load vs 0.5"))
    demand, capacity = buckling.split(": ", 1)[1].split(" against ")
    assert demand == "2 kN" and capacity.endswith(" kN") and capacity.startswith("0.")
    table = next(s for s in result.report() if s.title == "Margins").tables[0]
    row = next(r for r in table.rows if r[0].startswith("axial load vs 0.5"))
    assert row[3] == "kN" and capacity == f"{row[2]:.3f} kN"


def test_a_nut_far_softer_than_its_contacts_warns() -> None:
    """51 of the 54 balls of each nut 30 µm undersized: three balls carry the preload and the
    nut with bodies has 152 N/µm against the contacts' 1089 N/µm (all balls) — said, not hidden."""
    raw = raw_case()
    raw["loads"] = {"ball_diameter_error": [0.0 if k % 54 < 3 else -30e-6 for k in range(108)]}
    with pytest.warns(UserWarning, match="below 50% of the Hertz contacts"):
        result = design_check(case_from_dict(raw))
    assert result.nut_stiffness < 0.5 * result.contact_stiffness
    assert any("nut stiffness with the elastic bodies" in w for w in result.warnings)


def test_the_lift_off_margin_of_a_preloaded_nut_only() -> None:
    """Demand: the largest axial load; capacity: 2^1.5 F_p (HIWIN), for a double nut and a
    single nut preloaded by oversized balls alike; a single nut without preload has none (the
    old single nut had one loaded flank and no margin: the bug this test now guards)."""
    raw = raw_case()
    raw["operating"]["axial_load"] = "5 kN"
    with pytest.warns(UserWarning, match="lift-off load 2\\^1.5 F_p: 5 kN against 4.243 kN"):
        result = design_check(case_from_dict(raw))
    lift = next(m for m in result.margins if m.name == "lift_off")
    assert lift.capacity == pytest.approx(2.0**1.5 * 1500.0) and lift.status == "red"
    raw["screw"]["nuts"] = 1
    raw["operating"]["axial_load"] = "2 kN"
    single = design_check(case_from_dict(raw))
    lift = next(m for m in single.margins if m.name == "lift_off")
    assert lift.capacity == pytest.approx(2.0**1.5 * 1500.0) and lift.status == "green"
    raw["operating"]["preload"] = "0 N"
    unpreloaded = design_check(case_from_dict(raw))
    assert "lift_off" not in {m.name for m in unpreloaded.margins}


def test_single_nut_preload_methods_against_the_double_nut() -> None:
    """Oversized balls: both flanks of the same Z balls, so contacts, life and equivalent loads
    are those of a double nut of Z balls per nut; offset lead: a double nut of Z/2 balls per
    half, whose Hertz compliance is 2^(2/3) larger. The report names the method."""
    double = design_check(case_from_dict(raw_case()))
    raw = raw_case()
    raw["screw"]["nuts"] = 1
    four = design_check(case_from_dict(raw))
    assert four.flanks == 2
    assert four.equivalent_loads == pytest.approx(double.equivalent_loads, rel=1e-12)
    assert four.rating_life == pytest.approx(double.rating_life, rel=1e-12)
    assert four.contact_stiffness == pytest.approx(double.contact_stiffness, rel=1e-12)
    text = " ".join(p for s in four.report() for p in s.paragraphs)
    assert "Preload method: oversized_balls" in text
    raw["screw"]["preload_method"] = "offset_lead"
    offset = design_check(case_from_dict(raw))
    assert offset.compliance == pytest.approx(2.0 ** (2.0 / 3.0) * double.compliance, rel=1e-12)
    assert offset.contact_stiffness == pytest.approx(
        2.0 ** (-2.0 / 3.0) * double.contact_stiffness, rel=1e-12
    )
    raw["operating"]["preload"] = "0 N"
    bare = design_check(case_from_dict(raw))
    assert bare.flanks == 1 and bare.equivalent_loads == pytest.approx((2000.0, 0.0))
    assert "Preload method: none" in " ".join(p for s in bare.report() for p in s.paragraphs)


@pytest.mark.parametrize(
    ("screw", "message"),
    [
        ({"nuts": 2, "preload_method": "oversized_balls"}, "screw.preload_method = 'oversized"),
        ({"nuts": 1, "preload_method": "spacer"}, "oversized_balls or offset_lead"),
        ({"nuts": 1, "preload_method": "offset_lead", "balls_per_nut": 53}, "balls_per_nut = 53"),
    ],
)
def test_a_preload_method_that_does_not_fit_the_nuts_is_a_case_error(screw, message) -> None:
    raw = raw_case()
    raw["screw"].update(screw)
    with pytest.raises(BallscrewError, match=message):
        case_from_dict(raw)


def test_the_stiffness_curve_of_a_single_nut_without_preload() -> None:
    """One flank, δ = C F^(2/3): the Hertz tangent stiffness is 1.5 F^(1/3)/C (closed form), the
    curves start one step above zero load (no stiffness at F = 0, where the export used to fail
    asking for a preload), and the elastic bodies only soften it."""
    raw = raw_case()
    raw["screw"]["nuts"] = 1
    raw["operating"]["preload"] = "0 N"
    result = design_check(case_from_dict(raw))
    curve = result.to_xarray()
    loads = curve["axial_load"].values
    assert loads[0] > 0.0 and curve.attrs["nuts"] == 1
    closed = 1.5 * loads ** (1.0 / 3.0) / result.compliance
    np.testing.assert_allclose(curve["stiffness"].values, closed, rtol=1e-12)
    np.testing.assert_allclose(
        curve["deflection"].values, result.compliance * loads ** (2.0 / 3.0), rtol=1e-12
    )
    body_loads, body_k = curve["body_load"].values, curve["stiffness_bodies"].values
    hertz_k = 1.5 * body_loads ** (1.0 / 3.0) / result.compliance
    assert body_loads[0] > 0.0 and np.all(body_k > 0.0) and np.all(body_k < hertz_k)
    # measured from the unloaded nut (x(0) = 0), so the bodies add to the contacts' deflection
    hertz_x = result.compliance * body_loads ** (2.0 / 3.0)
    body_x = curve["deflection_bodies"].values
    assert np.all(body_x > hertz_x) and body_x[0] < 1.1 * hertz_x[0]


def test_lost_motion_of_the_nut_and_the_springs_in_series() -> None:
    """2 (x_nut(F) + F/K_shaft + F/K_bearings) at the largest load (the check had no lost
    motion): the springs' part is exact; the nut's travel lies between the Hertz contacts'
    alone (the bodies only add compliance) and F over the smallest tangent stiffness of the
    curve with the bodies (x = ∫ dF/K)."""
    result = design_check(case_from_dict(raw_case()))
    load = 2000.0
    travel = 0.5 * result.lost_motion - load * (1.0 / result.shaft_stiffness + 1e-9)
    contacts = float(design.nut_load_deflection(load, 1500.0, result.compliance))
    curve = result.to_xarray()
    within = curve["body_load"].values <= load
    softest = float(curve["stiffness_bodies"].values[within].min())
    assert contacts < travel < load / softest
    no_bearings = raw_case()
    del no_bearings["design"]["bearing_stiffness"]
    rigid = design_check(case_from_dict(no_bearings)).lost_motion
    assert result.lost_motion - rigid == pytest.approx(2.0 * load / 1e9, rel=1e-9)
    raw = raw_case()
    raw["operating"]["axial_load"] = "0 N"
    assert design_check(case_from_dict(raw)).lost_motion == 0.0
    summary = result.summary()
    assert summary["lost_motion"] == {"value": pytest.approx(result.lost_motion), "unit": "m"}
    rows = dict(next(s for s in result.report() if s.title == "Design values").tables[0].rows)
    assert rows["lost motion at a reversal of the largest load [µm]"] == pytest.approx(
        1e6 * result.lost_motion
    )


def test_lost_motion_formula() -> None:
    assert design.lost_motion(1e-6, 1000.0, 1e9, 5e8) == pytest.approx(2.0 * (1e-6 + 3e-6))
    assert design.lost_motion(2e-6, 0.0) == pytest.approx(4e-6)
    with pytest.raises(InputError, match=r"^stiffness"):
        design.lost_motion(1e-6, 1000.0, 0.0)


def test_the_preload_drag_torque_band_is_reported() -> None:
    """The ±30 % band was a constant nobody read; the summary and the report now give it."""
    result = design_check(case_from_dict(raw_case()))
    summary = result.summary()
    torque = result.preload_drag_torque
    assert summary["preload_drag_torque_min"]["value"] == pytest.approx(0.7 * torque)
    assert summary["preload_drag_torque_max"]["value"] == pytest.approx(1.3 * torque)
    rows = dict(next(s for s in result.report() if s.title == "Design values").tables[0].rows)
    assert rows["preload drag torque, upper end of the band [N·m]"] == pytest.approx(1.3 * torque)


def test_the_pretension_of_a_fixed_fixed_shaft_has_a_margin() -> None:
    """Pretension E A α ΔT plus the largest load against σ_perm A (THK A-694) — a value
    without a margin before; only where both ends are fixed (no pretension otherwise)."""
    free = design_check(case_from_dict(raw_case()))
    assert "pretension" not in {m.name for m in free.margins}
    fixed = design_check(case_from_dict(raw_case(mounting="fixed-fixed")))
    margin = next(m for m in fixed.margins if m.name == "pretension")
    assert margin.demand == pytest.approx(fixed.thermal_pretension + 2000.0)
    assert margin.capacity == pytest.approx(fixed.permissible_tension)
    hot = raw_case(mounting="fixed-fixed", temperature_rise="60 K")
    with pytest.warns(UserWarning, match="pretension \\+ axial load vs permissible tension"):
        result = design_check(case_from_dict(hot))
    assert next(m for m in result.margins if m.name == "pretension").status == "red"


def test_a_preloaded_single_nut_is_said_to_have_flanks_not_nuts() -> None:
    """The lift-off warning of a single nut said 'the second nut'; the curve's attribute 'nuts'
    held the flank count (2 for a single nut)."""
    raw = raw_case()
    raw["screw"]["nuts"] = 1
    raw["operating"]["axial_load"] = "5 kN"
    with pytest.warns(UserWarning, match="lift-off"):
        result = design_check(case_from_dict(raw))
    lift = next(w for w in result.warnings if "lift-off" in w)
    assert "second flank" in lift and "nut carries" not in lift
    curve = result.to_xarray()
    assert curve.attrs["nuts"] == 1 and curve.attrs["flanks"] == 2
    margins = " ".join(next(s for s in result.report() if s.title == "Margins").paragraphs)
    assert "second flank" in margins and "second nut" not in margins
    captions = " ".join(f.caption for f in result.figures())
    assert "second flank" in captions


@pytest.mark.filterwarnings("ignore::UserWarning")
def test_the_report_names_the_static_model_it_used() -> None:
    """The report said 'C_0a at 4200 MPa Hertz pressure (ISO 76)' for the palmgren model too."""
    raw = raw_case()
    del raw["design"]["static_load_rating"]
    raw["design"]["static_rating_model"] = "palmgren"
    result = design_check(case_from_dict(raw))
    text = " ".join(next(s for s in result.report() if s.title == "Design values").paragraphs)
    assert "model 'palmgren'" in text and "4200 MPa" not in text and "C_a by" not in text


def test_the_summary_gives_dn_its_unit() -> None:
    summary = design_check(case_from_dict(raw_case())).summary()
    assert summary["dn"]["unit"] == summary["margins"]["dn"]["demand"]["unit"] == "mm·rpm"


def test_the_largest_level_distribution_is_kept_for_the_report() -> None:
    """The ball figure reuses the distribution the check solved under the largest |F_a|: it
    balances that load (F1 − F2 = F_a) and is the report's own solve to rounding."""
    from ballscrew.analyses.design_check_report import ball_distribution

    raw = raw_case()
    raw.setdefault("loads", {})["distribution"] = "elastic"
    result = design_check(case_from_dict(raw))
    kept, f_max = result.largest_distribution, result.spectrum.max_load
    assert f_max == 2000.0
    f1, f2 = kept.nut_forces
    assert f1 - f2 == pytest.approx(f_max, rel=1e-10)
    np.testing.assert_allclose(kept.loads, ball_distribution(result, f_max).loads, rtol=1e-12)
