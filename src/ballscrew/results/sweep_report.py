"""Results folder of ``ballscrew sweep``: sweep.nc, line/map plots and report.html.

A sweep folder is written in place (it holds the point cache ``points/``), exports included,
not by the generic writer, but its summary and report state the same inputs and warnings
sections: the base case resolved with units, the axes and the analysis; one warning per failed
point.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import xarray as xr

from ballscrew.analyses.case_reads import case_reads
from ballscrew.case import Case
from ballscrew.case.inputs import guessed_defaults, resolved_inputs
from ballscrew.plotting import legend_outside, line_styles, pyplot, save_figure, zero_noise
from ballscrew.results.display import engineering, engineering_array, readable
from ballscrew.results.export import export_results, parse_formats
from ballscrew.results.folder import (
    SUMMARY_NAME,
    SWEEP_PATTERNS,
    atomic_file,
    write_marker,
    write_netcdf,
    writing,
)
from ballscrew.results.report import Section, inputs_warnings_sections, write_report
from ballscrew.results.summary import write_summary
from ballscrew.sweep.axes import SweepAxis
from ballscrew.units import KIND_OF_UNIT, NOISE_FLOOR, format_number

if TYPE_CHECKING:
    from matplotlib.figure import Figure


def _axis(ds: xr.Dataset, name: str) -> tuple[np.ndarray, str]:
    """Values of ``name`` in engineering units (round-off speeds as 0) and its axis label."""
    unit = ds[name].attrs.get("units", "")
    values = zero_noise(ds[name].values, NOISE_FLOOR.get(KIND_OF_UNIT.get(unit, ""), 0.0))
    values, unit = engineering_array(values, unit, name)
    return values, f"{readable(name)} [{unit}]" if unit else readable(name)


def _save(fig: Figure, path: Path) -> Path:
    with atomic_file(path) as tmp:
        save_figure(fig, tmp)
    return path


def plot_variable(ds: xr.Dataset, name: str, path: Path) -> Path:
    """One result over the sweep (PNG): a line over a 1-D sweep; over a 2-D sweep a contour map
    of the first two swept keys, or one distinct line per value of the second key when it has
    fewer than three values. Engineering units and readable names on the axes."""
    plt = pyplot()
    da = ds[name]
    dims = list(da.dims)
    x, xlabel = _axis(ds, dims[0])
    z, zlabel = _axis(ds, name)
    if len(dims) >= 2 and ds.sizes[dims[1]] >= 3 and ds.sizes[dims[0]] >= 3:
        y, ylabel = _axis(ds, dims[1])
        grid = z.reshape(len(x), len(y), -1)[:, :, 0]
        fig, ax = plt.subplots(figsize=(5.8, 4.0), layout="constrained")
        filled = ax.contourf(x, y, grid.T, levels=14, cmap="viridis")
        lines = ax.contour(x, y, grid.T, levels=filled.levels[::2], colors="white", linewidths=0.6)
        ax.clabel(lines, fontsize=7, fmt="%.4g")
        ax.plot(*np.meshgrid(x, y), ".", color="black", markersize=2)
        fig.colorbar(filled, ax=ax, label=zlabel)
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel)
        ax.set_title(readable(name), fontsize=10)
        return _save(fig, path)
    fig, ax = plt.subplots(figsize=(6.4, 3.6), layout="constrained")
    if len(dims) == 1:
        ax.plot(x, z, "o-", markersize=4)
    else:
        other = dims[1]
        levels, unit = engineering_array(
            ds[other].values, ds[other].attrs.get("units", ""), str(other)
        )
        for k, style in enumerate(line_styles(len(levels))):
            series = z.reshape(len(x), len(levels), -1)[:, k, 0]
            ax.plot(x, series, markersize=3, label=f"{levels[k]:.4g} {unit}".strip(), **style)
        legend_outside(ax, fontsize=7, title=readable(str(other)), title_fontsize=7)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(zlabel)
    ax.set_title(readable(name), fontsize=10)
    ax.grid(alpha=0.3)
    return _save(fig, path)


def plot_nut_forces(ds: xr.Dataset, path: Path) -> Path:
    """The nut forces F1 and F2 over a 1-D sweep, the lift-off of nut 2 marked (PNG)."""
    plt = pyplot()
    dim = ds["F1"].dims[0]
    x, xlabel = _axis(ds, dim)
    fig, ax = plt.subplots(figsize=(6.4, 3.6), layout="constrained")
    f1, f2 = ds["F1"].values * 1e-3, ds["F2"].values * 1e-3
    ax.plot(x, f1, "o-", markersize=4, label="nut 1 (loaded) F1")
    ax.plot(x, f2, "s--", markersize=4, label="nut 2 (preload side) F2")
    off = np.flatnonzero(f2 <= 1e-9 * np.nanmax(np.abs(f1)))
    if off.size:
        ax.axvline(x[off[0]], color="grey", linestyle=":", linewidth=1.2)
        ax.annotate(
            "nut 2 lifted off",
            (x[off[0]], 0.5 * np.nanmax(f1)),
            xytext=(4, 0),
            textcoords="offset points",
            fontsize=8,
            color="dimgray",
        )
    ax.axhline(0.0, color="black", linewidth=0.6)
    ax.set_xlabel(xlabel)
    ax.set_ylabel("nut force [kN]")
    ax.set_title("Nut forces", fontsize=10)
    ax.grid(alpha=0.3)
    legend_outside(ax, fontsize=7)
    return _save(fig, path)


def sweep_inputs(
    ds: xr.Dataset, case: Case | None = None, axes: Sequence[SweepAxis] = ()
) -> dict[str, Any]:
    """The inputs of a sweep: its analysis, its axes (values with units) and the base case."""
    described = {a.key: a.description for a in axes}
    dims = list(ds["failed"].dims)
    return {
        "analysis": ds.attrs["analysis"],
        "axes": {
            d: {
                "values": [float(v) for v in ds[d].values],
                "unit": ds[d].attrs.get("units", ""),
                **({"description": described[d]} if d in described else {}),
            }
            for d in dims
        },
        "case": resolved_inputs(case) if case is not None else {"name": ds.attrs["case"]},
    }


def write_sweep(
    ds: xr.Dataset,
    folder: Path,
    computed: int,
    case: Case | None = None,
    axes: Sequence[SweepAxis] = (),
    export: Sequence[str] = (),
) -> Path:
    """Write sweep.nc, one plot per result, summary.json, report.html and the exports
    ``export`` (:func:`~ballscrew.results.export.export_results`) into ``folder``.

    ``case`` is the base case and ``axes`` the swept keys (their inputs in the summary and the
    report). ``folder`` also holds the per-point store (``points/``), so it is written in
    place, each file through a temporary file; a failed write raises :class:`ResultsWriteError`.
    """
    folder = Path(folder)
    export = parse_formats(export)
    with writing(folder):
        swept = {f"case.{d}" for d in ds["failed"].dims}  # each point writes its own value
        reads = case_reads(str(ds.attrs["analysis"]))
        guessed = guessed_defaults(case, "case.", reads) if case is not None else {}
        guesses = {key: text for key, text in guessed.items() if key not in swept}
        _write_files(ds, folder, computed, sweep_inputs(ds, case, axes), guesses)
        if export:
            export_results(folder, export)
        write_marker(folder, "sweep", SWEEP_PATTERNS)
    return folder


def _shown_axes(inputs: dict[str, Any]) -> dict[str, Any]:
    """``inputs`` with each axis's values as one quantity, so the report shows them in
    engineering units (500, 1750, 3000 rpm), not as SI lists."""
    axes = {
        key: {"values": {"value": axis["values"], "unit": axis["unit"]}}
        | {k: v for k, v in axis.items() if k not in ("values", "unit")}
        for key, axis in inputs["axes"].items()
    }
    return inputs | {"axes": axes}


def _point(ds: xr.Dataset, dim: str, index: int) -> str:
    """``key=value unit`` of one swept value in engineering units (``operating.speed=3000 rpm``)."""
    value, unit = engineering(float(ds[dim].values[index]), ds[dim].attrs.get("units", ""), dim)
    return f"{dim}={format_number(value)} {unit}".rstrip()


def _point_warnings(ds: xr.Dataset) -> list[str]:
    """Each distinct warning of the points with the first point that gave it and how many."""
    if "warnings" not in ds:
        return []
    dims = list(ds["warnings"].dims)
    first: dict[str, str] = {}
    count: dict[str, int] = {}
    for idx in np.ndindex(ds["warnings"].shape):
        for message in filter(None, str(ds["warnings"].values[idx]).split("\n")):
            if message not in first:
                first[message] = ", ".join(_point(ds, d, i) for d, i in zip(dims, idx, strict=True))
            count[message] = count.get(message, 0) + 1
    return [
        f"point {first[m]}" + (f" (and {count[m] - 1} more)" if count[m] > 1 else "") + f": {m}"
        for m in first
    ]


#: Most rows of the report's table of every point (the rest are in sweep.nc and the exports).
MAX_TABLE_ROWS = 200


def _value_section(ds: xr.Dataset, names: Sequence[str]) -> Section:
    """Every point's swept values and results in engineering units, one row each."""
    dims = list(ds["failed"].dims)
    axes = [_axis(ds, d) for d in dims]
    results = [_axis(ds, n) for n in names]
    rows = [
        [float(values[i]) for (values, _), i in zip(axes, idx, strict=True)]
        + [float(values[idx]) for values, _ in results]
        for idx in np.ndindex(ds["failed"].shape)
    ]
    shown = "" if len(rows) <= MAX_TABLE_ROWS else f" The first {MAX_TABLE_ROWS} are shown."
    return Section(
        "Values at every point",
        paragraphs=[
            f"{len(rows)} points in engineering units; nan: a failed point or a value the "
            f"analysis does not give there. All of them: sweep.nc or --export csv.{shown}"
        ],
        tables=[([label for _, label in axes + results], rows[:MAX_TABLE_ROWS])],
    )


