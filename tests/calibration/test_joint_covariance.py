"""The joint fit's standard errors against an independent reference: scipy's curve_fit on a
hand-written closed form with its analytic Jacobian, cov = s² (JᵀJ)⁻¹, s² = RSS/(n − p)
(Seber & Wild 1989, §2.1).

K correlates with each offset at |ρ| ≈ 0.99, so the covariance amplifies a Jacobian column's
error about 1/(1 − ρ²) ≈ 70 times: with the forward-difference column (h = 0.01 in ln K) the
standard errors came out 2 % low; the central column of the covariance meets 1e-3."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import curve_fit

from ballscrew.calibration import measured_history
from ballscrew.calibration.joint import fit_joint
from ballscrew.calibration.multi import HistoryFit
from ballscrew.calibration.search import DIFF_STEP
from ballscrew.loads import preload_drag_torque

from .conftest import BETA, C_A, K_REF, LAMBDA, LEAD, LEVEL_DEPTHS, LEVEL_REVOLUTIONS
from .multi_model import FILM, GRID, MEASURED_AT, history

THREE = ("wear_coefficient", "torque_scale", "torque_offset")
TRUE = ((2.0e-4, 1.2, 0.05), (2.0e-4, 0.9, 0.12))  # (K, m_j, T_0,j)
NOISE = 0.004  # N·m
PRELOAD0 = 1500.0
TORQUE_PER_NEWTON = preload_drag_torque(1.0, LEAD, LAMBDA)  # (E9.1) at 1 N


def depth_per_k(revolutions: np.ndarray) -> np.ndarray:
    """h(N)/K of the stand-in without running-in (film factor 1): piecewise linear."""
    out = np.zeros_like(revolutions)
    for level, (dh, c) in enumerate(zip(LEVEL_DEPTHS, FILM, strict=True)):
        inside = np.clip(revolutions - level * LEVEL_REVOLUTIONS, 0.0, LEVEL_REVOLUTIONS)
        out += dh / K_REF / (1.0 + c**2) * inside / LEVEL_REVOLUTIONS
    return out


def torque(k: float, c: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """T(K) at scale 1, offset 0, and dT/dK, by hand: δ = C_a F_p0^(2/3) − K c/(sinβ cosλ),
    F = (δ/C_a)^(3/2), T = k_T F."""
    loss = c / (math.sin(BETA) * math.cos(LAMBDA))
    delta = C_A * PRELOAD0 ** (2.0 / 3.0) - k * loss
    force = (delta / C_A) ** 1.5
    return TORQUE_PER_NEWTON * force, TORQUE_PER_NEWTON * 1.5 * (delta / C_A) ** 0.5 * (-loss / C_A)


def stacked(n: int):
    """Model and Jacobian of both histories in (K, m_1, T_1, m_2, T_2)."""
    c = depth_per_k(MEASURED_AT)

    def model(_: object, k: float, m1: float, t1: float, m2: float, t2: float) -> np.ndarray:
        base, _ = torque(k, c)
        return np.r_[m1 * base + t1, m2 * base + t2]

    def jacobian(_: object, k: float, m1: float, t1: float, m2: float, t2: float) -> np.ndarray:
        base, slope = torque(k, c)
        jac = np.zeros((2 * n, 5))
        jac[:n, 0], jac[n:, 0] = m1 * slope, m2 * slope
        jac[:n, 1], jac[:n, 2] = base, 1.0
        jac[n:, 3], jac[n:, 4] = base, 1.0
        return jac

    return model, jacobian


def data(seed: int, k: float, m: float, t0: float) -> object:
    clean = m * torque(k, depth_per_k(MEASURED_AT))[0] + t0
    values = clean + np.random.default_rng(seed).normal(0.0, NOISE, clean.size)
    return measured_history(MEASURED_AT, values, "friction_torque", f"history {seed}")


class Model:
    """The stand-in on a grid holding every measured point (no interpolation error)."""

    def __call__(self, values):
        return history(dict(values), np.union1d(GRID, MEASURED_AT))


def test_the_hand_written_model_is_the_stand_in() -> None:
    """The reference model reproduces the closed form the fit sees (else the test proves
    nothing)."""
    want = history({"wear_coefficient": 2.0e-4}, MEASURED_AT).friction_torque
    np.testing.assert_allclose(torque(2.0e-4, depth_per_k(MEASURED_AT))[0], want, rtol=1e-12)


def joint_parts(measured: list) -> list[HistoryFit]:
    """One part per history fitting :data:`THREE` on the stand-in, from K = 1e-4."""
    return [
        HistoryFit(
            Model(),
            d,
            THREE,
            {"wear_coefficient": 1.0e-4},
            torque_scale=1.0,
            torque_offset=0.0,
            fit_until=None,
            max_evaluations=200,
            diff_step=DIFF_STEP,
            label="test",
        )
        for d in measured
    ]


def test_joint_standard_errors_match_curve_fit() -> None:
    measured = [data(seed, *truth) for seed, truth in enumerate(TRUE, start=11)]
    result = fit_joint(joint_parts(measured), ["wear_coefficient"])

    n = MEASURED_AT.size
    model, jacobian = stacked(n)
    y = np.concatenate([d.values for d in measured])
    p0 = [TRUE[0][0], *TRUE[0][1:], *TRUE[1][1:]]
    popt, pcov = curve_fit(model, None, y, p0=p0, jac=jacobian, method="lm", xtol=1e-15)
    # the same covariance by hand: s² (JᵀJ)⁻¹ at the optimum
    jac = jacobian(None, *popt)
    residual = model(None, *popt) - y
    by_hand = residual @ residual / (2 * n - 5) * np.linalg.inv(jac.T @ jac)
    np.testing.assert_allclose(pcov, by_hand, rtol=1e-5)

    got = [
        result.errors["wear_coefficient"],
        *(h.errors[name] for h in result.histories for name in THREE[1:]),
    ]
    values = [
        result.values["wear_coefficient"],
        *(h.values[name] for h in result.histories for name in THREE[1:]),
    ]
    np.testing.assert_allclose(values, popt, rtol=1e-4)
    np.testing.assert_allclose(got, np.sqrt(np.diag(pcov)), rtol=1e-3)
    assert result.degrees_of_freedom == 2 * n - 5
    # the correlations too: K with each offset, and each scale with its offset
    sigma = np.sqrt(np.diag(pcov))
    reference = pcov / np.outer(sigma, sigma)
    assert result.correlations["wear_coefficient,torque_offset[2]"] == pytest.approx(
        reference[0, 4], abs=1e-3
    )
    assert result.correlations["torque_scale[1],torque_offset[1]"] == pytest.approx(
        reference[1, 2], abs=1e-3
    )
