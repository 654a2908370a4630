"""Calibration of every parameter subset: known values come back from noisy synthetic
histories, the held-out error matches the noise, and the warnings fire."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew.analyses.operating_point import operating_point
from ballscrew.analyses.wear import wear_options
from ballscrew.calibration import (
    CalibrationError,
    calibrate,
    calibrated_case,
    fit_parameters,
    measured_history,
    residual_diagnostics,
)
from ballscrew.case import load_case, with_overrides
from ballscrew.errors import InputError

from .multi_model import MEASURED_AT, START, TRUE, MultiModel, history

NOISE = 0.002  # N·m
K_ONLY = {"wear_coefficient": START["wear_coefficient"]}


def noisy(names, seed: int = 1, noise: float = NOISE):
    truth = {k: v for k, v in TRUE.items() if k in names or k == "wear_coefficient"}
    model = {k: v for k, v in truth.items() if k != "torque_scale"}
    scale = TRUE["torque_scale"] if "torque_scale" in names else 1.0
    clean = history(model, MEASURED_AT, scale).friction_torque
    rng = np.random.default_rng(seed)
    return measured_history(
        MEASURED_AT, clean + rng.normal(0.0, noise, clean.size), "friction_torque"
    )


SUBSETS = [
    ("wear_coefficient",),
    ("wear_coefficient", "torque_scale"),
    ("wear_coefficient", "film_factor"),
    ("wear_coefficient", "running_in_depth"),
    ("wear_coefficient", "film_factor", "torque_scale"),
    ("wear_coefficient", "running_in_depth", "torque_scale"),
    ("film_factor", "torque_scale"),
]


@pytest.mark.parametrize("names", SUBSETS, ids=["+".join(s) for s in SUBSETS])
def test_known_parameters_come_back(names) -> None:
    start = {k: v for k, v in START.items() if k in names or k == "wear_coefficient"}
    if "wear_coefficient" not in names:
        start["wear_coefficient"] = TRUE["wear_coefficient"]
    result = fit_parameters(MultiModel(), noisy(names), names, start)
    for name in names:
        error = result.errors[name]
        assert abs(result.values[name] - TRUE[name]) < 3.5 * error, (name, result.values)
        assert 0.0 < error < 0.3 * TRUE[name]
    assert result.rms_residual == pytest.approx(NOISE, rel=0.3)
    assert not result.diagnostics["systematic"]


def test_held_out_error_matches_the_noise() -> None:
    names = ("wear_coefficient", "torque_scale")
    errors = []
    for seed in range(4):
        result = fit_parameters(MultiModel(), noisy(names, seed), names, K_ONLY, fit_until=0.75e6)
        assert result.n_fit == int(np.count_nonzero(MEASURED_AT <= 0.75e6))
        errors.append(result.prediction_rmse)
        band = result.prediction_sigma
        assert band is not None and np.all(band >= NOISE * 0.5)
    assert np.mean(errors) == pytest.approx(NOISE, rel=0.35)


def test_prediction_band_widens_beyond_the_fit() -> None:
    names = ("wear_coefficient", "torque_scale")
    result = fit_parameters(MultiModel(), noisy(names), names, K_ONLY, fit_until=0.5e6)
    rev, sigma = result.model_revolutions, result.prediction_sigma
    assert sigma[rev > 1.3e6].mean() > 1.05 * sigma[(rev > 0.1e6) & (rev < 0.5e6)].mean()


def test_systematic_residuals_are_flagged() -> None:
    """Data with strong running-in fitted by a model without it: long runs of one sign."""
    data = noisy(("wear_coefficient", "running_in_depth"), noise=2e-4)
    result = fit_parameters(MultiModel(), data, ("wear_coefficient", "torque_scale"), K_ONLY)
    assert result.diagnostics["systematic"]
    assert result.diagnostics["runs_test_p_value"] < 0.01


def test_runs_test_of_noise_and_of_a_trend() -> None:
    rng = np.random.default_rng(3)
    calm = residual_diagnostics(rng.normal(size=200))
    assert not calm.systematic and abs(calm.lag1_autocorrelation) < 0.15
    trend = residual_diagnostics(np.sin(np.linspace(0.0, 6.0, 200)))
    assert trend.systematic and trend.runs <= 3


def test_unknown_and_ill_posed_requests() -> None:
    with pytest.raises(InputError, match="--fit"):
        fit_parameters(MultiModel(), noisy(()), ("wear_depth_factor",), K_ONLY)
    preload = measured_history(MEASURED_AT, np.linspace(1500, 900, MEASURED_AT.size), "preload")
    with pytest.raises(InputError, match="torque_scale"):
        fit_parameters(MultiModel(), preload, ("torque_scale",), K_ONLY)
    with pytest.raises(InputError, match="--fit-until"):
        fit_parameters(MultiModel(), noisy(()), ("wear_coefficient",), K_ONLY, fit_until=2e6)
    with pytest.raises(CalibrationError, match="cannot determine"):
        fit_parameters(
            MultiModel(), noisy(()), ("wear_coefficient",), K_ONLY, fit_until=MEASURED_AT[0]
        )


class CaseModel:
    """The closed form driven by the case's ``[wear]`` keys."""

    def __call__(self, case):
        w = case.wear
        values = {"wear_coefficient": w.coefficient, "film_factor": w.film_factor}
        if w.running_in is not None:
            values["running_in_depth"] = w.running_in.depth
        return MultiModel()(values) if w.torque_scale == 1.0 else None


