"""Measured life-test histories: a CSV of one quantity against screw revolutions.

File format (``ballscrew calibrate --measured FILE.csv``)::

    # optional comment lines start with '#'
    revolutions,friction_torque [N*m]
    0,0.4231
    48000,0.4016
    ...

* A header row, then one row per measurement. Columns are separated by commas.
* ``revolutions`` (screw revolutions since the start of the test, ≥ 0, strictly increasing) and
  exactly one measured column: ``friction_torque`` (N·m), ``preload`` (N) or ``wear_depth`` (m,
  the largest wear depth of the screw raceway). Other columns (a time stamp, a sample number)
  are ignored.
* A column name may carry a unit in square brackets, ``wear_depth [um]``, ``preload [kN]``; it
  is converted to SI with :func:`ballscrew.units.to_si` and must have the dimension of the
  quantity (a dimensionless unit such as ``[%]`` is refused). Without a unit the numbers are SI.
* Optional schedule columns ``speed`` and ``axial_load`` (both or neither; e.g. ``speed [rpm]``,
  ``axial_load [kN]``) give the speed and load the bench ran at since the previous row (the
  first row's: since revolution 0); :func:`ballscrew.calibrate` then runs the model on that
  programme instead of the case's ``[[wear.programme]]``. With them, an optional ``stroke``
  column (e.g. ``stroke [mm]``; 0: the ``[wear]`` stroke) gives each row's reciprocating stroke.
* The measured values must be physically plausible: some > 0, none above
  :data:`PLAUSIBLE_MAX`, none below 0 except as noise around 0: down to −5 % of the largest
  value where the neighbouring points are within 5 % of 0 too (a negative torque among
  positive ones is a sign or data error); at most :data:`MAX_POINTS` rows.

A table already in memory (a pandas DataFrame or a dict of columns) is read by
:func:`read_table` with the same header rules: ``pandas.read_csv`` of a measured file gives
the same history as :func:`read_measured`.

Every problem raises :class:`ballscrew.errors.InputError` naming the file, the column, the row
(the file's line) and the value.
"""

from __future__ import annotations

import csv
import math
import re
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ballscrew.budget import check_memory, format_bytes
from ballscrew.case.base import MAX_FORCE, MAX_SPEED
from ballscrew.case.duty_spec import MAX_STROKE
from ballscrew.errors import InputError
from ballscrew.units import SI_UNITS, to_si

__all__ = [
    "MAX_POINTS",
    "PLAUSIBLE_MAX",
    "QUANTITIES",
    "MeasuredHistory",
    "check_values",
    "measured_history",
    "read_measured",
    "read_table",
]

#: Measured quantities a history may hold: column name → physical kind (see units.SI_UNITS).
QUANTITIES: dict[str, str] = {
    "friction_torque": "torque",
    "preload": "force",
    "wear_depth": "length",
}

#: Optional schedule columns of a test-bench file: name → physical kind.
SCHEDULE: dict[str, str] = {"speed": "angular_velocity", "axial_load": "force"}

#: Optional stroke column of a schedule: name → physical kind.
SCHEDULE_STROKE: dict[str, str] = {"stroke": "length"}

#: Largest value of each schedule column (SI): that of a ``wear.programme`` speed and load,
#: and of a ``[[duty]]`` stroke.
SCHEDULE_RANGE = (
    ("speed", MAX_SPEED, "rad/s"),
    ("axial_load", MAX_FORCE, "N"),
    ("stroke", MAX_STROKE, "m"),
)

#: Largest plausible measured value of each quantity (SI): a ball-screw drag torque, a preload
#: and a raceway wear depth beyond these are a unit or data error.
PLAUSIBLE_MAX: dict[str, float] = {
    "friction_torque": 1.0e4,
    "preload": 1.0e7,
    "wear_depth": 1.0e-2,
}
NOISE = 0.05
"""Negative values down to this share of the largest one are noise around 0 where their
neighbours lie within it of 0 too [GUESS: a data-cleaning threshold, not a measured rule]."""
MAX_REVOLUTIONS = 1.0e12
"""Largest plausible revolution count of a life test."""
MAX_POINTS = 100_000
"""Most measured points: the fit compares every point with each trial run (see FIT_BYTES)."""
FIT_BYTES = 3 * 801 * 8
"""Memory per measured point of the calibration's surrogate (801 trial K × 3 arrays) [bytes]."""
READ_FACTOR = 30
"""Memory of reading a CSV file per byte of it (text, lines, cells as Python objects)."""

