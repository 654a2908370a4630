"""The joint fit counts its parameters from their names: p is the number of column labels (a
shared parameter once, every other one per history), and its degrees of freedom are the
fitted points of all histories less p. The count used to be a formula written before the names
existed, so a part naming a parameter twice gave a p that no column matched."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from ballscrew.calibration.joint import fit_joint, joint_columns
from ballscrew.errors import InputError

from .test_joint_covariance import THREE, data, joint_parts

SHARED = ["wear_coefficient", "torque_scale"]


def _parts(names, count):
    return [SimpleNamespace(names=list(names)) for _ in range(count)]


def test_the_columns_are_the_shared_names_once_and_the_others_per_history():
    names, index = joint_columns(_parts(THREE, 3), SHARED)
    assert names == [
        "wear_coefficient",
        "torque_scale",
        "torque_offset[1]",
        "torque_offset[2]",
        "torque_offset[3]",
    ]
    assert [list(i) for i in index] == [[0, 1, 2], [0, 1, 3], [0, 1, 4]]


def test_a_parameter_named_twice_is_refused_before_any_model_run():
    with pytest.raises(InputError, match="each parameter once"):
        joint_columns(_parts(["wear_coefficient", "torque_offset", "torque_offset"], 2), SHARED)


def test_the_degrees_of_freedom_are_the_points_less_the_parameters():
    truths = ((2.0e-4, 1.1, 0.05), (2.0e-4, 1.1, 0.12), (2.0e-4, 1.1, 0.08))
    measured = [data(seed, *truth) for seed, truth in enumerate(truths, start=21)]
    result = fit_joint(joint_parts(measured), SHARED)
    points = sum(d.values.size for d in measured)
    assert result.degrees_of_freedom == points - 5  # K, m shared; three offsets
    labels = {name for pair in result.correlations for name in pair.split(",")}
    assert result.degrees_of_freedom == points - len(labels)
    np.testing.assert_allclose(result.values["torque_scale"], 1.1, rtol=0.05)