def _write_files(
    ds: xr.Dataset, folder: Path, computed: int, inputs: dict[str, Any], guesses: dict[str, str]
) -> None:
    write_netcdf(ds, folder / "sweep.nc")
    names = [n for n in ds.data_vars if n not in ("error", "failed", "warnings")]
    forces = {"F1", "F2"} <= set(names) and ds["F1"].ndim == 1
    figures = []
    if forces:
        names = [n for n in names if n not in ("F1", "F2")]
        figures.append(
            (
                plot_nut_forces(ds, folder / "sweep_nut_forces.png"),
                "Nut forces over the sweep; a dotted line marks the lift-off of nut 2.",
            )
        )
    figures += [
        (plot_variable(ds, n, folder / f"sweep_{n}.png"), f"{readable(str(n))} over the sweep")
        for n in names
    ]
    failed = np.argwhere(ds["failed"].values)
    dims = list(ds["failed"].dims)
    failures = [
        [
            ", ".join(_point(ds, d, i) for d, i in zip(dims, idx, strict=True)),
            str(ds["error"].values[tuple(idx)]),
        ]
        for idx in failed
    ]
    warnings = [f"point {point} failed: {error}" for point, error in failures]
    warnings += _point_warnings(ds)
    summary = {
        "analysis": ds.attrs["analysis"],
        "case": ds.attrs["case"],
        "points": int(ds.attrs["points"]),
        "computed_now": computed,
        "failed": len(failures),
        "axes": {d: {"values": ds[d].values, "unit": ds[d].attrs.get("units", "")} for d in dims},
        "failures": failures,
        "warnings": warnings,
        "guessed_defaults": sorted(guesses),
        "inputs": inputs,
    }
    with atomic_file(folder / SUMMARY_NAME) as tmp:
        write_summary(tmp, summary)
    sections = [
        *inputs_warnings_sections(_shown_axes(inputs), warnings, "sweep", guesses),
        Section(
            "Sweep",
            paragraphs=[
                f"{ds.attrs['points']} points over {', '.join(dims)}; {computed} computed in "
                f"this run, the rest reused from points/. {len(failures)} failed."
            ],
            tables=[(["point", "error"], failures)] if failures else [],
            figures=figures,
        ),
        _value_section(ds, [n for n in ds.data_vars if n not in ("error", "failed", "warnings")]),
    ]
    with atomic_file(folder / "report.html") as tmp:
        write_report(
            tmp,
            f"Sweep: {ds.attrs['case']}",
            f"ballscrew sweep --analysis {ds.attrs['analysis']}",
            sections,
        )
