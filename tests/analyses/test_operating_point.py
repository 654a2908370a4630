"""The coupled operating point: fixed point, energy balance, viscosity with temperature, CLI."""

from __future__ import annotations

import json
import math
from contextlib import nullcontext
from pathlib import Path

import pytest
import xarray as xr
from typer.testing import CliRunner

import ballscrew
from ballscrew.analyses.friction import friction_torque
from ballscrew.analyses.operating_point import (
    TOLERANCE,
    OperatingPointWarning,
    contact_readout,
    heat_overrides,
    medium_law,
    operating_point,
)
from ballscrew.analyses.result import AnalysisResult
from ballscrew.analyses.thermal import solve_field
from ballscrew.cli import app

RPM = 2 * math.pi / 60
FREE_NUT = {"thermal.mounting.kind": "free"}  # the nut in still air: hot at speed
LIBRARY_OIL = {
    "medium.viscosity": None,
    "medium.pressure_viscosity": None,
    "kinematics.lubricant": "iso_vg_68",
    "friction.model": "ball_model",
}


EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "gao2019_tcr.toml"


@pytest.fixture(scope="module")
def case():
    return ballscrew.load_case(EXAMPLE, {"numerics.cells_across": 16})


def test_friction_heat_is_torque_times_speed_less_the_work_done(case):
    point = operating_point(case, speed=1500 * RPM, axial_load=2000.0)
    work = 2000.0 * case.screw.lead / (2 * math.pi) * point.speed
    assert point.heat == pytest.approx(point.friction_torque * point.speed - work, rel=1e-12)
    balls = sum(s.heat for s in point.field.sources if "balls" in s.name)
    assert balls == pytest.approx(point.heat, rel=1e-9)  # all of it reaches the thermal model
    assert 0.0 < point.efficiency < 1.0
    assert point.nut_temperature > point.field.ambient_temperature


def test_the_fixed_point_does_not_depend_on_where_it_starts(case):
    oil = ballscrew.case.with_overrides(case, LIBRARY_OIL)
    cold = operating_point(oil, speed=1000 * RPM)
    hot = operating_point(oil, speed=1000 * RPM, start_temperature=400.0)
    assert hot.nut_temperature == pytest.approx(cold.nut_temperature, abs=0.05)
    assert hot.friction_torque == pytest.approx(cold.friction_torque, rel=1e-3)


@pytest.mark.parametrize(("rpm", "solves"), [(1000, 4), (2100, 4), (3000, 5)])
def test_the_point_is_the_fixed_point_to_its_tolerance(case, rpm, solves):
    """One more plain step T_c → T(T_c) from the answer, evaluated here by hand (friction at
    η(T_c), its heat on the network, the mean of nut and screw), moves it by ≤ 0.01 K; the
    secant step gets there in at most 4 thermal solves (the plain iteration took 5 at 2100 and
    3000 rpm), 5 at 3000 rpm since the asperities read the 3-D G of the raceway's profile G
    (surface.G_convention; 4 with the profile G read as a surface G)."""
    oil = ballscrew.case.with_overrides(case, LIBRARY_OIL)
    with pytest.warns(OperatingPointWarning) if rpm > 1500 else nullcontext():
        point = operating_point(oil, speed=rpm * RPM)
    eta = medium_law(point.case)(point.contact_temperature)[0]
    friction = friction_torque(point.case, viscosity=eta)
    heat = heat_overrides(friction.heat, friction.heat_to_screw, point.speed)
    field = solve_field(
        ballscrew.case.with_overrides(point.case, heat),
        "network",
        transient=False,
        thermoelastic=False,
    )
    screw, nut = contact_readout(field.solution.discretisation)
    steady = field.solution.steady
    again = field.ambient_temperature + 0.5 * (nut(steady) + float(screw @ steady))
    assert again == pytest.approx(point.contact_temperature, abs=TOLERANCE)
    assert point.iterations <= solves


def test_a_named_oil_thins_as_the_screw_heats(case):
    oil = ballscrew.case.with_overrides(case, {**LIBRARY_OIL, **FREE_NUT})
    point = operating_point(oil, speed=1500 * RPM)
    library = ballscrew.lubrication.lubricant_library.LUBRICANT_LIBRARY["iso_vg_68"]
    assert point.contact_temperature > 313.15
    assert point.viscosity < library.at(313.15).viscosity
    # η at the contact temperature, to the fixed point's 0.01 K (about 3e-4 of η)
    at_contact = library.at(point.contact_temperature).viscosity
    assert point.viscosity == pytest.approx(at_contact, rel=1e-3)
    assert point.film_thickness > 0.0


