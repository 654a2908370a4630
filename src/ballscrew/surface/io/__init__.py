"""Profile readers: CSV/text and ISO 25178-71 / BCR SDF, dispatched by :func:`read_profile`."""

from __future__ import annotations

from pathlib import Path

from ballscrew.surface.io._common import file_error, file_path
from ballscrew.surface.io.sdf import SDF_MAGIC, read_sdf, write_sdf
from ballscrew.surface.io.text import read_text_profile, write_text_profile
from ballscrew.surface.profile import Profile

__all__ = [
    "TEXT_EXTENSIONS",
    "read_profile",
    "read_sdf",
    "read_text_profile",
    "write_sdf",
    "write_text_profile",
]

#: File extensions read as CSV/text profiles.
TEXT_EXTENSIONS = (".csv", ".txt", ".dat", ".asc", ".tsv", ".prf")
_FORMATS = "CSV/text (" + ", ".join(TEXT_EXTENSIONS) + ") or ISO 25178-71/BCR SDF (.sdf)"


def read_profile(
    path: str | Path,
    *,
    format: str | None = None,
    spacing: float | str | None = None,
    x_unit: str | None = None,
    z_unit: str | None = None,
) -> Profile:
    """Read a measured profile (or areal measurement) into a :class:`Profile` in SI units.

    The format is ``format`` (``"sdf"`` or ``"text"``) if given, else the file's first bytes
    (``aBCR``/``aISO``/``bBCR``/``bISO`` → SDF), else its extension (``.sdf``; ``.csv``,
    ``.txt``, ``.dat``, ``.asc``, ``.tsv``, ``.prf`` → text), else text if it has no NUL bytes.
    ``spacing``, ``x_unit`` and ``z_unit`` apply to text files (see
    :func:`~ballscrew.surface.io.text.read_text_profile`).

    Raises:
        InputError: naming the file for a missing, empty or unrecognised file, and the field
            for a bad one.
    """
    path = file_path(path)
    if not path.is_file():
        raise file_error(path, "", str(path), "an existing profile file")
    with path.open("rb") as handle:
        head = handle.read(4096)
    if not head.strip():
        raise file_error(path, "", "an empty file", f"a profile file: {_FORMATS}")
    kind = (format.lower() or None) if isinstance(format, str) else format
    if kind not in (None, "sdf", "text"):
        raise file_error(path, "format", format, "'sdf' or 'text'")
    suffix = path.suffix.lower()
    if kind is None:
        if head.startswith(SDF_MAGIC) or suffix == ".sdf":
            kind = "sdf"
        elif suffix in TEXT_EXTENSIONS or b"\x00" not in head:
            kind = "text"
        else:
            raise file_error(path, "format", f"unknown ({suffix or 'no extension'})", _FORMATS)
    if kind == "sdf":
        if any(v is not None for v in (spacing, x_unit, z_unit)):
            raise file_error(path, "options", "spacing/x_unit/z_unit", "none for SDF (SI)")
        return read_sdf(path)
    return read_text_profile(path, spacing=spacing, x_unit=x_unit, z_unit=z_unit)
