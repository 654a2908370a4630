"""The difference Jacobian of the calibration never runs the model outside the parameter
bounds: backward at an upper bound, forward (one-sided) within a step of a lower bound."""

from __future__ import annotations

import numpy as np
import pytest

from ballscrew.calibration.multi import _SecantJacobian


@pytest.mark.parametrize("start", [0.0, 0.004, 0.5, 0.996, 1.0])
def test_central_differences_stay_inside_the_bounds(start: float) -> None:
    seen: list[float] = []

    def model(x: np.ndarray) -> np.ndarray:
        seen.append(float(x[0]))
        return np.array([x[0] ** 2, np.sin(x[0])])

    jacobian = _SecantJacobian(model, 0.01, ([0.0], [1.0]), fit_scale=False, scale=1.0)
    columns = jacobian.difference(np.array([start]), central=True)
    assert min(seen) >= 0.0 and max(seen) <= 1.0
    exact = np.array([[2.0 * start], [np.cos(start)]])
    np.testing.assert_allclose(columns, exact, atol=0.011)  # one-sided error ≤ h f''/2
    if 0.01 <= start <= 0.99:  # central: O(h²)
        np.testing.assert_allclose(columns, exact, atol=1e-4)
