"""Sweep files: a case, fixed overrides and swept axes in one TOML file.

    [sweep]
    case = "gao2019_tcr.toml"             # relative to this file
    analysis = "tcr"
    vary = ["surface.D=1.4:1.7:7"]
    set = { "surface.G" = "0.138 nm" }   # applied to every point

``ballscrew sweep FILE`` accepts such a file in place of a case file; ``--vary`` on the command
line adds axes (or replaces one of the same key).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ballscrew.budget import check_count, check_memory
from ballscrew.case import Case, CaseError, load_case
from ballscrew.case.loader import read_toml
from ballscrew.sweep.axes import SweepAxis, parse_axis

_KEYS = {"case", "analysis", "vary", "set", "description"}
POINT_BYTES = 64 * 2**10
"""Memory of one sweep point before and after it runs (overrides, validated case, record)."""


@dataclass(frozen=True)
class SweepSpec:
    """A validated sweep: the base case (overrides applied), its axes and the analysis."""

    case: Case
    axes: tuple[SweepAxis, ...]
    analysis: str | None = None
    description: str = ""
    fixed: dict[str, Any] = field(default_factory=dict)


def is_sweep_file(path: str | Path) -> bool:
    """True if ``path`` is a readable TOML file with a top-level ``[sweep]`` key."""
    try:
        return "sweep" in read_toml(path, "case or sweep file")
    except CaseError:
        return False


def load_sweep(path: str | Path) -> SweepSpec:
    """Read a sweep file; errors name the key and the file."""
    path = Path(path)
    source = str(path)
    document = read_toml(path, "sweep file")
    table = _sweep_table(document, source)
    fixed = _flatten(_typed(table, "set", dict, "a table of dotted case keys", source, {}))
    case_path = _typed(table, "case", str, "the path of the case file (a string)", source)
    case = load_case(path.parent / case_path, fixed)
    axes = tuple(parse_axis(text) for text in _vary(table, source))
    analysis = _analysis(table, source)
    description = _typed(table, "description", str, "a string", source, "")
    return SweepSpec(case, axes, analysis, description, fixed)


def _sweep_table(document: dict[str, Any], source: str) -> dict[str, Any]:
    """The ``[sweep]`` table, checked for its shape and unknown keys."""
    table = document.get("sweep")
    if not isinstance(table, dict):
        raise CaseError(
            [f"sweep = {table!r} is not allowed: a table ([sweep]) with the key 'case'"], source
        )
    unknown = sorted(set(table) - _KEYS)
    if unknown:
        raise CaseError(
            [f"sweep.{k}: unknown key; allowed: {', '.join(sorted(_KEYS))}" for k in unknown],
            source,
        )
    if "case" not in table:
        raise CaseError(["sweep.case is missing (path of the case file)"], source)
    return table


_MISSING = object()


def _typed(
    table: dict[str, Any], key: str, kind: type, allowed: str, source: str, default: Any = _MISSING
) -> Any:
    """``table[key]`` if it is a ``kind`` (``default`` when absent); else a :class:`CaseError`."""
    value = table.get(key, default)
    if value is not default and not isinstance(value, kind):
        raise CaseError([f"sweep.{key} = {value!r} is not allowed: {allowed}"], source)
    return value


def _analysis(table: dict[str, Any], source: str) -> str | None:
    """``sweep.analysis``: a registered analysis name, or None when absent."""
    from ballscrew.sweep.registry import SWEEPABLE

    allowed = f"one of {', '.join(SWEEPABLE)}"
    analysis = _typed(table, "analysis", str, allowed, source, None)
    if analysis is not None and analysis not in SWEEPABLE:
        raise CaseError([f"sweep.analysis = {analysis!r} is not allowed: {allowed}"], source)
    return analysis


def _vary(table: dict[str, Any], source: str) -> list[str]:
    """``sweep.vary``: a list of distinct-key axis strings."""
    allowed = 'a list of strings "KEY=START:STOP:NUM" or "KEY=V1,V2,..."'
    vary = _typed(table, "vary", list, allowed, source, [])
    keys: set[str] = set()
    for item in vary:
        if not isinstance(item, str):
            raise CaseError([f"sweep.vary item {item!r} is not allowed: {allowed}"], source)
        key = item.partition("=")[0].strip()
        if key in keys:
            raise CaseError([f"sweep.vary: {key} is swept twice; give each key once"], source)
        keys.add(key)
    return vary


def _flatten(table: dict[str, Any], prefix: str = "") -> dict[str, Any]:
    """Nested tables (``[sweep.set] surface.G = ...``) as dotted keys."""
    flat: dict[str, Any] = {}
    for key, value in table.items():
        if isinstance(value, dict):
            flat.update(_flatten(value, f"{prefix}{key}."))
        else:
            flat[f"{prefix}{key}"] = value
    return flat


def merge_axes(base: tuple[SweepAxis, ...], extra: list[SweepAxis]) -> tuple[SweepAxis, ...]:
    """``base`` axes with ``extra`` appended; an extra axis replaces a base axis of its key."""
    keys = {axis.key for axis in extra}
    return tuple(a for a in base if a.key not in keys) + tuple(extra)


def check_sweep_size(axes: tuple[SweepAxis, ...]) -> None:
    """Refuse a grid with more points than the step limit or the memory budget allows.

    Call it before the grid is expanded (``grid_points``) or its cases are validated.
    """
    points = math.prod(len(axis.values) for axis in axes)
    shape = " × ".join(f"{len(axis.values)} ({axis.key})" for axis in axes)
    check_count("--vary", shape, points, "points of the sweep grid")
    check_memory("--vary", shape, points * POINT_BYTES, f"a sweep of {points} points")