@pytest.fixture
def case(wear_case_path):
    return load_case(wear_case_path)


def test_calibrate_api_fits_the_scale_by_default_and_warns(case) -> None:
    data = noisy(("wear_coefficient", "running_in_depth", "torque_scale"), noise=2e-4)
    result = calibrate(case, data, model=CaseModel())
    assert set(result.values) == {"wear_coefficient", "torque_scale"}
    assert any("systematic" in w for w in result.warnings)
    assert result.calibrated_range["load_max"] == 4000.0
    with_running_in = with_overrides(
        case, {"wear.running_in": {"D": 1.3, "G": 1e-9, "depth": 1e-6}}
    )
    good = calibrate(
        with_running_in,
        data,
        fit="wear_coefficient,running_in_depth,torque_scale",
        fit_until=1.0e6,
        model=CaseModel(),
    )
    assert not any("systematic" in w for w in good.warnings)
    assert good.values["running_in_depth"] == pytest.approx(0.3e-6, rel=0.2)
    assert good.prediction_rmse < 3 * 2e-4
    with pytest.raises(InputError, match="running_in"):
        calibrate(case, data, fit=("wear_coefficient", "running_in_depth"), model=CaseModel())


def test_preload_data_fit_only_k_by_default(case) -> None:
    values = history({"wear_coefficient": 2e-4}, MEASURED_AT).preload
    data = measured_history(MEASURED_AT, values * (1 + 1e-3 * np.sin(MEASURED_AT)), "preload")
    result = calibrate(case, data, model=CaseModel())
    assert list(result.values) == ["wear_coefficient"]
    assert result.wear_coefficient == pytest.approx(2e-4, rel=0.01)


def test_calibrated_case_carries_the_range(case) -> None:
    from ballscrew.analyses.wear import wear_options
    from ballscrew.analyses.wear_duty import range_messages

    result = calibrate(case, noisy(("wear_coefficient",)), model=CaseModel())
    tuned = calibrated_case(result)
    assert tuned.wear.coefficient == pytest.approx(result.wear_coefficient)
    assert tuned.wear.calibrated.load_min == 2000.0
    assert range_messages(tuned.wear, wear_options(tuned).programme) == []
    fast = with_overrides(
        tuned, {"wear.programme": [{"axial_load": 3000, "speed": 157.0, "revolutions": 1e5}]}
    )
    (message,) = range_messages(fast.wear, wear_options(fast).programme)
    assert "1499 rpm" in message and "extrapolation" in message


