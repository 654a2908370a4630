"""Profiles in CSV or plain text: one column (z) or two columns (x, z).

Format accepted by :func:`read_text_profile`:

* comment lines start with ``#``, ``%``, ``;`` or ``//``; a comment ``key = value`` or
  ``key: value`` sets ``spacing`` (also ``dx``, ``x_spacing``), ``x_unit`` or ``z_unit``,
  e.g. ``# spacing = 0.5 um``; other such pairs go to the metadata;
* an optional header line of column names with units in brackets or parentheses,
  ``x [um], z [nm]`` or ``position (mm); height (um)``;
* data rows separated by commas, semicolons, tabs or blanks, all with the same number of
  columns (1: z, needs a spacing; 2: x then z, x uniformly spaced);
* ``nan`` marks a non-measured point.

Units come from (in this order) the keyword arguments, the header, the comments; without any
the numbers are taken as metres (SI, as everywhere in ballscrew).
"""

from __future__ import annotations

import math
import re
from pathlib import Path
from typing import Any

import numpy as np

from ballscrew.errors import InputError
from ballscrew.surface.io._common import checked_profile, file_error, file_path, length_factor
from ballscrew.surface.profile import MIN_POINTS, Profile, sampling_range

__all__ = ["read_text_profile", "write_text_profile"]

_COMMENT = ("#", "%", ";", "//")
_META = re.compile(r"^\s*([A-Za-z_][\w .-]*?)\s*[:=]\s*(.+?)\s*$")
_COLUMN = re.compile(r"^\s*(?P<name>[^\[\(]*?)\s*[\[\(]\s*(?P<unit>[^\]\)]*?)\s*[\]\)]\s*$")
_HEADER_TOKEN = re.compile(r"[^\s\[\(]+(?:\s*[\[\(][^\]\)]*[\]\)])?")
_SPACING_KEYS = {"spacing", "dx", "x_spacing", "sampling_interval", "sampling interval"}
#: Largest allowed deviation of an x value from the uniform grid, in sampling intervals.
UNIFORM_TOLERANCE = 0.05


def _split(line: str, delimiter: str | None) -> list[str]:
    if delimiter is None:
        return line.split()
    return [field.strip() for field in line.split(delimiter)]


def _delimiter(line: str) -> str | None:
    for candidate in (",", ";", "\t"):
        if candidate in line:
            return candidate
    return None


def _floats(fields: list[str]) -> list[float] | None:
    try:
        return [float(f) for f in fields]
    except ValueError:
        return None


def _quantity(text: str, path: Path, what: str) -> float:
    """A length given as '0.5 um' (or a bare number, metres) → m."""
    match = re.match(r"^\s*([-+0-9.eE]+)\s*(.*)$", text)
    if not match:
        raise file_error(path, what, text, "a length such as '0.5 um'")
    try:
        number = float(match.group(1))
    except ValueError:
        raise file_error(path, what, text, "a length such as '0.5 um'") from None
    return number * length_factor(match.group(2), path, what)


