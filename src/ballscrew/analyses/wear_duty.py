"""The wear programme of a case's duty cycle, each segment at its own operating point.

A ``[[duty]]`` segment turns the screw at ω for the moving share f of its duration t
(:func:`ballscrew.analyses.duty.moving_fraction`), i.e. N = f ω t/(2π) revolutions; a
standstill segment wears nothing. Each turning segment becomes a :class:`WearLevel` with the
contact temperature, viscosity η₀(T) and α_p(T) of :func:`ballscrew.operating_point` at its
speed and load (the supply state, ``medium.film_model`` and ``wear.film_factor``, as the case
gives it) and its own stroke. Run once (``duty_repeat = 1``) the segments are levels one after
the other; repeated, the cycle is one level whose rate per revolution is the revolution-weighted
mean of its segments' (theory manual, *Wear*, duty programmes).

A reverse segment (F_a < 0) keeps its sign in the level: the wear engine puts the larger force
on nut 2 (:func:`ballscrew.wear.setup.nut_force_pair`). Its operating point is that of |F_a|
(ASSUMED mirror symmetry, :func:`ballscrew.analyses.duty.mirrored_load`), shared with a forward
segment of the same speed, |F_a| and stroke.
"""

from __future__ import annotations

import dataclasses
import math
import warnings

from ballscrew.analyses.case_cache import CaseCache
from ballscrew.analyses.duty import mirrored_load, moving_fraction
from ballscrew.analyses.operating_point import operating_point
from ballscrew.case import Case
from ballscrew.case.wear_spec import REFERENCE_RANGE, CalibratedRange, WearSpec
from ballscrew.lubrication.lubricant_library import LUBRICANT_LIBRARY
from ballscrew.wear.programme import WearLevel

__all__ = [
    "CalibrationRangeWarning",
    "calibrated_range",
    "duty_programme",
    "range_messages",
    "warn_outside_range",
]

_RPM = math.pi / 30.0


class CalibrationRangeWarning(UserWarning):
    """A wear coefficient is used outside the speeds and loads it was calibrated at."""


def _pressure_viscosity(case: Case, temperature: float) -> float | None:
    """α_p of a named library lubricant at ``temperature``; None: the case's constant value."""
    name = case.kinematics.lubricant
    if name in LUBRICANT_LIBRARY and case.medium.viscosity is None:
        return LUBRICANT_LIBRARY[name].at(temperature).pressure_viscosity
    return None


def _segment_level(
    case: Case, speed: float, load: float, stroke: float, start: float | None
) -> WearLevel:
    point = operating_point(case, speed, load, start_temperature=start)
    eta = None if math.isnan(point.viscosity) else point.viscosity
    temperature = point.contact_temperature
    return WearLevel(
        axial_load=load,
        speed=speed,
        revolutions=1.0,
        viscosity=eta,
        pressure_viscosity=_pressure_viscosity(case, temperature) if eta is not None else None,
        stroke=stroke if stroke > 0.0 else None,
        temperature=temperature,
    )


def duty_programme(case: Case) -> tuple[WearLevel, ...]:
    """The wear levels of ``case.duty`` (see the module docstring); one operating point per
    distinct (speed, load). The operating points do not depend on ``[wear]``: a calibration's
    runs of one case (only its ``[wear]`` values change) reuse them."""
    return _programmes(case)


def _duty_programme(case: Case) -> tuple[WearLevel, ...]:
    points: dict[tuple[float, float, float], WearLevel] = {}
    levels: list[WearLevel] = []
    start = None  # each iteration starts at the previous contact temperature
    for segment in case.duty:
        fraction = moving_fraction(segment.speed, case.screw.lead, segment.stroke, segment.dwell)
        revolutions = fraction * segment.speed * segment.duration / (2.0 * math.pi)
        if revolutions <= 0.0:
            continue
        key = (segment.speed, mirrored_load(segment.axial_load), segment.stroke)
        if key not in points:
            points[key] = _segment_level(case, *key, start)
        template = points[key]
        start = template.temperature
        levels.append(
            dataclasses.replace(template, axial_load=segment.axial_load, revolutions=revolutions)
        )
    if not levels:
        return ()
    if case.duty_repeat == 1:
        return tuple(levels)
    cycle = sum(lv.revolutions for lv in levels)
    mean_speed = sum(lv.speed * lv.revolutions for lv in levels) / cycle
    return (
        WearLevel(
            axial_load=max((lv.axial_load for lv in levels), key=abs),
            speed=mean_speed,
            revolutions=case.duty_repeat * cycle,
            segments=tuple(levels),
        ),
    )


_programmes = CaseCache(_duty_programme, 16, exclude={"wear", "name", "description"})


def calibrated_range(spec: WearSpec) -> CalibratedRange | None:
    """The range the coefficient of ``spec`` holds for (the reference test's for the default)."""
    if spec.calibrated is not None:
        return spec.calibrated
    return REFERENCE_RANGE if spec.reference_calibration else None


def range_messages(spec: WearSpec, programme: tuple[WearLevel, ...]) -> list[str]:
    """One line per programme part whose speed or load lies outside the calibrated range
    (5 % margin)."""
    bounds = calibrated_range(spec)
    if bounds is None:
        return []
    out = []
    lo_s, hi_s = 0.95 * bounds.speed_min, 1.05 * bounds.speed_max
    lo_f, hi_f = 0.95 * bounds.load_min, 1.05 * bounds.load_max
    for i, level in enumerate(programme):
        for _, part in level.parts():
            if lo_s <= part.speed <= hi_s and lo_f <= abs(part.axial_load) <= hi_f:
                continue
            out.append(
                f"wear.coefficient = {spec.wear_coefficient:.4g} was calibrated at "
                f"{_span(bounds.speed_min / _RPM, bounds.speed_max / _RPM)} rpm and "
                f"{_span(bounds.load_min, bounds.load_max)} N; programme level {i + 1} runs at "
                f"{part.speed / _RPM:.4g} rpm and {part.axial_load:.4g} N: the wear prediction "
                "there is an extrapolation"
            )
    return out


def _span(low: float, high: float) -> str:
    """'low–high', or one number when the range is a single value (4 significant figures)."""
    a, b = f"{low:.4g}", f"{high:.4g}"
    return a if a == b else f"{a}–{b}"


def warn_outside_range(spec: WearSpec, programme: tuple[WearLevel, ...]) -> None:
    """Issue :func:`range_messages` as :class:`CalibrationRangeWarning` (first three)."""
    messages = range_messages(spec, programme)
    for text in messages[:3]:
        warnings.warn(text, CalibrationRangeWarning, stacklevel=3)
    if len(messages) > 3:
        warnings.warn(
            f"… and {len(messages) - 3} more levels outside the calibrated range",
            CalibrationRangeWarning,
            stacklevel=3,
        )
