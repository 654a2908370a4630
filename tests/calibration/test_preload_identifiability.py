"""The preload cannot be fitted with the torque scale: the as-new torque fixes only m·F_p, and
the loss's shape only K·F_p^(a − 2/3) (theory manual, *Wear*, calibration)."""

from __future__ import annotations

import numpy as np
import pytest

from ballscrew.calibration import (
    CalibrationError,
    CalibrationWarning,
    calibrate,
    calibrated_case,
    fit_parameters,
    measured_history,
)
from ballscrew.case import load_case, with_overrides
from ballscrew.errors import InputError
from ballscrew.loads import preload_after_wear, preload_drag_torque

from .conftest import BETA, C_A, LAMBDA, LEAD, MEASURED_AT, PRELOAD0, History, exact

DEPTH_EXPONENT = 1.8
"""Wear depth ∝ F_p^a: the exponent of the XJTU wear runs (theory manual, *Wear*)."""
TRUE = {"wear_coefficient": 1.3041e-4, "preload": PRELOAD0}
SCALE = 1.2


def history(values: dict[str, float], revolutions: np.ndarray = MEASURED_AT) -> History:
    """The conftest stand-in with the depth ∝ K F_p^a and the preload a parameter."""
    preload = values.get("preload", PRELOAD0)
    base = exact(values["wear_coefficient"], revolutions)
    depth = base.max_wear_depth * (preload / PRELOAD0) ** DEPTH_EXPONENT
    left = preload_after_wear(preload, C_A, depth, BETA, LAMBDA)
    torque = preload_drag_torque(1.0, LEAD, LAMBDA) * left
    return History(base.revolutions, depth, left, torque)


def measured(noise: float = 0.002):
    clean = SCALE * history(TRUE).friction_torque
    rng = np.random.default_rng(3)
    return measured_history(
        MEASURED_AT, clean + rng.normal(0.0, noise, clean.size), "friction_torque"
    )


def test_jacobian_of_m_preload_and_k_has_rank_two() -> None:
    """∂ln T/∂(ln m, ln F_p, ln K): the column of ln F_p is that of ln m plus (a − 2/3) times
    that of ln K, exactly (Hertz preload law), so the three have rank 2."""

    def log_torque(ln_m: float, ln_f: float, ln_k: float) -> np.ndarray:
        values = {"wear_coefficient": np.exp(ln_k), "preload": np.exp(ln_f)}
        return ln_m + np.log(history(values).friction_torque)

    x0 = np.array([np.log(SCALE), np.log(PRELOAD0), np.log(TRUE["wear_coefficient"])])
    step = 1e-5
    columns = []
    for i in range(3):
        up, down = x0.copy(), x0.copy()
        up[i] += step
        down[i] -= step
        columns.append((log_torque(*up) - log_torque(*down)) / (2.0 * step))
    jac = np.column_stack(columns)
    singular = np.linalg.svd(jac, compute_uv=False)
    assert singular[1] / singular[0] > 1e-2
    assert singular[2] / singular[0] < 1e-7
    combined = jac[:, 0] + (DEPTH_EXPONENT - 2.0 / 3.0) * jac[:, 2]
    np.testing.assert_allclose(jac[:, 1], combined, atol=1e-7)


class Model:
    """``simulate(values)``: the stand-in on its own grid."""

    grid = np.linspace(0.0, 1.44e6, 91)

    def __call__(self, values) -> History:
        return history(values, self.grid)


@pytest.mark.parametrize("k_factor", [1.0, 1.5])
def test_the_fitted_preload_is_only_as_good_as_the_wear_coefficient_assumed(k_factor) -> None:
    """m and F_p fitted with K given: the right K gives F_p = 1500 N back, a K 1.5× too large
    gives F_p = 1500 × 1.5^(−1/(a − 2/3)) = 1051 N with m·F_p and the residual unchanged (the
    data cannot tell), and the calibration warns naming the pair."""
    start = {"wear_coefficient": k_factor * TRUE["wear_coefficient"], "preload": 1000.0}
    with pytest.warns(CalibrationWarning, match=r"\(torque_scale,preload\)"):
        result = fit_parameters(Model(), measured(), ("preload", "torque_scale"), start)
    expected = PRELOAD0 * k_factor ** (-1.0 / (DEPTH_EXPONENT - 2.0 / 3.0))
    assert result.values["preload"] == pytest.approx(expected, rel=0.01)
    product = result.values["preload"] * result.values["torque_scale"]
    assert product == pytest.approx(SCALE * PRELOAD0, rel=0.005)
    assert result.rms_residual < 1.2 * 0.002


def test_k_m_and_the_preload_together_are_refused() -> None:
    """With K fitted too the three trade off completely (correlations ±1.000) and the fit is
    refused: the data do not determine K."""
    start = {"wear_coefficient": 1.0e-4, "preload": 1000.0}
    with (
        pytest.warns(CalibrationWarning, match="wear_coefficient,preload: correlation"),
        pytest.raises(CalibrationError, match="do not determine"),
    ):
        fit_parameters(Model(), measured(), ("wear_coefficient", "preload", "torque_scale"), start)


def test_calibrate_starts_the_preload_from_the_case_and_writes_it_back(wear_case_path) -> None:
    """``calibrate(fit="preload,torque_scale")`` takes F_p from ``operating.preload`` (1500 N,
    here the truth) and the calibrated case carries the fitted one."""

    def model(case) -> History:
        values = {"wear_coefficient": case.wear.coefficient, "preload": case.operating.preload}
        return history(values, Model.grid)

    case = with_overrides(load_case(wear_case_path), {"wear.coefficient": TRUE["wear_coefficient"]})
    with pytest.warns(CalibrationWarning, match="fixes only their product"):
        result = calibrate(case, measured(), fit="preload,torque_scale", model=model)
    assert result.values["preload"] == pytest.approx(PRELOAD0, rel=0.01)
    assert calibrated_case(result).operating.preload == result.values["preload"]


def test_a_case_without_preload_cannot_start_the_preload_fit(wear_case_path) -> None:
    """F_p is fitted as ln F_p from the case's value: a single nut with no preload (0 N) is
    refused in one line (it was a bare ``math domain error``), before any model run."""

    def model(case) -> History:
        raise AssertionError("no model run")

    single = {"screw.nuts": 1, "operating.preload": 0.0, "wear.coefficient": 1.3e-4}
    case = with_overrides(load_case(wear_case_path), single)
    with pytest.raises(InputError, match=r"--fit = 'preload' .*operating\.preload ≥ 1 N"):
        calibrate(case, measured(), fit="preload,torque_scale", model=model)


def test_fit_parameters_refuses_a_start_outside_its_log_bounds() -> None:
    """Called directly, a zero preload start (ln 0) is refused naming the start, not a
    ``math domain error``; so is a wear coefficient above its bound of 1."""
    for name, value in (("preload", 0.0), ("wear_coefficient", 2.0)):
        start = {**TRUE, name: value}
        with pytest.raises(
            InputError, match=rf"^start\['{name}'\] = {value} is not allowed: \S+ to "
        ):
            fit_parameters(Model(), measured(), (name, "torque_scale"), start)
