"""The resolved inputs of a case, each value with its SI unit, for summaries and reports."""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from typing import Any, get_args

from pydantic import BaseModel
from pydantic.fields import FieldInfo

__all__ = [
    "GUESS_MARKS",
    "field_description",
    "field_unit",
    "guessed_defaults",
    "input_rows",
    "resolved_inputs",
]

#: Words of a field description that label its default a guess.
GUESS_MARKS = ("GUESS", "ASSUMED")


def _field_infos(info: FieldInfo) -> Iterator[FieldInfo]:
    """``info`` and the field infos inside its annotation (a quantity inside ``X | None``)."""
    yield info
    stack = [info.annotation]
    while stack:
        annotation = stack.pop()
        for item in (*getattr(annotation, "__metadata__", ()), *get_args(annotation)):
            if isinstance(item, FieldInfo):
                yield from _field_infos(item)
            elif item is not annotation and (get_args(item) or hasattr(item, "__metadata__")):
                stack.append(item)


def field_unit(info: FieldInfo) -> str | None:
    """SI unit of a quantity field (also inside ``X | None``), None for a plain field."""
    for item in _field_infos(info):
        extra = item.json_schema_extra if isinstance(item.json_schema_extra, dict) else {}
        if "unit" in extra:
            return str(extra["unit"])
    return None


def field_description(info: FieldInfo) -> str:
    """Description of a field (also of a quantity inside ``X | None``); empty if none."""
    return next((item.description for item in _field_infos(info) if item.description), "")


def _resolve(value: Any, unit: str | None) -> Any:
    if isinstance(value, BaseModel):
        return resolved_inputs(value)
    if isinstance(value, list | tuple):
        return [_resolve(v, unit) for v in value]
    if unit is not None and isinstance(value, int | float) and not isinstance(value, bool):
        return {"value": float(value), "unit": unit}
    return value


def resolved_inputs(model: BaseModel) -> dict[str, Any]:
    """Every field of a validated case (or section), defaults included.

    A quantity is ``{"value": v, "unit": "m"}`` in SI; sections are nested dictionaries.
    """
    fields = type(model).model_fields
    return {name: _resolve(getattr(model, name), field_unit(fields[name])) for name in fields}


def input_rows(inputs: dict[str, Any], prefix: str = "") -> list[tuple[str, Any, str]]:
    """(dotted key, value, unit) rows of :func:`resolved_inputs`, for a report table."""
    rows: list[tuple[str, Any, str]] = []
    for key, value in inputs.items():
        dotted = f"{prefix}{key}"
        if isinstance(value, dict) and set(value) == {"value", "unit"}:
            rows.append((dotted, value["value"], value["unit"]))
        elif isinstance(value, dict):
            rows += input_rows(value, dotted + ".")
        elif isinstance(value, list) and value and all(isinstance(v, dict) for v in value):
            for k, item in enumerate(value):
                rows += input_rows(item, f"{dotted}[{k}].")
        elif value is not None:
            rows.append((dotted, value, ""))
    return rows


def guessed_defaults(
    model: BaseModel, prefix: str = "", reads: Sequence[str] | None = None
) -> dict[str, str]:
    """Dotted key → description of every field of ``model`` (a validated case) that was left
    at a default its description labels a guess (:data:`GUESS_MARKS`), nested sections
    included; a value the user wrote is no guess, nor is None unless the description gives the
    guessed rule that None stands for (``None = d_m + 5 D_b [GUESS]``). The inputs a case
    declares in its own ``[assumed]`` table are listed too, with the reason it gives.

    ``reads``: dotted prefixes of the inputs an analysis reads
    (:data:`ballscrew.analyses.case_reads.CASE_READS`); only the keys under one of them are
    kept (None keeps all). Keys are given with ``prefix`` in front, matched without it."""
    found = _guessed(model, prefix)
    if reads is None:
        return found
    return {key: text for key, text in found.items() if _is_read(key[len(prefix) :], reads)}


def _is_read(key: str, reads: Sequence[str]) -> bool:
    """Whether the input ``key`` (``friction.circuits``, ``duty[0].stroke``) is one of or
    inside the dotted prefixes ``reads`` (``friction``, ``duty``)."""
    return any(key == p or key.startswith((p + ".", p + "[")) for p in reads)


def _guessed(model: BaseModel, prefix: str) -> dict[str, str]:
    found: dict[str, str] = {}
    for name, info in type(model).model_fields.items():
        value, key = getattr(model, name), f"{prefix}{name}"
        if isinstance(value, BaseModel):
            found |= _guessed(value, key + ".")
        elif isinstance(value, list | tuple):
            for k, item in enumerate(value):
                if isinstance(item, BaseModel):
                    found |= _guessed(item, f"{key}[{k}].")
        elif name not in model.model_fields_set:
            text = field_description(info)
            if (value is not None or "None = " in text) and any(m in text for m in GUESS_MARKS):
                found[key] = text
    conditional = getattr(model, "guessed_inputs", None)  # guesses that depend on other inputs
    if callable(conditional):
        found |= {prefix + name: text for name, text in conditional().items()}
    declared = getattr(model, "assumed", None)  # the case's own [assumed] table
    if isinstance(declared, dict):
        for dotted, why in declared.items():
            found[prefix + _row_key(dotted)] = f"{why} [ASSUMED in the case file]"
    return found


def _row_key(dotted: str) -> str:
    """An input key as :func:`input_rows` writes it: list indices in brackets
    (``duty.0.stroke`` → ``duty[0].stroke``)."""
    key = ""
    for part in dotted.split("."):
        key += f"[{part}]" if part.isdigit() else f".{part}" if key else part
    return key
