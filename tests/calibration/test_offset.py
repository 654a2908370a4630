"""The torque offset T_0 and the joint fit: known (K, m, T_0) come back from noisy synthetic
histories, the held-out error matches the noise, the offset's Jacobian column is exact, and
the identifiability limits are reported."""

from __future__ import annotations

import json
import math
import warnings
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from ballscrew.calibration import (
    CalibrationError,
    calibrate,
    calibrate_joint,
    calibrated_case,
    fit_parameters,
    measured_history,
)
from ballscrew.calibration.multi import HistoryFit
from ballscrew.case import load_case, with_overrides
from ballscrew.cli import app
from ballscrew.errors import InputError

from .multi_model import GRID, MEASURED_AT, history

K = 2.0e-4
NOISE = 0.002  # N·m
THREE = ("wear_coefficient", "torque_scale", "torque_offset")
UNTIL = 1.0e6  # fit to 1e6 rev, predict the last 0.44e6


def noisy(scale: float, offset: float, seed: int, name: str = "synthetic") -> object:
    clean = scale * history({"wear_coefficient": K}, MEASURED_AT).friction_torque + offset
    rng = np.random.default_rng(seed)
    values = clean + rng.normal(0.0, NOISE, clean.size)
    return measured_history(MEASURED_AT, values, "friction_torque", name)


class Model:
    """``simulate(values)`` of the closed-form stand-in (multi_model) on its own grid."""

    def __call__(self, values):
        return history(dict(values), GRID)


class CaseModel:
    """``model(case)``: the stand-in driven by the case's K and torque scale; the torque
    offset of the case must reach it as 0 (the fit adds T_0)."""

    def __init__(self) -> None:
        self.offsets: list[float] = []

    def __call__(self, case):
        self.offsets.append(case.wear.torque_offset)
        h = history({"wear_coefficient": case.wear.coefficient}, GRID, case.wear.torque_scale)
        return type(h)(h.revolutions, h.max_wear_depth, h.preload, h.friction_torque)


def within(result, truth: dict[str, float], sigmas: float = 3.5) -> None:
    for name, value in truth.items():
        error = result.errors[name]
        assert abs(result.values[name] - value) < sigmas * error, (name, result.values)
        assert 0.0 < error < 0.3 * abs(value)


def test_offset_column_is_exact() -> None:
    """∂r/∂(T_0/s) = 1 for every point (the offset is fitted in units of the data scale)."""
    part = HistoryFit(
        Model(),
        noisy(1.2, 0.05, 1),
        THREE,
        {"wear_coefficient": K},
        torque_scale=1.0,
        torque_offset=0.0,
        fit_until=None,
        max_evaluations=20,
        diff_step=1e-2,
        label="test",
    )
    x = np.array([math.log(K), 1.1, 0.02])
    jac = part.jacobian.difference(x)
    assert np.array_equal(jac[:, -1], np.ones(len(MEASURED_AT)))
    step = 1e-3
    shifted = (part.residuals(x + np.array([0.0, 0.0, step])) - part.residuals(x)) / step
    np.testing.assert_allclose(jac[:, -1], shifted, rtol=1e-9)
    scale_column = (part.residuals(x + np.array([0.0, step, 0.0])) - part.residuals(x)) / step
    np.testing.assert_allclose(jac[:, -2], scale_column, rtol=1e-9)


def test_known_k_scale_and_offset_come_back() -> None:
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        result = fit_parameters(
            Model(), noisy(1.2, 0.05, 1), THREE, {"wear_coefficient": 1.0e-4}, fit_until=UNTIL
        )
    within(result, {"wear_coefficient": K, "torque_scale": 1.2, "torque_offset": 0.05})
    assert result.rms_residual == pytest.approx(NOISE, rel=0.35)
    assert result.prediction_rmse == pytest.approx(NOISE, rel=0.5)  # the noise level
    assert result.torque_offset == result.values["torque_offset"]
    # scale and offset trade off: their correlation is reported and warned about
    r = result.correlations["torque_scale,torque_offset"]
    assert r < -0.99
    assert any("hardly separate" in str(w.message) for w in seen)


def test_offset_alone_with_the_catalogue_scale() -> None:
    result = fit_parameters(
        Model(),
        noisy(1.0, 0.08, 3),
        ("wear_coefficient", "torque_offset"),
        {"wear_coefficient": 1.0e-4},
    )
    within(result, {"wear_coefficient": K, "torque_offset": 0.08})
    assert abs(result.correlations["wear_coefficient,torque_offset"]) < 0.995


