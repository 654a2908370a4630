"""Bad input found by fuzzing the command line: one line, exit 2, nothing written.

Each case is one perturbed input that once slipped through (a case printed that no command
accepts, a silently ignored cell, a run far outside the case's ranges or the correlations'
validity, a message naming the wrong field); the tests hold the one-line refusal.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from ballscrew.calibration import read_measured
from ballscrew.case import load_case
from ballscrew.case.loader import CaseError
from ballscrew.cli import app
from ballscrew.errors import InputError
from ballscrew.thermal.coolant import FLUIDS, BoreFlow

MEASURED = Path(__file__).parent.parent / "examples" / "measured" / "step_stress_torque.csv"
INIT = ("init", "--d0", "40", "--lead", "10", "--ball", "6.35", "--turns", "2.5x2")


def refused(*args: object) -> str:
    """Run ``ballscrew ARGS``; it must refuse with one ``error:`` line. Returns that line."""
    result = CliRunner().invoke(app, [str(a) for a in args])
    assert result.exception is None or isinstance(result.exception, SystemExit), result.output
    lines = [line for line in result.output.splitlines() if line.strip()]
    assert result.exit_code == 2 and len(lines) == 1, result.output
    assert lines[0].startswith("error: "), result.output
    return lines[0]


def test_kinematics_speed_option_above_the_case_range(tmp_path: Path, gao_case_path) -> None:
    """``--speed 1e12 rpm`` ran (1e11 rad/s, a 0.27 m film) where operating.speed stops at
    1e5 rad/s."""
    out = tmp_path / "out"
    line = refused("kinematics", gao_case_path, "--speed", "1e12 rpm", "--out", out)
    assert line.startswith("error: speed = 1047") and "100000] rad/s" in line
    assert not out.exists()


def test_bore_flow_beyond_the_pipe_correlations() -> None:
    """A 1 µm bore at 2 L/min (u = 4·10⁷ m/s, Re = 5·10⁷) ran the 3-D model with Gnielinski far
    outside 3000 ≤ Re ≤ 5·10⁶; the 12 mm bore of the tests (Re = 4123) still runs."""
    water = FLUIDS["water"]
    with pytest.raises(InputError, match=r"^thermal.shaft_coolant.flow_rate = 3.33.*Re = 4.9"):
        BoreFlow(1e-6, 2e-3 / 60.0, water)
    assert BoreFlow(0.012, 2e-3 / 60.0, water).reynolds < 5e6


def test_measured_row_with_more_cells_than_the_header(tmp_path: Path) -> None:
    """A third cell in a two-column CSV was dropped without a word."""
    path = tmp_path / "long.csv"
    path.write_text("revolutions,friction_torque\n0,0.48,5\n10000,0.47\n20000,0.46\n")
    with pytest.raises(InputError, match=r"^long.csv: line 2 = '0,0.48,5' is not allowed: at"):
        read_measured(path)
    path.write_text("revolutions,friction_torque,\n0,0.48,\n10000,0.47,\n")  # empty cells pass
    assert len(read_measured(path)) == 2


def test_fit_until_that_leaves_too_few_points_names_it(tmp_path: Path, wear_case_path) -> None:
    """``--fit-until 0`` said only '1 points cannot determine 2 parameter(s)'."""
    out = tmp_path / "out"
    line = refused(
        "calibrate", wear_case_path, "-q", "-m", MEASURED, "--fit-until", "0", "--out", out
    )
    assert line.startswith("error: --fit-until = 0.0 is not allowed: the 1 points")
    assert not out.exists()


def test_duty_stroke_longer_than_the_shaft(tmp_path: Path, gao_case_path) -> None:
    """A 5 m stroke on the 1 m shaft ran the duty cycle."""
    case = tmp_path / "case.toml"
    case.write_text(gao_case_path.read_text().replace('stroke = "400 mm"', 'stroke = "5 m"'))
    out = tmp_path / "out"
    line = refused("duty", case, "--out", out, "--set", "numerics.cells_across=16")
    assert line.startswith("error: duty.0.stroke = 5.0 is not allowed: at most 0.87 m")
    assert not out.exists()


@pytest.mark.parametrize(
    ("option", "value", "field"),
    [
        ("--d0", "1e30", "screw.pitch_diameter"),
        ("--preload", "1e30", "operating.preload"),
        ("--length", "1e30", "thermal.shaft_length"),
    ],
)
def test_init_refuses_options_whose_case_no_command_accepts(option, value, field) -> None:
    """``init --d0 1e30`` printed a case with d_m = 1e30 mm (exit 0) that every command
    refused."""
    args = list(INIT)
    if option in args:
        args[args.index(option) + 1] = value
    else:
        args += [option, value]
    line = refused(*args)
    assert line.startswith(f"error: {option} = '1e+30 ") and f"it gives {field} = " in line


def test_set_names_list_entries_by_index(gao_case_path) -> None:
    """``--set duty.0.stroke=…`` said 'duty.0.stroke: unknown key; allowed in duty: …, stroke,
    …'; an index now names the entry, and a missing one or a missing index is named."""
    assert load_case(gao_case_path, {"duty.1.duration": "5 min"}).duty[1].duration == 300.0
    with pytest.raises(CaseError, match=r"duty.5.stroke: duty has no entry 5 \(entries: 0 to 1\)"):
        load_case(gao_case_path, {"duty.5.stroke": 1.0})
    with pytest.raises(CaseError, match=r"duty.stroke: duty is a list; name an entry, e.g. duty.0"):
        load_case(gao_case_path, {"duty.stroke": 1.0})


