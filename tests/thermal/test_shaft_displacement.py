"""The displacement profile along the shaft ends at the elongation: one quantity, not two.

The network's profile stations are its cell centres; the profile used to start at the first
centre and stop at the last, half a cell short at each end (50.32 µm at the end of the profile
against an elongation of 50.67 µm on the reference screw).
"""

from __future__ import annotations

import numpy as np
import pytest

from ballscrew.thermal.axisymmetric import build_axisymmetric
from ballscrew.thermal.elongation import shaft_displacement, thermal_elongation
from ballscrew.thermal.network import build_network

from . import test_network as ref

ALPHA, RISE = 11.5e-6, 5.0


def test_a_uniform_rise_moves_the_end_face_by_alpha_rise_length_from_cell_centres():
    """Cells of unequal length over L = 0.5 m, stations at their centres: u(L) = αΔT·L."""
    faces = np.array([0.0, 0.05, 0.1, 0.2, 0.35, 0.5])
    centres = 0.5 * (faces[1:] + faces[:-1])
    z, u = shaft_displacement(centres, np.full(centres.size, RISE), ALPHA, 0.5)
    np.testing.assert_array_equal(z, [0.0, *centres, 0.5])
    np.testing.assert_allclose(u, ALPHA * RISE * z, rtol=1e-12)
    assert u[-1] == pytest.approx(28.75e-6, rel=1e-12)
    assert thermal_elongation(z, np.full(z.size, RISE), ALPHA) == pytest.approx(u[-1], rel=1e-12)


@pytest.mark.parametrize("build", [build_network, build_axisymmetric])
def test_both_models_give_alpha_rise_length_for_a_uniform_rise(build):
    """The elongation read-out e·θ and the end of the profile agree for a uniform ΔT."""
    problem = ref.engine_problem()
    disc = build(problem, 0.02)
    theta = np.full(disc.unknowns, RISE)
    length = problem.shaft_length
    closed_form = problem.expansion * RISE * length
    assert disc.elongation @ theta == pytest.approx(closed_form, rel=1e-9)
    z, u = shaft_displacement(disc.axis_z, disc.axis @ theta, problem.expansion, length)
    assert (z[0], z[-1]) == (0.0, pytest.approx(length, rel=1e-12))
    assert u[-1] == pytest.approx(closed_form, rel=1e-9)


def test_the_end_of_the_network_profile_is_its_elongation_for_a_graded_rise():
    """A rise that varies along the shaft (uniform cells): the end face moves by e·θ exactly."""
    problem = ref.engine_problem()
    disc = build_network(problem, 0.02)
    theta = np.linspace(1.0, 9.0, disc.unknowns)
    _, u = shaft_displacement(
        disc.axis_z, disc.axis @ theta, problem.expansion, problem.shaft_length
    )
    assert u[-1] == pytest.approx(disc.elongation @ theta, rel=1e-12)