def test_joint_fit_recovers_shared_k_and_each_offset() -> None:
    a, b = noisy(1.2, 0.05, 1, "a"), noisy(0.9, 0.12, 2, "b")
    model = CaseModel()
    case = load_case(Path(__file__).parents[2] / "examples" / "wear_step_stress.toml")
    case = with_overrides(case, {"wear.torque_offset": 0.01})
    result = calibrate_joint(
        case, [a, b], separate=("torque_scale", "torque_offset"), fit_until=UNTIL, model=model
    )
    assert set(model.offsets) == {0.0}  # the model runs without T_0
    assert abs(result.wear_coefficient - K) < 3.5 * result.errors["wear_coefficient"]
    for history_fit, (scale, offset) in zip(
        result.histories, [(1.2, 0.05), (0.9, 0.12)], strict=True
    ):
        within(history_fit, {"torque_scale": scale, "torque_offset": offset})
        assert history_fit.wear_coefficient == result.wear_coefficient
        assert history_fit.prediction_rmse == pytest.approx(NOISE, rel=0.5)
        assert history_fit.rms_residual == pytest.approx(NOISE, rel=0.35)
    # the shared K is better determined than either history's alone
    alone = calibrate(case, a, fit=THREE, fit_until=UNTIL, model=CaseModel())
    assert result.errors["wear_coefficient"] < alone.errors["wear_coefficient"]
    # equal cases share their runs: fewer runs than two single fits
    assert result.evaluations < 2 * alone.evaluations
    assert "wear_coefficient,torque_offset[2]" in result.correlations


def test_joint_fit_with_the_case_scale_and_offset_per_history() -> None:
    a, b = noisy(1.0, 0.05, 4, "a"), noisy(1.0, 0.12, 5, "b")
    case = load_case(Path(__file__).parents[2] / "examples" / "wear_step_stress.toml")
    result = calibrate_joint(case, [a, b], model=CaseModel())  # the default: T_0 per history
    assert result.shared == ("wear_coefficient",) and result.separate == ("torque_offset",)
    for history_fit, offset in zip(result.histories, (0.05, 0.12), strict=True):
        within(history_fit, {"torque_offset": offset})
    assert abs(result.wear_coefficient - K) < 3.5 * result.errors["wear_coefficient"]


def test_flat_history_with_scale_and_offset_is_not_identifiable() -> None:
    """A straight decline is best fitted by K → 0 with m → ∞: refused with the reason."""
    line = 0.5 - 0.05 * MEASURED_AT / MEASURED_AT[-1]
    data = measured_history(MEASURED_AT, line, "friction_torque", "line")
    with pytest.raises(CalibrationError, match="not identifiable"):
        fit_parameters(Model(), data, THREE, {"wear_coefficient": 1.0e-4})


def test_calibrated_case_carries_the_offset(wear_case_path) -> None:
    case = with_overrides(load_case(wear_case_path), {"wear.initial_torque": 0.6})
    result = calibrate(
        case, noisy(1.0, 0.08, 3), fit="wear_coefficient,torque_offset", model=CaseModel()
    )
    out = calibrated_case(result)
    assert out.wear.torque_offset == pytest.approx(result.torque_offset)
    assert out.wear.initial_torque is None
    assert out.wear.torque_scale == pytest.approx(result.torque_scale)


@pytest.mark.parametrize(
    ("kwargs", "field"),
    [
        ({"fit": ("wear_coefficient", "torque_offsett")}, "--fit"),
        ({"torque_offset": math.nan}, "wear.torque_offset"),
    ],
)
def test_bad_offset_input(kwargs, field) -> None:
    options = {"fit": THREE, **kwargs}
    with pytest.raises(InputError) as info:
        fit_parameters(Model(), noisy(1.2, 0.05, 1), start={"wear_coefficient": K}, **options)
    assert info.value.field == field


def test_offset_needs_torque_data() -> None:
    depth = measured_history(MEASURED_AT, 1e-7 + MEASURED_AT * 1e-12, "wear_depth")
    with pytest.raises(InputError, match="torque_offset"):
        fit_parameters(
            Model(), depth, ("wear_coefficient", "torque_offset"), {"wear_coefficient": K}
        )


def _run(*args):
    return CliRunner().invoke(app, [str(a) for a in args])


