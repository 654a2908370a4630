"""Case values given on the command line: ``KEY=VALUE`` assignments (``--set``)."""

from __future__ import annotations

import tomllib
from collections.abc import Iterable
from typing import Any

from ballscrew.case.loader import CaseError

__all__ = ["parse_assignments", "parse_value"]


def parse_value(text: str) -> Any:
    """The value of one assignment: a TOML value (``2000``, ``true``, ``[8, 32]``,
    ``"1500 rpm"``) or else the text itself (``1500 rpm``, ``network``)."""
    try:
        return tomllib.loads(f"value = {text}")["value"]
    except ValueError:  # a TOML syntax error, or an integer of more than 4300 digits
        return text.strip()


def parse_assignments(texts: Iterable[str], option: str = "--set") -> dict[str, Any]:
    """Dotted case keys and values of ``KEY=VALUE`` texts, for :func:`ballscrew.load_case`.

    A value may carry a unit (``operating.speed=1500 rpm``); without one it is SI. The keys
    are checked when the overrides are applied; here only the form and repeated keys are.
    """
    values: dict[str, Any] = {}
    for text in texts:
        key, sep, value = text.partition("=")
        key = key.strip()
        if not sep or not key or not value.strip():
            raise CaseError(
                [f"{option} {text!r}: expected KEY=VALUE, e.g. operating.speed='1500 rpm'"], option
            )
        if key in values:
            raise CaseError([f"{option} {key}: the key is set twice; set each key once"], option)
        values[key] = parse_value(value)
    return values
