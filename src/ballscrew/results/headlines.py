"""The headline numbers of a result, in engineering units: for the console, the report and the
index page alike.

The numbers are the ``summary.json`` entries an :class:`~ballscrew.analyses.result.Analysis`
names as its ``headlines`` (SI, each with its unit); :func:`ballscrew.units.format_quantity`
shows each in engineering units with four significant figures and solver noise as 0.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

from ballscrew.analyses.catalog import ANALYSES
from ballscrew.results.display import readable
from ballscrew.units import display_kind, format_number, format_quantity

__all__ = ["format_entry", "headline_keys", "headline_label", "headline_rows", "label_of"]

label_of = readable
"""A dotted summary key in words: an alias of :func:`ballscrew.results.display.readable`."""


def format_entry(dotted: str, entry: Any) -> str | None:
    """A summary entry (``{"value", "unit"}`` or a plain number) as text; None if no number."""
    unit = ""
    if isinstance(entry, dict) and set(entry) == {"value", "unit"}:
        entry, unit = entry["value"], str(entry["unit"])
    if isinstance(entry, bool) or not isinstance(entry, int | float):
        return None
    if isinstance(entry, int):
        return str(entry)
    kind = display_kind(unit, dotted)
    if kind is None:  # a unit without an engineering display
        return f"{format_number(entry)} {unit}".rstrip()
    return format_quantity(entry, kind)


def _lookup(summary: dict[str, Any], dotted: str) -> Any:
    node: Any = summary
    for key in dotted.split("."):
        if not isinstance(node, dict) or key not in node:
            return None
        node = node[key]
    return node


def headline_keys(analysis: str) -> tuple[str, ...]:
    """The dotted summary keys ``analysis`` declares as its headlines (none if unknown)."""
    return ANALYSES[analysis].headlines if analysis in ANALYSES.names else ()


def headline_label(analysis: str) -> Callable[[str], str]:
    """Words of a headline key of ``analysis``: the label its descriptor gives, else the key as
    words (:func:`~ballscrew.results.display.readable`)."""
    labels = ANALYSES[analysis].labels if analysis in ANALYSES.names else {}
    return lambda key: labels.get(key) or readable(key)


def headline_rows(
    summary: dict[str, Any],
    keys: Sequence[str] = (),
    most: int = 8,
    label: Callable[[str], str] = readable,
) -> list[tuple[str, str]]:
    """(label, value with unit) of the entries ``keys`` of ``summary`` that are numbers; with
    no keys, of its first top-level numbers. At most ``most`` rows."""
    rows = []
    for key in keys or list(summary):
        text = format_entry(key, _lookup(summary, key))
        if text is not None:
            rows.append((label(key), text))
    return rows[:most]
