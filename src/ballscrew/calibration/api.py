"""``ballscrew.calibrate(case, measured, fit=…, fit_until=…)``: the wear model of a case fitted
to a test bench's history (method: :mod:`ballscrew.calibration.multi`)."""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np

from ballscrew.analyses.result import recorded_warnings
from ballscrew.budget import BudgetError
from ballscrew.calibration.measured import (
    TABLES,
    MeasuredHistory,
    measured_history,
    read_table,
)
from ballscrew.calibration.measured import read_measured as read_file
from ballscrew.calibration.multi import (
    FIT_PARAMETERS,
    fit_parameters,
    warn_if_systematic,
    warn_implausible_scale,
)
from ballscrew.calibration.result import CalibrationError, CalibrationResult, WearHistory
from ballscrew.errors import InputError
from ballscrew.thread_warnings import record_warnings
from ballscrew.units import split_list

__all__ = [
    "DEFAULT_FIT",
    "CaseSetup",
    "as_measured",
    "calibrate",
    "calibrated_case",
    "case_setup",
    "last_fitted",
    "programme_range",
    "schedule_duty",
    "schedule_programme",
]

DEFAULT_FIT: tuple[str, ...] = ("wear_coefficient", "torque_scale")
"""Fitted by default; the torque scale only for friction-torque data."""


def as_measured(measured: Any, quantity: str = "friction_torque") -> MeasuredHistory:
    """A :class:`MeasuredHistory` from a CSV path, a pandas DataFrame or a dict of columns (read
    with the CSV header rules: :func:`~ballscrew.calibration.measured.read_table`) or an (n, 2)
    array of revolutions and ``quantity`` (SI)."""
    if isinstance(measured, MeasuredHistory):
        return measured
    if isinstance(measured, str | Path):
        return read_file(measured)
    if isinstance(measured, Mapping) or hasattr(measured, "columns"):
        return read_table(measured)
    try:
        array = np.asarray(measured, dtype=float)
    except (TypeError, ValueError):
        raise InputError("measured", type(measured).__name__, TABLES) from None
    if array.ndim != 2 or array.shape[1] != 2:
        raise InputError("measured", f"array of shape {array.shape}", "an (n, 2) array")
    return measured_history(array[:, 0], array[:, 1], quantity, "array")


def programme_range(case: Any, seen: float | None = None) -> dict[str, float] | None:
    """Speeds and loads of the case's wear programme (or duty), as the calibrated range.

    ``seen``: the revolutions of the last fitted measurement; only the levels that start before
    it were seen by the fit (None: every level)."""
    from ballscrew.analyses.wear import wear_options

    try:
        programme = wear_options(case).programme
    except (AttributeError, TypeError):  # a stand-in case without a programme
        return None
    starts = np.cumsum([0.0] + [lv.revolutions for lv in programme[:-1]])
    levels = [
        part
        for start, lv in zip(starts, programme, strict=True)
        if seen is None or start < seen or start == 0.0
        for _, part in lv.parts()
    ]
    speeds = [lv.speed for lv in levels]
    loads = [abs(lv.axial_load) for lv in levels]  # a reverse duty segment: its |F_a|
    return {
        "speed_min": min(speeds),
        "speed_max": max(speeds),
        "load_min": min(loads),
        "load_max": max(loads),
    }


def calibrated_case(result: CalibrationResult) -> Any:
    """The calibrated case: the case given to the fit with the fitted values in its ``[wear]``
    section and the calibrated speed/load range in ``[wear.calibrated]`` (a programme outside
    it then warns); all else is the user's own, ``[operating]``, ``[[duty]]`` and
    ``wear.programme`` included. A test-bench schedule, which the fit ran as ``[[duty]]``
    segments at their own operating points, is the test and not the screw's use: it stays out
    of the case (thermal and the design check run on the user's duty) and is kept only as the
    calibrated range."""
    from ballscrew.case import with_overrides

    overrides: dict[str, Any] = {FIT_PARAMETERS[n].key: v for n, v in result.values.items()}
    if {"torque_scale", "torque_offset"} & set(result.values):
        overrides["wear.initial_torque"] = None
        overrides["wear.torque_scale"] = result.torque_scale
    if result.calibrated_range is not None:
        overrides["wear.calibrated"] = dict(result.calibrated_range)
    return with_overrides(result.case, overrides)


