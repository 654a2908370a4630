"""The command line, run as a user would: exit codes, messages and the results folder."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
import xarray as xr
from typer.testing import CliRunner

from ballscrew.cli import app

runner = CliRunner()


def run(*args: str):
    return runner.invoke(app, [str(a) for a in args])


def edited_case(tmp_path: Path, source: Path, old: str, new: str) -> Path:
    text = source.read_text()
    assert old in text, f"{old!r} not in the example case"
    path = tmp_path / "case.toml"
    path.write_text(text.replace(old, new, 1))
    return path


@pytest.mark.parametrize("example", ["gao_case_path", "wear_case_path"])
def test_contact_writes_a_complete_results_folder(tmp_path, example, request):
    case_path = request.getfixturevalue(example)
    out = tmp_path / "out"
    result = run("contact", case_path, "--out", out)
    assert result.exit_code == 0, result.output
    names = {p.name for p in out.iterdir()}
    assert {"summary.json", "fields.nc", "report.html"} <= names
    assert {"pressure_screw.png", "pressure_nut.png"} <= names
    summary = json.loads((out / "summary.json").read_text())
    for side in ("screw", "nut"):
        contact = summary["contacts"][side]
        assert contact["numerical"]["peak_pressure"]["unit"] == "Pa"
        assert contact["hertz"]["semi_axis_x"]["unit"] == "m"
        # The exact raceway gap is within about 0.2 % of Hertz at these loads (both contacts).
        assert abs(contact["relative_difference_to_hertz"]["peak_pressure"]) < 5e-3
        assert contact["numerical"]["load"]["value"] == pytest.approx(
            summary["ball_load"]["value"], rel=1e-10
        )
    with xr.open_dataset(out / "fields.nc", engine="h5netcdf") as fields:
        assert fields["screw_pressure"].attrs["units"] == "Pa"
        assert fields["nut_gap"].attrs["units"] == "m"
        assert fields["screw_x"].attrs["units"] == "m"
    html = (out / "report.html").read_text()
    assert "data:image/png;base64," in html and "Hertz" in html
    assert "extrapolated between cells" in html and "half-cells (screw " in html


BAD_EDITS = [
    ('lead = "10 mm"', "", "screw.lead is missing"),
    ("[numerics]\n", "[numerics]\nspeeed = 3\n", "numerics.speeed: unknown key"),
    (
        'lead = "10 mm"',
        'lead = "-10 mm"',
        "screw.lead = '-10 mm' is not allowed: allowed range is (0, 1] m",
    ),
    (
        "screw_conformity = 0.52",
        "screw_conformity = 0.5",
        "screw.screw_conformity = 0.5 is not allowed",
    ),
    (
        'contact_angle = "45 deg"',
        'contact_angle = "90 deg"',
        "screw.contact_angle = '90 deg' is not allowed: allowed range is (0, 1.5708) rad",
    ),
    (
        'ball_diameter = "6.35 mm"',
        'ball_diameter = "45 mm"',
        "screw.ball_diameter = 0.045 m is "
        "not allowed: it must be smaller than pitch_diameter = 0.04 m",
    ),
    (
        "poissons_ratio = 0.3",
        "poissons_ratio = 0.55",
        "materials.ball.poissons_ratio = 0.55 is not allowed: allowed range is (0, 0.5)",
    ),
    ('preload = "1500 N"', 'preload = "-1500 N"', "operating.preload = '-1500 N' is not allowed"),
    ('preload = "1500 N"', 'preload = "0 N"', "a double nut needs a preload > 0 N"),
    ('lead = "10 mm"', 'lead = "10 mm', "TOML syntax error"),
    (
        "[numerics]",
        '[loads]\ncontact = "numerical"\n\n[numerics]',
        "loads.contact = 'numerical' needs loads.distribution = 'elastic'",
    ),
]


@pytest.mark.parametrize(("old", "new", "message"), BAD_EDITS)
def test_bad_input_is_one_line_exit_2_and_no_output(tmp_path, gao_case_path, old, new, message):
    case_path = edited_case(tmp_path, gao_case_path, old, new)
    out = tmp_path / "out"
    result = run("contact", case_path, "--out", out)
    assert result.exit_code == 2
    assert message in result.output
    assert "Traceback" not in result.output
    assert len(result.output.strip().splitlines()) == 1
    assert not out.exists()


def test_toml_error_names_the_line(tmp_path, gao_case_path):
    case_path = edited_case(tmp_path, gao_case_path, 'lead = "10 mm"', 'lead = "10 mm')
    lines = gao_case_path.read_text().splitlines()
    number = next(k for k, line in enumerate(lines, 1) if line.startswith('lead = "10 mm"'))
    result = run("contact", case_path, "--out", tmp_path / "out")
    assert f"line {number}" in result.output


def test_unwritable_output_folder(tmp_path, gao_case_path):
    blocker = tmp_path / "a_file"
    blocker.write_text("")
    result = run("contact", gao_case_path, "--out", blocker / "results")
    assert result.exit_code == 2
    assert result.output.startswith("error: --out = ")
    assert "Traceback" not in result.output


def test_existing_foreign_folder_is_not_overwritten(tmp_path, gao_case_path):
    (tmp_path / "notes.txt").write_text("mine")
    result = run("contact", gao_case_path, "--out", tmp_path)
    assert result.exit_code == 2
    assert (tmp_path / "notes.txt").read_text() == "mine"


def test_missing_case_file(tmp_path):
    result = run("contact", tmp_path / "nope.toml", "--out", tmp_path / "out")
    assert result.exit_code == 2
    assert "cannot read the case file" in result.output


def test_version():
    result = run("--version")
    assert result.exit_code == 0 and result.output.startswith("ballscrew ")


def test_solver_that_does_not_converge_is_an_error_with_its_residual(tmp_path, gao_case_path):
    case_path = edited_case(
        tmp_path, gao_case_path, "tolerance = 1e-8", "tolerance = 1e-14\nmax_iterations = 10"
    )
    out = tmp_path / "out"
    result = run("contact", case_path, "--out", out)
    assert result.exit_code == 2
    assert "did not converge: residual" in result.output
    assert "after 10 iterations" in result.output
    assert not out.exists()  # no half-written results folder


def test_tcr_command_writes_its_folder(tmp_path, gao_case_path):
    out = tmp_path / "tcr"
    result = run("tcr", gao_case_path, "--out", out, "--variant", "MT")
    assert result.exit_code == 0, result.output
    summary = json.loads((out / "summary.json").read_text())
    assert summary["options"]["variant"] == "MT"
    assert summary["options"]["cell_size"] == {"value": 8e-6, "unit": "m"}
    assert summary["resistance"]["unit"] == "K/W"
    assert summary["nut_forces"][0]["value"] == 1500.0
    assert set(summary["nuts"]) == {"nut1", "nut2"}
    with xr.open_dataset(out / "fields.nc", engine="h5netcdf") as fields:
        assert fields["nut1_screw_element_resistance"].attrs["units"] == "K/W"
        assert fields["nut2_nut_pressure"].attrs["units"] == "Pa"
    assert (out / "tcr_nut1_screw.png").is_file()


def test_bad_variant_is_refused(tmp_path, gao_case_path):
    result = run("tcr", gao_case_path, "--out", tmp_path / "o", "--variant", "V9")
    assert result.exit_code == 2
    assert "variant = 'V9' is not allowed" in result.output


@pytest.mark.parametrize(
    ("vary", "message"),
    [
        ("surface.X=1:2:3", "surface.X: unknown key"),
        ("surface.D=1.4:1.6:0", "the range is empty"),
        ("surface.D=1.5,2.5", "surface.D = 2.5 is not allowed: allowed range is (1, 2)"),
    ],
)
def test_bad_sweep_is_refused_before_any_work(tmp_path, gao_case_path, vary, message):
    out = tmp_path / "sweep"
    result = run("sweep", gao_case_path, "--vary", vary, "--out", out)
    assert result.exit_code == 2
    assert message in result.output
    assert "Traceback" not in result.output
    assert not (out / "points").exists()


def test_sweep_file_runs_and_resumes(tmp_path):
    sweep_file = tmp_path / "fig.toml"
    sweep_file.write_text(
        "[sweep]\n"
        f"case = {str(Path(__file__).parents[1] / 'examples' / 'gao2019_tcr.toml')!r}\n"
        'analysis = "tcr"\n'
        'set = { "numerics.cells_across" = 16 }\n'
        'vary = ["operating.axial_load=0,5000"]\n'
    )
    out = tmp_path / "sweep"
    first = run("sweep", sweep_file, "--out", out, "--workers", "1")
    assert first.exit_code == 0, first.output
    with xr.open_dataset(out / "sweep.nc", engine="h5netcdf") as ds:
        assert ds["F2"].values.tolist() == [1500.0, 0.0]  # nut 2 lifted off at 5000 N
    summary = json.loads((out / "summary.json").read_text())
    assert summary["computed_now"] == 2 and summary["failed"] == 0
    again = run("sweep", sweep_file, "--out", out)
    assert again.exit_code == 0
    assert json.loads((out / "summary.json").read_text())["computed_now"] == 0


def test_calibrate_on_the_example_history(tmp_path, wear_case_path):
    measured = Path(__file__).parents[1] / "examples" / "measured" / "step_stress_torque.csv"
    out = tmp_path / "cal"
    result = run(
        "calibrate",
        wear_case_path,
        "--measured",
        measured,
        "--out",
        out,
        "--fit-torque-scale",
        "--set",
        "kinematics.entrainment=ball_centre",  # the history's film: at the ball-centre speed
    )
    assert result.exit_code == 0, result.output
    summary = json.loads((out / "summary.json").read_text())
    # The synthetic history was made with K = 1.3041e-4 and a torque scale of 1.15.
    assert summary["wear_coefficient"]["value"] == pytest.approx(1.3041e-4, rel=0.05)
    assert summary["wear_coefficient_standard_error"]["value"] > 0
    assert summary["torque_scale"]["value"] == pytest.approx(1.15, rel=0.05)
    assert summary["rms_residual"]["unit"] == "N*m"


def test_calibrate_refuses_a_bad_csv(tmp_path, wear_case_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("revolutions,speed\n0,1\n1,2\n")
    result = run("calibrate", wear_case_path, "--measured", bad, "--out", tmp_path / "o")
    assert result.exit_code == 2
    assert "bad.csv" in result.output and "Traceback" not in result.output


def test_python_dash_m_runs_the_command_line(monkeypatch, capsys):
    """``python -m ballscrew`` is the ``ballscrew`` entry point (it was 'cannot be directly
    executed')."""
    import runpy
    import sys

    monkeypatch.setattr(sys, "argv", ["python -m ballscrew", "--version"])
    with pytest.raises(SystemExit) as exit_:
        runpy.run_module("ballscrew", run_name="__main__")
    assert exit_.value.code == 0
    assert capsys.readouterr().out.startswith("ballscrew ")


def test_importing_the_main_module_runs_nothing(monkeypatch):
    """``import ballscrew.__main__`` (pydoc, doctest collection, API-doc tools) ran the command
    line on the importer's argv and exited."""
    import importlib
    import sys

    monkeypatch.setattr(sys, "argv", ["importer", "--version"])
    monkeypatch.delitem(sys.modules, "ballscrew.__main__", raising=False)
    module = importlib.import_module("ballscrew.__main__")
    assert module.app is not None