def test_cli_fit_and_fit_until(tmp_path, wear_case_path, monkeypatch) -> None:
    """``--fit`` and ``--fit-until`` reach the fit; summary.json keeps its keys and adds the
    held-out error, the diagnostics and the calibrated range."""
    import json

    from typer.testing import CliRunner

    from ballscrew.analyses import wear
    from ballscrew.cli import app

    monkeypatch.setattr(wear, "wear_life", CaseModel())
    names = ("wear_coefficient", "film_factor", "torque_scale")
    data = noisy(names)
    csv = tmp_path / "bench.csv"
    rows = "\n".join(f"{n:g},{t:.6g}" for n, t in zip(data.revolutions, data.values, strict=True))
    csv.write_text("revolutions,friction_torque [N*m]\n" + rows + "\n")
    out = tmp_path / "cal"
    args = [str(wear_case_path), "--measured", str(csv), "--out", str(out)]
    run = CliRunner().invoke(
        app, ["calibrate", *args, "--fit", ",".join(names), "--fit-until", "1.0e6"]
    )
    assert run.exit_code == 0, run.output
    summary = json.loads((out / "summary.json").read_text())
    assert {"wear_coefficient", "torque_scale", "rms_residual"} <= set(summary)
    assert set(summary["fitted"]) == set(names)
    assert summary["fitted"]["film_factor"]["value"] == pytest.approx(0.5, rel=0.2)
    assert summary["prediction_rmse"]["value"] < 2 * NOISE
    assert summary["fit_until"] == 1.0e6
    assert summary["calibrated_range"]["load_max"]["value"] == 4000.0
    assert summary["residual_diagnostics"]["systematic"] is False
    bad = CliRunner().invoke(app, ["calibrate", *args, "--force", "--fit", "wear_depth"])
    assert bad.exit_code == 2 and "--fit" in bad.output


def test_schedule_columns_become_the_programme(tmp_path, case) -> None:
    from ballscrew.calibration import read_measured

    csv = tmp_path / "bench.csv"
    csv.write_text(
        "revolutions,speed [rpm],axial_load [kN],friction_torque [N*m]\n"
        "0,100,2,0.42\n4.8e5,100,2,0.30\n9.6e5,100,3,0.25\n1.44e6,300,3,0.21\n"
    )
    data = read_measured(csv)
    assert data.schedule[3, 0] == pytest.approx(300 * math.pi / 30)
    assert data.schedule[2, 1] == 3000.0
    seen = []

    def model(c):
        levels = wear_options(c).programme
        seen.append([(lv.speed, lv.axial_load, lv.revolutions) for lv in levels])
        return CaseModel()(c)

    calibrate(case, data, fit=("wear_coefficient",), model=model)
    assert seen[0] == [
        (pytest.approx(100 * math.pi / 30), 2000.0, pytest.approx(4.8e5, rel=1e-12)),
        (pytest.approx(100 * math.pi / 30), 3000.0, pytest.approx(4.8e5, rel=1e-12)),
        (pytest.approx(300 * math.pi / 30), 3000.0, pytest.approx(4.8e5, rel=1e-12)),
    ]
    half = tmp_path / "half.csv"
    half.write_text("revolutions,speed [rpm],friction_torque\n0,100,0.4\n1,100,0.3\n")
    with pytest.raises(InputError, match="axial_load"):
        read_measured(half)


def test_cli_refuses_the_torque_scale_for_preload_data(tmp_path, wear_case_path) -> None:
    from typer.testing import CliRunner

    from ballscrew.cli import app

    csv = tmp_path / "preload.csv"
    csv.write_text("revolutions,preload [N]\n0,1500\n1e5,1400\n2e5,1300\n")
    args = [str(wear_case_path), "--measured", str(csv), "--out", str(tmp_path / "o")]
    run = CliRunner().invoke(app, ["calibrate", *args, "--fit-torque-scale"])
    assert run.exit_code == 2 and "--fit-torque-scale" in run.output
    assert not (tmp_path / "o").exists()


