"""Parameter sweeps over case keys, run on Dask and collected into xarray."""

from ballscrew.sweep.axes import SweepAxis, grid_points, parse_axis, validate_points
from ballscrew.sweep.runner import PointRecord, assemble, run_point, run_sweep, warm_workers

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
