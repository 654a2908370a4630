"""The nut temperature of the FE models is the volume mean of the nut assembly."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import ballscrew as bs
from ballscrew.analyses.operating_point import operating_point
from ballscrew.thermal.axisymmetric import build_axisymmetric
from ballscrew.thermal.discretisation import nut_mean_row
from ballscrew.thermal.threed import build_threed

from .test_fe_rebind import EXAMPLE, small


def test_axisymmetric_volume_mean_by_hand():
    """θ = r² (exact in Q2) over the annulus R … r_o: (1/V)∫θ dV = ∫r³dr/∫r dr = (r_o² + R²)/2."""
    problem = small()
    disc = build_axisymmetric(problem, 0.005, 2)
    row = nut_mean_row(disc)
    theta = disc.extra["basis"].doflocs[0] ** 2
    r_o, r = problem.parts[0].outer_radius, problem.shaft_radius
    assert row @ theta == pytest.approx(0.5 * (r_o**2 + r**2), rel=1e-12)
    assert row.sum() == pytest.approx(1.0, rel=1e-12)


def test_3d_volume_mean_by_hand():
    """θ = z (exact on hexahedra) over a nut of uniform section: the mean is its centre."""
    problem = small()
    disc = build_threed(problem, 0.01, 12, 1, 0.1)
    row = nut_mean_row(disc)
    z = disc.extra["basis"].doflocs[2]
    assert row @ z == pytest.approx(problem.ring_centre, rel=1e-12)
    assert row.sum() == pytest.approx(1.0, rel=1e-12)


def test_the_fe_nut_temperature_is_a_mean_not_the_hot_spot():
    """Example at 1000 rpm on the axisymmetric model: the nut's mean is below the field's
    largest temperature (at the balls) and within 0.1 K of the network's nut mean."""
    case = bs.load_case(
        EXAMPLE,
        {"numerics.cells_across": 16, "thermal.mesh.size": "5 mm"},
    )
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        fe = operating_point(case, model="axisymmetric")
        net = operating_point(case, model="network")
    assert fe.nut_temperature < fe.max_temperature - 2.0
    assert fe.nut_temperature == pytest.approx(net.nut_temperature, abs=0.1)
    assert fe.field.nut_temperature == pytest.approx(fe.nut_temperature, rel=1e-12)
    assert np.isclose(fe.max_temperature, fe.field.max_temperature)
