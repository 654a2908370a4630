"""``calibrate(case, data)``: K and the torque scale go through the case's ``[wear]`` keys."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from ballscrew.calibration import calibrate, measured_history, read_measured
from ballscrew.case import load_case, with_overrides
from ballscrew.loads import preload_drag_torque

from .conftest import LAMBDA, LEAD, MEASURED_AT, PRELOAD0, SyntheticModel, exact

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "measured" / "step_stress_torque.csv"


class CaseModel:
    """``model(case)``: the closed-form stand-in driven by the case's ``[wear]`` keys."""

    def __init__(self) -> None:
        self.model = SyntheticModel()
        self.seen: list[tuple[float, float, float | None]] = []

    def __call__(self, case):
        w = case.wear
        self.seen.append((w.coefficient, w.torque_scale, w.initial_torque))
        if w.initial_torque is None:
            self.model.torque_scale = w.torque_scale
        else:  # K_T rescaled so that T(0) = initial_torque
            catalogue = preload_drag_torque(PRELOAD0, LEAD, LAMBDA)
            self.model.torque_scale = w.initial_torque / catalogue
        return self.model(w.coefficient)


@pytest.fixture
def case(wear_case_path: Path):
    return load_case(wear_case_path)


def noisy_torque(scale: float, seed: int = 0):
    rng = np.random.default_rng(seed)
    clean = exact(2.0e-4, MEASURED_AT, scale).friction_torque
    return measured_history(
        MEASURED_AT, clean + rng.normal(0.0, 0.004, clean.size), "friction_torque"
    )


def test_coefficient_goes_through_the_case(case) -> None:
    model = CaseModel()
    result = calibrate(case, noisy_torque(1.0), model=model)
    assert abs(result.wear_coefficient - 2.0e-4) < 3 * result.standard_error
    k_start, scale, initial = model.seen[1]  # the scan starts at the case's K
    assert k_start == pytest.approx(case.wear.coefficient, rel=1e-12)
    assert (scale, initial) == (1.0, None)
    assert len({k for k, _, _ in model.seen}) == result.evaluations
    assert result.initial_coefficient == case.wear.coefficient


def test_scale_relative_to_the_case_value(case) -> None:
    case = with_overrides(case, {"wear.torque_scale": 1.5})
    result = calibrate(case, noisy_torque(1.2), model=CaseModel(), fit_torque_scale=True)
    assert abs(result.torque_scale - 1.2) < 3 * result.torque_scale_error
    assert abs(result.wear_coefficient - 2.0e-4) < 3 * result.standard_error


def test_initial_torque_is_cleared_for_the_scale_fit(case) -> None:
    case = with_overrides(case, {"wear.initial_torque": 0.6})
    model = CaseModel()
    result = calibrate(case, noisy_torque(1.2), model=model, fit_torque_scale=True)
    assert all(t is None for _, _, t in model.seen)
    assert abs(result.torque_scale - 1.2) < 3 * result.torque_scale_error


def test_initial_torque_gives_the_effective_scale(case) -> None:
    """With T(0) fixed to 0.4231·1.2 N·m the reported scale is 1.2 (T_p(1500 N) = 0.4231 N·m)
    when only K is fitted (torque data fit the scale by default)."""
    case = with_overrides(case, {"wear.initial_torque": 1.2 * 0.42314})
    result = calibrate(case, noisy_torque(1.2), fit=("wear_coefficient",), model=CaseModel())
    assert result.torque_scale == pytest.approx(1.2, rel=1e-4)
    assert result.torque_scale_error is None
    assert abs(result.wear_coefficient - 2.0e-4) < 3 * result.standard_error


@pytest.mark.slow
def test_real_wear_model_on_the_example(case) -> None:
    """The real wear model fitted to the synthetic example (made with K = 1.3041e-4, scale 1.15).

    The example came from a stand-in whose depth grows linearly within each level and matches
    the reference step-stress run at the level ends; the real model reproduces that run within
    ±3 %, so K and the scale must come back within a few per cent.
    """
    data = read_measured(EXAMPLE)
    result = calibrate(case, data, fit_torque_scale=True)
    assert result.wear_coefficient == pytest.approx(1.3041e-4, rel=0.08)
    assert result.torque_scale == pytest.approx(1.15, rel=0.05)
    assert result.rms_residual < 0.008  # noise 0.004 N·m plus the stand-in's shape error
    assert result.evaluations <= 15
    assert 0.0 < result.relative_error < 0.05
    assert math.isfinite(result.correlation)
