"""The wear runs its programme ([wear] or [[duty]]), not [operating]: an [operating] point
above every level (a ``--set operating.axial_load`` too) is said not to be worn at."""

from __future__ import annotations

import warnings

import pytest

import ballscrew
from quick_cases import QUICK_WEAR, write_case


def test_an_operating_load_above_the_programme_is_said_to_be_ignored(tmp_path):
    case = ballscrew.load_case(
        write_case(tmp_path, "wear_step_stress.toml", QUICK_WEAR | {"operating.axial_load": 5e3})
    )
    with pytest.warns(UserWarning, match=r"axial_load = 5 kN above the \[wear\] programme's "):
        life = ballscrew.wear_life(case)
    assert any("not this point" in w for w in life.warnings)


def test_an_operating_point_inside_the_programme_is_not_warned_about(tmp_path):
    case = ballscrew.load_case(write_case(tmp_path, "wear_step_stress.toml", QUICK_WEAR))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        ballscrew.wear_life(case)
    assert not [w for w in caught if "not this point" in str(w.message)]
