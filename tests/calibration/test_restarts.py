"""The least-squares restarts of :func:`fit_parameters`: they end on exact data, and running out
of them is reported."""

from __future__ import annotations

import warnings

import pytest

from ballscrew.calibration import CalibrationWarning, fit_parameters, measured_history, multi

from .multi_model import GRID, START, TRUE, MultiModel, history

NAMES = ("wear_coefficient", "film_factor")


def exact_data():
    """The model's own values at its own revolutions: the residual at the truth is 0."""
    at = GRID[::4]
    truth = {k: TRUE[k] for k in NAMES}
    return measured_history(at, history(truth, at).friction_torque, "friction_torque")


def _start():
    return {k: START[k] for k in NAMES}


def test_exact_data_do_not_spend_every_restart(monkeypatch) -> None:
    """σ → 0 on exact data: without a floor on σ no step was small enough and every restart
    ran (3 runs); with it the second run's end is accepted, and nothing is warned."""
    runs = []
    solve = multi.solve_least_squares

    def counted(*args, **kwargs):
        runs.append(1)
        return solve(*args, **kwargs)

    monkeypatch.setattr(multi, "solve_least_squares", counted)
    with warnings.catch_warnings():
        warnings.simplefilter("error", CalibrationWarning)
        result = fit_parameters(MultiModel(), exact_data(), NAMES, _start())
    assert len(runs) <= 2
    assert result.values["film_factor"] == pytest.approx(TRUE["film_factor"], rel=1e-6)


def test_restarts_running_out_are_warned(monkeypatch) -> None:
    monkeypatch.setattr(multi, "_converged", lambda *args: False)
    with pytest.warns(CalibrationWarning, match=r"3 least-squares runs"):
        fit_parameters(MultiModel(), exact_data(), NAMES, _start())
