"""The one result protocol every analysis returns, and the descriptor of an analysis.

A result is immutable and knows how to present itself:

* :meth:`AnalysisResult.summary` — scalars, each ``{"value": …, "unit": …}`` in SI (nested
  dictionaries and lists allowed), in plain JSON types only (:func:`json_ready`): a number
  that is not defined (NaN) is ``{"value": None, "unit": …, "reason": …}``; ``summary.json``
  is this plus the warnings and the inputs;
* :meth:`AnalysisResult.to_xarray` — fields and histories with ``units`` attributes, always
  one :class:`xarray.Dataset` (several histories or spectra of different lengths each have
  their own dimension), written as ``<dataset_name>.nc`` (``fields.nc`` unless the result
  names it);
* :meth:`AnalysisResult.figures` — :class:`Figure` objects that draw a PNG on demand;
* :meth:`AnalysisResult.report` — the report's :class:`Section` objects;
* :attr:`AnalysisResult.inputs` — the resolved case, each value with its unit;
* :attr:`AnalysisResult.warnings` — what the user must know about the numbers.

The generic writer (:func:`ballscrew.results.write_results`) turns any such object into a
results folder; an :class:`Analysis` descriptor ties an analysis to the command line, the
sweeps and the index page.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path
from types import ModuleType
from typing import Any, ClassVar, Protocol, runtime_checkable

import numpy as np
import xarray as xr

from ballscrew.case.inputs import resolved_inputs
from ballscrew.registry import Registry
from ballscrew.thread_warnings import record_warnings

__all__ = [
    "ANALYSES",
    "Analysis",
    "AnalysisResult",
    "Figure",
    "Presented",
    "Section",
    "Table",
    "json_ready",
    "quantity",
    "recorded_warnings",
]


#: Why a summary number is None when its producer gives no reason of its own.
UNDEFINED = "not defined for this run (the computation gave no finite number)"
INFINITE = {True: "infinite (+∞): no limit", False: "infinite (−∞)"}
"""The reason given for a value of ±∞ (a lifted-off nut's resistance, a life without load)."""


def _reason(number: float) -> str:
    """Why the non-finite ``number`` is given as None: :data:`INFINITE` for ±∞, else
    :data:`UNDEFINED`."""
    return INFINITE[number > 0] if math.isinf(number) else UNDEFINED


def quantity(number: float, unit: str, undefined: str | None = None) -> dict[str, Any]:
    """A summary scalar with its SI unit, e.g. ``{"value": 1.35e9, "unit": "Pa"}``.

    JSON has no NaN: a number that is not finite is ``{"value": None, "unit": unit, "reason":
    …}``, the reason ``undefined`` where the caller says why (e.g. "not reached within the
    transient"), else that of :func:`json_ready` (infinite for ±∞, not defined for NaN).
    """
    number = float(number)
    if math.isfinite(number):
        return {"value": number, "unit": unit}
    return {"value": None, "unit": unit, "reason": undefined or _reason(number)}


def json_ready(obj: Any) -> Any:
    """``obj`` in plain JSON types, so ``json.dumps(obj, allow_nan=False)`` always works.

    NumPy scalars and arrays become Python numbers and lists, tuples lists, keys strings; a
    non-finite float becomes None, and a ``{"value": …, "unit": …}`` quantity whose value is
    None gets a ``reason`` (:data:`UNDEFINED` unless it has one).
    """
    if isinstance(obj, Mapping):
        out = {str(k): json_ready(v) for k, v in obj.items()}
        if "unit" in out and "value" in out and out["value"] is None:
            raw = obj["value"]
            out.setdefault(
                "reason", _reason(raw) if isinstance(raw, float | np.floating) else UNDEFINED
            )
        return out
    if isinstance(obj, list | tuple):
        return [json_ready(v) for v in obj]
    if isinstance(obj, np.ndarray):
        return json_ready(obj.tolist())
    if isinstance(obj, np.generic):
        return json_ready(obj.item())
    if isinstance(obj, float) and not math.isfinite(obj):
        return None
    return obj


@contextmanager
def recorded_warnings() -> Iterator[list[str]]:
    """Record the warnings raised inside the block (one line each) and raise them again.

    The list fills when the block ends; a result stores it as its ``warnings``, and the warnings
    still reach the console or the caller's filters.
    """
    messages: list[str] = []
    with record_warnings() as caught:  # this thread's alone (sweep points run in threads)
        yield messages
    for w in caught:
        text = " ".join(str(w.message).split())
        if text not in messages:  # each warning once, however often the physics raised it
            messages.append(text)
            warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)


