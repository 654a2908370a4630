"""The least-squares machinery of the calibration: secant Jacobian and run counts."""

from __future__ import annotations

import numpy as np
import pytest

from ballscrew.calibration import fit_parameters
from ballscrew.calibration.multi import _SecantJacobian

from .multi_model import START, MultiModel
from .test_subsets import noisy


def test_secant_update_keeps_a_linear_model_exact_and_learns_a_curved_one() -> None:
    a = np.array([[1.0, 2.0], [0.5, -1.0], [3.0, 0.0]])
    linear = _SecantJacobian(lambda x: a @ x, 1e-2, ([-np.inf] * 2, [np.inf] * 2), False, 2.0)
    np.testing.assert_allclose(linear(np.zeros(2)), a / 2.0)
    np.testing.assert_allclose(linear(np.array([0.3, -0.7])), a / 2.0, atol=1e-12)

    def curved(x: np.ndarray) -> np.ndarray:
        return np.array([np.exp(x[0]), x[0] * x[1], x[1] ** 2])

    jac = _SecantJacobian(curved, 1e-6, ([-np.inf] * 2, [np.inf] * 2), False, 1.0)
    jac(np.array([0.0, 1.0]))
    x, step = np.array([0.0, 1.0]), np.array([0.01, 0.0])
    moved = jac(x + step)
    # the secant condition: J_new Δx = Δy along the step just taken
    np.testing.assert_allclose(moved @ step, curved(x + step) - curved(x), rtol=1e-9)
    # the torque multiplier column is exact: the model values over the data scale
    scaled = _SecantJacobian(curved, 1e-6, ([-np.inf] * 2, [np.inf] * 2), True, 4.0)
    full = scaled(np.array([0.0, 1.0, 2.0]))
    np.testing.assert_allclose(full[:, -1], curved(np.array([0.0, 1.0])) / 4.0)
    np.testing.assert_allclose(full[:, 0], 2.0 * np.array([1.0, 1.0, 0.0]) / 4.0, rtol=1e-5)


@pytest.mark.parametrize(
    ("names", "most"),
    [
        (("wear_coefficient", "torque_scale"), 12),
        (("wear_coefficient", "film_factor", "torque_scale"), 36),
        (("wear_coefficient", "running_in_depth", "torque_scale"), 30),
    ],
)
def test_model_runs_per_fit(names, most) -> None:
    """Secant Jacobian and a start without line searches: about 40 % fewer runs than
    forward differences at every iteration (13 / 54 / 41 runs)."""
    start = {k: v for k, v in START.items() if k in names or k == "wear_coefficient"}
    model = MultiModel()
    result = fit_parameters(model, noisy(names), names, start)
    assert result.evaluations == model.runs <= most


def test_linear_fit_is_least_squares_against_numpy() -> None:
    """The closed-form torque scale m and offset c of search.linear_fit against numpy's
    polynomial and least-squares fits, for one model curve and a stack of them."""
    from ballscrew.calibration.search import linear_fit

    rng = np.random.default_rng(7)
    models = rng.uniform(0.2, 1.0, (3, 20))
    y = 1.3 * models[1] + 0.05 + rng.normal(0.0, 0.01, 20)
    m, c = linear_fit(models, y, fit_scale=True, fit_offset=True)
    for k in range(3):
        slope, intercept = np.polyfit(models[k], y, 1)
        assert m[k] == pytest.approx(slope, rel=1e-10)
        assert c[k] == pytest.approx(intercept, rel=1e-10)
    m, c = linear_fit(models[0], y, fit_scale=True, fit_offset=False, offset=0.02)
    expected = np.linalg.lstsq(models[0][:, None], y - 0.02, rcond=None)[0][0]
    assert (float(m), float(c)) == pytest.approx((expected, 0.02), rel=1e-10)
    m, c = linear_fit(models[2], y, fit_scale=False, fit_offset=True)
    assert (float(m), float(c)) == pytest.approx((1.0, np.mean(y - models[2])), rel=1e-10)
