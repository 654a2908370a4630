"""Exports of a results folder (CSV, XLSX, MAT) read back equal the NetCDF and summary values."""

from __future__ import annotations

import csv
import json
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pytest
import xarray as xr
from openpyxl import load_workbook
from scipy.io import loadmat

from ballscrew.errors import InputError
from ballscrew.results import export_results, write_results
from ballscrew.results.export import matlab_name
from ballscrew.results.folder import (
    MARKER_NAME,
    check_output_folder,
    claim_output,
    prepare_sweep_folder,
)
from ballscrew.results.sweep_report import write_sweep

RNG = np.random.default_rng(7)
TIME = np.linspace(0.0, 3600.0, 7)
SENSORS = ["S1", "S2", "S3"]


def _fields() -> dict[str, xr.Dataset]:
    history = xr.Dataset(
        {
            "max_temperature": ("time", 293.15 + RNG.random(7), {"units": "K"}),
            "elongation": ("time", 1e-5 * RNG.random(7), {"units": "m"}),
            "sensor_temperature": (("time", "sensor"), 293 + RNG.random((7, 3)), {"units": "K"}),
            "pressure": (("x", "y"), 1e9 * RNG.random((40, 30)), {"units": "Pa"}),
        },
        coords={
            "time": ("time", TIME, {"units": "s"}),
            "sensor": ("sensor", SENSORS),
            "x": ("x", np.linspace(-1e-4, 1e-4, 40), {"units": "m"}),
            "y": ("y", np.linspace(-2e-4, 2e-4, 30), {"units": "m"}),
        },
    )
    sweep = xr.Dataset(
        {"resistance": ("operating.axial_load", RNG.random(4), {"units": "K/W"})},
        coords={
            "operating.axial_load": ("operating.axial_load", [0.0, 1e3, 2e3, 3e3], {"units": "N"})
        },
    )
    return {"fields": history, "sweep": sweep}


@dataclass(frozen=True)
class _Result:
    analysis: str = "thermal"
    title: str = "A made-up result"
    inputs: dict = field(
        default_factory=lambda: {"screw": {"lead": {"value": 0.01, "unit": "m"}}, "name": "x"}
    )
    warnings: tuple[str, ...] = ()

    def summary(self) -> dict:
        return {
            "peak_elongation": {"value": 4.2e-5, "unit": "m"},
            "segment_heat": [{"value": 38.0, "unit": "W"}, {"value": 0.0, "unit": "W"}],
            "model": "axisymmetric",
        }

    def to_xarray(self) -> xr.Dataset:
        return _fields()["fields"]

    def figures(self) -> list:
        return []

    def report(self) -> list:
        return []


def _write(out: Path, export: list[str] | None = None) -> Path:
    """The folder of :class:`_Result` with a second NetCDF file, ``sweep.nc``, beside its own
    ``fields.nc`` (a command's extra file): the exports cover every NetCDF file of a folder."""
    sweep = bytes(_fields()["sweep"].to_netcdf(engine="h5netcdf"))
    return write_results(_Result(), out, extra_files={"sweep.nc": sweep}, export=export or [])


@pytest.fixture
def folder(tmp_path) -> Path:
    return _write(tmp_path / "run", export=["csv", "xlsx", "mat"])


def _read_csv(path: Path) -> tuple[list[str], list[list[str]]]:
    with path.open(encoding="utf-8") as handle:
        rows = list(csv.reader(handle))
    return rows[0], rows[1:]


def test_csv_round_trip_gives_the_netcdf_values_with_units(folder):
    header, rows = _read_csv(folder / "fields_time.csv")
    assert header == [
        "time [s]",
        "max_temperature [K]",
        "elongation [m]",
        "sensor_temperature[S1] [K]",
        "sensor_temperature[S2] [K]",
        "sensor_temperature[S3] [K]",
    ]
    table = np.array(rows, dtype=float)
    with xr.open_dataset(folder / "fields.nc", engine="h5netcdf") as ds:
        np.testing.assert_array_equal(table[:, 0], ds["time"].values)
        np.testing.assert_array_equal(table[:, 2], ds["elongation"].values)
        np.testing.assert_array_equal(table[:, 3:], ds["sensor_temperature"].values)
    header, rows = _read_csv(folder / "sweep_operating_axial_load.csv")
    assert header == ["operating.axial_load [N]", "resistance [K/W]"]
    summary = {row[0]: row[1:] for row in _read_csv(folder / "summary.csv")[1]}
    assert float(summary["peak_elongation"][0]) == 4.2e-5 and summary["peak_elongation"][1] == "m"
    assert summary["segment_heat[1]"] == ["0.0", "W"]
    assert not (folder / "fields_x.csv").exists()  # 2-D fields go to .mat only


