"""Measured data checked before fitting, and fits the data do not determine refused."""

from __future__ import annotations

import math
import time
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

import ballscrew.calibration
from ballscrew.calibration import CalibrationError, fit_wear_coefficient, measured_history, search
from ballscrew.calibration import fit as fit_module
from ballscrew.calibration.measured import MAX_POINTS, read_measured
from ballscrew.cli import app
from ballscrew.errors import InputError

from .conftest import MEASURED_AT, History

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
runner = CliRunner()
N = MEASURED_AT.size


def csv(tmp_path: Path, header: str, values) -> Path:
    path = tmp_path / "bench.csv"
    rows = [f"{n:g},{float(v)!r}" for n, v in zip(MEASURED_AT, values, strict=True)]
    path.write_text("\n".join([f"revolutions,{header}", *rows]) + "\n")
    return path


BAD_DATA = [
    ("friction_torque", np.zeros(N), r"friction_torque = 'largest value 0'"),
    ("friction_torque", -np.linspace(0.4, 0.2, N), r"largest value -0.2"),
    ("friction_torque", np.full(N, 1e30), r"\(point 1\) = 1e\+30 .*\[-500, 10000\] N\*m"),
    ("friction_torque", np.r_[0.4, -0.3, np.full(N - 2, 0.4)], r"\(point 2\) = -0.3"),
    ("preload", np.full(N, 1e9), r"preload \(point 1\) = 1000000000.0 .*1e\+07\] N"),
    ("wear_depth", np.full(N, 1.0), r"wear_depth \(point 1\) = 1.0"),
    ("wear_depth", np.r_[0.0, np.nan, np.zeros(N - 2)], r"\(point 2\) = .*nan.* a finite number"),
]


@pytest.mark.parametrize(("quantity", "values", "message"), BAD_DATA)
def test_implausible_data_refused(quantity, values, message):
    with pytest.raises(InputError, match=message):
        measured_history(MEASURED_AT, values, quantity)


def test_noise_around_zero_accepted():
    values = np.r_[0.0, -1e-9, np.linspace(1e-7, 2e-6, N - 2)]
    assert len(measured_history(MEASURED_AT, values, "wear_depth")) == N


@pytest.mark.parametrize("unit", ["%", "ppm", "dimensionless", "rad"])
def test_dimensionless_column_unit_refused(tmp_path, unit):
    path = csv(tmp_path, f"friction_torque [{unit}]", np.linspace(0.4, 0.2, N))
    with pytest.raises(InputError, match=r"column 'friction_torque' = '\[.*\]' is not allowed"):
        read_measured(path)


def test_million_rows_refused_before_parsing(tmp_path, monkeypatch):
    path = tmp_path / "big.csv"
    rows = 1_000_000
    path.write_text("revolutions,friction_torque\n" + "1,0.4\n" * rows)
    monkeypatch.setattr("ballscrew.calibration.measured.csv.reader", _unreachable)
    start = time.perf_counter()
    with pytest.raises(InputError, match=rf"number of points = {rows} .*at most {MAX_POINTS}"):
        read_measured(path)
    assert time.perf_counter() - start < 5.0


def test_huge_file_refused_before_reading(tmp_path, monkeypatch):
    path = tmp_path / "huge.csv"
    path.write_text("revolutions,friction_torque\n0,0.4\n1,0.3\n")
    monkeypatch.setenv("BALLSCREW_MEMORY_BUDGET", "100 B")
    with pytest.raises(InputError, match=r"^--measured = .*reading \d+ bytes of CSV"):
        read_measured(path)


def _unreachable(*args, **kwargs):
    raise AssertionError("the data must be refused first")


def test_undetermined_fit_refused():
    """A model nearly flat in K with noisy data: K ± more than K is an error, not a result."""
    rng = np.random.default_rng(3)
    data = measured_history(MEASURED_AT, 1.0 + rng.normal(0.0, 0.1, N), "preload")

    def model(k: float) -> History:
        level = 1.0 + 1e-3 * (math.log(k / 1e-4)) ** 2
        flat = np.full(N, level)
        return History(MEASURED_AT, flat, flat, flat)

    with pytest.raises(CalibrationError, match=r"do not determine the K: .* ± "):
        fit_wear_coefficient(model, data)


def test_check_determined():
    search.check_determined("x", "K", 1e-4, 0.9e-4)
    with pytest.raises(CalibrationError, match=r"1.3e-05 ± 7.4e\+25"):
        search.check_determined("x", "K", 1.3e-5, 7.4e25)


def test_model_beyond_the_work_limit_is_a_calibration_error(monkeypatch):
    """A trial K the wear model refuses to run (too many steps) ends the fit at once."""
    from ballscrew.analyses import wear
    from ballscrew.budget import BudgetError

    def refuse(case):
        raise BudgetError("wear.max_depth_step", 1e-7, "about 2e6 steps")

    monkeypatch.setattr(wear, "wear_life", refuse)
    case = ballscrew.load_case(EXAMPLES / "wear_step_stress.toml")
    data = measured_history(MEASURED_AT, np.linspace(0.4, 0.2, N), "friction_torque")
    with pytest.raises(CalibrationError, match="cannot run at the trial K"):
        ballscrew.calibration.calibrate(case, data)


@pytest.mark.parametrize(
    "values", [np.zeros(N), -np.linspace(0.4, 0.2, N), np.full(N, 1e30)], ids=["zero", "neg", "big"]
)
def test_cli_calibrate_refuses_up_front(tmp_path, monkeypatch, values):
    monkeypatch.setattr(fit_module, "fit_wear_coefficient", _unreachable)
    measured = csv(tmp_path, "friction_torque [N*m]", values)
    out = tmp_path / "out"
    start = time.perf_counter()
    result = runner.invoke(
        app,
        [
            "calibrate",
            str(EXAMPLES / "wear_step_stress.toml"),
            "-m",
            str(measured),
            "--out",
            str(out),
        ],
    )
    assert time.perf_counter() - start < 5.0
    assert result.exit_code == 2, result.output
    assert result.output.startswith("error: bench.csv: friction_torque")
    assert not out.exists()