def _csv(path: Path, data) -> Path:
    rows = "\n".join(
        f"{n:.10g},{v:.10g}" for n, v in zip(data.revolutions, data.values, strict=True)
    )
    path.write_text("revolutions,friction_torque [N*m]\n" + rows + "\n")
    return path


def test_cli_round_trip_with_the_offset(tmp_path, wear_case_path, monkeypatch) -> None:
    monkeypatch.setattr("ballscrew.analyses.wear.wear_life", CaseModel())
    a = _csv(tmp_path / "up.csv", noisy(1.2, 0.05, 1))
    b = _csv(tmp_path / "down.csv", noisy(0.9, 0.12, 2))
    result = _run(
        "calibrate",
        wear_case_path,
        "--measured",
        a,
        "--out",
        tmp_path / "one",
        "--fit",
        ",".join(THREE),
    )
    assert result.exit_code == 0, result.output
    summary = json.loads((tmp_path / "one" / "summary.json").read_text())
    assert summary["torque_offset"]["unit"] == "N*m"
    assert summary["fitted"]["torque_offset"]["unit"] == "N*m"
    assert (
        abs(summary["torque_offset"]["value"] - 0.05)
        < 3.5 * summary["torque_offset_standard_error"]["value"]
    )
    for key in ("wear_coefficient", "torque_scale", "rms_residual"):
        assert key in summary
    assert "torque_scale,torque_offset" in summary["correlations"]
    assert "torque offset" in (tmp_path / "one" / "report.html").read_text()
    joint = _run(
        "calibrate",
        wear_case_path,
        "-m",
        a,
        "-m",
        b,
        "--out",
        tmp_path / "two",
        "--fit-until",
        UNTIL,
    )
    assert joint.exit_code == 0, joint.output
    summary = json.loads((tmp_path / "two" / "summary.json").read_text())
    assert summary["joint"] and summary["shared"] == ["wear_coefficient"]
    assert summary["separate"] == ["torque_offset"]
    assert len(summary["histories"]) == 2 and len(summary["prediction_rmse"]) == 2
    # the standard errors' n − p is the joint one: fitted points of both, K and two offsets
    fitted = sum(h["measured"]["points"] for h in summary["histories"])
    assert summary["degrees_of_freedom"] == fitted - 3
    assert all("degrees_of_freedom" not in h["fit"] for h in summary["histories"])
    assert (tmp_path / "two" / "fit.csv").read_text().startswith("history,revolutions")