def test_xlsx_has_the_summary_with_units_and_a_sheet_per_group(folder):
    book = load_workbook(folder / "results.xlsx", read_only=True)
    assert book.sheetnames == [
        "summary",
        "inputs",
        "fields_time",
        "sweep_operating_axial_load",
    ]
    summary = list(book["summary"].iter_rows(values_only=True))
    assert summary[0] == ("key", "value", "unit")
    assert ("peak_elongation", 4.2e-5, "m") in summary
    assert ("screw.lead", 0.01, "m") in list(book["inputs"].iter_rows(values_only=True))
    rows = list(book["fields_time"].iter_rows(values_only=True))
    with xr.open_dataset(folder / "fields.nc", engine="h5netcdf") as ds:
        # a spreadsheet cell keeps about 15 significant digits
        np.testing.assert_allclose([r[1] for r in rows[1:]], ds["max_temperature"].values, 1e-14)


def test_mat_has_every_field_in_si_with_sanitised_names_and_units(folder):
    mat = loadmat(folder / "fields.mat", squeeze_me=True)
    with xr.open_dataset(folder / "fields.nc", engine="h5netcdf") as ds:
        np.testing.assert_array_equal(mat["pressure"], ds["pressure"].values)
        np.testing.assert_array_equal(mat["sensor_temperature"], ds["sensor_temperature"].values)
    assert mat["units"]["pressure"].item() == "Pa"
    assert list(mat["sensor"]) == SENSORS
    sweep = loadmat(folder / "sweep.mat", squeeze_me=True)
    np.testing.assert_array_equal(sweep["operating_axial_load"], [0.0, 1e3, 2e3, 3e3])
    assert sweep["names"]["operating_axial_load"].item() == "operating.axial_load"


def test_exports_are_listed_in_the_marker_so_a_rerun_may_replace_them(folder):
    marker = json.loads((folder / MARKER_NAME).read_text())
    assert {"summary.csv", "results.xlsx", "fields.mat", "fields_time.csv"} <= set(marker["files"])
    check_output_folder(folder)


def test_export_after_the_write_adds_to_the_marker(tmp_path):
    folder = _write(tmp_path / "run")
    written = export_results(folder, ["mat"])
    assert [p.name for p in written] == ["fields.mat", "sweep.mat"]
    assert "sweep.mat" in json.loads((folder / MARKER_NAME).read_text())["files"]
    check_output_folder(folder)


def test_unknown_format_is_refused_before_anything_is_written(tmp_path):
    folder = _write(tmp_path / "run")
    before = sorted(p.name for p in folder.iterdir())
    with pytest.raises(InputError, match=r"--export.*pdf.*csv, xlsx, mat"):
        export_results(folder, ["csv", "pdf"])
    assert sorted(p.name for p in folder.iterdir()) == before
    with pytest.raises(InputError, match="--export"):
        _write(tmp_path / "other", export=["hdf"])
    assert not (tmp_path / "other").exists()


def test_matlab_names_are_valid_and_unique():
    taken: set[str] = set()
    names = [matlab_name(n, taken) for n in ["nut1.force", "nut1_force", "2x", "a" * 80]]
    assert names[:3] == ["nut1_force", "nut1_force_2", "x_2x"]
    assert len(names[3]) == 63


def test_a_sweep_folder_writes_its_exports_with_the_rest(tmp_path):
    """A sweep exports within its own write: the files are there and listed in its marker."""
    data = xr.Dataset(
        {
            "R": (("F",), np.array([2.0, 1.5]), {"units": "K/W"}),
            "error": (("F",), np.array(["", ""])),
            "failed": (("F",), np.array([False, False])),
        },
        coords={"F": ("F", np.array([0.0, 1e3]), {"units": "N"})},
        attrs={"analysis": "tcr", "case": "demo", "points": 2},
    )
    out = tmp_path / "sweep"
    with claim_output(out, command="sweep"):
        prepare_sweep_folder(out)
        write_sweep(data, out, 2, export=["csv"])
    with (out / "sweep_F.csv").open() as fh:
        rows = list(csv.reader(fh))
    assert rows == [["F [N]", "R [K/W]", "error", "failed"], ["0.0", "2.0", "", "False"],
                    ["1000.0", "1.5", "", "False"]]  # fmt: skip
    files = json.loads((out / MARKER_NAME).read_text())["files"]
    assert {"summary.csv", "sweep_F.csv"} <= set(files)