def test_surface_resolution_too_coarse_for_the_profile(tmp_path: Path) -> None:
    """``--resolution 1 m`` on a 2 mm profile said 'heights = 4000 points per profile is not
    allowed: ≥ 64'; it now names the resolution and its limit L/60 (ω_top/3 ≥ 10/L)."""
    profile = MEASURED.parent.parent / "profiles" / "synthetic_wm_D1.59_G9e-10.sdf"
    out = tmp_path / "out"
    line = refused("surface", profile, "--resolution", "34 um", "--out", out)
    assert line.startswith("error: resolution = 3.4e-05 is not allowed: at most 3.33e-05 m")
    assert not out.exists()


def test_root_diameter_outside_the_thread(gao_case_path) -> None:
    """``design.root_diameter = 1e-12`` (allowed: > 0) made the ball-load Newton's Jacobian
    singular: a numpy LinAlgError traceback from ``ballscrew check``."""
    with pytest.raises(
        CaseError, match=r"design.root_diameter = 1e-12 m is not allowed: .* 0.0273"
    ):
        load_case(gao_case_path, {"design.root_diameter": 1e-12})
    with pytest.raises(CaseError, match=r"kinematics.root_diameter = 0.04 m is not allowed"):
        load_case(gao_case_path, {"kinematics.root_diameter": "40 mm"})
    assert load_case(gao_case_path, {"design.root_diameter": "34.4 mm"}).design.root_diameter


def test_singular_ball_load_newton_is_a_convergence_error() -> None:
    """A singular Jacobian (here G = 0) ends the ball-load Newton with its residual, not a
    LinAlgError."""
    from ballscrew.errors import ConvergenceError
    from ballscrew.loads.distribution import _newton

    with pytest.raises(ConvergenceError, match=r"residual 1\.000e\+00"):
        _newton(
            np.zeros((2, 2)),
            np.zeros((2, 1)),
            np.ones(2),
            np.zeros((1, 2)),
            np.ones(1),
            np.zeros(3),
        )


