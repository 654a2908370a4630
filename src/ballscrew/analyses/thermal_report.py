"""What the thermal analysis shows: its summary, fields, figures and report sections.

A result that followed the case's ``[[duty]]`` cycle adds that of the duty run
(:mod:`~ballscrew.analyses.duty_thermal_report`): its summary under ``duty``, its histories as
``duty_*`` variables over ``duty_time``, its figure and its sections.
"""

from __future__ import annotations

import math
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import xarray as xr

from ballscrew.analyses import duty_thermal_report
from ballscrew.analyses.result import Figure, Section, Table
from ballscrew.analyses.result import quantity as value
from ballscrew.plotting import label_box, legend_outside, plain, pyplot, save_figure
from ballscrew.thermal.elongation import shaft_displacement
from ballscrew.thermal.mesh3d import circle_angles
from ballscrew.units import format_number

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.tri import Triangulation

    from ballscrew.analyses.thermal import SensorReading, ThermalField

CELSIUS = 273.15


def _c(kelvin: float) -> float:
    return kelvin - CELSIUS


_NOT_REACHED = "95 % of the steady rise is not reached within thermal.transient.duration"


def summary(result: ThermalField) -> dict[str, Any]:
    """The scalars of a thermal analysis, each with its unit."""
    sol = result.solution
    problem = result.problem
    grid = sol.discretisation.grid
    t = sol.transient
    sensors = result.sensors
    summary: dict[str, Any] = {
        "case": result.case_name,
        "model": result.model,
        "unknowns": result.unknowns,
        "ambient_temperature": value(result.ambient_temperature, "K"),
        "steady": {
            "max_temperature": value(result.max_temperature, "K"),
            "max_temperature_rise": value(result.max_temperature_rise, "K"),
            "nut_temperature": value(result.nut_temperature, "K"),
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
                "time_to_95": value(s.time_to_95, "s", _NOT_REACHED),
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
    outlet = result.coolant_outlet_temperature
    if outlet is not None:
        summary["steady"]["coolant_outlet_temperature"] = value(outlet, "K")
    coupling = result.coupling
    if coupling is not None:
        summary["operating_point"] = {
            "friction_model": coupling.friction_model,
            "friction_torque": value(coupling.friction_torque, "N*m"),
            "heat": value(coupling.heat, "W"),
            "heat_to_screw": value(coupling.heat_to_screw, "W"),
            "contact_temperature": value(coupling.contact_temperature, "K"),
            "viscosity": value(coupling.viscosity, "Pa*s"),
            "iterations": coupling.iterations,
        }
    if result.duty is not None:
        summary["duty"] = duty_thermal_report.summary(result.duty)
    if t is not None:
        summary["transient"] = {
            "duration": value(t.time[-1], "s"),
            "time_step": value(t.time[1] - t.time[0], "s"),
            "final_max_temperature": value(result.ambient_temperature + t.max_rise[-1], "K"),
            "final_elongation": value(t.elongation[-1], "m"),
            "fraction_of_steady_rise": float(t.max_rise[-1] / result.max_temperature_rise)
            if result.max_temperature_rise > 0
            else None,
            "time_to_95": value(result.time_to_95, "s", _NOT_REACHED),
            "elongation_time_to_95": value(result.elongation_time_to_95, "s", _NOT_REACHED),
            "sensors": {s.name: value(s.final, "K") for s in sensors},
        }
    return summary


def fields(result: ThermalField) -> xr.Dataset:
    """Fields and histories of the thermal analysis with units (temperatures in K)."""
    sol = result.solution
    disc = sol.discretisation
    problem = result.problem
    amb = result.ambient_temperature

    def kelvin(long_name: str) -> dict[str, str]:
        return {"units": "K", "long_name": long_name}

    alpha = problem.expansion
    stations, displacement = shaft_displacement(disc.axis_z, sol.axis, alpha, problem.shaft_length)
    data: dict[str, Any] = {
        "axis_temperature": (
            "axis_z",
            amb + sol.axis,
            kelvin("steady cross-section mean temperature of the screw"),
        ),
        "axis_displacement": (
            "displacement_z",
            displacement,
            {
                "units": "m",
                "long_name": "steady axial thermal displacement α∫ΔT̄ dz from z = 0; "
                "at the end face z = L it is the elongation",
            },
        ),
        "sensor_temperature_steady": (
            "sensor",
            amb + sol.sensors,
            kelvin("steady sensor temperature"),
        ),
        "sensor_r": ("sensor", [s.r for s in problem.sensors], {"units": "m"}),
        "sensor_z": ("sensor", [s.z for s in problem.sensors], {"units": "m"}),
        "sensor_body": ("sensor", [s.body for s in problem.sensors]),
    }
    coords: dict[str, Any] = {
        "axis_z": ("axis_z", disc.axis_z, {"units": "m", "long_name": "axial position"}),
        "displacement_z": (
            "displacement_z",
            stations,
            {"units": "m", "long_name": "axial position: the profile's stations and both ends"},
        ),
        "sensor": ("sensor", [s.name for s in problem.sensors]),
    }
    t = sol.transient
    if t is not None:
        coords["time"] = ("time", t.time, {"units": "s", "long_name": "time"})
        coords["snapshot_time"] = ("snapshot_time", t.snapshot_times, {"units": "s"})
        data.update(
            max_temperature=("time", amb + t.max_rise, kelvin("largest temperature")),
            elongation=(
                "time",
                t.elongation,
                {"units": "m", "long_name": "thermal elongation α∫ΔT̄ dz of the screw"},
            ),
            sensor_temperature=(("time", "sensor"), amb + t.sensors, kelvin("sensor temperature")),
            axis_temperature_history=(
                ("time", "axis_z"),
                amb + t.axis,
                kelvin("cross-section mean temperature of the screw"),
            ),
            nut_offset=(
                "time",
                t.offset * disc.grid.dz,
                {"units": "m", "long_name": "nut stroke offset (resolved stroke)"},
            ),
        )
    if disc.model in ("axisymmetric", "3d"):
        fe_mesh = disc.extra["mesh"]
        nodal = disc.extra["basis"].nodal_dofs[0]
        node_axes = (
            (("node_r", "radius"), ("node_z", "axial position"))
            if disc.model == "axisymmetric"
            else (("node_x", "x"), ("node_y", "y"), ("node_z", "axial position"))
        )
        coords["node"] = ("node", np.arange(fe_mesh.mesh.p.shape[1]))
        for row, (name, long_name) in enumerate(node_axes):
            data[name] = ("node", fe_mesh.mesh.p[row], {"units": "m", "long_name": long_name})
        data.update(
            element_nodes=(
                ("element", "corner"),
                fe_mesh.mesh.t.T,
                {"units": "1", "long_name": "node numbers of each element"},
            ),
            element_body=(
                "element",
                fe_mesh.body,
                {"units": "1", "long_name": "0 = screw shaft, 1 = nut assembly"},
            ),
            temperature_steady=("node", amb + sol.steady[nodal], kelvin("steady temperature")),
        )
        if t is not None:
            data["temperature"] = (
                ("snapshot_time", "node"),
                amb + t.snapshots[:, nodal],
                kelvin("temperature"),
            )
    else:
        ex = disc.extra
        coords["ring_z"] = ("ring_z", ex["ring_z"], {"units": "m", "long_name": "nut cell centre"})
        for key, label in (
            ("ring_mean", "nut assembly mean"),
            ("ring_bore", "nut bore"),
            ("ring_outer", "nut outer surface"),
        ):
            data[f"{key}_temperature_steady"] = (
                "ring_z",
                amb + sol.steady[ex[key]],
                kelvin(f"steady {label} temperature"),
            )
        data["shaft_surface_temperature_steady"] = (
            "axis_z",
            amb + sol.steady[ex["shaft_surface"]],
            kelvin("steady screw surface temperature"),
        )
        if t is not None:
            data["ring_mean_temperature"] = (
                ("snapshot_time", "ring_z"),
                amb + t.snapshots[:, ex["ring_mean"]],
                kelvin("nut assembly mean temperature"),
            )
    dataset = xr.Dataset(
        data,
        coords=coords,
        attrs={
            "case": result.case_name,
            "model": result.model,
            "ambient_temperature_K": amb,
            "heat_input_W": result.heat_input,
            "max_temperature_rise_K": result.max_temperature_rise,
            "elongation_m": result.elongation,
            "unknowns": result.unknowns,
        },
    )
    if result.duty is None:
        return dataset
    cycle = duty_thermal_report.fields(result.duty)
    cycle = cycle.rename({name: f"duty_{name}" for name in cycle.data_vars}).rename(
        time="duty_time"
    )
    # the sensors are those of the field: an exact join, a mismatch is an error, not NaNs
    return dataset.merge(cycle, join="exact", combine_attrs="override")


def _sensor_markers(ax: Axes, result: ThermalField, z_scale: float = 1e3) -> None:
    """Sensor points circled in black and white, named in dark text on a white box."""
    for k, s in enumerate(result.problem.sensors):
        ax.plot(s.z * z_scale, s.r * 1e3, "o", ms=7, mfc="none", mec="white", mew=2.4)
        ax.plot(s.z * z_scale, s.r * 1e3, "o", ms=7, mfc="none", mec="black", mew=1.0)
        ax.annotate(
            plain(s.name),
            (s.z * z_scale, s.r * 1e3),
            textcoords="offset points",
            xytext=(5, -12 - 9 * (k % 2)),
            fontsize=7,
            color="black",
            bbox=label_box(),
        )


def _mixed_or_long(tri: Triangulation, body: np.ndarray, longest: float) -> np.ndarray:
    """Triangles joining screw and nut nodes or longer than ``longest``: outside the bodies."""
    corners = tri.triangles
    mixed = body[corners].min(axis=1) != body[corners].max(axis=1)
    x, y = tri.x[corners], tri.y[corners]
    edges = np.hypot(x - np.roll(x, 1, axis=1), y - np.roll(y, 1, axis=1)).max(axis=1)
    return mixed | (edges > longest)


def field_3d(result: ThermalField, path: Path) -> Path:
    """The 3-D model's steady field: the meridional section (z, r) at the mesh angle nearest
    θ = 0 (θ = 0 itself when the divisions are a multiple of 8) and the screw surface unrolled
    over (z, θ), where the helical ball-contact heat shows."""
    from matplotlib.tri import Triangulation

    plt = pyplot()
    disc = result.solution.discretisation
    m3 = disc.extra["mesh"]
    x, y, z = m3.mesh.p
    temp = _c(
        result.ambient_temperature + result.solution.steady[disc.extra["basis"].nodal_dofs[0]]
    )
    body = (np.arange(x.size) >= m3.shaft_nodes).astype(int)
    r, theta = np.hypot(x, y), np.arctan2(y, x)
    levels = np.linspace(temp.min(), temp.max() + 1e-9, 24)
    fig, axes = plt.subplots(2, 1, figsize=(8.0, 5.8), layout="constrained")
    angles = circle_angles(m3.divisions)
    cut = float(angles[np.argmin(np.abs(angles))])
    across = y * math.cos(cut) - x * math.sin(cut)
    plane = (np.abs(across) <= 1e-9 * r.max()) & (x * math.cos(cut) + y * math.sin(cut) >= 0.0)
    tri = Triangulation(z[plane] * 1e3, r[plane] * 1e3)
    spacing = np.diff(np.unique(np.round(z[plane] * 1e3, 6))).max(initial=0.0)
    spacing = max(spacing, np.diff(np.unique(np.round(r[plane] * 1e3, 6))).max(initial=0.0))
    tri.set_mask(_mixed_or_long(tri, body[plane], 1.5 * spacing))
    image = axes[0].tricontourf(tri, temp[plane], levels=levels, cmap="inferno")
    _sensor_markers(axes[0], result)
    axes[0].set(xlabel="z [mm]", ylabel="r [mm]")
    axes[0].set_title(f"section through the axis (θ = {math.degrees(cut):.3g}°)", fontsize=9)
    surface = (body == 0) & (r >= r[body == 0].max() * (1.0 - 1e-6))
    tri = Triangulation(z[surface] * 1e3, np.degrees(theta[surface]))
    axes[1].tricontourf(tri, temp[surface], levels=levels, cmap="inferno")
    axes[1].set(xlabel="z [mm]", ylabel="θ [°]", ylim=(-180, 180))
    axes[1].set_title("screw surface, unrolled", fontsize=9)
    fig.colorbar(image, ax=axes, label="steady temperature [°C]")
    fig.suptitle(plain(f"{result.case_name}: steady temperature (3-D model)"), fontsize=10)
    return save_figure(fig, path)


def temperature_map(result: ThermalField, path: Path) -> Path:
    """Steady temperature over the (z, r) section (whole screw and a zoom on the nut)."""
    from matplotlib.ticker import MaxNLocator
    from matplotlib.tri import Triangulation

    plt = pyplot()
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
        bar = fig.colorbar(image, ax=axes, label="steady temperature [°C]")
        bar.locator = MaxNLocator(8)  # round ticks, not the 30 contour levels (29.859 °C)
        bar.update_ticks()
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
        legend_outside(axes[0], fontsize=7)
    for ax in axes:
        ax.set_xlabel("z [mm]")
        if disc.model == "axisymmetric":
            ax.set_ylabel("r [mm]")
            _sensor_markers(ax, result)
    axes[1].set_xlim((ring_lo - pad) * 1e3, (ring_hi + pad) * 1e3)
    axes[0].set_title(plain(f"{result.case_name}: steady temperature ({result.model} model)"))
    axes[1].set_title("around the nut (sensors circled)", fontsize=9)
    return save_figure(fig, path)


def temperature_rise(result: ThermalField, path: Path) -> Path:
    """Temperature rise over time: the maximum and every sensor, steady values dashed."""
    plt = pyplot()
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
    legend_outside(ax, fontsize=7)
    ax.grid(alpha=0.3)
    return save_figure(fig, path)


def elongation_plot(result: ThermalField, path: Path) -> Path:
    """Thermal elongation over time and the steady axial profile of the screw."""
    plt = pyplot()
    sol = result.solution
    t = sol.transient
    if t is None:  # steady only: the profile, the elongation in the title (no empty time axis)
        fig, ax = plt.subplots(figsize=(6.4, 3.6), layout="constrained")
        profile = ax
        ax.set_title(f"steady elongation ΔL = α∫ΔT dz = {result.elongation * 1e6:.4g} µm")
    else:
        fig, axes = plt.subplots(1, 2, figsize=(9.0, 3.6), layout="constrained")
        axes[0].plot(t.time / 60.0, t.elongation * 1e6, "b-")
        axes[0].axhline(result.elongation * 1e6, color="b", ls="--", lw=0.8, label="steady")
        axes[0].set_xlabel("time [min]")
        axes[0].set_ylabel("elongation ΔL = α∫ΔT dz [µm]")
        legend_outside(axes[0], fontsize=7)
        axes[0].grid(alpha=0.3)
        profile = axes[1]
    z = sol.discretisation.axis_z * 1e3
    profile.plot(z, sol.axis, "r-")
    profile.set_xlabel("z [mm]")
    profile.set_ylabel("steady screw mean rise [K]", color="r")
    profile.grid(alpha=0.3)
    return save_figure(fig, path)


def _transient(sensor: SensorReading) -> tuple[object, str]:
    """(final [°C], time to 95 %) of a sensor; '–' for both without a transient."""
    if not math.isfinite(sensor.final):
        return "–", "–"
    return _c(sensor.final), _fmt_s(sensor.time_to_95)


def _fmt_s(seconds: float) -> str:
    return "not reached" if not math.isfinite(seconds) else f"{seconds / 60:.1f} min"


def figures(result: ThermalField) -> list[Figure]:
    """The figures of the field (:func:`field_figures`), then that of the duty cycle."""
    cycle = [] if result.duty is None else duty_thermal_report.figures(result.duty)
    return [*field_figures(result), *cycle]


def field_figures(result: ThermalField) -> list[Figure]:
    """Steady temperature map, rise over time (with a transient) and elongation."""
    out = [
        Figure(
            "temperature_map",
            "Steady temperature with the sensor points circled.",
            partial(temperature_map, result),
        ),
        Figure(
            "elongation",
            "Thermal elongation over time and the steady axial temperature profile."
            if result.solution.transient is not None
            else "Steady axial temperature profile of the screw and its thermal elongation.",
            partial(elongation_plot, result),
        ),
    ]
    if result.solution.discretisation.model == "3d":
        out.insert(
            1,
            Figure(
                "temperature_field_3d",
                "Steady 3-D temperature field: a section through the axis and the screw surface "
                "unrolled.",
                partial(field_3d, result),
            ),
        )
    if result.solution.transient is not None:
        out.insert(
            1,
            Figure(
                "temperature_rise",
                "Temperature rise of the maximum and of each sensor.",
                partial(temperature_rise, result),
            ),
        )
    return out


def sections(result: ThermalField) -> list[Section]:
    """The report sections: model, heat sources, convection, contact, results, heat balance."""
    problem = result.problem
    sol = result.solution
    parts = summary(result)["geometry"]["parts"]
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
        ["nut assembly mean temperature [°C]", _c(result.nut_temperature)],
        ["elongation α∫ΔT dz [µm]", result.elongation * 1e6],
    ]
    if result.coolant_outlet_temperature is not None:
        steady.append(
            ["shaft coolant outlet temperature [°C]", _c(result.coolant_outlet_temperature)]
        )
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
        [s.name, s.body, s.r * 1e3, s.z * 1e3, _c(s.steady), *_transient(s)] for s in result.sensors
    ]
    balance = [
        ["heat input [W]", result.heat_input],
        ["steady convective loss [W]", sol.heat_loss],
        ["steady relative error", format_number(result.heat_balance_error, 2)],
    ]
    if t is not None:
        balance += [
            ["transient: heat in [J]", t.heat_in],
            ["transient: stored + convected [J]", t.stored + t.convected],
            ["transient relative error", format_number(result.transient_heat_balance_error, 2)],
        ]
    return [
        Section(
            "Model and geometry",
            paragraphs=(
                "Screw shaft, nut(s) and spacer. The balls of each nut are "
                "smeared over its bore as an interface conductance h = 1/(R·A_bore), R being the "
                "nut's total screw-to-nut resistance: the micro TCR of the chain (A1–A3, by the "
                "[tcr] headline model) "
                "plus, unless switched off, the macro-constriction of the Hertz patches into ball "
                "and raceways. The ball-screw friction heat enters both faces of that interface; "
                "the spacer bore is adiabatic; every outer surface convects to ambient.",
            ),
            tables=(_table(("quantity", "value"), geometry_rows),),
        ),
        Section(
            "Heat sources (Q2–Q4)",
            paragraphs=_coupling_text(result),
            tables=(
                _table(
                    (
                        "source",
                        "method",
                        "torque [N·m]",
                        "heat [W]",
                        "into screw [W]",
                        "into nut [W]",
                    ),
                    sources,
                ),
            ),
        ),
        Section("Convection (Q5, Q6)", tables=(_table(("surface", "h [W/(m² K)]", "from"), conv),)),
        Section(
            "Thermal contact of the balls",
            paragraphs=(f"Micro TCR of the balls: {_micro_model(result)}.",),
            tables=(
                _table(
                    (
                        "nut",
                        "micro TCR [K/W]",
                        "constriction [K/W]",
                        "total R [K/W]",
                        "R″ of the chain [m² K/W]",
                        "smeared h [W/(m² K)]",
                    ),
                    contact,
                ),
            ),
        ),
        Section(
            "Results",
            tables=(
                _table(("quantity", "value"), steady),
                *(
                    (
                        _table(
                            (
                                "sensor",
                                "body",
                                "r [mm]",
                                "z [mm]",
                                "steady [°C]",
                                "final [°C]",
                                "time to 95 %",
                            ),
                            sensor_rows,
                        ),
                    )
                    if sensor_rows
                    else ()  # no [[thermal.sensors]]: no empty table
                ),
            ),
            paragraphs=_duty_text(result),
            figures=tuple(f.name for f in field_figures(result)),
        ),
        Section("Heat balance", tables=(_table(("quantity", "value"), balance),)),
        *([] if result.duty is None else duty_thermal_report.sections(result.duty)),
    ]


