"""Results folder of ``ballscrew sweep``: sweep.nc, line/map plots and report.html.

A sweep folder is written in place (it holds the point cache ``points/``), not by the generic
writer, but its summary and report state the same inputs and warnings sections: the base case
resolved with units, the axes and the analysis; one warning per failed point.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import xarray as xr

from ballscrew.case import Case
from ballscrew.case.inputs import resolved_inputs
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


def _label(da: xr.DataArray, name: str) -> str:
    unit = da.attrs.get("units", "")
    return f"{name} [{unit}]" if unit else name


def plot_variable(ds: xr.Dataset, name: str, path: Path) -> Path:
    """Line plot over the first swept key; one line per value of the second, if any (PNG)."""
    da = ds[name]
    dims = list(da.dims)
    fig, ax = plt.subplots(figsize=(5.6, 3.6), layout="constrained")
    x = ds[dims[0]]
    if len(dims) == 1:
        ax.plot(x, da, "o-", markersize=4)
    else:
        other = dims[1]
        for k, level in enumerate(ds[other].values):
            series = da.isel({other: k}).values.reshape(len(x), -1)[:, 0]
            unit = ds[other].attrs.get("units", "")
            ax.plot(x, series, "o-", markersize=3, label=f"{other} = {level:.4g} {unit}".strip())
        ax.legend(fontsize=7, ncol=2)
    ax.set_xlabel(_label(x, dims[0]))
    ax.set_ylabel(_label(da, name))
    ax.grid(alpha=0.3)
    with atomic_file(path) as tmp:
        fig.savefig(tmp, dpi=110, format="png")
    plt.close(fig)
    return path


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
) -> Path:
    """Write sweep.nc, one plot per result, summary.json and report.html into ``folder``.

    ``case`` is the base case and ``axes`` the swept keys (their inputs in the summary and the
    report). ``folder`` also holds the per-point store (``points/``), so it is written in
    place, each file through a temporary file; a failed write raises :class:`ResultsWriteError`.
    """
    folder = Path(folder)
    with writing(folder):
        _write_files(ds, folder, computed, sweep_inputs(ds, case, axes))
        write_marker(folder, "sweep", SWEEP_PATTERNS)
    return folder


def _write_files(ds: xr.Dataset, folder: Path, computed: int, inputs: dict[str, Any]) -> None:
    write_netcdf(ds, folder / "sweep.nc")
    names = [n for n in ds.data_vars if n not in ("error", "failed")]
    figures = [
        (plot_variable(ds, n, folder / f"sweep_{n}.png"), f"{n} over the sweep") for n in names
    ]
    failed = np.argwhere(ds["failed"].values)
    dims = list(ds["failed"].dims)
    failures = [
        [
            ", ".join(f"{d}={ds[d].values[i]:.4g}" for d, i in zip(dims, idx, strict=True)),
            str(ds["error"].values[tuple(idx)]),
        ]
        for idx in failed
    ]
    warnings = [f"point {point} failed: {error}" for point, error in failures]
    summary = {
        "analysis": ds.attrs["analysis"],
        "case": ds.attrs["case"],
        "points": int(ds.attrs["points"]),
        "computed_now": computed,
        "failed": len(failures),
        "axes": {d: {"values": ds[d].values, "unit": ds[d].attrs.get("units", "")} for d in dims},
        "failures": failures,
        "warnings": warnings,
        "inputs": inputs,
    }
    with atomic_file(folder / SUMMARY_NAME) as tmp:
        write_summary(tmp, summary)
    sections = [
        *inputs_warnings_sections(inputs, warnings),
        Section(
            "Sweep",
            paragraphs=[
                f"{ds.attrs['points']} points over {', '.join(dims)}; {computed} computed in "
                f"this run, the rest reused from points/. {len(failures)} failed."
            ],
            tables=[(["point", "error"], failures)] if failures else [],
            figures=figures,
        ),
    ]
    with atomic_file(folder / "report.html") as tmp:
        write_report(
            tmp,
            f"Sweep: {ds.attrs['case']}",
            f"ballscrew sweep --analysis {ds.attrs['analysis']}",
            sections,
        )
