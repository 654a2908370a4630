"""Joint calibration of several histories of one screw type: shared and per-history parameters.

Histories j = 1…H of one screw type on one programme (specimens of a life test, repeated
runs) share the wear-model parameters ``shared`` (one wear coefficient K: alike raceways wear
alike) and keep their own ``separate`` ones (the torque scale m_j and the offset T_0,j of each
specimen: seals and grease fill differ from screw to screw). The residuals of all histories
are stacked,

    r = [r_1(θ_s, θ_1); …; r_H(θ_s, θ_H)],   r_j = (m_j y_model,j + T_0,j − y_j)/s,

with one data scale s for every history (they must measure the same quantity, so their points
weigh alike), and minimised by the same trust-region least squares, restarts and secant
Jacobian as a single history (:mod:`ballscrew.calibration.multi`): each history's Jacobian
block comes from its own :class:`~ballscrew.calibration.multi.HistoryFit`, scattered into the
columns of the shared and its own parameters. The covariance of all parameters is
s_r² (JᵀJ)⁻¹ of the stacked Jacobian, s_r² = RSS/(n − p) over every fitted point (Seber & Wild
1989, §2.1); each history's standard errors, prediction band, RMS and held-out error
(``fit_until``) are read from it. Histories of equal cases share their model runs (one memo).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from functools import partial
from types import ModuleType
from typing import Any, ClassVar

import numpy as np

from ballscrew.analyses.result import Presented, recorded_warnings
from ballscrew.calibration import joint_report
from ballscrew.calibration.api import (
    CaseSetup,
    as_measured,
    case_setup,
    last_fitted,
    programme_range,
)
from ballscrew.calibration.multi import (
    FIT_PARAMETERS,
    HistoryFit,
    correlations,
    described,
    solve,
    start_values,
    too_few_points,
    warn_correlated,
    warn_if_systematic,
    warn_implausible_scale,
)
from ballscrew.calibration.result import CalibrationResult, WearHistory
from ballscrew.calibration.search import DIFF_STEP, SCAN_STEPS, covariance
from ballscrew.case.inputs import resolved_inputs
from ballscrew.errors import InputError
from ballscrew.units import split_list

__all__ = ["JointCalibrationResult", "calibrate_joint", "fit_joint", "joint_columns"]

_K = "wear_coefficient"


@dataclass(frozen=True)
class JointCalibrationResult(Presented):
    """Several histories fitted together.

    Attributes:
        histories: each history's fit (its values include the shared ones; its standard errors
            come from the joint covariance).
        shared: names of the shared parameters.
        separate: names of the per-history parameters.
        values: the shared parameters' values.
        errors: their standard errors.
        correlations: correlation of each pair of parameters, keyed ``"a,b"``; a per-history
            parameter is named ``name[j]`` (j from 1).
        rms_residual: RMS of (model − measured) over every fitted point [SI].
        evaluations: distinct model runs.
        message: the least-squares solver's termination message.
        degrees_of_freedom: fitted points of all histories less all fitted parameters, n − p
            (those of the standard errors and the noise estimate).
        case: the first history's case (its inputs head the report).
        warnings: warnings of the fit (one line each).
    """

    histories: tuple[CalibrationResult, ...]
    shared: tuple[str, ...]
    separate: tuple[str, ...]
    values: Mapping[str, float]
    errors: Mapping[str, float]
    correlations: Mapping[str, float]
    rms_residual: float
    evaluations: int
    message: str
    degrees_of_freedom: int
    case: Any = None
    options: Mapping[str, Any] = field(default_factory=dict)
    warnings: tuple[str, ...] = ()

    analysis: ClassVar[str] = "calibrate"
    presentation: ClassVar[ModuleType] = joint_report
    dataset_name: ClassVar[str] = "fit"

    @property
    def title(self) -> str:
        return f"Joint wear calibration: {self.case_name}"

    @property
    def case_name(self) -> str:
        """Name of the first history's case (its file's when there is no case)."""
        return self.histories[0].case_name

    @property
    def inputs(self) -> dict[str, Any]:
        return resolved_inputs(self.case) if self.case is not None else {}

    @property
    def wear_coefficient(self) -> float:
        """The shared K (or the first history's)."""
        return self.values.get(_K, self.histories[0].wear_coefficient)

    @property
    def prediction_rmse(self) -> tuple[float | None, ...]:
        """Each history's held-out RMS error (None without ``fit_until``)."""
        return tuple(h.prediction_rmse for h in self.histories)


def joint_columns(
    parts: Sequence[HistoryFit], shared: Sequence[str]
) -> tuple[list[str], list[np.ndarray]]:
    """The labels of the jointly fitted parameters (a shared one once, every other one per
    history: ``torque_offset[2]``) and each part's columns among them; p is their number.

    A part that names a parameter twice is refused (its columns would count it twice)."""
    names: list[str] = []
    index: list[np.ndarray] = []
    for j, part in enumerate(parts, start=1):
        if len(set(part.names)) != len(part.names):
            raise InputError("fit", ", ".join(part.names), "each parameter once")
        labels = [name if name in shared else f"{name}[{j}]" for name in part.names]
        names += [label for label in labels if label not in names]
        index.append(np.array([names.index(label) for label in labels]))
    return names, index


def fit_joint(
    parts: Sequence[HistoryFit],
    shared: Sequence[str],
    *,
    max_evaluations: int = 200,
    scan_steps: int = SCAN_STEPS,
    refine_steps: int = 6,
    label: str = "joint calibration (least squares)",
) -> JointCalibrationResult:
    """Fit the histories of ``parts`` together, the parameters ``shared`` common to all.

    Every part must fit the shared parameters; its other fitted ones are its own. The start
    is each part's own start (:func:`~ballscrew.calibration.multi.start_values`) with the
    shared model parameters at their geometric mean, ln K bounded to the union of the parts'
    brackets.
    """
    shared = list(dict.fromkeys(shared))
    source = " + ".join(p.data.source for p in parts)
    for part in parts:
        missing = [n for n in shared if n not in part.names]
        if missing:
            raise InputError("shared", ", ".join(missing), "parameters every history fits")
    names, index = joint_columns(parts, shared)
    n, p = sum(part.n_fit for part in parts), len(names)
    if n <= p:  # before the start-value scans, each dozens of model runs
        until = next((part.fit_until for part in parts if part.fit_until is not None), None)
        raise too_few_points(source, n, p, until)
    scale = max(part.scale for part in parts)
    for part in parts:  # one scale: the points of every history weigh alike
        part.scale = part.jacobian.scale = scale
    starts = [start_values(part, scan_steps, refine_steps) for part in parts]
    common = {
        n: math.exp(float(np.mean([math.log(s[0][n]) for s in starts])))
        for n in shared
        if FIT_PARAMETERS[n].kind == "model"
    }
    brackets = [s[2] for s in starts if s[2] is not None]
    bracket = (min(b[0] for b in brackets), max(b[1] for b in brackets)) if brackets else None
    x0, lower, upper = np.zeros(p), np.zeros(p), np.zeros(p)
    seen = np.zeros(p, dtype=bool)  # a shared parameter starts where the first part puts it
    for part, i, (base, _, _) in zip(parts, index, starts, strict=True):
        part.base = {**base, **common}
        x, lo, hi = (np.asarray(v, dtype=float) for v in part.begin(bracket))
        new = ~seen[i]
        x0[i[new]], lower[i[new]], upper[i[new]] = x[new], lo[new], hi[new]
        seen[i] = True
    rows = np.cumsum([0] + [part.n_fit for part in parts])

    def residuals(x: np.ndarray) -> np.ndarray:
        return np.concatenate([part.residuals(x[i]) for part, i in zip(parts, index, strict=True)])

    def stacked(block: Callable[[HistoryFit], Callable[[np.ndarray], np.ndarray]]):
        def jacobian(x: np.ndarray) -> np.ndarray:
            out = np.zeros((n, p))
            for j, (part, i) in enumerate(zip(parts, index, strict=True)):
                np.add.at(out, (slice(rows[j], rows[j + 1]), i), block(part)(x[i]))
            return out

        return jacobian

    difference = stacked(lambda part: part.jacobian.difference)
    x, message = solve(
        residuals,
        stacked(lambda part: part.jacobian),
        difference,
        x0,
        (lower, upper),
        n,
        max_evaluations,
        label,
        lambda: min(part.runs.best_rms for part in parts),
        source,
    )
    for part, i in zip(parts, index, strict=True):
        part.check_bracket(x[i], lower[i], upper[i])
    r = residuals(x)
    what = " and ".join(described(name) for name in names) + " together"
    central = stacked(lambda part: partial(part.jacobian.difference, central=True))
    cov = covariance(central(x), r, n, p, source, what)
    warn_correlated(cov, names, source)
    noise = scale * math.sqrt(float(r @ r) / (n - p))
    histories = tuple(
        part.result(x[i], cov[np.ix_(i, i)], noise, message, s[1])
        for part, i, s in zip(parts, index, starts, strict=True)
    )
    first = histories[0]
    return JointCalibrationResult(
        histories=histories,
        shared=tuple(shared),
        separate=tuple(n for n in parts[0].names if n not in shared),
        values={n: first.values[n] for n in shared},
        errors={n: first.errors[n] for n in shared},
        correlations=correlations(cov, names),
        rms_residual=scale * math.sqrt(float(r @ r) / n),
        evaluations=sum(part.runs.evaluations for part in parts),
        message=message,
        degrees_of_freedom=n - p,
    )


def calibrate_joint(
    cases: Any,
    measured: Sequence[Any],
    shared: Sequence[str] | str = (_K,),
    separate: Sequence[str] | str | None = None,
    fit_until: float | Sequence[float | None] | None = None,
    *,
    model: Callable[[Any], WearHistory] | None = None,
    **options: Any,
) -> JointCalibrationResult:
    """Fit one wear model to several measured histories of the same screw.

    Args:
        cases: one case for every history, or a sequence of cases (one per history).
        measured: the histories (each a CSV path, DataFrame, array or
            :class:`MeasuredHistory`), all of one quantity.
        shared: parameters common to every history (default: the wear coefficient).
        separate: parameters of each history on its own (default for friction-torque data:
            ``torque_offset``, the torque scale then the case's ``wear.torque_scale``: with both
            per history, K is not determined while the preload loss is small; otherwise none).
        fit_until: fit each history up to these revolutions and report its held-out error on
            the rest (one number for all, or one per history; None: fit all points).
        model: the wear model, case → history (default :func:`ballscrew.wear_life`).
        options: ``max_evaluations``, ``scan_steps``, ``refine_steps`` of :func:`fit_joint`,
            ``diff_step`` of the Jacobian.

    Returns:
        :class:`JointCalibrationResult`; ``histories[j]`` is history j's
        :class:`CalibrationResult` (values, standard errors, ``rms_residual``,
        ``prediction_rmse``).
    """
    data = [as_measured(m) for m in measured]
    if len(data) < 2:
        raise InputError("--measured", len(data), "two or more histories for a joint fit")
    quantities = sorted({d.quantity for d in data})
    if len(quantities) > 1:
        raise InputError("--measured", ", ".join(quantities), "histories of one quantity")
    shared_names = split_list(shared)
    if separate is None:
        separate_names = ["torque_offset"] if quantities[0] == "friction_torque" else []
    else:
        separate_names = split_list(separate)
    both = set(shared_names) & set(separate_names)
    if both:
        raise InputError("--separate", ", ".join(sorted(both)), "names not also shared")
    case_list = list(cases) if isinstance(cases, list | tuple) else [cases] * len(data)
    until = list(fit_until) if isinstance(fit_until, list | tuple) else [fit_until] * len(data)
    if len(case_list) != len(data) or len(until) != len(data):
        raise InputError(
            "cases" if len(case_list) != len(data) else "fit_until",
            len(case_list) if len(case_list) != len(data) else len(until),
            f"one per history ({len(data)})",
        )
    names = shared_names + separate_names
    setups = [case_setup(c, d, names, model) for c, d in zip(case_list, data, strict=True)]
    diff_step = options.pop("diff_step", DIFF_STEP)
    max_evaluations = options.get("max_evaluations", 200)
    runs = _SharedRuns(setups)
    parts = [
        HistoryFit(
            runs.simulate(j),
            d,
            names,
            s.start,
            torque_scale=s.torque_scale,
            torque_offset=s.torque_offset,
            fit_until=u,
            max_evaluations=max_evaluations,
            diff_step=diff_step,
            label="joint calibration (least squares)",
        )
        for j, (s, d, u) in enumerate(zip(setups, data, until, strict=True))
    ]
    result = fit_joint(parts, shared_names, **options)
    with recorded_warnings() as messages:
        for group in dict.fromkeys(runs.group):  # each distinct case ran (and warned) once
            setups[group].reissue(result.histories[group].values)
        for history in result.histories:
            warn_if_systematic(history)
            warn_implausible_scale(history)
    histories = tuple(
        replace(h, case=c, calibrated_range=programme_range(s.case, last_fitted(d, u)))
        for h, c, s, d, u in zip(result.histories, case_list, setups, data, until, strict=True)
    )
    return replace(
        result,
        histories=histories,
        case=case_list[0],
        warnings=tuple(messages),
        evaluations=len(runs.memo),
    )


class _SharedRuns:
    """One memo of model runs for the histories whose cases (and run overrides) are equal."""

    def __init__(self, setups: Sequence[CaseSetup]) -> None:
        self.setups = setups
        self.group = [
            next(i for i, o in enumerate(setups) if o.case == s.case and o.base == s.base)
            for s in setups
        ]
        self.memo: dict[tuple[int, tuple[tuple[str, float], ...]], WearHistory] = {}

    def simulate(self, j: int) -> Callable[[Mapping[str, float]], WearHistory]:
        group = self.group[j]

        def run(values: Mapping[str, float]) -> WearHistory:
            key = (group, tuple(sorted(values.items())))
            if key not in self.memo:
                self.memo[key] = self.setups[group].simulate(values)
            return self.memo[key]

        return run
