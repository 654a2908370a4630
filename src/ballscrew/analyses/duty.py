"""The duty cycle of a case as a schedule of constant phases in time.

A case's ``[[duty]]`` segments, run ``duty_repeat`` times, become phases with a start and end
time. Within a segment the nut runs strokes of length S at the feed v = ω L/(2π) and stands
still for the dwell t_d at each stroke end, so the screw turns for the fraction

    f = (S/v) / (S/v + t_d)

of the segment (f = 1 without dwell or stroke). The time means of the speed and of the friction
heat of the segment are then f·ω and f·Q(ω): the thermal time constants of a screw (minutes)
are long against a stroke (seconds), so the model follows the mean of each segment.

The axial load keeps its sign (F_a < 0: the reverse direction, on nut 2); the chains that run
an operating point of a segment take |F_a| (:func:`mirrored_load`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ballscrew.case import Case
from ballscrew.units import format_quantity

__all__ = ["DutyPhase", "duty_schedule", "mirrored_load", "operating_excess"]


@dataclass(frozen=True)
class DutyPhase:
    """One constant phase of the duty cycle (SI)."""

    start: float
    """Start time [s]."""
    end: float
    """End time [s]."""
    speed: float
    """Screw speed while turning, ω [rad/s]."""
    axial_load: float
    """Axial load F_a [N], signed (< 0: the reverse direction, on nut 2)."""
    stroke: float
    """Stroke of the nut S [m] (0: the nut turns in place)."""
    moving_fraction: float
    """Share f of the phase during which the screw turns [-]."""

    @property
    def duration(self) -> float:
        """Length of the phase [s]."""
        return self.end - self.start

    @property
    def mean_speed(self) -> float:
        """Time-mean screw speed f·ω [rad/s]."""
        return self.moving_fraction * self.speed


def operating_excess(case: Case, max_load: float, max_speed: float, levels: str) -> list[str]:
    """What of ``[operating]`` lies above the largest |F_a| ``max_load`` [N] and speed
    ``max_speed`` [rad/s] of the ``levels`` an analysis runs instead (its words, e.g. "duty"):
    such a point, a ``--set operating.…`` too, is then not analysed."""
    op, over = case.operating, []
    if abs(op.axial_load) > max_load * (1.0 + 1e-9):
        over.append(
            f"axial_load = {format_quantity(abs(op.axial_load), 'N')} above the {levels}'s "
            f"largest {format_quantity(max_load, 'N')}"
        )
    if op.speed > max_speed * (1.0 + 1e-9):
        over.append(
            f"speed = {format_quantity(op.speed, 'rad/s')} above the {levels}'s largest "
            f"{format_quantity(max_speed, 'rad/s')}"
        )
    return over


def mirrored_load(axial_load: float) -> float:
    """|F_a|: the load of the mirror image of a reverse segment [N].

    A symmetric nut under −F_a is the nut under +F_a with nut 1 and nut 2 (flank 1 and 2)
    swapped, so its friction torque, heat and operating point are those of |F_a| (ASSUMED
    mirror symmetry: the elastic distribution's shaft load path and flange side break it;
    theory manual, *Operating point*, reverse loads).
    """
    return abs(axial_load)


def moving_fraction(speed: float, lead: float, stroke: float, dwell: float) -> float:
    """Share of the time the screw turns: (S/v)/(S/v + t_d), v = ω L/(2π); 1 without dwell."""
    if speed <= 0.0:
        return 0.0
    if dwell <= 0.0 or stroke <= 0.0:
        return 1.0
    stroke_time = stroke / (speed * lead / (2.0 * math.pi))
    return stroke_time / (stroke_time + dwell)


def duty_schedule(case: Case) -> tuple[DutyPhase, ...]:
    """The phases of ``case.duty`` run ``case.duty_repeat`` times (empty without a duty)."""
    lead = case.screw.lead
    phases: list[DutyPhase] = []
    start = 0.0
    for _ in range(case.duty_repeat):
        for segment in case.duty:
            end = start + segment.duration
            fraction = moving_fraction(segment.speed, lead, segment.stroke, segment.dwell)
            phases.append(
                DutyPhase(start, end, segment.speed, segment.axial_load, segment.stroke, fraction)
            )
            start = end
    return tuple(phases)
