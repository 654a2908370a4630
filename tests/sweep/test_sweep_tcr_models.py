"""A TCR sweep carries every rival model and the spread, not the headline alone."""

from __future__ import annotations

import numpy as np

from ballscrew.analyses.screw_tcr import tcr_scalars
from ballscrew.case import with_overrides


def test_tcr_scalars_carry_every_model_inside_the_band(coarse_case):
    rough = with_overrides(coarse_case, {"surface.G": 2 * coarse_case.surface.G})
    points = [tcr_scalars(coarse_case), tcr_scalars(rough)]
    names = [
        k.removesuffix("_resistance_per_area")
        for k in points[0]
        if k.startswith("model_") and k.endswith("_resistance_per_area")
    ]
    assert {"model_CMY", "model_V2", "model_V2_patch", "model_Mikic"} <= set(names)
    for scalars in points:
        assert scalars["uncertainty_low"][1] == "m^2*K/W"
        per_area = np.array([scalars[f"{n}_resistance_per_area"][0] for n in names])
        assert scalars["uncertainty_low"][0] == per_area.min()
        assert scalars["uncertainty_high"][0] == per_area.max()
        assert scalars["model_CMY_resistance"][0] == scalars["resistance"][0]  # the headline
    # Rougher raceway, higher resistance for every model (Gao, Wang & Liu 2019, R rises with G).
    for name in names:
        assert points[1][f"{name}_resistance"][0] > points[0][f"{name}_resistance"][0], name
