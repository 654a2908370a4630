"""Sweep axes: ``--vary KEY=START:STOP:NUM`` or ``--vary KEY=V1,V2,...``."""

from __future__ import annotations

import itertools
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from ballscrew.case import Case, CaseError, with_overrides
from ballscrew.case.loader import _field_info, check_field_path


@dataclass(frozen=True)
class SweepAxis:
    """One swept case key and its values (SI)."""

    key: str
    values: tuple[float, ...]

    @property
    def unit(self) -> str:
        """SI unit of the swept field ('' when dimensionless)."""
        return _field_info(tuple(self.key.split(".")))[1]

    @property
    def description(self) -> str:
        """Description of the swept field, from the case model."""
        return _field_info(tuple(self.key.split(".")))[0]


def parse_axis(text: str) -> SweepAxis:
    """Parse ``KEY=START:STOP:NUM`` (linearly spaced, ends included) or ``KEY=V1,V2,...``.

    The key must be a case field (dotted), the range must hold at least one value.
    """
    key, sep, spec = text.partition("=")
    key = key.strip()
    if not sep or not key or not spec.strip():
        raise CaseError([f"--vary {text!r}: expected KEY=START:STOP:NUM or KEY=V1,V2,..."], "sweep")
    check_field_path(key.split("."), "sweep")
    try:
        if ":" in spec:
            start, stop, num = spec.split(":")
            count = int(num)
            if count < 1:
                raise ValueError
            values = np.linspace(float(start), float(stop), count)
        else:
            values = np.array([float(v) for v in spec.split(",") if v.strip()])
    except ValueError:
        raise CaseError(
            [f"--vary {text!r}: the range is empty or not numbers (START:STOP:NUM with NUM ≥ 1)"],
            "sweep",
        ) from None
    if values.size == 0:
        raise CaseError([f"--vary {text!r}: the range is empty"], "sweep")
    return SweepAxis(key, tuple(float(v) for v in values))


def grid_points(axes: Sequence[SweepAxis]) -> list[dict[str, float]]:
    """All combinations of the axes' values (the first axis varies slowest)."""
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
