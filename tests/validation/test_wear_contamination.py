"""Wear in a contaminated environment: THK's foundry-dust test of a BIF3210 screw (catalogue A-820).

THK ran a BIF3210-5G0+1500LC5 screw (32 mm shaft, lead 10 mm, offset-preload single nut, 1.31 kN
internal load) at up to 1000 rpm over a 900 mm stroke for 2000 km of travel, with 5 g/h of FCD400
foundry dust (250 µm) fed onto the shaft, once with wiper rings and once with labyrinth seals, and
printed the ball wear at 2000 km and the distance at which the raceway flaked. This is the only
published wear *amount* of a second ball screw (besides the XJTU torque history) whose number
could be read here. It is recorded, not compared: the wear model wears the screw raceway only
(ball wear is neglected, theory manual, Wear) and has no third-body abrasion by foreign particles.
"""

from __future__ import annotations

import pytest

SOURCE = "THK General Catalog, A-820 (Wiper Ring W, contaminated-environment test)"

ASSUMPTIONS = (
    "BIF3210-5G0+1500LC5: shaft 32 mm, lead 10 mm (read from the model code: ASSUMED), "
    "offset-preload single nut, overall length 1500 mm; 1000 rpm maximum, 60 ms time constant, "
    "1 s dwell, stroke 900 mm, internal load 1.31 kN, AFG grease 8 cm³ at the start only (source)",
    "2000 km of travel = 2.0e8 screw revolutions at the 10 mm lead (derived)",
    "foundry dust FCD400, mean particle 250 µm, 5 g/h per shaft (source)",
)

REASON = (
    "the measured quantity is the wear of the balls under a fed abrasive (foundry dust): the wear "
    "model wears the screw raceway only (ball wear neglected) and has no third-body abrasion. "
    "Missing inputs: a ball-wear output and a contamination description (particle size, hardness, "
    "mass rate, seal type) with an abrasive wear law"
)


@pytest.mark.parametrize(
    ("seal", "key"),
    [("wiper", "ball_wear_wiper_um"), ("labyrinth", "ball_wear_labyrinth_um")],
    ids=["wiper_ring", "labyrinth_seal"],
)
def test_thk_bif3210_ball_wear_in_foundry_dust(validation, dataset, seal: str, key: str) -> None:
    data = dataset("wear_contamination", "thk_bif3210_foundry_dust")
    sealing = {"wiper": "wiper ring W", "labyrinth": "labyrinth seal"}[seal]
    validation.not_compared(
        f"thk_bif3210_ball_wear_dust_{seal}",
        model="wear (law A, screw raceway)",
        source=SOURCE,
        reference=data,
        quantity=f"ball wear after 2000 km of travel in foundry dust, {sealing}",
        unit="µm",
        measured=data[key],
        assumptions=(*ASSUMPTIONS, f"sealing: {sealing} at both nut ends (source)"),
        reason=REASON,
    )