def test_measured_schedule_beyond_the_case_ranges(tmp_path: Path) -> None:
    """A schedule row at 1e12 rpm fitted (exit 0); a negative speed was reported as
    'np.float64(-10.47…)'."""
    path = tmp_path / "sched.csv"
    head = "revolutions,friction_torque,speed [rpm],axial_load [N]\n0,0.48,100,2000\n"
    path.write_text(head + "20000,0.47,1e12,2000\n40000,0.46,100,2000\n")
    with pytest.raises(InputError, match=r"^sched.csv: speed \(point 2\) = 1047.*\[0, 100000\]"):
        read_measured(path)
    path.write_text(head + "20000,0.47,-100,2000\n40000,0.46,100,2000\n")
    with pytest.raises(InputError, match=r"^sched.csv: speed \(point 2\) = -10.47\d+ is not"):
        read_measured(path)


@pytest.mark.parametrize(
    ("args", "start"),
    [
        (("sweep", "{case}", "--vary", "surface.D=1.5,1.6", "--workers", "0"), "'--workers'"),
        (("kinematics", "{case}", "--level", "abc"), "'--level'"),
        (("surface", "{tmp}"), "'PROFILE_FILE': file '"),
        (("init", "--d0", "40"), "Missing option '--lead'"),
        (("kinematics",), "Missing argument 'CASE_FILE'"),
        (("kinematic", "{case}"), "No such command 'kinematic'"),
        (("--bogus",), "No such option: --bogus"),
    ],
)
def test_usage_errors_are_one_line(tmp_path: Path, gao_case_path, args, start) -> None:
    """A value click cannot parse (``--workers 0``, ``--level abc``, a folder for a file, a
    missing option) printed click's three-line usage box instead of one ``error:`` line."""
    out = tmp_path / "out"
    given = [a.format(case=gao_case_path, tmp=tmp_path) for a in args]
    line = refused(*given, *(["--out", out] if given[0] == "sweep" else []))
    assert start in line
    assert not out.exists()


def test_sweep_workers_beyond_the_memory_budget(tmp_path: Path, gao_case_path) -> None:
    """``--workers 1000000000`` started a local Dask cluster of 10⁹ processes (a hang); the
    count is now held against the memory budget before any work."""
    from ballscrew.sweep.cluster import check_workers

    out = tmp_path / "out"
    args = ("sweep", gao_case_path, "--vary", "surface.D=1.5,1.6", "--out", out)
    line = refused(*args, "--workers", "1000000000")
    assert line.startswith("error: --workers = 1000000000 is not allowed: 1000000000 local")
    assert not out.exists()
    with pytest.raises(InputError, match=r"^--workers = 0 is not allowed: an integer ≥ 1"):
        check_workers(0)
    check_workers(2)


def test_surface_gamma_next_to_one(tmp_path: Path) -> None:
    """``--gamma 1.0000001`` (allowed: > 1) binned the spectrum into ln γ/16-wide sub-bins:
    a 9 GiB allocation and a MemoryError traceback. γ now starts at 1.01."""
    profile = MEASURED.parent.parent / "profiles" / "synthetic_wm_D1.59_G9e-10.sdf"
    out = tmp_path / "out"
    line = refused("surface", profile, "--gamma", "1.0000001", "--out", out)
    allowed = "W-M frequency ratio 1.01 ≤ γ ≤ 10 (usually 1.5)"
    assert line == f"error: gamma = 1.0000001 is not allowed: {allowed}"
    assert not out.exists()