@dataclass(frozen=True)
class Figure:
    """A figure of a result: ``draw(path)`` writes the PNG to ``path`` and returns it."""

    name: str
    """File stem of the PNG (``pressure_screw`` → ``pressure_screw.png``)."""
    caption: str
    draw: Callable[[Path], Path]


@dataclass(frozen=True)
class Table:
    """A report table: a header row and rows of cells (floats to four significant figures)."""

    header: tuple[str, ...]
    rows: tuple[tuple[object, ...], ...]


@dataclass(frozen=True)
class Section:
    """One report section: a heading, paragraphs, tables and figures (in that order)."""

    title: str
    paragraphs: tuple[str, ...] = ()
    tables: tuple[Table, ...] = ()
    figures: tuple[str, ...] = ()
    """Names of the result's :class:`Figure` objects shown in this section."""


@runtime_checkable
class AnalysisResult(Protocol):
    """What every analysis returns (see the module docstring)."""

    @property
    def analysis(self) -> str:
        """Name of the analysis that produced the result (``"contact"``, ``"tcr"``, …)."""

    @property
    def title(self) -> str:
        """Title of the report."""

    @property
    def inputs(self) -> Mapping[str, Any]:
        """The resolved inputs, each value with its unit."""

    @property
    def warnings(self) -> tuple[str, ...]:
        """Warnings about the numbers, one line each."""

    def summary(self) -> dict[str, Any]:
        """Scalars with their SI units, in plain JSON types (:func:`json_ready`)."""

    def to_xarray(self) -> xr.Dataset:
        """Fields and histories with units, one dataset."""

    def figures(self) -> Sequence[Figure]:
        """The figures of the report."""

    def report(self) -> Sequence[Section]:
        """The sections of the report, after the inputs and the warnings."""


class Presented:
    """The protocol's methods for a result class whose presentation is one module.

    The class sets ``presentation`` to a module with ``summary(result)``, ``fields(result)``,
    ``figures(result)`` and ``sections(result)``; ``inputs`` resolves the result's ``case``.
    ``summary()`` is made JSON-ready here, so a presentation may hand back NumPy values.
    """

    presentation: ClassVar[ModuleType]
    dataset_name: ClassVar[str] = "fields"
    """File stem of :meth:`to_xarray` in a results folder (``fields`` → ``fields.nc``)."""

    @property
    def inputs(self) -> dict[str, Any]:
        return resolved_inputs(self.case)  # type: ignore[attr-defined]

    def summary(self) -> dict[str, Any]:
        return json_ready(self.presentation.summary(self))

    def to_xarray(self) -> xr.Dataset:
        return self.presentation.fields(self)

    def figures(self) -> list[Figure]:
        return self.presentation.figures(self)

    def report(self) -> list[Section]:
        return self.presentation.sections(self)


@dataclass(frozen=True)
class Analysis:
    """Descriptor of an analysis: what the command line, sweeps and the index know of it."""

    name: str
    """Command and sweep name (``ballscrew NAME``, ``--analysis NAME``)."""
    title: str
    """One line for help texts."""
    scalars: Callable[[Any], dict[str, tuple[float, str]]] | None = None
    """Sweepable scalars of a case, ``name → (value, SI unit)``; None = not sweepable."""
    headlines: tuple[str, ...] = field(default_factory=tuple)
    """Dotted ``summary.json`` keys the index page shows for a results folder."""
    labels: Mapping[str, str] = field(default_factory=dict)
    """Words for headline keys whose own words would mislead (default: the key as words)."""
    key_figure: str | None = None
    """The PNG the index page shows for a results folder (None: its first PNG)."""


ANALYSES: Registry[Analysis] = Registry("analysis", "--analysis")
"""Every analysis of the package, by name (filled by :mod:`ballscrew.analyses.catalog`)."""