_HEADER = re.compile(r"^\s*([A-Za-z_][A-Za-z0-9_]*)\s*(?:\[(.*)\])?\s*$")


@dataclass(frozen=True)
class MeasuredHistory:
    """A measured history, in SI units.

    Attributes:
        revolutions: screw revolutions of each measurement (≥ 0, strictly increasing).
        values: the measured quantity at each of them, SI unit.
        quantity: ``"friction_torque"``, ``"preload"`` or ``"wear_depth"``.
        source: where the data came from (the file name), for messages and reports.
    """

    revolutions: NDArray[np.float64]
    values: NDArray[np.float64]
    quantity: str
    source: str = "measured data"
    schedule: NDArray[np.float64] | None = None
    """Speed (rad/s), axial load (N) and, optionally, stroke (m) run since the previous row, one
    row per point (a stroke of 0: the ``[wear]`` stroke); None: the case's programme."""
    notes: tuple[str, ...] = ()
    """The comment lines before the header of a CSV file: what it says about its data."""

    @property
    def unit(self) -> str:
        """SI unit of :attr:`values` (pint spelling)."""
        return SI_UNITS[QUANTITIES[self.quantity]]

    def __len__(self) -> int:
        return int(self.revolutions.size)


def measured_history(
    revolutions: ArrayLike,
    values: ArrayLike,
    quantity: str,
    source: str = "measured data",
    min_points: int = 2,
    schedule: ArrayLike | None = None,
    notes: tuple[str, ...] = (),
    lines: Sequence[int] | None = None,
) -> MeasuredHistory:
    """Validate arrays (SI) and return them as a read-only :class:`MeasuredHistory`.

    ``lines`` (the file's line of each point) names the line in error messages.

    Raises:
        InputError: unknown quantity, shapes that differ, non-finite numbers, negative or not
            strictly increasing revolutions, or fewer than ``min_points`` points.
    """
    if quantity not in QUANTITIES:
        raise InputError(f"{source}: quantity", quantity, f"one of {', '.join(QUANTITIES)}")
    rev = np.array(revolutions, dtype=np.float64).reshape(-1)
    val = np.array(values, dtype=np.float64).reshape(-1)
    if rev.shape != val.shape:
        raise InputError(
            f"{source}: {quantity}", f"{val.size} values", f"one per revolution count ({rev.size})"
        )
    for name, arr in (("revolutions", rev), (quantity, val)):
        bad = ~np.isfinite(arr)
        if np.any(bad):
            row = int(np.flatnonzero(bad)[0])
            raise _refuse(source, name, row, lines, arr[row], "a finite number")
    _check_count(source, rev.size)
    if rev.size and rev[-1] > MAX_REVOLUTIONS:
        raise _refuse(source, "revolutions", rev.size - 1, lines, rev[-1], f"≤ {MAX_REVOLUTIONS:g}")
    check_values(source, quantity, val, lines)
    if rev.size and rev[0] < 0.0:
        raise _refuse(source, "revolutions", 0, lines, rev[0], "a count ≥ 0")
    steps = np.diff(rev)
    if np.any(steps <= 0.0):
        row = int(np.flatnonzero(steps <= 0.0)[0]) + 1
        raise _refuse(
            source,
            "revolutions",
            row,
            lines,
            rev[row],
            f"strictly increasing revolutions (previous point: {rev[row - 1]:g})",
        )
    if rev.size < min_points:
        raise InputError(
            f"{source}: number of points",
            int(rev.size),
            f"at least {min_points} (more points than fitted parameters)",
        )
    rev.setflags(write=False)
    val.setflags(write=False)
    plan = None if schedule is None else _check_schedule(source, schedule, rev.size, lines)
    return MeasuredHistory(
        revolutions=rev, values=val, quantity=quantity, source=source, schedule=plan, notes=notes
    )


def _refuse(
    source: str, column: str, row: int, lines: Sequence[int] | None, value: float, allowed: str
) -> InputError:
    """The error of a bad ``value`` at 0-based ``row``: ``bench.csv: preload (point 5) = -3.0
    is not allowed: … (line 7)``, the file's line where ``lines`` gives it."""
    line = "" if lines is None else f" (line {lines[row]})"
    return InputError(f"{source}: {column} (point {row + 1})", float(value), allowed + line)


