"""The XJTU friction-torque history with one preload per screw: fit the first half, predict the
rest.

Same data and split as ``test_wear_history.py`` (XJTU degradation dataset; rows 1–15, 0–490 h,
fitted; rows 16–30 predicted). The earlier joint fits give both screws one preload history, so
the ratio of their relative torque losses is 1 (torque law alone) or T_Up(0)/T_Down(0) ≈ 0.76
(with T_0 per screw) against the measured 0.611. Here the lower screw's 29 % higher as-new
torque is read as a higher preload setting: ``calibrate_joint`` takes one case per history, Up at
the published 1500 N and Down at 1500 N × T_Down(0)/T_Up(0), with one K and one torque scale m
for the screw type (T = m K_T F_p(N) L/(2π), no T_0). Each forecast must beat a straight line in
revolutions fitted to the same first half; the loss ratio must lie within 2σ of the measured one.
"""

from __future__ import annotations

import functools

import pytest

import ballscrew
from ballscrew.case import with_overrides

from .test_wear_history import ASSUMPTIONS, _case
from .test_wear_history_offset import (
    KEYS,
    MISSES,
    _data,
    _histories,
    _until,
    check_forecast,
    check_loss_ratio,
)

UP_PRELOAD = 1500.0
"""The screw type's preload [N] (the dataset's README), kept for the upper screw."""


def _down_preload() -> float:
    """Down's preload [N] if its higher as-new torque is all preload: F_p T_Down(0)/T_Up(0)."""
    data = _data()
    return UP_PRELOAD * data["down_Nm"][0] / data["up_Nm"][0]


PRELOAD_ASSUMPTIONS = (
    *ASSUMPTIONS,
    "drag torque T = m K_T F_p(N) L/2π with one torque scale m for the screw type, no T_0 "
    "(ASSUMED: both screws of one type, one K_T)",
    f"Up at the published {UP_PRELOAD:.0f} N; Down at 1500 N × T_Down(0)/T_Up(0) = "
    f"{_down_preload():.0f} N, its 29 % higher as-new torque read as a higher preload setting "
    "(ASSUMED hypothesis; the dataset gives one preload, 1500 N, for the screw type)",
)
SPECIMENS = (
    "Up and Down: the upper and the lower screw of one rig (the dataset's README), one K and one "
    "m for the type, each screw with its own preload and so its own preload history"
)
pytestmark = pytest.mark.filterwarnings("ignore::ballscrew.calibration.CalibrationWarning")
"""The fit's warnings are recorded in the rows' tolerance basis instead."""
MODEL = "wear_life per duty segment + calibrate_joint(one case per screw; one K and one m; 490 h)"


@functools.cache
def _joint() -> ballscrew.calibration.JointCalibrationResult:
    case = _case(_data())
    cases = [case, with_overrides(case, {"operating.preload": f"{_down_preload()} N"})]
    histories = _histories()
    return ballscrew.calibrate_joint(
        cases,
        [histories[k] for k in KEYS],
        shared=("wear_coefficient", "torque_scale"),
        separate=(),
        fit_until=_until(),
    )


def _fitted() -> str:
    joint = _joint()
    k, m = joint.values["wear_coefficient"], joint.values["torque_scale"]
    dk, dm = joint.errors["wear_coefficient"], joint.errors["torque_scale"]
    return (
        f"fitted: K = {k:.3g} ± {dk:.2g}, m = {m:.3g} ± {dm:.2g} (one of each for both screws); "
        f"preloads {UP_PRELOAD:.0f} N (Up) and {_down_preload():.0f} N (Down); joint RMS "
        f"residual {joint.rms_residual:.4f} N m; calibration warnings: "
        f"{' / '.join(joint.warnings) or 'none'}"
    )


@pytest.mark.parametrize(("key", "known_miss"), MISSES)
def test_xjtu_preload_per_screw_forecast(validation, key, known_miss) -> None:
    """Up −1.5 % (line −50.2 %), Down −15.0 % (line −5.2 %, a known miss: held-out RMS 0.045
    against the line's 0.021 N m); Up's fitted half is flagged systematic (lag-1
    autocorrelation 0.54). With wear.asperity_roughness = "cell": Up +31.5 %, Down +2.2 % (the
    one cell variant whose Down beat the line)."""
    result = _joint().histories[KEYS.index(key)]
    check_forecast(
        validation,
        "xjtu_preload_per_screw_forecast",
        key,
        result,
        MODEL,
        _fitted(),
        PRELOAD_ASSUMPTIONS,
        known_miss,
    )


def test_xjtu_preload_per_screw_loss_ratio(validation) -> None:
    """Down/Up ratio of the relative torque losses with Down's preload raised to 1941 N: 0.969
    against the measured 0.611, a known miss (+59 %; 1.43 with wear.asperity_roughness =
    "cell"), no closer than one preload history (1.00 or 0.76). The numbers that follow are
    those of "cell". In the model the fraction of preload lost *rises* with the preload: a small
    depth h removes ΔF_p/F_p = h/(sinβ cosλ (⅔ C_a F_p^(2/3) + c_b F_p)) ∝ h F_p^(−2/3) (contacts
    only; F_p^(−1) if the bodies take the approach), and the worn depth by 1015 h grows about as
    F_p^1.8, so ΔF_p/F_p ∝ F_p^1.13 and (1941/1500)^1.13 = 1.34. The measured 0.611 =
    1.294^(−1.91) needs a depth ∝ F_p^(−1.25) (Down wearing 27 % less than Up). Even a depth
    independent of the preload gives 0.77–0.84, above the 2σ band (≤ 0.70). Wear Model C on both
    screws gives 1.47 (Up +33.1 %, Down +3.4 % at 1015 h). No published wear law whose depth falls
    with the load was found; the likelier reading is that part of Down's higher as-new torque is
    not preload (the T_0 rows). Theory manual, *Wear*, one preload per screw."""
    check_loss_ratio(
        validation,
        "xjtu_preload_per_screw_loss_ratio",
        _joint(),
        "calibrate_joint with one case per screw: T = m K_T F_p(N) L/2π, one K and one m, "
        "preload per screw from the as-new torques",
        f"; {_fitted()}",
        PRELOAD_ASSUMPTIONS,
        SPECIMENS,
    )