def test_measured_as_path_frame_or_array(tmp_path) -> None:
    import pandas as pd

    from ballscrew.calibration import as_measured

    frame = pd.DataFrame({"revolutions": [0.0, 1e5, 2e5], "preload": [1500.0, 1400.0, 1350.0]})
    assert as_measured(frame).quantity == "preload"
    array = as_measured(np.array([[0.0, 0.4], [1e5, 0.38]]))
    assert array.quantity == "friction_torque" and array.values[1] == 0.38
    csv = tmp_path / "t.csv"
    csv.write_text("revolutions,wear_depth [um]\n0,0\n1e5,0.5\n")
    assert as_measured(str(csv)).values[1] == pytest.approx(0.5e-6)
    with pytest.raises(InputError, match="measured"):
        as_measured(np.zeros((3, 3)))


def test_the_calibrated_range_holds_only_the_levels_the_fit_saw(case) -> None:
    """With --fit-until, a level that starts after the last fitted point was not calibrated: a
    calibrated case that runs it must warn (before, the whole programme's 2000–4000 N was
    stored whatever the split)."""
    from ballscrew.analyses.wear import wear_options
    from ballscrew.analyses.wear_duty import range_messages

    data = noisy(("wear_coefficient", "torque_scale"))
    spans = {}
    for until in (None, 1.0e6, 7.2e5, 4.0e5):
        result = calibrate(case, data, model=CaseModel(), fit_until=until)
        spans[until] = (result.calibrated_range["load_min"], result.calibrated_range["load_max"])
    assert spans == {
        None: (2000.0, 4000.0),
        1.0e6: (2000.0, 4000.0),  # the 4000 N level starts at 9.6e5 rev, a point after it is fitted
        7.2e5: (2000.0, 3000.0),
        4.0e5: (2000.0, 2000.0),
    }
    fitted = calibrated_case(calibrate(case, data, model=CaseModel(), fit_until=7.2e5))
    messages = range_messages(fitted.wear, wear_options(fitted).programme)
    assert len(messages) == 1 and "level 3" in messages[0] and "4000 N" in messages[0]


def test_each_schedule_level_runs_at_its_operating_point(tmp_path, case) -> None:
    """A test-bench file's speed steps wear at each step's own contact temperature and viscosity
    (before, its levels all took the case's constant lubricant values)."""
    oil = with_overrides(
        case,
        {
            "medium.viscosity": None,
            "medium.pressure_viscosity": None,
            "kinematics.lubricant": "iso_vg_68",
        },
    )
    csv = tmp_path / "bench.csv"
    csv.write_text(
        "revolutions,speed [rpm],axial_load [kN],friction_torque [N*m]\n"
        "0,100,2,0.42\n4.8e5,100,2,0.30\n9.6e5,1500,2,0.25\n1.44e6,1500,2,0.21\n"
    )
    levels = []

    def model(c):
        levels.append(wear_options(c).programme)
        return CaseModel()(c)

    calibrate(oil, csv, fit=("wear_coefficient",), model=model)
    slow, fast = levels[0]
    for level, rpm in ((slow, 100), (fast, 1500)):
        point = operating_point(oil, rpm * math.pi / 30, 2000.0)
        assert level.viscosity == pytest.approx(point.viscosity, rel=1e-3)
        assert level.temperature == pytest.approx(point.contact_temperature, abs=0.02)
    assert (slow.revolutions, fast.revolutions) == (pytest.approx(4.8e5), pytest.approx(9.6e5))
    assert fast.temperature > slow.temperature + 5.0  # the faster step runs hotter, thinner oil
    assert fast.viscosity < 0.8 * slow.viscosity


