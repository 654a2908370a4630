"""The fit recovers a known K (and torque scale) from synthetic noisy histories.

The data come from the closed form of conftest.py evaluated at the measured revolutions; the fit
sees the same closed form only through its own coarse grid (interpolated), so no test compares
the code with itself. Noise: 0.03 µm on the wear depth, 15 N on the preload, 0.004 N·m on the
torque (about 1 % of the initial values).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew.calibration import (
    CalibrationError,
    CalibrationResult,
    fit_wear_coefficient,
    measured_history,
)
from ballscrew.errors import ConvergenceError, InputError

from .conftest import MEASURED_AT, SyntheticModel, exact

K_TRUE = 2.0e-4
NOISE = {"wear_depth": 0.03e-6, "preload": 15.0, "friction_torque": 0.004}
FIELD = {"wear_depth": "max_wear_depth", "preload": "preload", "friction_torque": "friction_torque"}


def bench(quantity: str, seed: int, k: float = K_TRUE, scale: float = 1.0):
    """Synthetic bench data: exact history + Gaussian noise."""
    rng = np.random.default_rng(seed)
    clean = getattr(exact(k, MEASURED_AT, scale), FIELD[quantity])
    noisy = clean + rng.normal(0.0, NOISE[quantity], clean.size)
    return measured_history(MEASURED_AT, noisy, quantity, source=f"synthetic {quantity}")


@pytest.mark.parametrize("quantity", ["wear_depth", "preload", "friction_torque"])
@pytest.mark.parametrize("start", [1.0e-4, 3.0e-6, 1.0e-2])
def test_recovers_known_coefficient(quantity: str, start: float) -> None:
    model = SyntheticModel()
    result = fit_wear_coefficient(model, bench(quantity, seed=11), initial_coefficient=start)
    assert isinstance(result, CalibrationResult)
    assert abs(result.wear_coefficient - K_TRUE) < 3.0 * result.standard_error
    assert 1e-4 < result.relative_error < 0.02
    assert 0.6 < result.rms_residual / NOISE[quantity] < 1.4  # residuals look like the noise
    assert result.evaluations == model.runs <= 15
    assert result.torque_scale == 1.0 and result.torque_scale_error is None
    assert result.n_points == 31 and result.parameters == 1
    assert result.quantity == quantity and result.fitted.shape == (31,)


def test_recovers_coefficient_and_torque_scale() -> None:
    data = bench("friction_torque", seed=3, scale=1.25)
    model = SyntheticModel()
    result = fit_wear_coefficient(model, data, fit_torque_scale=True)
    assert abs(result.wear_coefficient - K_TRUE) < 3.0 * result.standard_error
    assert result.torque_scale_error is not None and result.correlation is not None
    assert abs(result.torque_scale - 1.25) < 3.0 * result.torque_scale_error
    assert result.torque_scale_error < 0.02
    assert -1.0 < result.correlation < 1.0
    assert result.evaluations <= 15
    # without the scale the same data force a biased K and a worse fit
    biased = fit_wear_coefficient(SyntheticModel(), data)
    assert biased.rms_residual > 2.0 * result.rms_residual


def test_torque_scale_is_relative_to_the_case_value() -> None:
    """A model run at torque scale 2 that needs ×0.625 reports 1.25."""
    data = bench("friction_torque", seed=4, scale=1.25)
    result = fit_wear_coefficient(
        SyntheticModel(torque_scale=2.0), data, torque_scale=2.0, fit_torque_scale=True
    )
    assert abs(result.torque_scale - 1.25) < 3.0 * result.torque_scale_error


def test_standard_error_matches_the_scatter_over_repeats() -> None:
    """Over 40 noise draws the z-scores (K_fit − K_true)/σ have unit spread."""
    z = []
    for seed in range(40):
        result = fit_wear_coefficient(SyntheticModel(), bench("preload", seed))
        z.append((result.wear_coefficient - K_TRUE) / result.standard_error)
    z = np.asarray(z)
    assert 0.7 < np.std(z) < 1.4
    assert abs(np.mean(z)) < 0.5
    assert np.mean(np.abs(z) < 2.0) >= 0.85


def test_noise_free_data_give_the_exact_coefficient() -> None:
    data = measured_history(MEASURED_AT, exact(K_TRUE, MEASURED_AT).max_wear_depth, "wear_depth")
    fine = SyntheticModel()
    fine.grid = MEASURED_AT  # wear depth is linear between the grid points: interpolation exact
    result = fit_wear_coefficient(fine, data)
    assert result.wear_coefficient == pytest.approx(K_TRUE, rel=1e-4)
    assert result.rms_residual < 1e-3 * NOISE["wear_depth"]


def test_linear_model_matches_ordinary_least_squares() -> None:
    """Wear depth is linear in K (h = K·c): K̂ = c·y/c·c, σ² = RSS/(n − 1)/c·c in closed form."""
    data = bench("wear_depth", seed=5)
    c = exact(1.0, MEASURED_AT).max_wear_depth
    k_ols = float(c @ data.values / (c @ c))
    rss = float(np.sum((data.values - k_ols * c) ** 2))
    sigma_ols = math.sqrt(rss / (data.revolutions.size - 1) / float(c @ c))
    result = fit_wear_coefficient(SyntheticModel(), data)
    assert result.wear_coefficient == pytest.approx(k_ols, rel=1e-5)
    assert result.standard_error == pytest.approx(sigma_ols, rel=5e-3)


def test_fitted_curve_and_scan_are_reported() -> None:
    result = fit_wear_coefficient(SyntheticModel(), bench("wear_depth", 1))
    assert result.model_revolutions[0] == 0.0 and result.model_revolutions[-1] == 1.44e6
    np.testing.assert_allclose(
        np.interp(result.revolutions, result.model_revolutions, result.model_values),
        result.fitted,
    )
    assert len(result.scan) >= 3
    best = min(result.scan, key=lambda item: item[1])[0]
    assert best / 10 < result.wear_coefficient < best * 10


def test_torque_scale_needs_torque_data() -> None:
    with pytest.raises(InputError, match="friction_torque"):
        fit_wear_coefficient(SyntheticModel(), bench("preload", 1), fit_torque_scale=True)


def test_too_few_points() -> None:
    data = measured_history([0.0, 4.8e5], [0.42, 0.26], "friction_torque")
    with pytest.raises(CalibrationError, match="2 points"):
        fit_wear_coefficient(SyntheticModel(), data, fit_torque_scale=True)


def test_data_beyond_the_simulated_test() -> None:
    data = measured_history([0.0, 1.0e6, 2.0e6], [0.0, 1e-6, 2e-6], "wear_depth")
    with pytest.raises(InputError, match="within the simulated test"):
        fit_wear_coefficient(SyntheticModel(), data)


def test_insensitive_model_is_reported() -> None:
    """A model that does not respond to K cannot be calibrated."""
    flat = SyntheticModel()

    def simulate(k: float):
        return flat(K_TRUE)

    with pytest.raises(CalibrationError, match=r"scanned range|does not determine"):
        fit_wear_coefficient(simulate, bench("preload", 1))


def test_unreachable_data_are_reported() -> None:
    """A preload above the initial 1500 N is beyond any K of the model (wear only lowers it)."""
    data = measured_history(MEASURED_AT, 3000.0 + MEASURED_AT * 1e-6, "preload")
    with pytest.raises(CalibrationError, match="cannot reach"):
        fit_wear_coefficient(SyntheticModel(), data)


def test_evaluation_budget_raises_convergence_error() -> None:
    with pytest.raises(ConvergenceError, match="least squares on ln K"):
        fit_wear_coefficient(SyntheticModel(), bench("preload", 1), max_evaluations=5)


def test_result_is_frozen() -> None:
    result = fit_wear_coefficient(SyntheticModel(), bench("wear_depth", 2))
    with pytest.raises(AttributeError):
        result.wear_coefficient = 1.0  # type: ignore[misc]
    assert math.isclose(result.relative_error, result.standard_error / result.wear_coefficient)


def test_evaluation_budget_reports_a_finite_residual() -> None:
    """The ConvergenceError of a spent budget carries the best RMS so far (N), not NaN."""
    with pytest.raises(ConvergenceError) as info:
        fit_wear_coefficient(SyntheticModel(), bench("preload", 1), max_evaluations=5)
    assert "nan" not in str(info.value)
    assert math.isfinite(info.value.residual) and info.value.residual > 0.0
