"""Reading, overriding and validating case files."""

from __future__ import annotations

import copy
import difflib
import tomllib
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from pydantic import BaseModel, ValidationError

from ballscrew.case.models import Case
from ballscrew.errors import BallscrewError


class CaseError(BallscrewError, ValueError):
    """A case file or an override is invalid. Each line of the message names one field."""

    def __init__(self, problems: list[str], source: str = "case") -> None:
        self.problems = problems
        self.source = source
        super().__init__("\n".join(f"{source}: {p}" for p in problems))


def load_case(path: str | Path, overrides: Mapping[str, Any] | None = None) -> Case:
    """Read a TOML case file, apply ``overrides`` and validate it.

    ``overrides`` maps dotted keys to values (SI numbers or unit strings), e.g.
    ``{"surface.D": 1.5, "operating.axial_load": 3000.0}``. Raises :class:`CaseError` with one
    line per problem, each naming the field, the value and the allowed range.
    """
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as exc:
        raise CaseError([f"cannot read the case file ({exc.strerror})"], str(path)) from None
    try:
        raw = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise CaseError([f"TOML syntax error: {exc}"], str(path)) from None
    raw.setdefault("name", path.stem)
    return case_from_dict(raw, overrides, source=str(path))


def case_from_dict(
    raw: Mapping[str, Any], overrides: Mapping[str, Any] | None = None, source: str = "case"
) -> Case:
    """Validate a case given as nested dictionaries (as read from TOML)."""
    data = apply_overrides(raw, overrides or {}, source)
    try:
        return Case.model_validate(data)
    except ValidationError as exc:
        raise CaseError(describe_errors(exc), source) from None


def with_overrides(case: Case, overrides: Mapping[str, Any]) -> Case:
    """A new validated case: ``case`` with dotted-key ``overrides`` applied."""
    return case_from_dict(case.model_dump(), overrides, source=case.name)


def apply_overrides(
    raw: Mapping[str, Any], overrides: Mapping[str, Any], source: str = "case"
) -> dict[str, Any]:
    """Copy of ``raw`` with each dotted key of ``overrides`` set. The key must name a field."""
    data = copy.deepcopy(dict(raw))
    for dotted, value in overrides.items():
        keys = dotted.split(".")
        check_field_path(keys, source)
        node = data
        for key in keys[:-1]:
            child = node.get(key)
            if not isinstance(child, dict):
                child = {}
                node[key] = child
            node = child
        node[keys[-1]] = value
    return data


def check_field_path(keys: list[str], source: str = "case") -> None:
    """Raise :class:`CaseError` unless ``keys`` walk down existing fields of :class:`Case`."""
    model: type[BaseModel] | None = Case
    for depth, key in enumerate(keys):
        fields = model.model_fields if model is not None else {}
        if key not in fields:
            where = ".".join(keys[:depth]) or "the case"
            raise CaseError([unknown_key_message(".".join(keys), key, list(fields), where)], source)
        model = _submodel(fields[key].annotation)


def _submodel(annotation: Any) -> type[BaseModel] | None:
    """The BaseModel class inside ``annotation`` (``X``, ``X | None``), if any."""
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return annotation
    for arg in getattr(annotation, "__args__", ()):
        found = _submodel(arg)
        if found is not None:
            return found
    return None


def _field_keys(loc: tuple[Any, ...]) -> list[str]:
    """The field names of an error location, without list indices (``programme.1.speed``)."""
    return [key for key in loc if isinstance(key, str)]


def _field_info(loc: tuple[Any, ...]) -> tuple[str, str]:
    """(description, SI unit) of the field at ``loc``, or empty strings if not found."""
    model: type[BaseModel] | None = Case
    info = None
    for key in _field_keys(loc):
        if model is None or key not in model.model_fields:
            return "", ""
        info = model.model_fields[key]
        model = _submodel(info.annotation)
    if info is None:
        return "", ""
    extra = info.json_schema_extra if isinstance(info.json_schema_extra, dict) else {}
    return info.description or "", str(extra.get("unit", ""))


def unknown_key_message(dotted: str, key: str, allowed: list[str], where: str) -> str:
    """'unknown key' line with the nearest allowed spelling."""
    near = difflib.get_close_matches(key, allowed, n=1)
    hint = f" (did you mean '{near[0]}'?)" if near else ""
    return f"{dotted}: unknown key{hint}; allowed in {where}: {', '.join(allowed)}"


_BOUNDS = {"greater_than", "greater_than_equal", "less_than", "less_than_equal"}


def _allowed_range(loc: tuple[Any, ...]) -> str:
    """The interval a numeric field accepts, from its constraints, e.g. ``(0, 1.5708)``."""
    model: type[BaseModel] | None = Case
    info = None
    for key in _field_keys(loc):
        info = model.model_fields.get(key) if model is not None else None
        model = _submodel(info.annotation) if info is not None else None
    low, high = "(-inf", "inf)"
    for constraint in info.metadata if info is not None else ():
        for attr, fmt in (("gt", "({:.6g}"), ("ge", "[{:.6g}")):
            if getattr(constraint, attr, None) is not None:
                low = fmt.format(getattr(constraint, attr))
        for attr, fmt in (("lt", "{:.6g})"), ("le", "{:.6g}]")):
            if getattr(constraint, attr, None) is not None:
                high = fmt.format(getattr(constraint, attr))
    return f"{low}, {high}"


def describe_errors(exc: ValidationError) -> list[str]:
    """One readable line per pydantic error: field, value and allowed range."""
    lines = []
    for err in exc.errors():
        loc = tuple(k for k in err["loc"] if not isinstance(k, int) or k >= 0)
        dotted = ".".join(str(k) for k in loc)
        kind = err["type"]
        description, unit = _field_info(loc)
        unit_text = f" {unit}" if unit else ""
        if kind == "missing":
            what = f" ({description}{', in ' + unit if unit else ''})" if description else ""
            lines.append(f"{dotted} is missing{what}")
        elif kind == "extra_forbidden":
            parent = loc[:-1]
            model: type[BaseModel] | None = Case
            for key in _field_keys(parent):
                field = model.model_fields.get(key) if model else None
                model = _submodel(field.annotation) if field else None
            allowed = list(model.model_fields) if model else []
            where = ".".join(str(k) for k in parent) or "the case"
            lines.append(unknown_key_message(dotted, str(loc[-1]), allowed, where))
        elif kind in _BOUNDS:
            meaning = f" ({description})" if description else ""
            lines.append(
                f"{dotted} = {err['input']!r} is not allowed: allowed range is "
                f"{_allowed_range(loc)}{unit_text}{meaning}"
            )
        elif kind == "literal_error":
            lines.append(
                f"{dotted} = {err['input']!r} is not allowed: it must be one of "
                f"{err['ctx']['expected']}"
            )
        elif kind == "value_error":
            message = str(err["ctx"]["error"])
            if " = " in message:  # a model validator naming its own field
                lines.append(f"{dotted}.{message}" if dotted else message)
            else:
                lines.append(f"{dotted}: {message}")
        else:
            value = f" = {err['input']!r}" if "input" in err and loc else ""
            lines.append(f"{dotted or 'case'}{value}: {err['msg']}")
    return lines