def test_the_calibrated_case_of_a_schedule_fit_keeps_the_users_duty(tmp_path, case) -> None:
    """The fit runs a test-bench schedule as [[duty]] segments, but the calibrated case is the
    user's: no [[duty]] of the bench (thermal and the design check would follow it), the user's
    own programme and [operating]; the bench's speeds and loads are its calibrated range."""
    csv = tmp_path / "bench.csv"
    csv.write_text(
        "revolutions,speed [rpm],axial_load [kN],friction_torque [N*m]\n"
        "0,100,2,0.42\n4.8e5,100,2,0.30\n9.6e5,150,3,0.25\n1.44e6,150,3,0.21\n"
    )
    duties = []

    def model(c):
        duties.append(len(c.duty))
        return CaseModel()(c)

    result = calibrate(case, csv, fit=("wear_coefficient",), model=model)
    assert min(duties) == 2  # the fit did run the bench's two speed steps as [[duty]]
    tuned = calibrated_case(result)
    assert tuned.duty == case.duty == [] and tuned.duty_repeat == case.duty_repeat
    assert tuned.wear.programme == case.wear.programme and tuned.operating == case.operating
    assert tuned.wear.coefficient == result.wear_coefficient
    bench = tuned.wear.calibrated
    assert (bench.load_min, bench.load_max) == (2000.0, 3000.0)
    assert bench.speed_max == pytest.approx(150 * math.pi / 30)


def test_a_stroke_column_sets_each_schedule_level_s_stroke(tmp_path, case) -> None:
    """A schedule's stroke column (0: the [wear] stroke) reaches each level's L_w (E8.3); equal
    speed and load with another stroke is another level; a stroke without speed is refused."""
    from ballscrew.calibration import read_measured

    csv = tmp_path / "bench.csv"
    csv.write_text(
        "revolutions,speed [rpm],axial_load [kN],stroke [mm],friction_torque [N*m]\n"
        "0,100,2,300,0.42\n4.8e5,100,2,300,0.30\n9.6e5,100,2,600,0.25\n1.44e6,100,2,0,0.21\n"
    )
    data = read_measured(csv)
    assert data.schedule[:, 2].tolist() == pytest.approx([0.3, 0.3, 0.6, 0.0])
    levels = []

    def model(c):
        levels.append(wear_options(c).programme)
        return CaseModel()(c)

    calibrate(case, data, fit=("wear_coefficient",), model=model)
    assert [(lv.stroke, lv.revolutions) for lv in levels[0]] == [
        (pytest.approx(0.3), pytest.approx(4.8e5)),
        (pytest.approx(0.6), pytest.approx(4.8e5)),
        (None, pytest.approx(4.8e5)),  # 0: the [wear] stroke
    ]
    alone = tmp_path / "alone.csv"
    alone.write_text("revolutions,stroke [mm],friction_torque\n0,300,0.4\n1,300,0.3\n")
    with pytest.raises(InputError, match="stroke"):
        read_measured(alone)


def test_a_schedule_is_not_warned_about_against_the_cases_operating_point(tmp_path, case) -> None:
    """A test-bench schedule replaces the programme, so the case's [operating] point (100 rpm,
    2 kN, above the bench's 50 rpm and 1 kN) is not the bench's: the wear runs' warning that
    [operating] lies above every level, asking to add it to a [[duty]] the user never wrote, is
    left out of the fit's warnings; with the case's own programme it is kept."""
    from ballscrew.analyses.wear import OperatingOutsideWarning, _warn_operating_outside

    def model(c):  # the stand-in, with the wear run's own check of [operating]
        _warn_operating_outside(c, wear_options(c).programme)
        return CaseModel()(c)

    csv = tmp_path / "bench.csv"
    csv.write_text(
        "revolutions,speed [rpm],axial_load [kN],friction_torque [N*m]\n"
        "0,50,1,0.42\n4.8e5,50,1,0.30\n9.6e5,50,1,0.25\n1.44e6,50,1,0.21\n"
    )
    with pytest.warns(OperatingOutsideWarning):  # the runs do raise it
        model(with_overrides(case, {"operating.axial_load": 5000.0}))
    scheduled = calibrate(case, csv, fit=("wear_coefficient",), model=model)
    assert not [w for w in scheduled.warnings if "not this point" in w]
    harder = with_overrides(case, {"operating.axial_load": 5000.0})
    own = calibrate(harder, noisy(("wear_coefficient",)), fit=("wear_coefficient",), model=model)
    assert [w for w in own.warnings if "not this point" in w]
