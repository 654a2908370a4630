"""Ball load (Q1) against the TCR and the wear reference screws."""

import math

import numpy as np
import pytest

from ballscrew.errors import InputError
from ballscrew.loads import ball_load, nut_forces

BETA = math.radians(45.0)
ALPHA = math.atan(10e-3 / (math.pi * 40e-3))  # (G2): 4.549865°


def test_lead_angle_as_in_doc() -> None:
    assert math.degrees(ALPHA) == pytest.approx(4.549865, rel=1e-6)


def test_ball_load_at_preload() -> None:
    assert float(ball_load(1500.0, 54, BETA, ALPHA)) == pytest.approx(39.40790, rel=1e-6)


def test_ball_load_of_loaded_nut_t1_11() -> None:
    """Wear reference screw: Q at F1 for F_a = 2000/3000/4000 N, F_p = 1500 N."""
    f1 = [nut_forces(1500.0, fa).f1 for fa in (2000.0, 3000.0, 4000.0)]
    np.testing.assert_allclose(ball_load(f1, 54, BETA, ALPHA), [68.69, 85.91, 105.79], rtol=2e-4)


def test_ball_load_vectorised_shape() -> None:
    q = ball_load(np.ones((2, 3)), 10, BETA, 0.0)
    assert q.shape == (2, 3)
    np.testing.assert_allclose(q, 1.0 / (10 * math.sin(BETA)))


@pytest.mark.parametrize(
    ("args", "field"),
    [
        ((-1.0, 54, BETA, ALPHA), "axial_force"),
        ((1.0, 0, BETA, ALPHA), "balls"),
        ((1.0, 2.5, BETA, ALPHA), "balls"),
        ((1.0, 54, 0.0, ALPHA), "contact_angle"),
        ((1.0, 54, BETA, -0.1), "lead_angle"),
    ],
)
def test_ball_load_rejects_bad_inputs(args: tuple, field: str) -> None:
    with pytest.raises(InputError, match=field):
        ball_load(*args)
