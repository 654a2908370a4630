"""The reference wear coefficients: each reproduces the step-stress test's 2.43 µm.

``REFERENCE_COEFFICIENTS`` holds, per ``wear.asperity_roughness``, the K that gives the example
screw (Model A, 32 × 128 grid) h_max = 2.43 µm after 1.44e6 rev; a case without a coefficient of
its own runs with it. 'cell' was calibrated with the paper's ball-centre entrainment; 'film'
holds under either entrainment rule, since its asperities carry the whole load (ψ = 1).
"""

from __future__ import annotations

import pytest

import ballscrew
from ballscrew.case import with_overrides
from ballscrew.case.wear_spec import REFERENCE_COEFFICIENTS

from .conftest import REF_PATH

REFERENCE_DEPTH = 2.43e-6  # m, the step-stress test's wear depth after 1.44e6 rev


@pytest.mark.parametrize(
    ("roughness", "entrainment"),
    [("film", "rolling"), ("film", "ball_centre"), ("cell", "ball_centre")],
)
def test_each_reference_coefficient_gives_the_reference_depth(roughness, entrainment) -> None:
    case = with_overrides(
        ballscrew.load_case(REF_PATH),
        {
            "wear.coefficient": None,
            "wear.asperity_roughness": roughness,
            "kinematics.entrainment": entrainment,
        },
    )
    assert case.wear.wear_coefficient == REFERENCE_COEFFICIENTS[roughness]
    result = ballscrew.wear_life(case)
    assert result.life.max_wear_depth[-1] == pytest.approx(REFERENCE_DEPTH, rel=5e-3)
    source = result.summary()["wear_coefficient"]["source"]
    assert "h_max = 2.43 µm at 1.44×10⁶ rev" in source and f"= '{roughness}'" in source
