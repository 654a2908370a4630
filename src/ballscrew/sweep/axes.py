"""Sweep axes: ``--vary KEY=START:STOP:NUM`` or ``--vary KEY=V1,V2,...``."""

from __future__ import annotations

import itertools
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from ballscrew.case import Case, CaseError, with_overrides
from ballscrew.case.loader import check_field_path, field_spec
from ballscrew.units import format_number, split_list, to_si


@dataclass(frozen=True)
class SweepAxis:
    """One swept case key and its values (SI)."""

    key: str
    values: tuple[float, ...]

    @property
    def unit(self) -> str:
        """SI unit of the swept field ('' when dimensionless)."""
        return field_spec(tuple(self.key.split("."))).unit

    @property
    def description(self) -> str:
        """Description of the swept field, from the case model."""
        return field_spec(tuple(self.key.split("."))).description


#: Most values one axis may hold.
MAX_AXIS_POINTS = 100_000


def parse_axis(text: str) -> SweepAxis:
    """Parse ``KEY=START:STOP:NUM`` (linearly spaced, ends included) or ``KEY=V1,V2,...``.

    The key must be a case field (dotted), the range must hold 1 to :data:`MAX_AXIS_POINTS`
    values. START, STOP and the values are SI numbers or quantities with a unit of the field's
    kind (``operating.speed=1500 rpm:3000 rpm:4``).
    """
    key, sep, spec = text.partition("=")
    key = key.strip()
    if not sep or not key or not spec.strip():
        raise CaseError([f"--vary {text!r}: expected KEY=START:STOP:NUM or KEY=V1,V2,..."], "sweep")
    check_field_path(key.split("."), "sweep")
    kind = field_spec(tuple(key.split("."))).kind or "dimensionless"
    try:
        if ":" in spec:
            start, stop, num = spec.split(":")
            count = int(num)
            if not 1 <= count <= MAX_AXIS_POINTS:
                raise ValueError(f"NUM = {count} is not in [1, {MAX_AXIS_POINTS}]")
            values = np.linspace(to_si(start.strip(), kind), to_si(stop.strip(), kind), count)
        else:
            values = np.array([to_si(v, kind) for v in split_list(spec)])
    except ValueError as exc:
        raise CaseError(
            [
                f"--vary {text!r}: the range is empty or not numbers (START:STOP:NUM with "
                f"1 ≤ NUM ≤ {MAX_AXIS_POINTS}): {exc}"
            ],
            "sweep",
        ) from None
    if values.size == 0:
        raise CaseError([f"--vary {text!r}: the range is empty"], "sweep")
    if values.size > MAX_AXIS_POINTS:
        raise CaseError([f"--vary {text!r}: more than {MAX_AXIS_POINTS} values"], "sweep")
    unique, counts = np.unique(values, return_counts=True)
    if np.any(counts > 1):
        twice = format_number(float(unique[np.argmax(counts > 1)]), 6)
        problem = f"--vary {text!r}: the value {twice} (SI) is given twice; give each value once"
        raise CaseError([problem], "sweep")
    return SweepAxis(key, tuple(float(v) for v in values))


def check_unique(axes: Sequence[SweepAxis]) -> None:
    """Raise :class:`CaseError` if two axes vary the same key."""
    keys = [axis.key for axis in axes]
    repeated = sorted({key for key in keys if keys.count(key) > 1})
    if repeated:
        raise CaseError(
            [f"--vary {key}: the key is varied twice; give each key once" for key in repeated],
            "sweep",
        )


def grid_points(axes: Sequence[SweepAxis]) -> list[dict[str, float]]:
    """All combinations of the axes' values (the first axis varies slowest); keys must differ."""
    check_unique(axes)
    keys = [axis.key for axis in axes]
    return [
        dict(zip(keys, combo, strict=True))
        for combo in itertools.product(*(a.values for a in axes))
    ]


def validate_points(base: Case, points: Sequence[Mapping[str, float]]) -> list[Case]:
    """Validate every point before any work starts; the first bad one raises :class:`CaseError`."""
    cases = []
    for overrides in points:
        try:
            cases.append(with_overrides(base, overrides))
        except CaseError as exc:
            where = ", ".join(f"{k}={v:g}" for k, v in overrides.items())
            raise CaseError(
                [f"sweep point ({where}): {p}" for p in exc.problems], "sweep"
            ) from None
    return cases
