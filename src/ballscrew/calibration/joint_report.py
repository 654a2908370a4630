"""What a joint calibration shows: the shared values, each history's fit (its summary, table,
figure and section as a single calibration shows them) and the correlations."""

from __future__ import annotations

from functools import partial
from typing import TYPE_CHECKING, Any

import xarray as xr

from ballscrew.analyses.result import Figure, Section, Table
from ballscrew.analyses.result import quantity as value
from ballscrew.calibration import report

if TYPE_CHECKING:
    from ballscrew.calibration.joint import JointCalibrationResult
    from ballscrew.calibration.result import CalibrationResult

__all__ = ["fields", "figures", "fit_table", "sections", "summary"]


def _history_summary(history: CalibrationResult) -> dict[str, Any]:
    """One history's summary; its fit block counts the parameters it has in the joint fit,
    while the standard errors use the joint degrees of freedom (the top level's)."""
    out = report.summary(history, inflated_errors=False)
    fit = out["fit"]
    fit["parameters_in_this_history"] = fit.pop("parameters")
    fit.pop("degrees_of_freedom")
    return out


def summary(result: JointCalibrationResult) -> dict[str, Any]:
    """The shared values first, then each history's summary (:func:`report.summary`)."""
    from ballscrew.calibration.multi import FIT_PARAMETERS

    first = result.histories[0]
    return {
        "case": result.case_name,
        "joint": True,
        "shared": list(result.shared),
        "separate": list(result.separate),
        **{
            name: value(v, FIT_PARAMETERS[name].unit)
            for name, v in result.values.items()
            if name in result.shared
        },
        "standard_errors": {
            name: value(e, FIT_PARAMETERS[name].unit) for name, e in result.errors.items()
        },
        "rms_residual": value(result.rms_residual, first.unit),
        "prediction_rmse": [
            None if h.prediction_rmse is None else value(h.prediction_rmse, first.unit)
            for h in result.histories
        ],
        "correlations": dict(result.correlations),
        "model_evaluations": result.evaluations,
        "message": result.message,
        "degrees_of_freedom": result.degrees_of_freedom,
        "histories": [_history_summary(h) for h in result.histories],
        "options": dict(result.options),
        "note": "One wear coefficient for every history of the screw type; the separate "
        "parameters (e.g. each specimen's torque scale and offset) per history. Standard errors "
        "from the stacked Jacobian, one noise level for all histories.",
        "standard_errors_cover": JOINT_ERRORS,
    }


JOINT_ERRORS = (
    "The standard errors come from the residual scatter only: they leave out the model-form "
    "error and understate the uncertainty when the residuals are correlated (each history's "
    "lag-1 autocorrelation is in its residual diagnostics)."
)
"""What the joint fit's standard errors cover."""


def fields(result: JointCalibrationResult) -> xr.Dataset:
    """Each history's measured, model and residual (:func:`report.fit_dataset`) in one
    dataset: history j's variables and dimension end in ``_j`` (``measured_2`` over
    ``point_2``), as the histories differ in length and may differ in quantity."""
    parts = []
    for j, history in enumerate(result.histories, start=1):
        data = report.fit_dataset(history)
        part = data.rename({name: f"{name}_{j}" for name in (*data.variables, *data.dims)})
        part.attrs = {f"{key}_{j}": text for key, text in data.attrs.items()}
        parts.append(part)
    return xr.merge(parts, combine_attrs="no_conflicts")


def fit_table(result: JointCalibrationResult) -> str:
    """CSV text of every history (:func:`report.fit_table`), a ``history`` column first."""
    lines: list[str] = []
    for j, history in enumerate(result.histories):
        header, *rows = report.fit_table(history).splitlines()
        if not lines:
            lines.append("history," + header)
        lines += [f"{j + 1}," + row for row in rows]
    return "\n".join(lines) + "\n"


def figures(result: JointCalibrationResult) -> list[Figure]:
    """Each history with its fitted model."""
    out = []
    for j, history in enumerate(result.histories):
        label = report.DISPLAY[history.quantity][0]
        title = f"{result.case_name}, history {j + 1} ({history.source}): {label}"
        out.append(
            Figure(
                f"fit_{j + 1}",
                f"Measured {label} of history {j + 1} and the jointly fitted model.",
                partial(report.fit_plot, history, title),
            )
        )
    return out


def sections(result: JointCalibrationResult) -> list[Section]:
    """The shared values and correlations, then each history's section."""
    rows: list[tuple[object, ...]] = [(f"{name} (shared)", v) for name, v in result.values.items()]
    rows += [(f"standard error of {name}", e) for name, e in result.errors.items()]
    rows += [(f"correlation ({pair})", r) for pair, r in result.correlations.items()]
    rows += [
        ("RMS residual, all histories [SI]", result.rms_residual),
        ("model evaluations", result.evaluations),
    ]
    out = [
        Section(
            "Joint calibration",
            paragraphs=(
                f"{len(result.histories)} histories fitted together by nonlinear least squares "
                f"on the stacked residuals: shared {', '.join(result.shared)}; per history "
                f"{', '.join(result.separate) or 'nothing'}. Standard errors and correlations "
                "from the stacked Jacobian, cov = RSS/(n − p)·(JᵀJ)⁻¹, one noise level for all "
                "histories. " + JOINT_ERRORS,
            ),
            tables=(Table(("quantity", "value"), tuple(rows)),),
        )
    ]
    for j, history in enumerate(result.histories):
        (section,) = report.sections(history, inflated_errors=False)
        out.append(
            Section(
                f"History {j + 1}: {history.source}",
                paragraphs=(section.paragraphs[0], *report.data_notes(history)),
                tables=section.tables,
                figures=(f"fit_{j + 1}",),
            )
        )
    return out
