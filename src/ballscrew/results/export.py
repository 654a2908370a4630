"""Export a results folder for spreadsheets and MATLAB: CSV, XLSX and ``.mat``.

From the folder's ``summary.json`` and NetCDF files (values stay SI, each with its unit):

* ``csv``  — ``summary.csv`` (``key, value, unit``) and one file per 1-D group of each dataset,
  ``<stem>_<dimension>.csv``: the coordinate, then every variable along that dimension, a
  column per variable with its unit in the header (``time [s]``); a variable with a second,
  short dimension (sensors, nuts) gives one column per entry (``sensor_temperature[S1] [K]``);
* ``xlsx`` — ``results.xlsx``: a ``summary`` sheet, an ``inputs`` sheet and one sheet per
  1-D group, the same tables as the CSV files;
* ``mat``  — ``<stem>.mat`` per dataset: every variable (fields of any dimension) under a
  MATLAB-safe name, and a struct ``units`` (name → unit) and ``names`` (name → original name).

The files are listed in the folder's marker file, so a later run may replace them.
"""

from __future__ import annotations

import csv
import io
import json
import re
from collections.abc import Iterator, Sequence
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr

from ballscrew.case.inputs import input_rows
from ballscrew.errors import InputError
from ballscrew.files import atomic_file
from ballscrew.results.folder import MARKER_NAME, SUMMARY_NAME, writing
from ballscrew.units import split_list

__all__ = ["FORMATS", "export_results", "parse_formats"]

FORMATS = ("csv", "xlsx", "mat")
"""The export formats, in the order they are written."""

SHORT_DIMENSION = 16
"""Longest second dimension spread into columns of a 1-D table (sensors, nuts, flanks)."""

_MATLAB_NAME = 63  # namelengthmax of MATLAB


def parse_formats(text: str | Sequence[str]) -> list[str]:
    """``"csv,xlsx"`` or ``["csv", "xlsx"]`` → the formats, checked; unknown → InputError."""
    formats = [f.lower() for f in split_list(text)]
    for name in formats:
        if name not in FORMATS:
            raise InputError("--export", name, f"one of {', '.join(FORMATS)}")
    return list(dict.fromkeys(formats))


# --- what is exported ------------------------------------------------------------------------


def summary_rows(summary: dict[str, Any], prefix: str = "") -> list[tuple[str, Any, str]]:
    """(dotted key, value, unit) of every scalar of ``summary.json`` (inputs and warnings
    excluded); list entries are ``key[k]``."""
    rows: list[tuple[str, Any, str]] = []
    for key, item in summary.items():
        if not prefix and key in ("inputs", "warnings"):
            continue
        name = f"{prefix}{key}"
        rows += _rows(name, item)
    return rows


def _rows(name: str, item: Any) -> list[tuple[str, Any, str]]:
    if isinstance(item, dict) and "value" in item and "unit" in item:
        extra = {k: v for k, v in item.items() if k not in ("value", "unit")}
        return [(name, item["value"], item["unit"]), *summary_rows(extra, name + ".")]
    if isinstance(item, dict):
        return summary_rows(item, name + ".")
    if isinstance(item, list):
        return [row for k, entry in enumerate(item) for row in _rows(f"{name}[{k}]", entry)]
    return [(name, item, "")]


def _unit(variable: xr.DataArray) -> str:
    return str(variable.attrs.get("units", ""))


def _labels(coord: xr.DataArray) -> list[str]:
    return [str(v.item() if hasattr(v, "item") else v) for v in coord.values]


