"""summary.json, fit.csv, plot and report of ``ballscrew calibrate``; the command's plumbing."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
import typer
from typer.testing import CliRunner

import ballscrew.calibration
from ballscrew.calibration import fit_wear_coefficient, measured_history
from ballscrew.case import load_case
from ballscrew.commands import calibrate as command
from ballscrew.results import write_results

from .conftest import MEASURED_AT, SyntheticModel, exact

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "measured" / "step_stress_torque.csv"
REQUIRED = ("wear_coefficient", "wear_coefficient_standard_error", "torque_scale", "rms_residual")


def test_results_folder(tmp_path: Path, wear_case_path: Path) -> None:
    """The result on the protocol: the generic writer makes its folder."""
    from dataclasses import replace

    from protocol_check import assert_protocol_folder

    rng = np.random.default_rng(0)
    clean = exact(2.0e-4, MEASURED_AT).max_wear_depth
    data = measured_history(
        MEASURED_AT, clean + rng.normal(0.0, 3e-8, clean.size), "wear_depth", source="b.csv"
    )
    case = load_case(wear_case_path)
    result = replace(
        fit_wear_coefficient(SyntheticModel(), data),
        case=case,
        options={"fit_torque_scale": False},
    )
    folder = write_results(result, tmp_path / "out", wear_case_path)
    assert sorted(p.name for p in folder.iterdir()) == [
        ".ballscrew-results.json",  # the marker naming the files ballscrew wrote
        "case.toml",
        "fit.nc",
        "fit.png",
        "inputs.json",
        "report.html",
        "summary.json",
    ]
    summary = assert_protocol_folder(result, folder)
    assert summary["analysis"] == "calibrate" and summary["options"] == dict(result.options)
    for key in REQUIRED:
        assert set(summary[key]) == {"value", "unit"}
    assert summary["wear_coefficient"]["value"] == pytest.approx(result.wear_coefficient)
    assert summary["wear_coefficient_standard_error"]["value"] == pytest.approx(
        result.standard_error
    )
    assert summary["torque_scale"]["value"] == 1.0
    assert summary["torque_scale_fitted"] is False
    assert summary["rms_residual"]["unit"] == "m"
    assert summary["measured"]["points"] == 31
    assert summary["fit"]["model_evaluations"] == result.evaluations
    assert f"Wear calibration: {case.name}" in (folder / "report.html").read_text()


def test_command_writes_the_folder(
    tmp_path: Path, wear_case_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The subcommand with the wear model replaced by the closed-form stand-in."""

    def stand_in(case, data, fit=("wear_coefficient",), fit_until=None):
        assert fit_until is None
        return fit_wear_coefficient(SyntheticModel(), data, fit_torque_scale="torque_scale" in fit)

    monkeypatch.setattr(ballscrew.calibration, "calibrate", stand_in)
    app = typer.Typer()
    app.command()(command.calibrate)
    out = tmp_path / "cal"
    args = [str(wear_case_path), "--measured", str(EXAMPLE), "--out", str(out)]
    run = CliRunner().invoke(app, [*args, "--fit-torque-scale"])
    assert run.exit_code == 0, run.output
    summary = json.loads((out / "summary.json").read_text())
    assert summary["torque_scale_fitted"] is True
    # the example was made with K = 1.3041e-4 and a torque scale of 1.15 (its header says so)
    k, sk = (
        summary["wear_coefficient"]["value"],
        summary["wear_coefficient_standard_error"]["value"],
    )
    assert abs(k - 1.3041e-4) < 3 * sk
    assert (
        abs(summary["torque_scale"]["value"] - 1.15)
        < 3 * (summary["torque_scale_standard_error"]["value"])
    )
    assert summary["rms_residual"]["unit"] == "N*m"
    # the file's own words about its data reach the summary and the report
    assert summary["measured"]["notes"][0].startswith("SYNTHETIC example, NOT measured data")
    report = (out / "report.html").read_text(encoding="utf-8")
    assert "step_stress_torque.csv says about its data: SYNTHETIC example" in report
    table = np.loadtxt(out / "fit.csv", delimiter=",", skiprows=1)
    np.testing.assert_allclose(table[:, 3], table[:, 2] - table[:, 1], atol=1e-15)
    assert {"fit.csv", "fit.nc", "fit.png", "case.toml", "inputs.json"} <= set(
        json.loads((out / ".ballscrew-results.json").read_text())["files"]
    )

    bad = tmp_path / "bad.csv"
    bad.write_text("revolutions,preload\n0,1500\n0,1400\n")
    run = CliRunner().invoke(app, [str(wear_case_path), "--measured", str(bad), "-o", str(out)])
    assert run.exit_code == 2
    assert "strictly increasing" in run.output
    run = CliRunner().invoke(
        app,
        [str(wear_case_path), "--measured", str(bad).replace("bad", "none"), "-o", str(out)],
    )
    assert run.exit_code == 2


def test_the_report_states_each_correlation_once() -> None:
    """The (ln K, torque scale) correlation was shown twice, once as
    'correlation (wear_coefficient,torque_scale)'."""
    from ballscrew.calibration.report import sections

    from .test_fit import bench

    data = bench("friction_torque", seed=3, scale=1.25)
    result = fit_wear_coefficient(SyntheticModel(), data, fit_torque_scale=True)
    labels = [row[0] for row in sections(result)[0].tables[0].rows]
    assert [label for label in labels if label.startswith("correlation")] == [
        "correlation (ln K, torque scale)"
    ]


def test_the_plot_scales_its_revolution_axis_to_the_data(tmp_path: Path, monkeypatch) -> None:
    """The revolution axis was always divided by 10⁶: a 14 400-revolution bench read as
    0.000–0.014; it now takes the power of 10³ of the data (:func:`revolutions_axis`)."""
    import dataclasses

    import matplotlib.axes

    from ballscrew.calibration.report import fit_plot

    from .test_fit import bench

    data = bench("friction_torque", seed=3, scale=1.25)
    fitted = fit_wear_coefficient(SyntheticModel(), data, fit_torque_scale=True)
    result = dataclasses.replace(  # the same history on a 14 400-revolution bench
        fitted,
        revolutions=fitted.revolutions / 100.0,
        model_revolutions=fitted.model_revolutions / 100.0,
    )
    labels: list[str] = []
    original = matplotlib.axes.Axes.set_xlabel
    monkeypatch.setattr(
        matplotlib.axes.Axes,
        "set_xlabel",
        lambda self, text, *a, **k: labels.append(text) or original(self, text, *a, **k),
    )
    fit_plot(result, "bench", tmp_path / "fit.png")
    assert [t for t in labels if t] == ["screw revolutions [10³ rev]"]
    assert (tmp_path / "fit.png").exists()