def test_at_rest_there_is_no_friction_heat(case):
    point = operating_point(case, speed=0.0)
    assert point.heat == 0.0
    assert point.nut_temperature == pytest.approx(point.field.ambient_temperature, abs=1e-9)


def test_a_hot_nut_is_a_warning(case):
    mounted = operating_point(case, speed=1500 * RPM, axial_load=3000.0)
    assert mounted.nut_temperature < 333.15 and not mounted.warnings
    free = ballscrew.case.with_overrides(case, FREE_NUT)
    point = operating_point(free, speed=1500 * RPM, axial_load=3000.0)
    assert point.nut_temperature > 333.15
    assert any("the nut runs at" in w for w in point.warnings)


def test_python_equals_the_command_line(tmp_path):
    out = tmp_path / "op"
    result = CliRunner().invoke(
        app,
        [
            "operating-point",
            str(EXAMPLE),
            "--out",
            str(out),
            "--speed",
            "1200 rpm",
            "--axial-load",
            "1 kN",
        ],
    )
    assert result.exit_code == 0, result.output
    summary = json.loads((out / "summary.json").read_text())
    full = ballscrew.load_case(EXAMPLE)
    point = operating_point(full, speed=1200 * RPM, axial_load=1000.0)
    assert isinstance(point, AnalysisResult)
    for key in ("friction_torque", "heat", "nut_temperature", "screw_temperature"):
        assert summary[key]["value"] == pytest.approx(getattr(point, key), rel=1e-12)
    assert "inputs" in summary and (out / "report.html").read_text().count("Inputs")


def test_bad_speed_is_one_line(tmp_path):
    result = CliRunner().invoke(
        app,
        ["operating-point", str(EXAMPLE), "--out", str(tmp_path / "x"),
         "--speed", "9**9**9 rpm"],
    )  # fmt: skip
    assert result.exit_code == 2 and result.output.startswith("error: --speed")
    assert not (tmp_path / "x").exists()


def test_speed_limits_and_boundary_lubrication_are_warnings(case):
    fast = operating_point(case, speed=3000 * RPM)  # d·n = 40 mm × 3000 rpm = 120 000
    assert any("d·n" in w for w in fast.warnings)
    thin = ballscrew.case.with_overrides(
        case, {"friction.model": "ball_model", "medium.viscosity": "1 mPa*s"}
    )
    slow = operating_point(thin, speed=30 * RPM)
    assert any("boundary lubrication" in w for w in slow.warnings)


def test_a_cooled_shaft_reports_its_coolant_outlet(case):
    """The summary carries the outlet of the hollow-shaft coolant, warmer than its inlet by
    the heat the bore takes (positive), and a solid shaft has no such key."""
    cooled = ballscrew.load_case(
        EXAMPLE,
        {
            "numerics.cells_across": 16,
            "thermal.shaft_coolant.bore_diameter": "12 mm",
            "thermal.shaft_coolant.flow_rate": "2 L/min",
            "thermal.shaft_coolant.inlet_temperature": "19 degC",
        },
    )
    point = operating_point(cooled, speed=1500 * RPM, axial_load=2000.0)
    outlet = point.summary()["coolant_outlet_temperature"]
    inlet = 273.15 + 19.0
    assert outlet["unit"] == "K"
    assert inlet < outlet["value"] < point.nut_temperature
    solid = operating_point(case, speed=1500 * RPM, axial_load=2000.0)
    assert "coolant_outlet_temperature" not in solid.summary()


def test_the_steady_field_of_a_point_reads_cleanly(case):
    """The operating-point report showed 'nan' for the sensors' final temperatures, the heat
    balance as '1.33e-15' and 'the fixed torque … (not coupled)' for the coupled point's heat."""
    from ballscrew.analyses import thermal_report

    point = operating_point(case, speed=1500 * RPM)
    sections = {s.title: s for s in thermal_report.sections(point.field)}
    heat = sections["Heat sources (Q2–Q4)"].paragraphs[0]
    assert "not coupled" not in heat and "source = 'operating_point'" in heat
    sensors = sections["Results"].tables[1].rows
    assert sensors and all(row[-2:] == ("–", "–") for row in sensors)
    balance = dict(sections["Heat balance"].tables[0].rows)
    assert "e-" not in balance["steady relative error"]


