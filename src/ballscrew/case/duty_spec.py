"""Case list ``[[duty]]``: a duty cycle of constant segments, run ``duty_repeat`` times.

Each segment holds the screw speed, the axial load and the nut's stroke for a duration; a
``dwell`` at each stroke end is time at standstill within the segment. Example::

    duty_repeat = 8                # e.g. eight hours of a one-hour cycle

    [[duty]]
    speed = "1500 rpm"
    axial_load = "2 kN"
    stroke = "400 mm"
    dwell = "2 s"
    duration = "40 min"

    [[duty]]                       # the return stroke pulls: the reverse direction
    speed = "1500 rpm"
    axial_load = "-1 kN"
    duration = "10 min"

    [[duty]]                       # standstill
    speed = 0
    duration = "20 min"

The axial load is signed: F_a ≥ 0 presses on nut 1 of a double nut (flank 1 of a single nut),
F_a < 0 is the reverse direction, which presses on nut 2 (flank 2).
"""

from __future__ import annotations

from typing import Annotated

from pydantic import Field, model_validator

from ballscrew.case.base import MAX_FORCE, MAX_SPEED, Model, quantity

__all__ = ["MAX_DUTY_TIME", "MAX_STROKE", "DutySegment", "require_time_shares"]

MAX_DUTY_TIME = 1.0e8
"""Longest segment or cycle a case accepts, s (about three years)."""

MAX_STROKE = 100.0
"""Longest stroke of a segment, m (also the stroke column of a measured wear schedule)."""


class DutySegment(Model):
    """One segment of the duty cycle: constant speed, load and stroke for a duration."""

    speed: quantity(
        "angular_velocity", 'screw speed ω (rad/s; "1500 rpm" also works)', ge=0, le=MAX_SPEED
    ) = 0.0
    axial_load: quantity(
        "force",
        "external axial load F_a during the segment, signed: ≥ 0 presses on nut 1 (flank 1), "
        "< 0 the reverse direction on nut 2 (flank 2)",
        ge=-MAX_FORCE,
        le=MAX_FORCE,
    ) = 0.0
    stroke: quantity(
        "length", "stroke of the nut (0: the nut turns in place)", ge=0, le=MAX_STROKE
    ) = 0.0
    dwell: quantity(
        "time", "standstill at each stroke end, within the segment", ge=0, le=MAX_DUTY_TIME
    ) = 0.0
    duration: quantity("time", "length of the segment", gt=0, le=MAX_DUTY_TIME)

    @model_validator(mode="after")
    def _dwell_fits(self) -> DutySegment:
        if self.dwell >= self.duration:
            raise ValueError(
                f"dwell = {self.dwell:g} s is not allowed: it must be shorter than the segment's "
                f"duration = {self.duration:g} s"
            )
        return self


DutyRepeat = Annotated[
    int, Field(ge=1, le=100_000, description="how many times the [[duty]] list is run")
]


def require_time_shares(duty: object) -> None:
    """One error for a ``[[duty]]`` list whose segments lack their duration (time share).

    Without durations the segments have no weights, so neither a cube-mean load nor a life
    exists; the error names every such segment in one line.
    """
    if not isinstance(duty, list):
        return
    missing = [k for k, seg in enumerate(duty) if isinstance(seg, dict) and "duration" not in seg]
    if missing:
        where = ", ".join(f"duty.{k}" for k in missing)
        raise ValueError(
            f"duty = {len(missing)} segment(s) without a duration is not allowed: every [[duty]] "
            f'segment needs its duration, its time share of the cycle (e.g. duration = "10 min"); '
            f"missing in {where}"
        )
