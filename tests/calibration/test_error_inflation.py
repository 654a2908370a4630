"""Standard errors that allow for correlated residuals: the effective number of points of an
AR(1) series (Bayley & Hammersley 1946) in closed form, and a simulation in which the plain
least-squares errors understate the scatter of the fitted K and the inflated ones do not."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew.calibration import fit_wear_coefficient, measured_history
from ballscrew.calibration.diagnostics import effective_points, error_inflation
from ballscrew.calibration.report import sections, summary

from .conftest import MEASURED_AT, SyntheticModel, exact

K_TRUE = 2.0e-4
SIGMA = 15.0  # N, marginal noise of the preload


def test_effective_points_in_closed_form() -> None:
    assert effective_points(31, 0.5) == pytest.approx(31 / 3)
    assert effective_points(31, -0.2) == 31.0  # anticorrelated: no credit taken
    assert error_inflation(31, 2, 0.5) == pytest.approx(math.sqrt(29 / (31 / 3 - 2)))
    assert error_inflation(31, 2, 0.0) == 1.0
    assert error_inflation(31, 2, 0.9) is None  # n_eff = 1.63 ≤ p


def ar1(rho: float, seed: int, n: int = MEASURED_AT.size) -> np.ndarray:
    """A stationary AR(1) series of unit variance."""
    rng = np.random.default_rng(seed)
    e = np.empty(n)
    e[0] = rng.normal()
    for i in range(1, n):
        e[i] = rho * e[i - 1] + math.sqrt(1.0 - rho * rho) * rng.normal()
    return e


def z_scores(rho: float, draws: int) -> tuple[np.ndarray, np.ndarray]:
    """(K̂ − K)/σ with the plain and with the inflated standard errors over ``draws`` fits."""
    plain, inflated = [], []
    clean = exact(K_TRUE, MEASURED_AT).preload
    for seed in range(draws):
        data = measured_history(MEASURED_AT, clean + SIGMA * ar1(rho, seed), "preload")
        result = fit_wear_coefficient(SyntheticModel(), data)
        errors = result.inflated_errors
        assert errors is not None
        plain.append((result.wear_coefficient - K_TRUE) / result.standard_error)
        inflated.append((result.wear_coefficient - K_TRUE) / errors["wear_coefficient"])
    return np.asarray(plain), np.asarray(inflated)


QUIET = pytest.mark.filterwarnings("ignore::ballscrew.calibration.CalibrationWarning")
"""Some correlated draws look systematic or leave a Gauss–Newton step: warned, not tested."""


@QUIET
def test_correlated_noise_plain_errors_understate_inflated_ones_do_not() -> None:
    """AR(1) noise, ρ = 0.5, 31 points: the plain z-scores spread ≈ 1.9 (errors too small by
    half); with n_eff the spread is ≈ 1.25 (r₁ of 31 residuals is biased low, so some of the
    understatement remains)."""
    plain, inflated = z_scores(0.5, 100)
    assert np.std(plain) > 1.6
    assert 0.85 < np.std(inflated) < 1.45
    assert np.mean(np.abs(inflated) < 2.0) > 0.85 > np.mean(np.abs(plain) < 2.0)


@QUIET
def test_independent_noise_keeps_the_errors_near_the_plain_ones() -> None:
    plain, inflated = z_scores(0.0, 80)
    assert 0.8 < np.std(plain) < 1.3
    assert 0.75 < np.std(inflated) < 1.25


def test_summary_and_report_say_what_the_errors_leave_out() -> None:
    clean = exact(K_TRUE, MEASURED_AT).preload
    data = measured_history(MEASURED_AT, clean + SIGMA * ar1(0.6, 7), "preload", "bench.csv")
    result = fit_wear_coefficient(SyntheticModel(), data)
    r1 = result.diagnostics["lag1_autocorrelation"]
    assert r1 > 0.2
    n_eff = 31 * (1 - r1) / (1 + r1)
    fitted = summary(result)["fitted"]["wear_coefficient"]
    assert fitted["standard_error_correlated_residuals"] == pytest.approx(
        fitted["standard_error"] * math.sqrt(30 / (n_eff - 1))
    )
    assert summary(result)["effective_points"] == pytest.approx(n_eff)
    assert "model-form error" in summary(result)["standard_errors_cover"]
    (section,) = sections(result)
    assert any("model-form error" in p for p in section.paragraphs)
    rows = dict(section.tables[0].rows)
    assert rows["effective points n_eff"] == pytest.approx(n_eff)


def test_a_joint_history_leaves_out_errors_of_its_own_degrees_of_freedom() -> None:
    """A history of a joint fit has the joint degrees of freedom: no per-history inflation."""
    clean = exact(K_TRUE, MEASURED_AT).preload
    data = measured_history(MEASURED_AT, clean + SIGMA * ar1(0.6, 7), "preload", "bench.csv")
    result = fit_wear_coefficient(SyntheticModel(), data)
    fitted = summary(result, inflated_errors=False)["fitted"]["wear_coefficient"]
    assert fitted["standard_error_correlated_residuals"] is None
    rows = dict(sections(result, inflated_errors=False)[0].tables[0].rows)
    assert not any("correlated residuals" in str(label) for label in rows)
