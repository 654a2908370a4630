"""Analyses that ``ballscrew sweep --analysis NAME`` can run at every point."""

from __future__ import annotations

from ballscrew.analyses.catalog import ANALYSES, sweep_function
from ballscrew.sweep.runner import Analysis

__all__ = ["SWEEPABLE", "get_analysis"]

SWEEPABLE: tuple[str, ...] = tuple(n for n, a in ANALYSES.items() if a.scalars is not None)
"""Names of the analyses with sweepable scalars."""


def get_analysis(name: str) -> Analysis:
    """The scalar function of the sweepable analysis ``name``."""
    return sweep_function(name).scalars