def read_text_profile(
    path: str | Path,
    *,
    spacing: float | str | None = None,
    x_unit: str | None = None,
    z_unit: str | None = None,
) -> Profile:
    """Read a one- or two-column CSV/text profile into a :class:`Profile` (SI units).

    Args:
        path: the file.
        spacing: sampling interval for one-column files, m or a string such as ``"0.5 um"``
            (overrides a ``spacing`` comment).
        x_unit, z_unit: units of the columns (override the header and comments).

    Raises:
        InputError: naming the file and the part of it (line, column, spacing) that is wrong:
            an empty file, a row with a missing or extra column, a non-numeric value,
            non-uniform or non-monotonic x, an unknown unit, a missing spacing.
    """
    path = file_path(path)
    try:
        raw = path.read_bytes()
    except OSError as exc:
        raise file_error(path, "", str(path), f"a readable file ({exc.strerror})") from None
    if b"\x00" in raw:
        raise file_error(path, "format", "binary data", "a CSV or text profile")
    text = raw.decode("utf-8", errors="replace")
    meta: dict[str, Any] = {}
    header: list[str] | None = None
    rows: list[list[float]] = []
    delimiter: str | None = None
    n_cols = 0
    for number, line in enumerate(text.splitlines(), start=1):
        stripped = line.strip().lstrip("\ufeff")
        if not stripped:
            continue
        if stripped.startswith(_COMMENT):
            match = _META.match(stripped.lstrip("#%;/ "))
            if match:
                meta[match.group(1).strip().lower()] = match.group(2)
            continue
        if not rows and header is None:
            delimiter = _delimiter(stripped)
        fields = _split(stripped, delimiter)
        values = _floats(fields)
        if values is None:
            if delimiter is None:  # keep "z [um]" together in a blank-separated header
                fields = _HEADER_TOKEN.findall(stripped)
            if rows or header is not None:
                raise file_error(
                    path, f"line {number}", stripped[:60], "numbers only after the header line"
                )
            header = fields
            n_cols = len(fields)
            continue
        if n_cols == 0:
            n_cols = len(values)
        if len(values) != n_cols:
            raise file_error(
                path,
                f"line {number}",
                f"{len(values)} column(s)",
                f"{n_cols} column(s) like the {'header' if header else 'first row'}",
            )
        rows.append(values)
    if not rows:
        what = "data" if header is not None or meta else ""
        raise file_error(path, what, "no data rows", "a profile with numeric rows")
    if n_cols not in (1, 2):
        raise file_error(path, "columns", n_cols, "1 column (z) or 2 columns (x, z)")
    data = np.asarray(rows, dtype=np.float64)
    if data.shape[0] < MIN_POINTS:
        raise file_error(path, "data", f"{data.shape[0]} points", f"at least {MIN_POINTS} points")

    units = ["", ""] if n_cols == 2 else [""]
    names = ["x", "z"] if n_cols == 2 else ["z"]
    if header is not None:
        for i, column in enumerate(header):
            match = _COLUMN.match(column)
            if match:
                names[i] = match.group("name") or names[i]
                units[i] = match.group("unit")
            else:
                names[i] = column
    header_x_unit = units[0] if n_cols == 2 else ""
    x_u = x_unit if x_unit is not None else (header_x_unit or meta.get("x_unit", ""))
    z_u = z_unit if z_unit is not None else (units[-1] or meta.get("z_unit", ""))
    with np.errstate(over="ignore"):
        z = data[:, -1] * length_factor(z_u, path, f"unit of column {names[-1]!r}")
    if np.isinf(z).any():
        raise file_error(path, f"column {names[-1]!r}", "an infinite height", "finite or nan")

    if n_cols == 2:
        x = data[:, 0] * length_factor(x_u, path, f"unit of column {names[0]!r}")
        if not np.all(np.isfinite(x)):
            raise file_error(path, f"column {names[0]!r}", "non-finite x", "finite positions")
        if x[-1] < x[0]:
            x, z = x[::-1], z[::-1]
        index = np.arange(x.size, dtype=np.float64)
        step, start = np.polyfit(index, x, 1)
        deviation = np.abs(x - (start + step * index)).max() / step if step > 0 else math.inf
        if not (step > 0.0 and deviation <= UNIFORM_TOLERANCE):
            raise file_error(
                path,
                f"column {names[0]!r} (spacing)",
                f"non-uniform x (max deviation {deviation:.3g} sampling intervals)",
                f"uniformly spaced, increasing x (within {UNIFORM_TOLERANCE:g} of a step)",
            )
        dx = float(step)
        if spacing is not None:
            raise InputError("spacing", spacing, "given only for one-column files")
    else:
        if isinstance(spacing, bool | complex | np.complexfloating):
            raise InputError("spacing", spacing, "a sampling interval > 0 (m or '0.5 um')")
        if spacing is not None:
            source: object = spacing
            dx = _quantity(spacing, path, "spacing") if isinstance(spacing, str) else spacing
        else:
            key = next((k for k in meta if k in _SPACING_KEYS), None)
            if key is None:
                raise file_error(
                    path,
                    "spacing",
                    None,
                    "a sampling interval: spacing='0.5 um' or a '# spacing = 0.5 um' comment",
                )
            source = meta[key]
            dx = _quantity(source, path, "spacing")
            if x_u and not re.search(r"[A-Za-z\u00b5\u03bc\u00c5]", source):
                dx *= length_factor(x_u, path, "x_unit")  # a bare number is in x_unit
        try:
            dx = float(dx)
        except (TypeError, ValueError):
            raise file_error(path, "spacing", source, "a sampling interval > 0") from None
        if not (math.isfinite(dx) and dx > 0.0):
            raise file_error(path, "spacing", source, "a sampling interval > 0")
    allowed = sampling_range(dx, z.size)
    if allowed is not None:
        if n_cols == 1 and spacing is not None:
            raise InputError("spacing", spacing, allowed)
        what = f"column {names[0]!r} (spacing)" if n_cols == 2 else "spacing"
        raise file_error(path, what, dx if n_cols == 2 else source, allowed)
    meta.update(
        {
            "format": "text",
            "columns": names,
            "x_unit": x_u or "m",
            "z_unit": z_u or "m",
        }
    )
    return Profile(z, dx, None, meta, str(path))


def write_text_profile(
    path: str | Path,
    profile: Profile,
    *,
    x_unit: str = "um",
    z_unit: str = "nm",
    delimiter: str = ",",
) -> Path:
    """Write a single profile as two columns ``x [x_unit], z [z_unit]`` (CSV by default)."""
    profile = checked_profile(profile)
    if profile.n_profiles != 1:
        raise InputError("profile", f"{profile.n_profiles} rows", "a single profile")
    path = file_path(path)
    fx = length_factor(x_unit, path, "x_unit")
    fz = length_factor(z_unit, path, "z_unit")
    sep = delimiter if delimiter != " " else " "
    lines = ["# profile written by ballscrew", f"# spacing = {profile.spacing / fx:.12g} {x_unit}"]
    lines.append(f"x [{x_unit}]{sep}z [{z_unit}]")
    x = profile.x / fx
    z = np.asarray(profile.heights) / fz
    lines += [f"{xi:.12g}{sep}{zi:.12g}" for xi, zi in zip(x, z, strict=True)]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path
