"""Fixtures of the sweep tests."""

from __future__ import annotations

import pytest

from ballscrew import load_case


@pytest.fixture
def coarse_case(gao_case_path):
    """The TCR reference screw on a coarse contact grid (quick points)."""
    return load_case(
        gao_case_path, {"numerics.cells_across": 24, "numerics.gap_model": "quadratic"}
    )
