"""Results folder of ``ballscrew contact``: summary.json, fields.nc, pressure maps, report."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr

from ballscrew import plotting as plots
from ballscrew.analyses.ball_contact import SIDES, BallContacts, RacewayContact
from ballscrew.results.folder import results_folder, write_netcdf
from ballscrew.results.report import Section, write_report
from ballscrew.results.summary import value, write_summary

_LABEL = {"screw": "screw contact A", "nut": "nut contact B"}


def _relative(numerical: float, reference: float) -> float:
    return (numerical - reference) / reference


def contact_summary(contact: RacewayContact) -> dict[str, Any]:
    """Scalars of one contact: numerical, Hertz, Hamrock–Brewe and relative differences."""
    sol, hz, hb = contact.solution, contact.hertz, contact.hamrock_brewe
    a_num, b_num = contact.semi_axes
    numerical = {
        "peak_pressure": value(sol.peak_pressure, "Pa"),
        "semi_axis_x": value(a_num, "m"),
        "semi_axis_y": value(b_num, "m"),
        "approach": value(sol.approach, "m"),
        "contact_area": value(sol.contact_area, "m^2"),
        "load": value(sol.load, "N"),
        "iterations": sol.iterations,
        "residual": sol.residual,
        "grid": [int(contact.x.size), int(contact.y.size)],
        "cell_size": [value(sol.dx, "m"), value(sol.dy, "m")],
    }

    def closed_form(h: Any) -> dict[str, Any]:
        return {
            "peak_pressure": value(h.p0, "Pa"),
            "semi_axis_x": value(h.a, "m"),
            "semi_axis_y": value(h.b, "m"),
            "approach": value(h.approach, "m"),
            "contact_area": value(h.area, "m^2"),
        }

    difference = {
        "peak_pressure": _relative(sol.peak_pressure, hz.p0),
        "semi_axis_x": _relative(a_num, hz.a),
        "semi_axis_y": _relative(b_num, hz.b),
        "approach": _relative(sol.approach, hz.approach),
        "contact_area": _relative(sol.contact_area, hz.area),
    }
    cv = contact.curvature
    return {
        "ball_load": value(contact.load, "N"),
        "e_star": value(contact.e_star, "Pa"),
        "curvature": {
            "h_xx": value(cv.h_xx, "1/m"),
            "h_yy": value(cv.h_yy, "1/m"),
            "h_xy": value(cv.h_xy, "1/m"),
        },
        "numerical": numerical,
        "hertz": closed_form(hz),
        "hamrock_brewe": closed_form(hb),
        "relative_difference_to_hertz": difference,
    }


def contact_fields(result: BallContacts) -> xr.Dataset:
    """Pressure, gap and deformation of both contacts on their grids, with units."""
    variables: dict[str, Any] = {}
    coords: dict[str, Any] = {}
    for side in SIDES:
        c = result.contact(side)
        dims = (f"{side}_x", f"{side}_y")
        coords[dims[0]] = (dims[0], c.x, {"units": "m", "long_name": f"{side}: rolling direction"})
        coords[dims[1]] = (dims[1], c.y, {"units": "m", "long_name": f"{side}: across groove"})
        for name, data, unit, long_name in (
            ("pressure", c.solution.pressure, "Pa", "contact pressure"),
            ("gap", c.gap, "m", "initial gap h"),
            ("deformation", c.solution.displacement, "m", "elastic deformation u (both bodies)"),
        ):
            variables[f"{side}_{name}"] = (
                dims,
                np.asarray(data),
                {"units": unit, "long_name": f"{_LABEL[side]}: {long_name}"},
            )
    return xr.Dataset(
        variables,
        coords=coords,
        attrs={"case": result.case.name, "ball_load_N": result.ball_load},
    )


def _summary(result: BallContacts) -> dict[str, Any]:
    g = result.geometry
    return {
        "analysis": "contact",
        "case": result.case.name,
        "gap_model": result.case.numerics.gap_model,
        "lead_angle": value(g.lead_angle, "rad"),
        "nut_force": value(result.nut_force, "N"),
        "ball_load": value(result.ball_load, "N"),
        "contacts": {side: contact_summary(result.contact(side)) for side in SIDES},
    }


def _comparison_rows(summary: dict[str, Any]) -> list[list[object]]:
    rows = []
    for side in SIDES:
        s = summary["contacts"][side]
        for key, label, scale, unit in (
            ("peak_pressure", "peak pressure", 1e-9, "GPa"),
            ("semi_axis_x", "semi-axis along x", 1e6, "µm"),
            ("semi_axis_y", "semi-axis along y", 1e6, "µm"),
            ("approach", "approach δ", 1e6, "µm"),
            ("contact_area", "contact area", 1e12, "µm²"),
        ):
            rows.append(
                [
                    f"{_LABEL[side]}: {label} [{unit}]",
                    s["numerical"][key]["value"] * scale,
                    s["hertz"][key]["value"] * scale,
                    s["hamrock_brewe"][key]["value"] * scale,
                    f"{100 * s['relative_difference_to_hertz'][key]:+.3f} %",
                ]
            )
    return rows


def write_ball_contacts(result: BallContacts, out: str | Path) -> Path:
    """Write the ``contact`` results folder and return its path."""
    summary = _summary(result)
    case = result.case
    with results_folder(out) as folder:
        write_summary(folder / "summary.json", summary)
        write_netcdf(contact_fields(result), folder / "fields.nc")
        figures = []
        for side in SIDES:
            c = result.contact(side)
            semi = (c.hertz.a, c.hertz.b)
            figures.append(
                (
                    plots.pressure_map(
                        c.x,
                        c.y,
                        c.solution.pressure,
                        semi,
                        f"{_LABEL[side]}, Q = {c.load:.2f} N",
                        folder / f"pressure_{side}.png",
                    ),
                    f"Pressure of the {_LABEL[side]} with the Hertz ellipse (dashed).",
                )
            )
            figures.append(
                (
                    plots.pressure_profiles(
                        c.x,
                        c.y,
                        c.solution.pressure,
                        c.hertz.p0,
                        semi,
                        f"{_LABEL[side]}: centre-line profiles",
                        folder / f"profiles_{side}.png",
                    ),
                    f"Centre-line pressure of the {_LABEL[side]} against Hertz.",
                )
            )
        iterations = ", ".join(
            f"{side} {summary['contacts'][side]['numerical']['iterations']}" for side in SIDES
        )
        sections = [
            Section(
                "Operating point",
                paragraphs=[case.description] if case.description else [],
                tables=[
                    (
                        ["quantity", "value"],
                        [
                            ["preload [N]", case.operating.preload],
                            ["axial load [N]", case.operating.axial_load],
                            ["force on the loaded nut [N]", result.nut_force],
                            ["ball load Q [N]", result.ball_load],
                            ["lead angle [deg]", np.degrees(result.geometry.lead_angle)],
                            ["contact angle [deg]", np.degrees(result.geometry.contact_angle)],
                            ["gap model", case.numerics.gap_model],
                        ],
                    )
                ],
            ),
            Section(
                "Contact pressure: Polonsky–Keer on the raceway gap vs Hertz",
                paragraphs=[
                    "Numerical: Polonsky–Keer conjugate gradient with DC-FFT and Love's "
                    "rectangular-cell influence coefficients, on the "
                    f"{case.numerics.gap_model} raceway gap. Hertz: exact elliptical solution of "
                    "the quadratic gap. The difference is the non-Hertzian effect of the helical "
                    f"raceway plus discretisation. CG iterations: {iterations}.",
                ],
                tables=[
                    (
                        ["quantity", "numerical", "Hertz", "Hamrock–Brewe", "num. vs Hertz"],
                        _comparison_rows(summary),
                    )
                ],
                figures=figures,
            ),
        ]
        write_report(
            folder / "report.html",
            f"Ball–raceway contact: {case.name}",
            "ballscrew contact",
            sections,
        )
    return Path(out).resolve()