def test_the_report_tells_the_screw_torque_from_its_friction_part(case):
    """'friction torque' is the screw torque with the work on the load; the report said
    'friction torque [N·m] 3.727' at 2 kN where 0.54 N·m of it is friction."""
    from ballscrew.analyses import operating_point_report

    point = operating_point(case, speed=1500 * RPM, axial_load=2000.0)
    rows = dict(operating_point_report.sections(point)[0].tables[0].rows)
    assert rows["screw torque T, work F_a·L/2π included [N·m]"] == point.friction_torque
    work = 2000.0 * case.screw.lead / (2 * math.pi)
    part = rows["friction part of T = heat / ω [N·m]"]
    assert part == pytest.approx(point.friction_torque - work, rel=1e-9)


def test_the_torque_is_reported_by_part_with_its_regime(case):
    """The summary and report gave only the total torque: neither its parts nor the film
    parameter and traction coefficient the ball model ran at."""
    from ballscrew.analyses import operating_point_report

    point = operating_point(
        ballscrew.load_case(EXAMPLE, {"numerics.cells_across": 16, **LIBRARY_OIL}),
        speed=100 * RPM,
        axial_load=1000.0,
    )
    summary = point.summary()
    parts = {k: q["value"] for k, q in summary["torque_parts"].items()}
    assert sum(parts.values()) == pytest.approx(point.friction_torque, rel=1e-12)
    assert parts["sliding"] > 0.0 and parts["ball_ball"] > 0.0
    assert summary["friction_part"]["value"] == pytest.approx(point.heat / point.speed, rel=1e-9)
    assert 0.0 < summary["film_parameter"]["value"] < 100.0
    assert summary["lubrication_regime"] in ("boundary", "mixed", "EHL")
    assert 0.0 < summary["traction_coefficient"]["value"] < 0.2
    section = operating_point_report.sections(point)[1]
    assert section.title == "Torque by part"
    assert dict(section.tables[0].rows)["ball–ball friction"] == pytest.approx(
        1e3 * parts["ball_ball"]
    )
    assert "Λ = " in section.paragraphs[0] and "μ = " in section.paragraphs[0]
    catalogue = operating_point(case, speed=100 * RPM).summary()
    # Λ is the operating point's, not the friction model's: the catalogue model reports it too
    assert "preload" in catalogue["torque_parts"] and "traction_coefficient" not in catalogue
    assert 0.0 < catalogue["film_parameter"]["value"] < 1.0  # 58 nm over σ = 302 nm
    assert catalogue["lubrication_regime"] == "boundary"


def test_a_steady_field_draws_no_empty_time_axis(case, tmp_path, monkeypatch):
    """Without a transient the elongation figure had an empty 0–1 min time axis."""
    from ballscrew.analyses import thermal_report

    point = operating_point(case, speed=1500 * RPM)
    drawn = []
    original = thermal_report.save_figure
    monkeypatch.setattr(
        thermal_report,
        "save_figure",
        lambda fig, *a, **k: drawn.append(fig) or original(fig, *a, **k),
    )
    thermal_report.elongation_plot(point.field, tmp_path / "e.png")
    [ax] = drawn[0].axes
    assert ax.get_xlabel() == "z [mm]" and "µm" in ax.get_title()


def test_the_friction_part_at_rest_is_no_zero(case):
    """At rest the report's 'friction part of T = heat / ω' read 0 N·m (no heat) while the
    summary's friction_part gave T − F_a·L/2π = 0.54 N·m: the torque to start the screw."""
    from ballscrew.analyses import operating_point_report

    point = operating_point(case, speed=0.0, axial_load=2000.0)
    rows = dict(operating_point_report.sections(point)[0].tables[0].rows)
    part = point.summary()["friction_part"]["value"]
    assert part > 0.1 and rows["friction part of T = heat / ω [N·m]"] == pytest.approx(part)


def test_the_catalogue_band_is_checked_on_the_preload_losses_alone(case):
    """The band warning compared everything but the work on the load (the working load's
    friction and the seals included) with the catalogue preload torque: eight wipers
    (0.8 N·m) made a ball model of 0.24 N·m at the preload 'outside 0.5–2 ×', and a nut
    without preload (a band of 0 N·m) warned at any load. Ball losses far above the band
    still warn."""
    ball = {"numerics.cells_across": 16, "friction.model": "ball_model"}
    band = "catalogue preload torque"
    sealed = ballscrew.load_case(EXAMPLE, {**ball, "friction.seals": 8})
    point = operating_point(sealed, speed=1000 * RPM, axial_load=3000.0)
    assert point.friction.parts["seals"] == pytest.approx(0.8)
    assert not any(band in w for w in point.warnings)
    single = ballscrew.load_case(
        EXAMPLE,
        {
            **ball,
            "screw.nuts": 1,
            "operating.preload": 0.0,
            "operating.axial_load": 1000.0,
            "thermal.sensors": [],
        },
    )
    assert not any(band in w for w in operating_point(single, 1000 * RPM).warnings)
    crowded = ballscrew.load_case(EXAMPLE, {**ball, "friction.ball_ball_load_ratio": 0.5})
    [warning] = [w for w in operating_point(crowded, speed=1000 * RPM).warnings if band in w]
    assert "3.96 N·m" in warning  # ball–ball friction 3.79 of it, against 0.423 N·m


