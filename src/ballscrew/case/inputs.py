"""The resolved inputs of a case, each value with its SI unit, for summaries and reports."""

from __future__ import annotations

from typing import Any, get_args

from pydantic import BaseModel
from pydantic.fields import FieldInfo

__all__ = ["GUESS_MARKS", "field_unit", "guessed_defaults", "input_rows", "resolved_inputs"]

#: Words of a field description that label its default a guess.
GUESS_MARKS = ("GUESS", "ASSUMED")


def field_unit(info: FieldInfo) -> str | None:
    """SI unit of a quantity field (also inside ``X | None``), None for a plain field."""
    extra = info.json_schema_extra if isinstance(info.json_schema_extra, dict) else {}
    if "unit" in extra:
        return str(extra["unit"])
    return _annotation_unit(info.annotation)


def _annotation_unit(annotation: Any) -> str | None:
    for item in (*getattr(annotation, "__metadata__", ()), *get_args(annotation)):
        if isinstance(item, FieldInfo):
            unit = field_unit(item)
            if unit is not None:
                return unit
        elif item is not annotation and (get_args(item) or hasattr(item, "__metadata__")):
            unit = _annotation_unit(item)
            if unit is not None:
                return unit
    return None


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


def guessed_defaults(model: BaseModel, prefix: str = "") -> dict[str, str]:
    """Dotted key → description of every field of ``model`` (a validated case) that was left
    at a default its description labels a guess (:data:`GUESS_MARKS`), nested sections
    included; a value the user wrote, or None, is no guess."""
    found: dict[str, str] = {}
    for name, info in type(model).model_fields.items():
        value, key = getattr(model, name), f"{prefix}{name}"
        if isinstance(value, BaseModel):
            found |= guessed_defaults(value, key + ".")
        elif isinstance(value, list | tuple):
            for k, item in enumerate(value):
                if isinstance(item, BaseModel):
                    found |= guessed_defaults(item, f"{key}[{k}].")
        elif (
            value is not None
            and name not in model.model_fields_set
            and any(mark in (info.description or "") for mark in GUESS_MARKS)
        ):
            found[key] = info.description or ""
    return found