def test_tracebacks_of_odd_text(tmp_path: Path, gao_case_path) -> None:
    """Three texts that ended in a traceback: ``init --name 'a"b'`` wrote an unquoted name into
    the TOML it checks (TOMLDecodeError); an integer of 5000 digits in a case file or a
    ``--set`` (Python's int-conversion limit, a ValueError); ``--set duty.².stroke=1`` (a
    digit ``int()`` cannot read)."""
    result = CliRunner().invoke(app, [*INIT, "--name", 'a"b\\c\nd'])
    assert result.exit_code == 0, result.output
    assert 'name = "a\\"b\\\\c\\nd"\n' in result.output
    case = tmp_path / "case.toml"
    case.write_text("name = " + "9" * 5000 + "\n")
    out = tmp_path / "out"
    line = refused("tcr", case, "--out", out)
    assert "case.toml: TOML syntax error: Exceeds the limit (4300 digits)" in line
    line = refused("tcr", gao_case_path, "--out", out, "--set", "operating.speed=" + "9" * 5000)
    assert line.startswith(f"error: {gao_case_path}: operating.speed: cannot read '9999")
    line = refused("tcr", gao_case_path, "--out", out, "--set", "duty.².stroke=1")
    assert line.endswith("duty.².stroke: duty is a list; name an entry, e.g. duty.0")
    assert not out.exists()


def test_tcr_without_rebinning_writes_its_folder(tmp_path: Path, gao_case_path) -> None:
    """``--set tcr.rebin=false`` (a documented option) ended in a TypeError traceback: the
    NetCDF writer refused the attribute cell_size_m = None."""
    out = tmp_path / "out"
    args = ("--set", "tcr.rebin=false", "--set", "numerics.cells_across=8", "-q")
    result = CliRunner().invoke(app, ["tcr", str(gao_case_path), "--out", str(out), *args])
    assert result.exit_code == 0, result.output
    assert (out / "summary.json").exists()


def test_friction_torque_arguments_beyond_the_case_ranges(gao_case_path) -> None:
    """``friction_torque(case, axial_load=1e30)`` gave 1.7e27 N m (operating.axial_load stops
    at 1e8 N), and a viscosity of NaN, −1 or inf was ignored without a word by the catalogue
    model."""
    from ballscrew import friction_torque

    case = load_case(gao_case_path)
    with pytest.raises(InputError, match=r"^axial_load = 1e\+30 is not allowed: a force in \[0,"):
        friction_torque(case, axial_load=1e30)
    for bad in (math.nan, -1.0, math.inf):
        with pytest.raises(InputError, match=r"^viscosity = .* is not allowed: a finite number"):
            friction_torque(case, viscosity=bad)
    assert friction_torque(case, axial_load=1e8, viscosity=0.06).total > 0.0


def test_empty_model_names_are_refused(tmp_path: Path, gao_case_path) -> None:
    """``tcr --variant ''`` and ``sweep --analysis ''`` ran the case's variant and the tcr
    analysis: an empty name was taken for no name."""
    out = tmp_path / "out"
    line = refused("tcr", gao_case_path, "--variant", "", "--out", out)
    assert line == "error: tcr.variant = '' is not allowed: one of V2, MT, V1"
    args = ("sweep", gao_case_path, "--vary", "surface.D=1.5,1.6", "--out", out)
    assert "'' is not allowed" in refused(*args, "--analysis", "")
    assert not out.exists()


def test_public_functions_refuse_what_is_no_case(gao_case_path) -> None:
    """``ball_loads``, ``operating_point`` and ``design_check`` given a path instead of a case
    raised AttributeError, ``load_case(None)`` a TypeError and ``operating_point(case,
    speed="abc")`` a ValueError; each is now the one-line error the other functions give."""
    import ballscrew

    for function in (ballscrew.ball_loads, ballscrew.operating_point, ballscrew.design_check):
        with pytest.raises(InputError, match=r"^case = 'x.toml' is not allowed: a case from"):
            function("x.toml")
    with pytest.raises(CaseError, match=r"path = None: expected the path of a case file"):
        load_case(None)
    case = load_case(gao_case_path)
    with pytest.raises(CaseError, match=r"operating.speed: cannot read 'abc' as a quantity"):
        ballscrew.operating_point(case, speed="abc")