def test_both_efficiencies_and_the_lubricant_reach_the_user(case, tmp_path):
    """summary.json and the report had the driving efficiency only, and the console neither
    efficiency, viscosity nor film. Closed forms of THK's efficiency (λ = atan L/(π d_m),
    ρ′ = atan 0.003) and η at the point = F_a L/(2π T)."""
    from ballscrew.analyses import operating_point_report

    point = operating_point(case, speed=1000 * RPM, axial_load=2000.0)
    lam, rho = math.atan(0.01 / (math.pi * 0.04)), math.atan(0.003)
    summary = point.summary()
    assert summary["efficiency"]["value"] == pytest.approx(math.tan(lam) / math.tan(lam + rho))
    back = math.tan(lam - rho) / math.tan(lam)
    assert summary["efficiency_backdriving"]["value"] == pytest.approx(back, rel=1e-12)
    overall = 2000.0 * 0.01 / (2 * math.pi * point.friction_torque)
    assert summary["efficiency_overall"]["value"] == pytest.approx(overall, rel=1e-12)
    assert overall < summary["efficiency"]["value"]  # the preload torque costs efficiency
    rows = dict(operating_point_report.sections(point)[0].tables[0].rows)
    assert any(k.startswith("back-driving efficiency") and v == back for k, v in rows.items())
    at_rest = operating_point(case, speed=0.0).summary()["efficiency_overall"]
    assert at_rest["value"] is None and "at rest" in at_rest["reason"]
    out = tmp_path / "op"
    result = CliRunner().invoke(app, ["operating-point", str(EXAMPLE), "--out", str(out)])
    assert result.exit_code == 0, result.output
    for text in ("driving efficiency", "0.9634", "viscosity at the contacts", "60 mPa·s", "nm"):
        assert text in result.output


def test_the_command_draws_curves_over_a_speed_range(tmp_path):
    """`ballscrew operating-point` gave one speed only. Its curve: the catalogue torque
    K F_p L/2π at every speed, heat = T_f ω, the oil thinner and the screw warmer as the speed
    rises, the case's own point on it, each point's warnings kept with it."""
    out = tmp_path / "op"
    args = ["operating-point", str(EXAMPLE), "--out", str(out), "--curve-to", "2000 rpm"]
    result = CliRunner().invoke(app, [*args, "--curve-points", "4"])
    assert result.exit_code == 0, result.output
    curve = json.loads((out / "summary.json").read_text())["speed_curve"]
    speed = [v * 30 / math.pi for v in curve["speed"]["value"]]
    assert speed == pytest.approx([500.0, 1000.0, 1500.0, 2000.0])
    params = ballscrew.analyses.parameters.ScrewParameters.from_case(ballscrew.load_case(EXAMPLE))
    g = params.geometry
    catalogue = ballscrew.loads.preload_drag_torque(params.preload, g.lead, g.lead_angle)
    torque, heat = curve["friction_part"]["value"], curve["heat"]["value"]
    assert torque == pytest.approx([catalogue] * 4, rel=1e-12)
    omega = curve["speed"]["value"]
    assert heat == pytest.approx([t * w for t, w in zip(torque, omega, strict=True)], rel=1e-12)
    screw = curve["screw_temperature"]["value"]
    assert sorted(screw) == screw and len(set(screw)) == len(screw)
    one = tmp_path / "one"
    no_curve = ["operating-point", str(EXAMPLE), "--out", str(one), "--curve-points", "0"]
    assert CliRunner().invoke(app, no_curve).exit_code == 0
    single = json.loads((one / "summary.json").read_text())
    assert "speed_curve" not in single
    assert screw[1] == pytest.approx(single["screw_temperature"]["value"], rel=1e-12)
    warned = [" ".join(w) for w in curve["warnings"]]
    assert "Λ" in warned[0] and not warned[2] and "d·n = 80000" in warned[3]
    assert (out / "speed_curve.png").stat().st_size > 0
    with xr.open_dataset(out / "fields.nc") as data:
        assert data["curve_heat"].values.tolist() == pytest.approx(heat, rel=1e-12)
    assert "Speed curve" in (out / "report.html").read_text()
    bad = CliRunner().invoke(app, [*args[:4], "--curve-to", "0 rpm", "--out", str(tmp_path / "b")])
    assert bad.exit_code == 2 and not (tmp_path / "b").exists()


