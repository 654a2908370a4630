"""The preload loop's body compliance c_b with the numerical contact law (theory manual, *Wear*:
the interference of the elastic distribution beyond the ball contacts' own approach)."""

from __future__ import annotations

import pytest

import ballscrew
from ballscrew.analyses.parameters import ScrewParameters
from ballscrew.analyses.wear import _preload_loop_compliance

ELASTIC = {"loads.distribution": "elastic"}
NUMERICAL = ELASTIC | {"loads.contact": "numerical"}


def _compliance(path, overrides) -> float:
    case = ballscrew.load_case(path, overrides)
    return _preload_loop_compliance(case, ScrewParameters.from_case(case))


def test_the_body_compliance_does_not_depend_on_the_contact_law(gao_case_path):
    """c_b is the shaft and nut bodies' share: the numerical law's own approach is taken off.
    On a Hertz-shaped table (quadratic gap) it equals the Hertz path's to the tabulation accuracy
    (the Hertz approach taken off instead left 1.7e-3); on the conforming groove (exact gap)
    within 1e-4 (it was 2.4 % off)."""
    hertz = _compliance(gao_case_path, ELASTIC)
    quadratic = _compliance(gao_case_path, NUMERICAL | {"numerics.gap_model": "quadratic"})
    exact = _compliance(gao_case_path, NUMERICAL)
    assert hertz > 0.0
    assert quadratic / hertz == pytest.approx(1.0, rel=1e-5)
    assert exact / hertz == pytest.approx(1.0, rel=1e-4)