def _duty_text(result: ThermalField) -> tuple[str, ...]:
    """Where the results stand with respect to the case's ``[[duty]]`` list (none: nothing)."""
    if not result.case.duty:
        return ()
    if result.duty is None:
        return (
            "These results are at the single [operating] point; the case's [[duty]] cycle was "
            "not run (--no-duty, or duty=False in Python): ballscrew duty follows it.",
        )
    return (
        "These results are at the single [operating] point; the sections after the heat "
        "balance follow the case's [[duty]] cycle on the same model (the run of ballscrew "
        "duty).",
    )


def _coupling_text(result: ThermalField) -> tuple[str, ...]:
    """How the balls' heat was found: the coupled operating point, or the case's fixed heat."""
    c = result.coupling
    if c is None:
        source = result.case.thermal.drag_torque.source if result.case.thermal else "given"
        return (
            "The balls' heat is held fixed in this solve: [thermal.drag_torque] source = "
            f"{source!r} (the method column).",
        )
    viscosity = "a dry contact" if math.isnan(c.viscosity) else f"η = {1e3 * c.viscosity:.4g} mPa s"
    return (
        f"The balls' heat is that of the coupled operating point ({c.friction_model} friction "
        f"model): screw torque {c.friction_torque:.4g} N·m, heat {c.heat:.4g} W "
        f"({c.heat_to_screw:.4g} W into the screw) with the lubricant at the contact "
        f"temperature {_c(c.contact_temperature):.4g} °C "
        f"({viscosity}), {c.iterations} fixed-point iteration{'s' * (c.iterations != 1)} on the "
        f"{result.model} model.",
    )


def _table(header: tuple[str, ...], rows: list[list[object]]) -> Table:
    return Table(header, tuple(tuple(r) for r in rows))


def _micro_model(result: ThermalField) -> str:
    """Which model gave the micro TCR of the balls, as text."""
    contact = result.case.thermal.contact if result.case.thermal else None
    if contact is None or contact.source == "given":
        return "the case's given R″"
    if contact.tcr_model is not None:
        return f"model {contact.tcr_model} of the TCR analysis ([thermal.contact] tcr_model)"
    return f"the headline TCR model ({result.case.tcr.headline}, [tcr] headline)"