@pytest.mark.parametrize(
    ("extra", "word"),
    [
        (("--fit", "wear_coefficient,torque_offsett"), "torque_offsett"),
        (("--set", "wear.torque_offset=nan"), "torque_offset"),
        (("--separate", "torque_offset"), "--separate"),
    ],
)
def test_cli_bad_input_is_one_line(tmp_path, wear_case_path, extra, word) -> None:
    a = _csv(tmp_path / "up.csv", noisy(1.2, 0.05, 1))
    out = tmp_path / "o"
    result = _run("calibrate", wear_case_path, "--measured", a, "--out", out, *extra)
    assert result.exit_code == 2, result.output
    lines = [line for line in result.output.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("error:") and word in lines[0], result.output
    assert not out.exists()


def test_an_initial_torque_at_or_below_the_offset_is_named(wear_case_path) -> None:
    """The calibration refuses it as the wear run does, naming wear.initial_torque (not a
    negative torque scale derived from it)."""
    case = with_overrides(
        load_case(wear_case_path), {"wear.initial_torque": 0.01, "wear.torque_offset": 0.5}
    )
    with pytest.raises(InputError) as info:
        calibrate(case, noisy(1.0, 0.05, 1), fit="wear_coefficient", model=CaseModel())
    assert info.value.field == "wear.initial_torque"


def test_separate_names_are_checked_as_separate(tmp_path, wear_case_path) -> None:
    """A per-history name the data cannot take is reported against --separate."""
    rows = "\n".join(f"{n:.10g},{1e-7 + n * 1e-13:.10g}" for n in MEASURED_AT)
    depth = tmp_path / "depth.csv"
    depth.write_text("revolutions,wear_depth [m]\n" + rows + "\n")
    out = tmp_path / "o"
    args = ("-m", depth, "-m", depth, "--fit", "wear_coefficient", "--separate", "torque_offset")
    result = _run("calibrate", wear_case_path, "--out", out, *args)
    assert result.exit_code == 2, result.output
    assert result.output.strip().startswith("error: --separate = "), result.output
    assert not out.exists()


def test_joint_fit_reissues_the_warnings_of_every_case() -> None:
    """Histories of two different cases: each case's model warnings reach the result."""

    class Warning_(CaseModel):
        def __call__(self, case):
            warnings.warn(f"model note {case.wear.stroke:g}", UserWarning, stacklevel=1)
            return super().__call__(case)

    case = load_case(Path(__file__).parents[2] / "examples" / "wear_step_stress.toml")
    other = with_overrides(case, {"wear.stroke": 2 * case.wear.stroke})
    a, b = noisy(1.0, 0.05, 4, "a"), noisy(1.0, 0.12, 5, "b")
    result = calibrate_joint([case, other], [a, b], model=Warning_())
    notes = [w for w in result.warnings if w.startswith("model note")]
    assert len(set(notes)) == 2, result.warnings


def _profile_sse(k: float, data: list) -> float:
    """Σ_j min over (m_j, T_0,j) of Σ_i (m_j y_i(K) + T_0,j − d_ij)²: linear in m_j, T_0,j."""
    y = history({"wear_coefficient": k}, MEASURED_AT).friction_torque
    basis = np.column_stack([y, np.ones_like(y)])
    return sum(float(np.linalg.lstsq(basis, d.values, rcond=None)[1][0]) for d in data)


def test_joint_fit_weighs_every_point_alike() -> None:
    """One noise level for all histories: the joint K minimises the plain sum of squares of
    both histories (scale and offset per history profiled out), here with histories of
    different size and different preferred K, where any per-history weighting moves it."""
    rng = np.random.default_rng(7)
    data = []
    for k, scale, offset, name in ((K, 3.0, 0.05, "big"), (2 * K, 1.0, 0.12, "small")):
        clean = scale * history({"wear_coefficient": k}, MEASURED_AT).friction_torque + offset
        noisy_values = clean + rng.normal(0.0, NOISE, clean.size)
        data.append(measured_history(MEASURED_AT, noisy_values, "friction_torque", name))
    case = load_case(Path(__file__).parents[2] / "examples" / "wear_step_stress.toml")
    result = calibrate_joint(
        case, data, separate=("torque_scale", "torque_offset"), model=CaseModel()
    )
    best = result.wear_coefficient
    at_best = _profile_sse(best, data)
    for step in (0.98, 1.02):
        assert _profile_sse(step * best, data) > at_best


def test_a_fixed_case_offset_is_added_when_not_fitted(wear_case_path) -> None:
    """T_0 from the case, not fitted: data shifted by it give the fit of the unshifted data."""
    case = load_case(wear_case_path)
    data = noisy(1.2, 0.0, 3)
    shifted = measured_history(data.revolutions, data.values + 0.03, data.quantity, "shifted")
    fit = ("wear_coefficient", "torque_scale")
    plain = calibrate(case, data, fit=fit, model=CaseModel())
    offset_case = with_overrides(case, {"wear.torque_offset": 0.03})
    moved = calibrate(offset_case, shifted, fit=fit, model=CaseModel())
    assert moved.torque_offset == 0.03
    assert moved.wear_coefficient == pytest.approx(plain.wear_coefficient, rel=1e-6)
    assert moved.torque_scale == pytest.approx(plain.torque_scale, rel=1e-6)
    assert moved.rms_residual == pytest.approx(plain.rms_residual, rel=1e-6)


def test_the_joint_report_states_what_each_file_says_about_its_data() -> None:
    from dataclasses import replace

    from ballscrew.calibration import joint_report

    a, b = noisy(1.0, 0.05, 4, "a"), noisy(1.0, 0.12, 5, "b")
    a = replace(a, notes=("bench A, screws run in grease",))
    case = load_case(Path(__file__).parents[2] / "examples" / "wear_step_stress.toml")
    result = calibrate_joint(case, [a, b], model=CaseModel())
    first, second = (s for s in joint_report.sections(result) if s.title.startswith("History"))
    assert f"What {a.source} says about its data: bench A, screws run in grease" in (
        first.paragraphs
    )
    assert not any("says about its data" in text for text in second.paragraphs)
    assert joint_report.summary(result)["histories"][0]["measured"]["notes"] == [
        "bench A, screws run in grease"
    ]