def test_spacer_far_shorter_than_an_axial_cell(tmp_path: Path, gao_case_path) -> None:
    """``thermal.spacer_length = 1e-30`` (allowed: ≥ 0) failed an assert of the axial grid,
    whose ring spacings could give the spacer no cell: an AssertionError traceback."""
    out = tmp_path / "out"
    sets = ("--set", "thermal.spacer_length=1e-30", "--set", "numerics.cells_across=16")
    line = refused("thermal", gao_case_path, "--out", out, *sets)
    assert line.startswith("error: thermal.spacer_length = 1e-30 is not allowed: 0 (none) or at")
    assert not out.exists()


def test_control_characters_in_case_text(gao_case_path) -> None:
    """``name = "a\\u0000b"`` ran ``ballscrew contact`` to the end and failed writing the NetCDF
    attribute (h5py ValueError traceback); an ESC would drive the terminal. Tab and line
    breaks still pass."""
    with pytest.raises(CaseError, match=r"name = 'a\\x00b' is not allowed: text without control"):
        load_case(gao_case_path, {"name": "a\x00b"})
    with pytest.raises(CaseError, match=r"thermal.sensors.0.name = 'x\\x1b\[31m' is not allowed"):
        load_case(gao_case_path, {"thermal.sensors.0.name": "x\x1b[31m"})
    assert load_case(gao_case_path, {"description": "a\tb\nc"}).description == "a\tb\nc"


def test_true_or_false_for_a_number_is_refused(gao_case_path) -> None:
    """``balls_per_nut = true`` was read as 1 ball; a boolean field still takes one."""
    with pytest.raises(CaseError, match=r"screw.balls_per_nut = True is not allowed: a number"):
        load_case(gao_case_path, {"screw.balls_per_nut": True})
    assert load_case(gao_case_path, {"operating.coupled": True}).operating.coupled is True


def test_a_value_given_twice_on_a_sweep_axis_is_refused() -> None:
    """``--vary surface.D=1.5,1.5`` ran the same point twice."""
    from ballscrew.sweep import parse_axis

    with pytest.raises(CaseError, match=r"surface.D=1.5,1.6,1.5'?: the value 1.5 \(SI\) is given"):
        parse_axis("surface.D=1.5,1.6,1.5")
    with pytest.raises(CaseError, match=r"given twice"):
        parse_axis("operating.speed=100 rpm:100 rpm:3")
    assert parse_axis("surface.D=1.5:1.5:1").values == (1.5,)


def test_out_folder_that_cannot_be_created_says_so() -> None:
    """``--out /proc/xx`` (a folder no one can create) said 'another run holds the lock'."""
    line = refused(
        "tcr", Path(__file__).parent.parent / "examples" / "gao2019_tcr.toml", "--out", "/proc/xx"
    )
    assert line.startswith("error: --out = '/proc/xx' is not allowed: a folder that can be")
    assert "another run" not in line and "/proc/.xx.lock" in line


@pytest.mark.parametrize(
    ("option", "value", "start", "allowed"),
    [
        ("--spacing", "1e30 m", "error: spacing = '1e30 m' is not allowed: ", "≤ 1 m / 64 points"),
        ("--spacing", "1e-30 m", "error: spacing = '1e-30 m' is not allowed: ", "1e-11 m ≤ Δx"),
        ("--gamma", "1e30", "error: gamma = 1e+30 is not allowed: ", "1.01 ≤ γ ≤ 10"),
    ],
)
def test_surface_spacing_and_gamma_far_outside_a_profile(
    tmp_path: Path, option: str, value: str, start: str, allowed: str
) -> None:
    """``--spacing '1e30 m'`` (a 6·10³¹ m record) and ``--gamma 1e30`` (W–M lines 30 decades
    apart, none inside the measured band) ran and gave finite but meaningless D and G."""
    profile = tmp_path / "z.txt"
    profile.write_text("\n".join(f"{math.sin(0.7 * i) * 1e-7:.6g}" for i in range(64)))
    spacing = () if option == "--spacing" else ("--spacing", "1 um")
    out = tmp_path / "out"
    line = refused("surface", profile, option, value, *spacing, "--out", out)
    assert line.startswith(start) and allowed in line
    assert not out.exists()