def calibrate(
    case: Any,
    measured: Any,
    fit: Sequence[str] | str = DEFAULT_FIT,
    fit_until: float | None = None,
    *,
    model: Callable[[Any], WearHistory] | None = None,
    fit_torque_scale: bool | None = None,
    **options: Any,
) -> CalibrationResult:
    """Fit the wear model of ``case`` to a measured history.

    Args:
        case: the case of the tested screw and its programme (``[wear]`` or ``[[duty]]``).
        measured: CSV path, DataFrame or dict of columns (CSV header rules), (n, 2) array or
            :class:`MeasuredHistory`; a schedule
            (speed and axial-load columns) replaces the case's programme.
        fit: names from ``wear_coefficient``, ``torque_scale``, ``torque_offset``,
            ``film_factor``, ``running_in_depth``, ``preload`` (a comma-separated string also
            works; the preload with the torque scale warns: only m·F_p is determined). The
            default fits K and, for friction-torque data, the torque scale. ``torque_offset``
            is T_0 of T = m K_T F_p L/(2π) + T_0 (case default ``wear.torque_offset``, 0).
        fit_until: fit the points up to these revolutions and report ``prediction_rmse`` on the
            rest (None: fit all points).
        model: the wear model, case → history (default :func:`ballscrew.wear_life`).
        fit_torque_scale: former switch; True/False fit K with/without the torque scale.
        options: go to :func:`ballscrew.calibration.multi.fit_parameters`.

    Returns:
        :class:`CalibrationResult`: ``values`` and ``errors`` of the fitted parameters (also
        ``wear_coefficient``, ``standard_error``, ``torque_scale``, ``torque_scale_error``),
        ``rms_residual``, ``prediction_rmse``, ``prediction_sigma``, ``diagnostics``,
        ``calibrated_range`` and ``warnings`` (systematic residuals; the model's own).
    """

    data = as_measured(measured)
    names = _names(fit, fit_torque_scale, data)
    setup = case_setup(case, data, names, model)
    result = fit_parameters(
        setup.simulate,
        data,
        names,
        setup.start,
        torque_scale=setup.torque_scale,
        torque_offset=setup.torque_offset,
        fit_until=fit_until,
        **options,
    )
    with recorded_warnings() as messages:
        setup.reissue(result.values)
        warn_if_systematic(result)
        warn_implausible_scale(result)
    return replace(
        result,
        case=case,
        warnings=tuple(messages),
        calibrated_range=programme_range(setup.case, last_fitted(data, fit_until)),
    )


def last_fitted(data: MeasuredHistory, fit_until: float | None) -> float:
    """Revolutions of the last measurement the fit sees (all, or those up to ``fit_until``)."""
    revolutions = data.revolutions
    if fit_until is not None:
        revolutions = revolutions[revolutions <= fit_until]
    return float(revolutions.max())


@dataclass
class CaseSetup:
    """The wear model of one case as the fitters see it: ``simulate({name: value})`` runs the
    case with those values (its torque without T_0, which the fit adds), the model
    parameters' start, the torque scale and offset the fit starts from, and the warnings of
    each run."""

    case: Any
    base: dict[str, Any]
    """Case overrides of every run."""
    start: dict[str, float]
    torque_scale: float
    torque_offset: float
    model: Callable[[Any], WearHistory]
    source: str
    quantity: str
    warned: dict[tuple[tuple[str, float], ...], list[warnings.WarningMessage]] = field(
        default_factory=dict
    )
    ignored: tuple[type[Warning], ...] = ()
    """Warning categories of the runs that do not concern the fit (left out of ``warned``)."""

    def simulate(self, values: Mapping[str, float]) -> WearHistory:
        """One model run of the case at ``values``; a BudgetError becomes a CalibrationError."""
        from ballscrew.case import with_overrides

        overrides = {**self.base, **{FIT_PARAMETERS[n].key: v for n, v in values.items()}}
        with record_warnings() as seen:
            try:
                history = self.model(with_overrides(self.case, overrides))
            except BudgetError as exc:
                trial = ", ".join(
                    ("K" if n == "wear_coefficient" else n) + f" = {v:.3g}"
                    for n, v in values.items()
                )
                raise CalibrationError(
                    f"{self.source}: the wear model cannot run at the trial {trial} ({exc}); "
                    f"the measured {self.quantity} is out of the model's reach (check the data)"
                ) from None
        kept = [w for w in seen if not issubclass(w.category, self.ignored)]
        self.warned[tuple(sorted(values.items()))] = kept
        return history

    def reissue(self, fitted: Mapping[str, float]) -> None:
        """Warn again the warnings of the run nearest the fitted values."""
        if not self.warned:
            return

        def distance(key: tuple[tuple[str, float], ...]) -> float:
            return sum(abs(math.log(v / fitted.get(k, v))) for k, v in key)

        for w in self.warned[min(self.warned, key=distance)]:
            warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)


