"""Building blocks of the case models: the strict base model and unit-aware float fields."""

from __future__ import annotations

import difflib
import unicodedata
from collections.abc import Iterable
from functools import partial
from typing import Annotated, Any, Literal, get_args, get_origin

from pydantic import (
    AfterValidator,
    BaseModel,
    BeforeValidator,
    ConfigDict,
    Field,
    ValidationInfo,
    field_validator,
)

from ballscrew.registry import Registry
from ballscrew.units import SI_UNITS, to_si

#: Highest screw speed a case accepts, rad/s (about 10⁶ rpm, far above any ball screw).
MAX_SPEED = 1e5

#: Largest force a case accepts (preload, axial loads), N.
MAX_FORCE = 1e8


def nearest_hint(name: str, allowed: Iterable[str]) -> str:
    """``" (did you mean 'lead'?)"``: the ``allowed`` name nearest ``name`` (difflib), or ``""``."""
    near = difflib.get_close_matches(name, list(allowed), n=1)
    return f" (did you mean '{near[0]}'?)" if near else ""


def quantity(kind: str, description: str, **constraints: float) -> Any:
    """An annotated float field that accepts finite SI numbers or unit strings of ``kind``."""
    extra = {"unit": SI_UNITS[kind], "kind": kind}
    return Annotated[
        float,
        BeforeValidator(partial(to_si, kind=kind)),
        Field(description=description, json_schema_extra=extra, **constraints),
    ]


def model_choice(registry: Registry[Any], description: str) -> Any:
    """A string field naming one model of ``registry``; the allowed names come from it."""

    def check(name: str) -> str:
        if name not in registry:
            raise ValueError(f"is not allowed: it must be one of {', '.join(registry)}")
        return name

    return Annotated[
        str,
        AfterValidator(check),
        Field(description=description, json_schema_extra={"enum": list(registry)}),
    ]


def _accepts_bool(annotation: Any) -> bool:
    """Whether a field of type ``annotation`` takes a boolean (``bool``, ``bool | None``, a
    ``Literal`` of booleans, ``Any``)."""
    if annotation is bool or annotation is Any:
        return True
    if get_origin(annotation) is Literal:
        return any(isinstance(v, bool) for v in get_args(annotation))
    return any(_accepts_bool(a) for a in get_args(annotation) if a is not annotation)


class Model(BaseModel):
    """Base of every case section: unknown keys are rejected, instances are immutable.

    No float field accepts inf or NaN.
    """

    model_config = ConfigDict(
        extra="forbid", frozen=True, validate_default=True, allow_inf_nan=False
    )

    @field_validator("*", mode="before")
    @classmethod
    def _no_bool_for_a_number(cls, value: Any, info: ValidationInfo) -> Any:
        """Refuse ``true``/``false`` where the field takes no boolean (pydantic would read
        ``balls_per_nut = true`` as 1)."""
        if isinstance(value, bool) and info.field_name is not None:
            if not _accepts_bool(cls.model_fields[info.field_name].annotation):
                raise ValueError("is not allowed: a number or text, not true/false")
        return value

    @field_validator("*", mode="after")
    @classmethod
    def _no_control_characters(cls, value: Any) -> Any:
        """Refuse text with control characters (NUL, ESC, …; tab and line breaks pass): a NUL
        cannot be stored in a NetCDF attribute, an escape sequence would drive the terminal."""
        if isinstance(value, str) and any(
            unicodedata.category(c) == "Cc" and c not in "\t\n\r" for c in value
        ):
            raise ValueError("is not allowed: text without control characters (NUL, ESC, …)")
        return value
