"""Helpers shared by the profile readers: errors that name the file, unit factors."""

from __future__ import annotations

from pathlib import Path

from ballscrew.errors import InputError
from ballscrew.units import to_si


def file_error(path: str | Path, what: str, value: object, allowed: str) -> InputError:
    """An :class:`InputError` whose field names the file and the part of it (``what``)."""
    field = f"{Path(path).name}: {what}" if what else str(Path(path).name)
    err = InputError(field, value, allowed)
    err.path = str(path)  # type: ignore[attr-defined]
    return err


def length_factor(unit: str, path: str | Path, what: str) -> float:
    """Metres per ``unit`` (pint spelling: m, mm, um, µm, nm, Å, in…)."""
    if not isinstance(unit, str):
        raise file_error(path, what, unit, "a length unit (a string) such as mm, um or nm")
    text = unit.strip()
    if not text:
        return 1.0
    try:
        factor = to_si(f"1 {text}", "length")
    except ValueError:
        raise file_error(
            path, what, unit, "a length unit such as m, mm, um (µm), nm or angstrom"
        ) from None
    if not factor > 0.0:
        raise file_error(path, what, unit, "a length unit with a positive scale")
    return factor