def case_setup(
    case: Any,
    data: MeasuredHistory,
    names: Sequence[str],
    model: Callable[[Any], WearHistory] | None = None,
) -> CaseSetup:
    """The :class:`CaseSetup` of ``case`` for fitting ``names`` to ``data`` (a schedule in the
    data replaces the case's programme; ``model`` defaults to :func:`ballscrew.wear_life`)."""
    from ballscrew.case import with_overrides

    if data.schedule is not None:
        if getattr(case, "duty", None):
            raise InputError(
                f"{data.source}: speed, axial_load", "a schedule", "a case without [[duty]]"
            )
        from ballscrew.case.wear_spec import WearSpec

        default = [level.model_dump() for level in WearSpec().programme]
        duty = schedule_duty(data)
        case = with_overrides(case, {"wear.programme": default, "duty": duty, "duty_repeat": 1})
    if model is None:
        from ballscrew.analyses.wear import wear_life

        model = wear_life
    wear = getattr(case, "wear", None)
    start = {"wear_coefficient": getattr(wear, "wear_coefficient", None) or 1.0e-4}
    if "film_factor" in names:
        start["film_factor"] = getattr(wear, "film_factor", 1.0)
    if "running_in_depth" in names:
        running = getattr(wear, "running_in", None)
        if running is None:
            raise InputError("--fit", "running_in_depth", "a case with a [wear.running_in] section")
        start["running_in_depth"] = running.depth
    if "preload" in names:
        least = FIT_PARAMETERS["preload"].lower  # the fit works on ln F_p: it starts above 0
        if not case.operating.preload >= least:
            raise InputError("--fit", "preload", f"a case with operating.preload ≥ {least:g} N")
        start["preload"] = case.operating.preload
    scale0 = getattr(wear, "torque_scale", None) or 1.0
    offset0 = float(getattr(wear, "torque_offset", 0.0) or 0.0)
    initial_torque = getattr(wear, "initial_torque", None)
    # the model's torque without T_0: the fit adds it (and the initial torque's share of it)
    base: dict[str, Any] = {"wear.torque_offset": 0.0} if wear is not None else {}
    if initial_torque is not None:
        if not initial_torque > offset0:  # the wear run's own check, before the scale from it
            raise InputError(
                "wear.initial_torque",
                initial_torque,
                f"more than wear.torque_offset = {offset0:g} N·m",
            )
        base["wear.initial_torque"] = None
        if "torque_scale" not in names:
            scale0 = _initial_torque_scale(case, float(initial_torque) - offset0)
            base["wear.torque_scale"] = scale0
    ignored: tuple[type[Warning], ...] = ()
    if data.schedule is not None:  # the bench's levels, not the case's [operating] or [[duty]]
        from ballscrew.analyses.wear import OperatingOutsideWarning

        ignored = (OperatingOutsideWarning,)
    return CaseSetup(
        case,
        base,
        start,
        float(scale0),
        offset0,
        model,
        data.source,
        data.quantity,
        ignored=ignored,
    )


def schedule_programme(data: MeasuredHistory) -> list[dict[str, float]]:
    """Levels of a measured schedule (axial load, speed, revolutions[, stroke]): the interval up
    to each row at that row's speed, load (and stroke), equal neighbours merged; standstill
    intervals dropped."""
    assert data.schedule is not None
    starts = np.r_[0.0, data.revolutions[:-1]]
    names = ("speed", "axial_load", "stroke")[: data.schedule.shape[1]]
    levels: list[dict[str, float]] = []
    for start, end, row in zip(starts, data.revolutions, data.schedule, strict=True):
        plan = {name: float(v) for name, v in zip(names, row, strict=True)}
        if end <= start or plan["speed"] <= 0.0:
            continue
        if levels and all(levels[-1][name] == plan[name] for name in names):
            levels[-1]["revolutions"] += float(end - start)
        else:
            levels.append({**plan, "revolutions": float(end - start)})
    return levels


def schedule_duty(data: MeasuredHistory) -> list[dict[str, float]]:
    """``[[duty]]`` segments of a measured schedule, so that each level runs at its own
    operating point (contact temperature, viscosity, film): the levels of
    :func:`schedule_programme` as turning segments of duration 2πN/ω, no dwell, the schedule's
    stroke or the ``[wear]`` one (a segment longer than the largest duty time is split)."""
    from ballscrew.case.duty_spec import MAX_DUTY_TIME

    segments: list[dict[str, float]] = []
    for level in schedule_programme(data):
        revolutions = level.pop("revolutions")
        duration = 2.0 * math.pi * revolutions / level["speed"]
        pieces = math.ceil(duration / MAX_DUTY_TIME)
        segments += [{**level, "duration": duration / pieces} for _ in range(pieces)]
    return segments


def _names(
    fit: Sequence[str] | str, fit_torque_scale: bool | None, data: MeasuredHistory
) -> list[str]:
    if fit_torque_scale is not None:
        return ["wear_coefficient"] + (["torque_scale"] if fit_torque_scale else [])
    names = split_list(fit)
    if tuple(names) == DEFAULT_FIT and data.quantity != "friction_torque":
        names = ["wear_coefficient"]
    return names


def _initial_torque_scale(case: Any, initial_torque: float) -> float:
    """Effective K_T factor of a case whose drag torque is rescaled to T(0) (E9.1, E9.3)."""
    from ballscrew.loads import preload_drag_torque

    lead, diameter = case.screw.lead, case.screw.pitch_diameter
    lead_angle = math.atan2(lead, math.pi * diameter)  # (G2)
    return initial_torque / preload_drag_torque(case.operating.preload, lead, lead_angle)
