"""Wear and preload loss over a public degradation history: fit the first half, predict the rest.

XJTU ball-screw degradation dataset (friction torque of two preloaded screws of one type, the
upper and the lower, after every 35 h of running, speed raised from 300 to 1700 rpm in 140 h
steps, 1000 N external load): the wear model
(K and the torque scale fitted with ``ballscrew.calibrate(..., fit_until=...)`` on the first 15
rows, each speed step at its own operating point) predicts the last 15 rows. The baseline it must
beat is a straight line in revolutions fitted to the same 15 rows; a model that does worse is a
strict known miss with its numbers. A third row compares the two screws: on one programme the
model gives nominally identical screws one preload history, hence the same fraction of torque
lost.
"""

from __future__ import annotations

import math
import tomllib
from typing import Any

import numpy as np

import ballscrew
from ballscrew.calibration import measured_history
from ballscrew.case import case_from_dict

from .conftest import EXAMPLES

SOURCE = "XJTU degradation dataset (2026), Up_FT/Down_FT, rows 1–30 (0–1015 h)"
HOURS_PER_ROW = 35.0
ROWS_PER_SPEED = 4  # 140 h per speed step
FIT_ROWS = 15  # 0–490 h: the first half

ASSUMPTIONS = (
    "row k at 35·k h; speed 300 rpm for the first 140 h, then +200 rpm every 140 h up to "
    "1700 rpm (source, README of 2026-07-09); revolutions = speed × running time (continuous "
    "running ASSUMED)",
    "Up_FT and Down_FT: the upper and the lower screw, each forecast from its own first half "
    "(source, README of 2026-07-09)",
    "torque in N m, measured without external load (ASSUMED, as in the drag-torque rows)",
    "screw: pitch diameter 32 mm, lead 8 mm, double nut of 2 × 60 balls of 4.7625 mm, "
    "conformity 0.52, contact angle 45°, bearing steel H = 7 GPa, raceway D = 1.4, "
    "G = 1e-10 m as the reference screw (all ASSUMED but the lead and the 1500 N preload)",
    "lubricant ISO VG 68 following the temperature of each speed step's operating point, "
    "stroke 0.2 m (ASSUMED; neither is published)",
    "coarse wear grid 8 × 32, depth step 0.3 µm, torque every 5e6 rev (numerical; the fitted "
    "K absorbs the grid: on 12 × 48 the held-out RMS errors are 0.035 (Up) and 0.041 (Down) N m "
    "with wear.asperity_roughness = 'cell')",
    "asperity share of the wear engine on σ_Λ = 1.005 µm of the raceway (the default "
    "wear.asperity_roughness = 'film'; the reference screw's G is a 3-D surface G, "
    "surface.G_convention = 'surface', whose profile G gives σ_Λ; 1.405 µm before the "
    "convention): ψ = 1.00 from 300 to 1700 rpm at the starts of the segments (Λ = 0.17–0.35 "
    "with the reference K; 0.25 to 0.015 on the σ of one grid cell, 'cell')",
)


def _case(data: dict[str, Any]) -> ballscrew.case.Case:
    with (EXAMPLES / "wear_step_stress.toml").open("rb") as fh:
        raw = tomllib.load(fh)
    raw["screw"].update(
        pitch_diameter="32 mm",
        lead=f"{data['lead_mm']} mm",
        ball_diameter="4.7625 mm",
        balls_per_nut=60,
        screw_conformity=0.52,
        nut_conformity=0.52,
    )
    raw["operating"].update(preload=f"{data['preload_N']} N", axial_load="1000 N")
    raw["medium"].pop("viscosity")
    raw["medium"].pop("pressure_viscosity")
    raw["kinematics"] = {"lubricant": "iso_vg_68"}
    raw["wear"].pop("programme")
    raw["wear"].pop("asperity_roughness")  # the default, "film": σ_Λ as the friction model
    raw["wear"].update(grid=[8, 32], max_depth_step="0.3 um", torque_sampling=5.0e6)
    rows = len(data["up_Nm"]) - 1
    steps = math.ceil(rows / ROWS_PER_SPEED)
    raw["duty"] = [
        {
            "speed": f"{300 + 200 * i} rpm",
            "axial_load": f"{data['external_load_during_degradation_N']} N",
            "stroke": "0.2 m",
            "duration": f"{HOURS_PER_ROW * min(ROWS_PER_SPEED, rows - ROWS_PER_SPEED * i)} h",
        }
        for i in range(steps)
    ]
    return case_from_dict(raw)