def _check_schedule(
    source: str, schedule: ArrayLike, points: int, lines: Sequence[int] | None = None
) -> NDArray[np.float64]:
    plan = np.array(schedule, dtype=np.float64)
    if plan.shape not in ((points, 2), (points, 3)):
        raise InputError(
            f"{source}: schedule", plan.shape, f"(speed, axial_load[, stroke]) per row ({points})"
        )
    for column, (name, high, unit) in enumerate(SCHEDULE_RANGE[: plan.shape[1]]):
        values = plan[:, column]
        bad = np.flatnonzero(~(np.isfinite(values) & (values >= 0.0) & (values <= high)))
        if bad.size:
            row = int(bad[0])
            allowed = f"in [0, {high:g}] {unit}"
            raise _refuse(source, name, row, lines, values[row], allowed)
    if not np.any(plan[:, 0] > 0.0):
        raise InputError(f"{source}: speed", "all 0", "a turning screw in some rows")
    plan.setflags(write=False)
    return plan


def _check_count(source: str, points: int) -> None:
    if points > MAX_POINTS:
        raise InputError(
            f"{source}: number of points",
            points,
            f"at most {MAX_POINTS} (a fit of {points} points needs about "
            f"{format_bytes(points * FIT_BYTES)}; thin the data)",
        )


def check_values(
    source: str,
    quantity: str,
    values: NDArray[np.float64],
    lines: Sequence[int] | None = None,
) -> None:
    """Measured values: some > 0, none above :data:`PLAUSIBLE_MAX`, none below 0 except as
    noise around 0.

    The quantities are ≥ 0; a value below 0 is measurement noise when it and its neighbours lie
    within NOISE × the largest value of 0 (the series is near 0 there); a larger negative value,
    or a negative one among clearly positive neighbours, is a sign or data error.
    """
    unit = SI_UNITS[QUANTITIES[quantity]]
    bound = PLAUSIBLE_MAX[quantity]
    peak = float(np.max(values)) if values.size else 0.0
    if not peak > 0.0:
        raise InputError(
            f"{source}: {quantity}", f"largest value {peak:g}", f"some values > 0 {unit}"
        )
    tol = NOISE * min(peak, bound)
    allowed = f"a measured {quantity} in [{-tol:.3g}, {bound:g}] {unit}"
    bad = np.flatnonzero(~((values >= -tol) & (values <= bound)))  # also NaN
    near_zero = np.abs(values) <= tol
    lone = (values < 0.0) & ~(np.r_[True, near_zero[:-1]] & np.r_[near_zero[1:], True])
    if bad.size or np.any(lone):
        row = int(bad[0]) if bad.size else int(np.flatnonzero(lone)[0])
        if not bad.size:
            allowed = f"≥ 0 {unit} (below 0 only as noise where the neighbours are near 0 too)"
        raise _refuse(source, quantity, row, lines, values[row], allowed)


def _unit_factor(source: str, name: str, unit: str | None, kind: str) -> float:
    """Factor that converts numbers in ``unit`` to the SI unit of ``kind`` (1 without unit)."""
    if unit is None or not unit.strip():
        return 1.0
    try:
        to_si(f"1 {unit.strip()}", "dimensionless")
    except ValueError:
        pass  # a dimensional unit: checked against the quantity below
    else:
        raise InputError(
            f"{source}: column {name!r}", f"[{unit}]", f"a unit of {kind}, not a dimensionless one"
        )
    try:
        factor = to_si(f"1 {unit.strip()}", kind)
    except ValueError as exc:
        raise InputError(f"{source}: column {name!r}", f"[{unit}]", str(exc)) from None
    if not (math.isfinite(factor) and factor > 0.0):
        raise InputError(f"{source}: column {name!r}", f"[{unit}]", "a unit with a positive scale")
    return factor


def _parse_header(source: str, header: list[str]) -> dict[str, tuple[int, str | None]]:
    """Column name → (index, unit or None)."""
    columns: dict[str, tuple[int, str | None]] = {}
    for index, cell in enumerate(header):
        match = _HEADER.match(cell)
        if match is None:
            if not cell.strip():
                continue
            raise InputError(
                f"{source}: header column {index + 1}", cell, "a name such as 'wear_depth [um]'"
            )
        name, unit = match.group(1), match.group(2)
        if name in columns:
            raise InputError(f"{source}: header", name, "each column name once")
        columns[name] = (index, unit)
    return columns


