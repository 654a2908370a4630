"""Results folder of ``ballscrew thermal``: summary.json, fields.nc, plots and report.html."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.tri import Triangulation

from ballscrew.analyses.thermal import ThermalField
from ballscrew.plotting import plain
from ballscrew.results.folder import results_folder, write_netcdf
from ballscrew.results.report import Section, write_report
from ballscrew.results.summary import value, write_summary

CELSIUS = 273.15


def _c(kelvin: float) -> float:
    return kelvin - CELSIUS


def thermal_summary(result: ThermalField) -> dict[str, Any]:
    """The scalars of a thermal analysis, each with its unit."""
    sol = result.solution
    problem = result.problem
    grid = sol.discretisation.grid
    t = sol.transient
    sensors = result.sensors
    summary: dict[str, Any] = {
        "analysis": "thermal",
        "case": result.case_name,
        "model": result.model,
        "unknowns": result.unknowns,
        "ambient_temperature": value(result.ambient_temperature, "K"),
        "steady": {
            "max_temperature": value(result.max_temperature, "K"),
            "max_temperature_rise": value(result.max_temperature_rise, "K"),
            "elongation": value(result.elongation, "m"),
            "elongation_thermoelastic": (
                None
                if result.elongation_thermoelastic is None
                else value(result.elongation_thermoelastic, "m")
            ),
            "sensors": {s.name: value(s.steady, "K") for s in sensors},
        },
        "sensors": [
            {
                "name": s.name,
                "body": s.body,
                "r": value(s.r, "m"),
                "z": value(s.z, "m"),
                "steady": value(s.steady, "K"),
                "final": value(s.final, "K"),
                "time_to_95": value(s.time_to_95, "s"),
            }
            for s in sensors
        ],
        "heat_balance": {
            "heat_input": value(result.heat_input, "W"),
            "convective_loss": value(sol.heat_loss, "W"),
            "relative_error": result.heat_balance_error,
            "transient_relative_error": (
                None if t is None else result.transient_heat_balance_error
            ),
        },
        "heat_sources": [
            {
                "name": s.name,
                "method": s.method,
                "torque": value(s.torque, "N*m"),
                "heat": value(s.heat, "W"),
                "into_screw": value(s.into_screw, "W"),
                "into_nut": value(s.into_nut, "W"),
            }
            for s in result.sources
        ],
        "convection": {
            c.surface: {"value": value(c.value, "W/(m^2*K)"), "correlation": c.correlation}
            for c in result.convection
        },
        "contact": [
            {
                "nut": i.name,
                "micro_resistance": value(i.micro_resistance, "K/W"),
                "constriction_resistance": value(i.constriction_resistance, "K/W"),
                "resistance": value(i.resistance, "K/W"),
                "resistance_per_area_tcr": value(i.resistance_per_area, "m^2*K/W"),
                "bore_area": value(i.bore_area, "m^2"),
                "conductance_per_area": value(i.conductance_per_area, "W/(m^2*K)"),
            }
            for i in result.interfaces
        ],
        "geometry": {
            "shaft_length": value(problem.shaft_length, "m"),
            "shaft_diameter": value(2 * problem.shaft_radius, "m"),
            "nut_position": value(problem.ring_centre, "m"),
            "parts": [
                {
                    "name": p.name,
                    "length": value(p.length, "m"),
                    "modelled_length": value(cells * grid.dz, "m"),
                    "outer_diameter": value(2 * p.outer_radius, "m"),
                }
                for p, cells in zip(problem.parts, grid.part_cells, strict=True)
            ],
            "stroke": value(problem.stroke, "m"),
            "modelled_stroke": value(2 * grid.half_stroke_cells * grid.dz, "m"),
            "feed_speed": value(result.feed_speed, "m/s"),
            "stroke_mode": result.stroke_mode,
        },
        "timing": {k: value(v, "s") for k, v in sol.seconds.items()}
        | {"total": value(result.seconds, "s")},
    }
    if t is not None:
        summary["transient"] = {
            "duration": value(t.time[-1], "s"),
            "time_step": value(t.time[1] - t.time[0], "s"),
            "final_max_temperature": value(result.ambient_temperature + t.max_rise[-1], "K"),
            "final_elongation": value(t.elongation[-1], "m"),
            "fraction_of_steady_rise": float(t.max_rise[-1] / result.max_temperature_rise)
            if result.max_temperature_rise > 0
            else None,
            "time_to_95": value(result.time_to_95, "s"),
            "elongation_time_to_95": value(result.elongation_time_to_95, "s"),
            "sensors": {s.name: value(s.final, "K") for s in sensors},
        }
    return summary


def _sensor_markers(ax: plt.Axes, result: ThermalField, z_scale: float = 1e3) -> None:
    for k, s in enumerate(result.problem.sensors):
        ax.plot(s.z * z_scale, s.r * 1e3, "o", ms=6, mfc="none", mec="cyan", mew=1.5)
        ax.annotate(
            plain(s.name),
            (s.z * z_scale, s.r * 1e3),
            textcoords="offset points",
            xytext=(4, -10 - 8 * (k % 2)),
            fontsize=7,
            color="cyan",
        )


def temperature_map(result: ThermalField, path: Path) -> Path:
    """Steady temperature over the (z, r) section (whole screw and a zoom on the nut)."""
    sol = result.solution
    disc = sol.discretisation
    problem = result.problem
    ring_lo = problem.ring_centre - 0.5 * (problem.ring_length + problem.stroke)
    ring_hi = problem.ring_centre + 0.5 * (problem.ring_length + problem.stroke)
    pad = 1.5 * problem.ring_length
    fig, axes = plt.subplots(2, 1, figsize=(8.0, 5.6), layout="constrained")
    if disc.model == "axisymmetric":
        am = disc.extra["mesh"]
        nodal = disc.extra["basis"].nodal_dofs[0]
        temp = _c(result.ambient_temperature + sol.steady[nodal])
        t4 = am.mesh.t
        tri = Triangulation(
            am.mesh.p[1] * 1e3, am.mesh.p[0] * 1e3, np.hstack([t4[[0, 1, 2]], t4[[0, 2, 3]]]).T
        )
        levels = np.linspace(temp.min(), temp.max() + 1e-9, 30)
        for ax in axes:
            image = ax.tricontourf(tri, temp, levels=levels, cmap="inferno")
        fig.colorbar(image, ax=axes, label="steady temperature [°C]")
    else:
        ex = disc.extra
        amb = result.ambient_temperature
        zc = disc.axis_z * 1e3
        for ax in axes:
            ax.plot(zc, _c(amb + sol.steady[ex["shaft_mean"]]), label="screw mean")
            ax.plot(zc, _c(amb + sol.steady[ex["shaft_surface"]]), label="screw surface")
            rz = ex["ring_z"] * 1e3
            ax.plot(rz, _c(amb + sol.steady[ex["ring_bore"]]), label="nut bore")
            ax.plot(rz, _c(amb + sol.steady[ex["ring_outer"]]), label="nut outer surface")
            for s, v in zip(problem.sensors, sol.sensors, strict=True):
                ax.plot(s.z * 1e3, _c(amb + v), "o", mfc="none", mec="black")
                ax.annotate(
                    plain(s.name),
                    (s.z * 1e3, _c(amb + v)),
                    textcoords="offset points",
                    xytext=(4, 4),
                    fontsize=7,
                )
            ax.set_ylabel("steady temperature [°C]")
            ax.grid(alpha=0.3)
        axes[0].legend(fontsize=7)
    for ax in axes:
        ax.set_xlabel("z [mm]")
        if disc.model == "axisymmetric":
            ax.set_ylabel("r [mm]")
            _sensor_markers(ax, result)
    axes[1].set_xlim((ring_lo - pad) * 1e3, (ring_hi + pad) * 1e3)
    axes[0].set_title(plain(f"{result.case_name}: steady temperature ({result.model} model)"))
    axes[1].set_title("around the nut (sensors circled)", fontsize=9)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def temperature_rise(result: ThermalField, path: Path) -> Path:
    """Temperature rise over time: the maximum and every sensor, steady values dashed."""
    t = result.solution.transient
    assert t is not None
    fig, ax = plt.subplots(figsize=(6.8, 4.0), layout="constrained")
    minutes = t.time / 60.0
    line = ax.plot(minutes, t.max_rise, "k-", lw=2, label="maximum")[0]
    ax.axhline(result.max_temperature_rise, color=line.get_color(), ls="--", lw=0.8)
    steady = result.solution.sensors
    for k, s in enumerate(result.problem.sensors):
        line = ax.plot(minutes, t.sensors[:, k], label=plain(f"sensor {s.name} ({s.body})"))[0]
        ax.axhline(steady[k], color=line.get_color(), ls="--", lw=0.8)
    t95 = result.time_to_95
    if math.isfinite(t95):
        ax.axvline(t95 / 60.0, color="grey", ls=":", lw=1, label="95 % of steady maximum")
    ax.set_xlabel("time [min]")
    ax.set_ylabel("temperature rise [K]")
    ax.set_title("Temperature rise from ambient (dashed: steady state)", fontsize=10)
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def elongation_plot(result: ThermalField, path: Path) -> Path:
    """Thermal elongation over time and the steady axial profile of the screw."""
    sol = result.solution
    t = sol.transient
    fig, axes = plt.subplots(1, 2, figsize=(9.0, 3.6), layout="constrained")
    if t is not None:
        axes[0].plot(t.time / 60.0, t.elongation * 1e6, "b-")
    axes[0].axhline(result.elongation * 1e6, color="b", ls="--", lw=0.8, label="steady")
    axes[0].set_xlabel("time [min]")
    axes[0].set_ylabel("elongation ΔL = α∫ΔT dz [µm]")
    axes[0].legend(fontsize=7)
    axes[0].grid(alpha=0.3)
    z = sol.discretisation.axis_z * 1e3
    axes[1].plot(z, sol.axis, "r-")
    axes[1].set_xlabel("z [mm]")
    axes[1].set_ylabel("steady screw mean rise [K]", color="r")
    axes[1].grid(alpha=0.3)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def _fmt_s(seconds: float) -> str:
    return "not reached" if not math.isfinite(seconds) else f"{seconds / 60:.1f} min"


def _sections(result: ThermalField, summary: dict[str, Any], figures: list) -> list[Section]:
    problem = result.problem
    sol = result.solution
    parts = summary["geometry"]["parts"]
    geometry_rows = [
        ["shaft length [mm]", problem.shaft_length * 1e3],
        ["shaft diameter [mm]", 2e3 * problem.shaft_radius],
        ["nut assembly centre z [mm]", problem.ring_centre * 1e3],
        *[
            [
                f"{p['name']}: length / modelled / OD [mm]",
                f"{p['length']['value'] * 1e3:.4g} / {p['modelled_length']['value'] * 1e3:.4g} / "
                f"{p['outer_diameter']['value'] * 1e3:.4g}",
            ]
            for p in parts
        ],
        ["stroke [mm] (mode)", f"{problem.stroke * 1e3:.4g} ({result.stroke_mode})"],
        ["feed speed [m/s]", result.feed_speed],
        ["model, unknowns", f"{result.model}, {result.unknowns}"],
    ]
    sources = [
        [s.name, s.method, s.torque, s.heat, s.into_screw, s.into_nut] for s in result.sources
    ]
    conv = [[c.surface, c.value, c.correlation] for c in result.convection]
    contact = [
        [
            i.name,
            i.micro_resistance,
            i.constriction_resistance,
            i.resistance,
            i.resistance_per_area,
            i.conductance_per_area,
        ]
        for i in result.interfaces
    ]
    steady = [
        ["max temperature [°C]", _c(result.max_temperature)],
        ["max temperature rise [K]", result.max_temperature_rise],
        ["elongation α∫ΔT dz [µm]", result.elongation * 1e6],
    ]
    if result.elongation_thermoelastic is not None:
        steady.append(
            ["thermo-elastic end displacement [µm]", result.elongation_thermoelastic * 1e6]
        )
    t = sol.transient
    if t is not None:
        steady += [
            [
                f"max temperature after {t.time[-1] / 60:.0f} min [°C]",
                _c(result.ambient_temperature + t.max_rise[-1]),
            ],
            [f"elongation after {t.time[-1] / 60:.0f} min [µm]", t.elongation[-1] * 1e6],
            ["time to 95 % of the steady maximum rise", _fmt_s(result.time_to_95)],
            ["time to 95 % of the steady elongation", _fmt_s(result.elongation_time_to_95)],
        ]
    sensor_rows = [
        [s.name, s.body, s.r * 1e3, s.z * 1e3, _c(s.steady), _c(s.final), _fmt_s(s.time_to_95)]
        for s in result.sensors
    ]
    balance = [
        ["heat input [W]", result.heat_input],
        ["steady convective loss [W]", sol.heat_loss],
        ["steady relative error", f"{result.heat_balance_error:.2e}"],
    ]
    if t is not None:
        balance += [
            ["transient: heat in [J]", t.heat_in],
            ["transient: stored + convected [J]", t.stored + t.convected],
            ["transient relative error", f"{result.transient_heat_balance_error:.2e}"],
        ]
    return [
        Section(
            "Model and geometry",
            paragraphs=[
                "Screw shaft, nut(s) and spacer (contact-tcr.md §9). The balls of each nut are "
                "smeared over its bore as an interface conductance h = 1/(R·A_bore), R being the "
                "nut's total screw-to-nut resistance: the fractal micro TCR of the chain (A1–A3) "
                "plus, unless switched off, the macro-constriction of the Hertz patches into ball "
                "and raceways. The ball-screw friction heat enters both faces of that interface; "
                "the spacer bore is adiabatic; every outer surface convects to ambient.",
            ],
            tables=[(["quantity", "value"], geometry_rows)],
        ),
        Section(
            "Heat sources (Q2–Q4)",
            tables=[
                (
                    [
                        "source",
                        "method",
                        "torque [N·m]",
                        "heat [W]",
                        "into screw [W]",
                        "into nut [W]",
                    ],
                    sources,
                )
            ],
        ),
        Section("Convection (Q5, Q6)", tables=[(["surface", "h [W/(m² K)]", "from"], conv)]),
        Section(
            "Thermal contact of the balls",
            tables=[
                (
                    [
                        "nut",
                        "micro TCR [K/W]",
                        "constriction [K/W]",
                        "total R [K/W]",
                        "R″ of the chain [m² K/W]",
                        "smeared h [W/(m² K)]",
                    ],
                    contact,
                )
            ],
        ),
        Section(
            "Results",
            tables=[
                (["quantity", "value"], steady),
                (
                    [
                        "sensor",
                        "body",
                        "r [mm]",
                        "z [mm]",
                        "steady [°C]",
                        "final [°C]",
                        "time to 95 %",
                    ],
                    sensor_rows,
                ),
            ],
            figures=figures,
        ),
        Section("Heat balance", tables=[(["quantity", "value"], balance)]),
    ]


def write_thermal(result: ThermalField, out: str | Path) -> Path:
    """Write the ``thermal`` results folder and return its path."""
    summary = thermal_summary(result)
    with results_folder(out) as folder:
        write_summary(folder / "summary.json", summary)
        write_netcdf(result.to_xarray(), folder / "fields.nc")
        figures = [
            (
                temperature_map(result, folder / "temperature_map.png"),
                "Steady temperature with the sensor points circled.",
            ),
            (
                elongation_plot(result, folder / "elongation.png"),
                "Thermal elongation over time and the steady axial temperature profile.",
            ),
        ]
        if result.solution.transient is not None:
            figures.insert(
                1,
                (
                    temperature_rise(result, folder / "temperature_rise.png"),
                    "Temperature rise of the maximum and of each sensor.",
                ),
            )
        write_report(
            folder / "report.html",
            f"Temperature field and thermal elongation: {result.case_name}",
            "ballscrew thermal",
            _sections(result, summary, figures),
        )
    return Path(out).resolve()
