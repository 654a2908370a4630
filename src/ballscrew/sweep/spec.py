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
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ballscrew.budget import check_count, check_memory
from ballscrew.case import Case, CaseError, load_case
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
    """True if ``path`` is a TOML file with a top-level ``[sweep]`` table."""
    try:
        return "sweep" in tomllib.loads(Path(path).read_text(encoding="utf-8"))
    except (OSError, tomllib.TOMLDecodeError):
        return False


def load_sweep(path: str | Path) -> SweepSpec:
    """Read a sweep file; errors name the key and the file."""
    path = Path(path)
    try:
        table = tomllib.loads(path.read_text(encoding="utf-8"))["sweep"]
    except tomllib.TOMLDecodeError as exc:
        raise CaseError([f"TOML syntax error: {exc}"], str(path)) from None
    unknown = set(table) - _KEYS
    if unknown:
        raise CaseError(
            [f"sweep.{k}: unknown key; allowed: {', '.join(sorted(_KEYS))}" for k in unknown],
            str(path),
        )
    if "case" not in table:
        raise CaseError(["sweep.case is missing (path of the case file)"], str(path))
    fixed = dict(table.get("set", {}))
    case = load_case(path.parent / table["case"], fixed)
    axes = tuple(parse_axis(text) for text in table.get("vary", []))
    return SweepSpec(case, axes, table.get("analysis"), table.get("description", ""), fixed)


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