@dataclass(frozen=True)
class _Layout:
    """What a table's header says: the measured quantity and, per column to read, its header
    position and the factor to SI (revolutions, measured quantity, then the schedule)."""

    quantity: str
    columns: tuple[tuple[str, int, float], ...]
    scheduled: tuple[str, ...]
    """The schedule columns read: none, or speed and axial_load[, stroke]."""


def _layout(source: str, header: Sequence[str]) -> _Layout:
    """Read a header row: ``revolutions``, exactly one measured column, optional schedule."""
    columns = _parse_header(source, header)
    if "revolutions" not in columns:
        raise InputError(
            f"{source}: header", ",".join(header), "a 'revolutions' column (screw revolutions)"
        )
    measured = [name for name in QUANTITIES if name in columns]
    allowed = "exactly one of " + ", ".join(QUANTITIES)
    if len(measured) != 1:
        raise InputError(f"{source}: measured column", measured or ",".join(header), allowed)
    quantity = measured[0]
    rev_index, rev_unit = columns["revolutions"]
    if rev_unit is not None and rev_unit.strip() not in ("", "rev", "revolutions", "1"):
        raise InputError(f"{source}: column 'revolutions'", f"[{rev_unit}]", "no unit or [rev]")
    scheduled = [name for name in SCHEDULE if name in columns]
    if scheduled and len(scheduled) != len(SCHEDULE):
        raise InputError(f"{source}: schedule columns", scheduled, "both speed and axial_load")
    if "stroke" in columns:
        if not scheduled:
            raise InputError(f"{source}: stroke column", "without speed", "speed and axial_load")
        scheduled.append("stroke")
    kinds = {quantity: QUANTITIES[quantity]} | {
        name: (SCHEDULE | SCHEDULE_STROKE)[name] for name in scheduled
    }
    read = [("revolutions", rev_index, 1.0)] + [
        (name, columns[name][0], _unit_factor(source, name, columns[name][1], kind))
        for name, kind in kinds.items()
    ]
    return _Layout(quantity, tuple(read), tuple(scheduled))


_Column = Sequence[object] | NDArray[Any]
"""A table column's cells: a sequence of cells, or a numeric array (:func:`_cells`)."""


def _numbers(
    source: str, name: str, cells: _Column, lines: Sequence[int] | None
) -> NDArray[np.float64]:
    """The cells of one column as floats; a cell that is no number names its row (the file's
    ``line`` where ``lines`` gives it, else ``row`` counted from 1). A numeric array (a NumPy or
    pandas column of ints or floats, :func:`_cells`) holds no cell to check: converted at once."""
    if isinstance(cells, np.ndarray) and cells.dtype.kind in "fiu":
        return cells.astype(np.float64)
    numbers = np.empty(len(cells))
    for row, cell in enumerate(cells):
        text = cell.strip() if isinstance(cell, str) else cell
        try:
            if isinstance(text, bool | np.bool_):  # float(True) is 1.0: no measured number
                raise TypeError
            numbers[row] = float(text)  # type: ignore[arg-type]
        except (TypeError, ValueError):
            shown = text if isinstance(text, str | int | float) else repr(text)
            where = f"row {row + 1}" if lines is None else f"line {lines[row]}"
            raise InputError(f"{source}: {where}, column {name!r}", shown, "a number") from None
    return numbers


def _history(
    source: str,
    layout: _Layout,
    cells: Mapping[str, _Column],
    lines: Sequence[int] | None,
    min_points: int,
    notes: tuple[str, ...] = (),
) -> MeasuredHistory:
    """The history of a table's cells (column name → cells), converted to SI."""
    values = {
        name: _numbers(source, name, cells[name], lines) * factor
        for name, _, factor in layout.columns
    }
    schedule = (
        np.column_stack([values[name] for name in layout.scheduled]) if layout.scheduled else None
    )
    return measured_history(
        values["revolutions"],
        values[layout.quantity],
        layout.quantity,
        source=source,
        min_points=min_points,
        schedule=schedule,
        notes=notes,
        lines=lines,
    )