def tables(dataset: xr.Dataset) -> Iterator[tuple[str, list[str], list[np.ndarray]]]:
    """(dimension, header, columns) of every 1-D group of ``dataset``.

    The group of dimension ``d`` holds ``d``'s coordinate (or the index), each variable whose
    only dimension is ``d`` and each ``(d, k)`` variable with ``k`` at most
    :data:`SHORT_DIMENSION` long, one column per entry of ``k``.
    """
    for dim, size in dataset.sizes.items():
        if size < 2 and dim not in dataset.coords:
            continue
        header: list[str] = []
        columns: list[np.ndarray] = []
        for name, var in dataset.data_vars.items():
            if var.dims == (dim,):
                header.append(_heading(str(name), _unit(var)))
                columns.append(var.values)
            elif len(var.dims) == 2 and var.dims[0] == dim:
                other = var.dims[1]
                if dataset.sizes[other] > SHORT_DIMENSION:
                    continue
                labels = (
                    _labels(dataset[other])
                    if other in dataset.coords
                    else [str(k) for k in range(dataset.sizes[other])]
                )
                for k, label in enumerate(labels):
                    header.append(_heading(f"{name}[{label}]", _unit(var)))
                    columns.append(var.values[:, k])
        if not columns:
            continue
        if dim in dataset.coords:
            coord = dataset[dim]
            header.insert(0, _heading(str(dim), _unit(coord)))
            columns.insert(0, coord.values)
        else:
            header.insert(0, str(dim))
            columns.insert(0, np.arange(size))
        yield str(dim), header, columns


def _heading(name: str, unit: str) -> str:
    return f"{name} [{unit}]" if unit else name


def _cell(item: Any) -> Any:
    """A spreadsheet cell: Python numbers and strings; NaN/inf become empty cells."""
    if isinstance(item, np.generic):
        item = item.item()
    if isinstance(item, float) and not np.isfinite(item):
        return None
    if isinstance(item, bytes):
        return item.decode("utf-8", "replace")
    return item


def _file_part(text: str) -> str:
    return re.sub(r"[^A-Za-z0-9_-]+", "_", text).strip("_") or "data"


def _datasets(folder: Path) -> dict[str, xr.Dataset]:
    found = {}
    for path in sorted(folder.glob("*.nc")):
        with xr.open_dataset(path, engine="h5netcdf") as ds:
            found[path.stem] = ds.load()
    return found


# --- writers -----------------------------------------------------------------------------------


def _csv_text(header: Sequence[str], rows: Sequence[Sequence[Any]]) -> bytes:
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(header)
    for row in rows:
        writer.writerow(["" if (c := _cell(v)) is None else c for v in row])
    return buffer.getvalue().encode("utf-8")


def _group_files(datasets: dict[str, xr.Dataset]) -> Iterator[tuple[str, list[str], list]]:
    """(name, header, rows) of each 1-D group, ``name`` = ``<stem>_<dimension>``."""
    for stem, dataset in datasets.items():
        for dim, header, columns in tables(dataset):
            rows = [list(row) for row in zip(*columns, strict=True)]
            yield f"{_file_part(stem)}_{_file_part(dim)}", header, rows


def _csv(folder: Path, summary: dict, datasets: dict[str, xr.Dataset]) -> dict[str, bytes]:
    files = {"summary.csv": _csv_text(["key", "value", "unit"], summary_rows(summary))}
    for name, header, rows in _group_files(datasets):
        files[f"{name}.csv"] = _csv_text(header, rows)
    return files


def _sheet_name(name: str, taken: set[str]) -> str:
    base = re.sub(r"[\[\]:*?/\\']", "_", name)[:31] or "sheet"
    candidate, k = base, 2
    while candidate.lower() in taken:
        suffix = f"~{k}"
        candidate, k = base[: 31 - len(suffix)] + suffix, k + 1
    taken.add(candidate.lower())
    return candidate


