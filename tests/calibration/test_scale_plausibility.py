"""A torque history in N·mm read as N·m fits a torque scale of ~1000: the calibration warns."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from ballscrew.calibration import calibrate, measured_history
from ballscrew.case import load_case

from .conftest import MEASURED_AT, exact
from .test_case import CaseModel


def torque(factor: float):
    """The stand-in's torque history at scale 1.2, its numbers times ``factor``, with noise."""
    rng = np.random.default_rng(5)
    clean = exact(2.0e-4, MEASURED_AT, 1.2).friction_torque
    noisy = clean * (1.0 + rng.normal(0.0, 0.01, clean.size))
    return measured_history(MEASURED_AT, factor * noisy, "friction_torque")


@pytest.mark.parametrize(("factor", "warned"), [(1.0, False), (1e3, True), (1e-3, True)])
def test_an_implausible_torque_scale_names_the_unit(wear_case_path: Path, factor, warned) -> None:
    result = calibrate(load_case(wear_case_path), torque(factor), model=CaseModel())
    assert result.torque_scale == pytest.approx(1.2 * factor, rel=0.05)
    hints = [w for w in result.warnings if "friction_torque [N*mm]" in w]
    assert bool(hints) is warned, result.warnings
    if warned:
        assert f"torque scale {result.torque_scale:.4g} is outside the plausible 0.2–5" in hints[0]