def read_measured(path: str | Path, min_points: int = 2) -> MeasuredHistory:
    """Read a measured history from a CSV file (format in the module docstring).

    Args:
        path: the CSV file.
        min_points: the least number of data rows accepted (the fit needs more points than
            parameters).

    Returns:
        The history in SI units, revolutions strictly increasing.

    Raises:
        InputError: unreadable file, no header, missing ``revolutions`` column, none or more
            than one measured column, a unit of the wrong dimension, a non-numeric or missing
            cell, a row with more cells than the header, revolutions that are negative or not
            strictly increasing, too few rows.
    """
    path = Path(path)
    source = path.name
    try:
        size = path.stat().st_size
        check_memory("--measured", str(path), READ_FACTOR * size, f"reading {size} bytes of CSV")
        text = path.read_text(encoding="utf-8-sig")
    except OSError as exc:
        raise InputError("--measured", str(path), f"a readable CSV file ({exc.strerror})") from None
    except UnicodeDecodeError:
        raise InputError("--measured", str(path), "a UTF-8 text (CSV) file") from None
    numbered = [
        (number, line)
        for number, line in enumerate(text.splitlines(), start=1)
        if line.strip() and not line.lstrip().startswith("#")
    ]
    if not numbered:
        raise InputError("--measured", str(path), "a CSV file with a header row and data rows")
    _check_count(source, len(numbered) - 1)
    rows = list(csv.reader(line for _, line in numbered))
    header, rows = rows[0], rows[1:]
    layout = _layout(source, header)
    lines = [number for number, _ in numbered[1:]]
    for line_number, row in zip(lines, rows, strict=True):
        if any(cell.strip() for cell in row[len(header) :]):
            raise InputError(
                f"{source}: line {line_number}",
                ",".join(row),
                f"at most {len(header)} cells, one per header column ({','.join(header)})",
            )
    cells = {
        name: [row[index] if index < len(row) else "" for row in rows]
        for name, index, _ in layout.columns
    }
    return _history(source, layout, cells, lines, min_points, _leading_comments(text))


TABLES = (
    "a CSV path, a pandas DataFrame or a dict of columns with a 'revolutions' column and one "
    f"of {', '.join(QUANTITIES)} (units in brackets), an (n, 2) array or a MeasuredHistory"
)
"""What :func:`ballscrew.calibrate` accepts as measured data, for error messages."""


def read_table(table: object, min_points: int = 2) -> MeasuredHistory:
    """Read a measured history from a table in memory with the header rules of a CSV file.

    Args:
        table: a pandas DataFrame (e.g. ``pandas.read_csv(path, comment="#")`` of a measured
            file) or a dict of columns (``{"revolutions": [...], "wear_depth [um]": [...]}``);
            the column names carry the units as in a CSV header.
        min_points: the least number of rows accepted.

    Raises:
        InputError: a table of another kind, or anything :func:`read_measured` refuses (the
            rows are named ``row N``, counted from 1).
    """
    if isinstance(table, Mapping):
        source, names = "dict", list(table)
    elif hasattr(table, "columns") and hasattr(table, "__getitem__"):
        source, names = "DataFrame", list(table.columns)  # type: ignore[attr-defined]
    else:
        raise InputError("measured", type(table).__name__, TABLES)
    bad = [name for name in names if not isinstance(name, str)]
    if bad:
        raise InputError(f"{source}: column name", bad[0], "a name such as 'wear_depth [um]'")
    layout = _layout(source, names)
    cells = {name: _cells(table[names[index]]) for name, index, _ in layout.columns}  # type: ignore[index]
    lengths = {len(values) for values in cells.values()}
    if len(lengths) > 1:
        raise InputError(f"{source}: column lengths", sorted(lengths), "columns of one length")
    _check_count(source, lengths.pop())
    return _history(source, layout, cells, None, min_points)


def _cells(column: object) -> _Column:
    """A column's cells as a flat sequence (a pandas Series, list, tuple, array or generator);
    a numeric NumPy or pandas column stays an array (its cells are numbers: no check by cell)."""
    if isinstance(column, Iterator):  # a generator: its items, not one cell holding it
        column = list(column)
    to_numpy = getattr(column, "to_numpy", None)
    if callable(to_numpy):
        column = to_numpy()
    if isinstance(column, np.ndarray) and column.dtype.kind in "fiu":
        return column.reshape(-1)
    array = np.asarray(column, dtype=object)
    return list(array.reshape(-1)) if array.ndim else [array.item()]


def _leading_comments(text: str) -> tuple[str, ...]:
    """The ``#`` lines before the first other non-blank line, without their ``#`` (blank ones
    and a bare ``#`` left out)."""
    notes = []
    for line in map(str.strip, text.splitlines()):
        if line and not line.startswith("#"):
            break
        if line[1:].strip():
            notes.append(line[1:].strip())
    return tuple(notes)