def _xlsx(folder: Path, summary: dict, datasets: dict[str, xr.Dataset]) -> dict[str, bytes]:
    from openpyxl import Workbook
    from openpyxl.styles import Font

    book = Workbook()
    taken: set[str] = set()
    sheets = [
        ("summary", ["key", "value", "unit"], summary_rows(summary)),
        ("inputs", ["input", "value", "unit"], input_rows(summary.get("inputs") or {})),
        *_group_files(datasets),
    ]
    book.remove(book.active)
    for name, header, rows in sheets:
        sheet = book.create_sheet(_sheet_name(name, taken))
        sheet.append(list(header))
        for cell in sheet[1]:
            cell.font = Font(bold=True)
        for row in rows:
            sheet.append([_xlsx_cell(v) for v in row])
        sheet.freeze_panes = "A2"
        for k, title in enumerate(header):
            sheet.column_dimensions[sheet.cell(1, k + 1).column_letter].width = max(
                12, min(40, len(str(title)) + 2)
            )
    buffer = io.BytesIO()
    book.save(buffer)
    return {"results.xlsx": buffer.getvalue()}


def _xlsx_cell(item: Any) -> Any:
    item = _cell(item)
    if isinstance(item, list | dict | tuple):
        return json.dumps(item)
    return item


def matlab_name(name: str, taken: set[str]) -> str:
    """A valid, unused MATLAB identifier for ``name`` (letters, digits, ``_``; ≤ 63 chars)."""
    base = re.sub(r"\W", "_", name, flags=re.ASCII).strip("_") or "x"
    if not base[0].isalpha():
        base = "x_" + base
    base = base[:_MATLAB_NAME]
    candidate, k = base, 2
    while candidate in taken:
        suffix = f"_{k}"
        candidate, k = base[: _MATLAB_NAME - len(suffix)] + suffix, k + 1
    taken.add(candidate)
    return candidate


def _mat(folder: Path, summary: dict, datasets: dict[str, xr.Dataset]) -> dict[str, bytes]:
    from scipy.io import savemat

    files = {}
    for stem, dataset in datasets.items():
        taken = {"units", "names"}
        content: dict[str, Any] = {}
        units: dict[str, str] = {}
        names: dict[str, str] = {}
        for name, var in dataset.variables.items():
            key = matlab_name(str(name), taken)
            values = var.values
            if values.dtype.kind in "OU":
                values = np.asarray(values, dtype=str)
            content[key] = values
            units[key] = _unit(var)
            names[key] = str(name)
        content["units"] = units
        content["names"] = names
        buffer = io.BytesIO()
        savemat(buffer, content, do_compression=True, oned_as="column", long_field_names=True)
        files[f"{_file_part(stem)}.mat"] = buffer.getvalue()
    return files


_WRITERS = {"csv": _csv, "xlsx": _xlsx, "mat": _mat}


def _add_to_marker(folder: Path, names: Sequence[str]) -> None:
    path = folder / MARKER_NAME
    if not path.is_file():
        return  # a folder being written: its marker, written last, lists every file
    marker = json.loads(path.read_text(encoding="utf-8"))
    marker["files"] = sorted(set(marker.get("files", [])) | set(names))
    with atomic_file(path) as tmp:
        tmp.write_text(json.dumps(marker, indent=1) + "\n", encoding="utf-8")


def export_results(folder: str | Path, formats: Sequence[str]) -> list[Path]:
    """Write the exports ``formats`` (of :data:`FORMATS`) of the results ``folder``.

    Returns the paths written. An unknown format or a folder that is not a results folder
    raises :class:`InputError` before anything is written; a failed write removes what this
    call wrote and raises :class:`~ballscrew.results.folder.ResultsWriteError`.
    """
    folder = Path(folder)
    formats = parse_formats(formats)
    summary_path = folder / SUMMARY_NAME
    if not summary_path.is_file():
        raise InputError("--out", str(folder), f"a results folder (with {SUMMARY_NAME})")
    summary = json.loads(summary_path.read_text(encoding="utf-8"))
    datasets = _datasets(folder)
    files: dict[str, bytes] = {}
    for name in formats:
        files.update(_WRITERS[name](folder, summary, datasets))
    written: list[Path] = []
    try:
        with writing(folder):
            for name, content in files.items():
                with atomic_file(folder / name) as tmp:
                    tmp.write_bytes(content)
                written.append(folder / name)
            _add_to_marker(folder, list(files))
    except BaseException:
        for path in written:
            path.unlink(missing_ok=True)
        raise
    return written
