"""Analyses that ``ballscrew sweep --analysis NAME`` can run at every point."""

from __future__ import annotations

from ballscrew.analyses.catalog import ANALYSES, sweep_function
from ballscrew.errors import InputError
from ballscrew.sweep.runner import Analysis

__all__ = ["SWEEPABLE", "get_analysis", "resolve_analysis"]

SWEEPABLE: tuple[str, ...] = tuple(n for n, a in ANALYSES.items() if a.scalars is not None)
"""Names of the analyses with sweepable scalars."""


def get_analysis(name: str) -> Analysis:
    """The scalar function of the sweepable analysis ``name``."""
    return sweep_function(name).scalars


def _qualified(function: Analysis) -> str:
    module = getattr(function, "__module__", None) or "?"
    return f"{module}.{getattr(function, '__qualname__', type(function).__name__)}"


def resolve_analysis(
    analysis: Analysis | str, name: str | None = None
) -> tuple[Analysis, str, str]:
    """The function, the name and the identity of the analysis a sweep runs.

    ``analysis`` is a sweepable analysis's name, its function, or a function of the user's.
    ``name`` may be left out; given, it must be the built-in analysis's own name, and a
    user's function may not take a built-in's name (its points would be stored and labelled
    as that analysis). The identity is what a sweep store records: the built-in's name, or
    the user's function by module and qualified name.
    """
    if isinstance(analysis, str):
        own = analysis
        function = sweep_function(analysis, "analysis").scalars
    else:
        function = analysis
        own = next((n for n in SWEEPABLE if get_analysis(n) is analysis), None)
    if own is not None:
        if name is not None and name != own:
            raise InputError("analysis_name", name, f"{own!r}, the name of the analysis given")
        return function, own, own
    identity = _qualified(function)
    if name in SWEEPABLE:
        raise InputError(
            "analysis_name",
            name,
            f"a name other than the built-in analyses ({', '.join(SWEEPABLE)}): "
            f"{identity} is none of their functions",
        )
    return function, name or identity, identity