def test_the_film_is_reported_for_each_nut_at_its_own_ball_load(case):
    """Only the loaded nut's film was reported. Hamrock–Dowson's central film goes as
    W^−0.067 at a fixed speed and lubricant, so the nut the load relieves has the thicker film,
    (Q₂/Q₁)^−0.067 times nut 1's; a nut lifted off has none."""
    params = ballscrew.analyses.parameters.ScrewParameters.from_case
    loaded = operating_point(case, speed=1000 * RPM, axial_load=2000.0)
    q1, q2 = (n.ball_load for n in params(loaded.case).flank_loads)
    h1, h2 = loaded.film_thickness_per_nut
    assert h1 == loaded.film_thickness
    assert h2 / h1 == pytest.approx((q2 / q1) ** -0.067, rel=1e-9)
    lifted = operating_point(case, speed=1000 * RPM, axial_load=6000.0)
    assert math.isnan(lifted.film_thickness_per_nut[1])
    nut2 = lifted.summary()["film_thickness_per_nut"]["nut2"]
    assert nut2["value"] is None and "lifted off" in nut2["reason"]


def test_a_physics_torque_is_set_beside_the_catalogue_reference(case):
    """The ball model's torque (then 0.12 N·m) and the catalogue's (0.42 N·m) were reported
    apart with no guidance. The result gives both at the preload and their ratio: the
    catalogue's closed form K F_p L/2π, K = 0.05/√tan λ (0.42314 N·m for the example)."""
    from ballscrew.analyses import operating_point_report

    ball = ballscrew.case.with_overrides(case, {"friction.model": "ball_model"})
    point = operating_point(ball, speed=1000 * RPM, axial_load=2000.0)
    lam = math.atan(0.01 / (math.pi * 0.04))
    catalogue = 0.05 / math.sqrt(math.tan(lam)) * 1500.0 * 0.01 / (2 * math.pi)
    summary = point.summary()
    assert summary["catalogue_preload_torque"]["value"] == pytest.approx(catalogue, rel=1e-12)
    parts = point.friction.parts
    losses = point.friction_torque - parts["work"] - parts["load"] - parts["seals"]
    assert summary["preload_torque"]["value"] == pytest.approx(losses, rel=1e-12)
    note = operating_point_report.sections(point)[1].paragraphs[0]
    assert f"{losses / catalogue:.2f} × the makers' catalogue preload torque" in note


def test_a_curve_beyond_the_speed_range_blames_its_option(tmp_path):
    """--curve-to above the case's speed range (1e5 rad/s) was refused only after the case's
    point was solved, and in the name of operating.speed; it is --curve-to's error up front."""
    out = tmp_path / "fast"
    args = ["operating-point", str(EXAMPLE), "--out", str(out), "--curve-to", "1e9"]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 2 and not out.exists()
    assert "--curve-to" in result.output and "operating.speed" not in result.output
    assert "100000" in result.output


def test_the_speed_curve_does_not_blame_operating_speed_for_its_points(case):
    """A curve of 750 and 1500 rad/s (d·n 2.9e5 and 5.7e5 mm·rpm, beyond any screw's 2e5): no
    'operating.speed = 750 rad/s' on the console, which the user never set (each point still
    keeps its own d·n message)."""
    import warnings

    from ballscrew.analyses.operating_point import speed_curve
    from ballscrew.errors import ImplausibleValueWarning

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        curve = speed_curve(case, [750.0, 1500.0, 2500.0])
    assert not [w for w in caught if issubclass(w.category, ImplausibleValueWarning)]
    assert all(any("d·n" in m for m in point) for point in curve.warnings)
    # Re_ω = ω d²/ν = 2500 × 0.04²/1.589e-5 = 2.5e5 < 4.3e5 < 4.9e5 at 4900 rad/s: kept, not raised
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        curve = speed_curve(case, [4900.0])
    assert not caught and any("Kreith" in m for m in curve.warnings[0])


def test_a_field_without_sensors_has_no_empty_sensor_table(case):
    """No [[thermal.sensors]]: the results section had a sensor table of headers only."""
    from ballscrew.analyses import thermal_report
    from ballscrew.case import with_overrides

    point = operating_point(with_overrides(case, {"thermal.sensors": []}), speed=1500 * RPM)
    results = {s.title: s for s in thermal_report.sections(point.field)}["Results"]
    assert [t.header[0] for t in results.tables] == ["quantity"]
