import math

import pytest

from ballscrew.errors import InputError
from ballscrew.loads import preload_drag_torque


def test_catalogue_example_of_contact_tcr_q4():
    # F_p = 1500 N, L = 10 mm, d_m = 40 mm: K = 0.17725, T_p = 0.42314 N·m, Q = 44.31 W at 1000 rpm.
    alpha = math.atan(0.010 / (math.pi * 0.040))
    torque = preload_drag_torque(1500.0, 0.010, alpha)
    assert torque == pytest.approx(0.42314, rel=1e-5)
    assert torque * 1000 * 2 * math.pi / 60 == pytest.approx(44.31, rel=1e-4)


def test_torque_is_proportional_to_preload_and_zero_without_it():
    alpha = 0.0794
    assert preload_drag_torque(0.0, 0.01, alpha) == 0.0
    assert preload_drag_torque(3000.0, 0.01, alpha) == pytest.approx(
        2 * preload_drag_torque(1500.0, 0.01, alpha), rel=1e-14
    )


@pytest.mark.parametrize(
    ("args", "field"),
    [((-1, 0.01, 0.08), "preload"), ((1, 0.0, 0.08), "lead"), ((1, 0.01, 0.0), "lead_angle")],
)
def test_bad_input(args, field):
    with pytest.raises(InputError, match=field):
        preload_drag_torque(*args)
