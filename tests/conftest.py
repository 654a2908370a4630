"""Shared fixtures: paths of the example cases."""

from __future__ import annotations

from pathlib import Path

import pytest

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


@pytest.fixture
def gao_case_path() -> Path:
    """The TCR reference screw (theory manual, *Reference screws*)."""
    return EXAMPLES / "gao2019_tcr.toml"


@pytest.fixture
def wear_case_path() -> Path:
    """The step-stress wear reference screw (theory manual, *Reference screws*)."""
    return EXAMPLES / "wear_step_stress.toml"