def test_bearing_band_far_narrower_than_an_axial_cell(tmp_path: Path, gao_case_path) -> None:
    """``thermal.bearings.0.width = 1e-30`` (allowed: > 0) gave the band no length in any cell
    of the network: 0/0 heat shares and an error naming ``temperature_difference = nan``."""
    out = tmp_path / "out"
    sets = ("--set", "thermal.bearings.0.width=1e-30", "--set", "numerics.cells_across=16")
    line = refused("thermal", gao_case_path, "--out", out, *sets)
    assert line.startswith("error: thermal.bearings.0.width = 1e-30 is not allowed: at least")
    assert "thermal.mesh.network_cell" in line and "nan" not in line
    assert not out.exists()


def test_sweep_console_caps_the_failed_points(
    tmp_path: Path, gao_case_path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """``ballscrew sweep`` printed one console line per failed point (thousands on a big
    sweep); now at most ten, then a count. summary.json and the report keep every point."""
    import ballscrew.sweep as sweep_package
    from ballscrew.sweep import PointRecord, assemble, grid_points

    def every_point_fails(case, axes, function, name, folder, *args):
        points = grid_points(axes)
        records = [PointRecord(p, None, "RuntimeError: injected", 0.0) for p in points]
        return assemble(axes, records, name, case), len(points)

    monkeypatch.setattr(sweep_package, "run_sweep", every_point_fails)
    out = tmp_path / "out"
    vary = ("--vary", "surface.D=1.4:1.6:25")
    result = CliRunner().invoke(app, ["sweep", str(gao_case_path), *vary, "--out", str(out)])
    assert result.exit_code == 0, result.output
    said = [line for line in result.output.splitlines() if line.startswith("warning: ")]
    assert len(said) == 11, result.output
    assert said[-1] == "warning: … and 15 more failed points (see summary.json / report.html)"
    summary = json.loads((out / "summary.json").read_text(encoding="utf-8"))
    assert summary["failed"] == 25
    assert sum("failed: RuntimeError" in w for w in summary["warnings"]) == 25
    assert (out / "report.html").read_text(encoding="utf-8").count("RuntimeError: injected") >= 25


def test_init_ball_too_small_for_the_thread_names_the_ball() -> None:
    """``init --ball 1e-30`` (6·10³² balls per nut) blamed ``--d0 = '40 mm'``."""
    args = [*INIT]
    args[args.index("--ball") + 1] = "1e-30"
    line = refused(*args)
    assert line.startswith("error: --ball = '1e-30 mm' is not allowed: a value that gives")
    assert "screw.balls_per_nut" in line and "[1, 10000]" in line


def test_a_bearing_band_without_a_facet_is_named_by_its_case_key(tmp_path: Path, gao_case_path):
    """On the 3-D model a band too narrow to hold a facet was refused as 'bearings.fixed.width',
    a name the case does not have; it is the list entry thermal.bearings.0.width (a 6 mm band
    passes the network check, 5 mm cells, but holds no facet of the 60 mm far 3-D mesh)."""
    case = tmp_path / "case.toml"
    case.write_text(
        gao_case_path.read_text().replace(
            'size = "5 mm"',
            'size = "5 mm"\nsize_3d = "20 mm"\nfar_size_3d = "60 mm"\ndivisions_3d = 16\n'
            "layers_3d = 2",
        )
    )
    out = tmp_path / "out"
    line = refused(
        "thermal", case, "--model", "3d", "--set", "thermal.bearings.0.width=6 mm", "--out", out
    )
    assert line.startswith("error: thermal.bearings.0.width = 0.006 is not allowed: a band")
    assert not out.exists()
