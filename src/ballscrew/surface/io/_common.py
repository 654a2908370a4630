"""Helpers shared by the profile readers: errors that name the file, unit factors."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from ballscrew.errors import InputError
from ballscrew.surface.profile import Profile
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


def file_path(path: Any) -> Path:
    """``path`` as a :class:`Path` if it is a string or path-like object."""
    if not isinstance(path, str | os.PathLike) or not str(path):
        raise InputError("path", path, "a file path (a non-empty string or os.PathLike)")
    return Path(path)


def checked_profile(profile: Any) -> Profile:
    """``profile`` if it is a :class:`Profile` (writers need its spacing and rows)."""
    if not isinstance(profile, Profile):
        raise InputError("profile", type(profile).__name__, "a ballscrew.surface.Profile")
    return profile
