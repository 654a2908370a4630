"""Parameter sweeps over case keys, run on Dask and collected into xarray.

The public names are imported on first use (PEP 562 module ``__getattr__``), so
:mod:`ballscrew.sweep.cluster` starts a local cluster before the runner's xarray and case models
are loaded in this process (:func:`ballscrew.sweep.cluster.start_client`).
"""

from __future__ import annotations

from importlib import import_module
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from ballscrew.sweep.axes import SweepAxis, grid_points, parse_axis, validate_points
    from ballscrew.sweep.runner import PointRecord, assemble, run_point, run_sweep, warm_workers

_PUBLIC: dict[str, str] = {
    "PointRecord": "ballscrew.sweep.runner",
    "SweepAxis": "ballscrew.sweep.axes",
    "assemble": "ballscrew.sweep.runner",
    "grid_points": "ballscrew.sweep.axes",
    "parse_axis": "ballscrew.sweep.axes",
    "run_point": "ballscrew.sweep.runner",
    "run_sweep": "ballscrew.sweep.runner",
    "validate_points": "ballscrew.sweep.axes",
    "warm_workers": "ballscrew.sweep.runner",
}

__all__ = [
    "PointRecord",
    "SweepAxis",
    "assemble",
    "grid_points",
    "parse_axis",
    "run_point",
    "run_sweep",
    "validate_points",
    "warm_workers",
]


def __getattr__(name: str) -> Any:
    if name not in _PUBLIC:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(import_module(_PUBLIC[name]), name)
    globals()[name] = value
    return value
