"""The reference wear coefficients: each reproduces the step-stress test's 2.43 µm.

``REFERENCE_COEFFICIENTS`` holds, per ``wear.asperity_roughness``, the K that gives the example
screw (Model A, 32 × 128 grid) h_max = 2.43 µm after 1.44e6 rev; a case without a coefficient of
its own runs with it. 'cell' was calibrated with the paper's ball-centre entrainment; 'film'
holds under either entrainment rule, since its asperities carry the whole load (ψ = 1).
"""

from __future__ import annotations

import numpy as np
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


#: The K that gives the step-stress screw its 2.43 µm with the default 'film' asperities under each
#: preload update (theory manual, *Which preload update is the default*): (loads.distribution,
#: wear.preload_contact) → (K, F_p left [N], preload lost per level [N]).
PRELOAD_UPDATES = {
    ("uniform", "hertz"): (9.607e-5, 244.5, (558.2, 363.6, 333.9)),
    ("uniform", "worn"): (9.508e-5, 278.6, (463.4, 385.7, 372.4)),
    ("elastic", "hertz"): (9.598e-5, 305.3, (521.4, 344.6, 328.7)),
    ("elastic", "worn"): (9.499e-5, 346.3, (429.6, 360.8, 363.4)),
}


@pytest.mark.slow
def test_each_preload_update_keeps_more_preload_at_the_reference_depth() -> None:
    """Recalibrated to the same 2.43 µm, the elastic bodies and the worn groove's contact each
    keep more preload than the contact-only Hertz law (E1.13), together the most; the loss per
    level stays largest in the first level under every update (none accelerates)."""
    base = with_overrides(ballscrew.load_case(REF_PATH), {"wear.asperity_roughness": "film"})
    left = []
    for (distribution, contact), (k, preload, losses) in PRELOAD_UPDATES.items():
        case = with_overrides(
            base,
            {
                "wear.coefficient": k,
                "loads.distribution": distribution,
                "wear.preload_contact": contact,
            },
        )
        life = ballscrew.wear_life(case).life
        assert life.max_wear_depth[-1] == pytest.approx(REFERENCE_DEPTH, rel=5e-4)
        ends = np.interp(np.cumsum([4.8e5] * 3), life.revolutions, life.preload)
        lost = -np.diff(np.r_[case.operating.preload, ends])
        assert ends[-1] == pytest.approx(preload, rel=2e-3)
        assert lost == pytest.approx(losses, rel=2e-3)
        assert lost[0] == max(lost)
        left.append(ends[-1])
    hertz, worn, elastic, both = left
    assert hertz < worn < elastic < both
