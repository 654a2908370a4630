"""Drag torque: HIWIN's printed torque test report of a preloaded 5 mm lead screw.

HIWIN prints one of its production torque reports (S99TE20-1610, Fig 2.5; BS-08-2-EN-1704-K,
Fig. 2.4): the preload drag torque of shaft 113H-3-R1, lead 5 mm, over 750 mm of travel in both
directions of rotation, with the maximum, mean and minimum of each trace. The catalogues state
the measuring conditions of these reports (JIS B 1192: 100 rpm, ISO VG 68, no wiper, return tube
up). It is a measured as-delivered torque of a screw other than the XJTU and THK ones. It is
recorded, not compared: the report does not give the shaft or pitch diameter, the ball size, the
nut type or the preload, and every torque model here (the catalogue's K F_p L/2π and the physics
ball model) scales with the preload.
"""

from __future__ import annotations

import pytest

SOURCE = "HIWIN S99TE20-1610 (2016), Fig 2.5; BS-08-2-EN-1704-K (2017), Fig. 2.4"

ASSUMPTIONS = (
    "lead 5 mm, travel 0-750 mm (source: the report); measured at 100 rpm with ISO VG 68 oil, "
    "no wiper, return tube up (source: HIWIN's measuring conditions for preload drag torque, "
    "section 4 of S99TE20-1610 and 3.6.3 of BS-08-2-EN-1704-K; ASSUMED to apply to this report)",
    "the middle value of each printed triple is the mean actual torque (ASSUMED: unlabelled in "
    "the report; it lies between the printed MAX and MIN); 1 kgf cm = 0.0980665 N m",
    "the upper and the lower trace are the two directions of rotation (ASSUMED from the sign)",
)

REASON = (
    "the report gives neither the preload nor the size of the screw (shaft and pitch diameter, "
    "ball diameter, turns, single or double nut), and both torque models (catalogue K F_p L/2π, "
    "physics ball model) scale with the preload. Missing: the preload and the nut geometry of "
    "shaft 113H-3-R1"
)


@pytest.mark.parametrize("direction", ["forward", "reverse"])
def test_hiwin_torque_report_mean_drag_torque(validation, dataset, direction: str) -> None:
    data = dataset("torque_sources", "hiwin_torque_test_report")
    torque = abs(data[f"{direction}_mean_kgf_cm"]) * data["kgf_cm_to_N_m"]
    trace = {"forward": "upper trace", "reverse": "lower trace"}[direction]
    validation.not_compared(
        f"hiwin_torque_report_mean_{direction}",
        model="drag_torque (catalogue K F_p L/2π) / friction_torque (ball_model)",
        source=SOURCE,
        reference=data,
        quantity=f"mean preload drag torque over 750 mm, {trace}, lead 5 mm, 100 rpm",
        unit="N m",
        measured=torque,
        assumptions=ASSUMPTIONS,
        reason=REASON,
    )