def _revolutions(rows: int) -> np.ndarray:
    rpm = 300.0 + 200.0 * (np.arange(rows - 1) // ROWS_PER_SPEED)
    return np.r_[0.0, np.cumsum(rpm * 60.0 * HOURS_PER_ROW)]


def _forecast(data: dict[str, Any], key: str) -> dict[str, float]:
    torque = np.asarray(data[key], dtype=float)
    revolutions = _revolutions(torque.size)
    history = measured_history(revolutions, torque, "friction_torque", key)
    until = float(revolutions[FIT_ROWS - 1])
    result = ballscrew.calibrate(_case(data), history, fit_until=until)
    line = np.polyfit(revolutions[:FIT_ROWS], torque[:FIT_ROWS], 1)
    held = slice(FIT_ROWS, None)
    line_rmse = float(np.sqrt(np.mean((np.polyval(line, revolutions[held]) - torque[held]) ** 2)))
    return {
        "measured_end": float(torque[-1]),
        "model_end": float(result.fitted[-1]),
        "line_end": float(np.polyval(line, revolutions[-1])),
        "model_rmse": float(result.prediction_rmse),
        "line_rmse": line_rmse,
        "wear_coefficient": result.wear_coefficient,
        "torque_scale": result.torque_scale,
    }


def _check(validation, dataset, key: str, known_miss: bool) -> None:
    data = dataset("drag_torque", "xjtu_friction_torque")
    out = _forecast(data, key)
    line_error = abs(out["line_end"] - out["measured_end"]) / out["measured_end"]
    validation.check(
        f"xjtu_wear_forecast_{key.removesuffix('_Nm')}",
        model="wear_life per duty segment + calibrate(fit_until=490 h)",
        source=SOURCE,
        reference=data,
        quantity=f"friction torque at 1015 h ({key.removesuffix('_Nm')}), forecast from 0–490 h",
        unit="N*m",
        measured=out["measured_end"],
        predicted=out["model_end"],
        tolerance=line_error,
        relative=True,
        tolerance_basis=(
            "the error of a straight line in revolutions fitted to the same first 15 rows "
            f"({line_error:.1%}): the model must forecast at least as well; over the whole "
            f"held-out half the RMS errors are {out['model_rmse']:.4f} N m (model) and "
            f"{out['line_rmse']:.4f} N m (line); fitted on rows 1–{FIT_ROWS} (0–490 h): "
            f"K = {out['wear_coefficient']:.3g}, torque scale {out['torque_scale']:.3g}"
        ),
        assumptions=ASSUMPTIONS,
        known_miss=known_miss,
    )


def test_xjtu_up_forecast(validation, dataset) -> None:
    """Up: model −21.5 % at 1015 h against the line's −50.2 % (held-out RMS 0.040 vs 0.074 N m);
    with wear.asperity_roughness = "cell" +12.5 % (0.019 N m)."""
    _check(validation, dataset, "up_Nm", known_miss=False)


def test_xjtu_down_forecast(validation, dataset) -> None:
    """Down: model −0.9 % against the line's −5.2 % (held-out RMS 0.016 vs 0.021 N m).

    With wear.asperity_roughness = "cell" it was +14.9 % (0.032 N m), a known miss: the film
    over the σ of one grid cell made the wear per revolution fall faster than 1/speed (ψ = 0.25
    at 300 rpm, 0.015 at 1700 rpm) while the measured torque falls about linearly in time. Over
    σ_Λ = 1.005 µm (1.405 µm before surface.G_convention) the asperities carry the load at every
    speed of the test (ψ = 1.00) and the wear per revolution stays nearly constant. The
    line's 5 % is a lucky split: fitted to rows 1–10 or 1–20 it misses by −14 % and −13 %
    (theory manual, *Why Down misses*)."""
    _check(validation, dataset, "down_Nm", known_miss=False)


def _relative_loss(hours: np.ndarray, torque: np.ndarray) -> tuple[float, float]:
    """Torque loss over the test relative to the start, from a line in time, and its σ."""
    (slope, start), cov = np.polyfit(hours, torque, 1, cov=True)
    return float(-slope * hours[-1] / start), float(np.sqrt(cov[0, 0]) / abs(slope))


def test_xjtu_specimen_loss_ratio(validation, dataset) -> None:
    """The upper and the lower screw are of one type and run one programme, so the model gives
    both one preload history, and a drag torque proportional to the preload (E9.1, any torque
    scale per screw) loses the same fraction in both; measured, the lower screw loses 0.61 of the
    upper one's fraction (and starts 26 % higher): a known miss, the specimens differ in ways
    that nominal inputs do not carry (preload setting, grease, a preload-independent torque)."""
    data = dataset("drag_torque", "xjtu_friction_torque")
    up, down = (np.asarray(data[k], dtype=float) for k in ("up_Nm", "down_Nm"))
    hours = HOURS_PER_ROW * np.arange(up.size)
    loss_up, rel_up = _relative_loss(hours, up)
    loss_down, rel_down = _relative_loss(hours, down)
    lead, pitch_diameter = data["lead_mm"] * 1e-3, 0.032
    lead_angle = math.atan(lead / (math.pi * pitch_diameter))
    preload = data["preload_N"]
    torque = ballscrew.loads.preload_drag_torque
    predicted = []
    for start in (up[0], down[0]):  # each screw scaled to its own as-new torque
        scale = start / torque(preload, lead, lead_angle)
        worn = scale * torque(preload * (1.0 - loss_up), lead, lead_angle)
        predicted.append(1.0 - worn / start)
    sigma = math.hypot(rel_up, rel_down)
    validation.check(
        "xjtu_specimen_loss_ratio",
        model="drag torque T = m K_T F_p L/2π (E9.1) on one preload history, m per screw",
        source=SOURCE,
        reference=data,
        quantity="relative torque loss over 0–1015 h, lower / upper screw (lines in time)",
        unit="-",
        measured=loss_down / loss_up,
        predicted=predicted[1] / predicted[0],
        tolerance=2.0 * sigma,
        relative=True,
        tolerance_basis=(
            f"2σ of the measured ratio ({2.0 * sigma:.1%}), σ from the slopes' standard errors "
            f"of the two lines; relative losses {loss_up:.3f} (Up) and {loss_down:.3f} (Down)"
        ),
        assumptions=(
            "row k at 35·k h (source, README of 2026-07-09)",
            "Up and Down: the upper and the lower screw, of one type and on one programme "
            "(source, README of 2026-07-09); the model gives them one preload history (nominal "
            "inputs)",
            "pitch diameter 32 mm (ASSUMED; the ratio does not depend on it)",
        ),
        known_miss=True,
    )
