"""Analyses that ``ballscrew sweep --analysis NAME`` can run at every point."""

from __future__ import annotations

from importlib import import_module

from ballscrew.errors import InputError
from ballscrew.sweep.runner import Analysis

#: name → "module:function" returning {quantity: (value, SI unit)} for a case.
ANALYSES: dict[str, str] = {
    "contact": "ballscrew.analyses.ball_contact:contact_scalars",
    "tcr": "ballscrew.analyses.screw_tcr:tcr_scalars",
    "thermal": "ballscrew.analyses.thermal:thermal_scalars",
    "thermal-fe": "ballscrew.analyses.thermal:thermal_fe_scalars",
}


def get_analysis(name: str) -> Analysis:
    """The analysis function registered under ``name``."""
    if name not in ANALYSES:
        raise InputError("--analysis", name, f"one of {', '.join(sorted(ANALYSES))}")
    module, _, function = ANALYSES[name].partition(":")
    return getattr(import_module(module), function)
