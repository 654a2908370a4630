"""Registries of rival published models: one name → model table per family.

A family (the raceway gap, the element thermal contact resistance, the thermal model, the drag
torque, …) has one :class:`Registry`. A model joins it with one decorated function::

    GAP_MODELS = Registry("gap model", "numerics.gap_model")

    @GAP_MODELS.register("quadratic", "Hertz quadratic gap")
    def quadratic_gap(...): ...

The case file's allowed names come from the table (``ballscrew.case`` validates against
:attr:`Registry.names`), and an unknown name is refused with the list of known ones.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass
from typing import Generic, TypeVar

from ballscrew.errors import InputError

__all__ = ["Entry", "Registry"]

T = TypeVar("T")


@dataclass(frozen=True)
class Entry(Generic[T]):
    """One registered model: its name, what it is, and the object that computes it."""

    name: str
    description: str
    model: T


class Registry(Mapping[str, T]):
    """An ordered name → model table of one family of rival models.

    Args:
        family: what the models compute, for messages ("gap model").
        field: the case key that selects one ("numerics.gap_model"), for messages.
    """

    def __init__(self, family: str, field: str) -> None:
        self.family = family
        self.field = field
        self._entries: dict[str, Entry[T]] = {}

    def register(self, name: str, description: str) -> Callable[[T], T]:
        """Decorator adding ``model`` under ``name``; a name can be registered once."""

        def add(model: T) -> T:
            self.add(name, description, model)
            return model

        return add

    def add(self, name: str, description: str, model: T) -> None:
        """Add ``model`` under ``name`` (not a decorator)."""
        if name in self._entries:
            raise ValueError(f"{self.family} {name!r} is registered twice")
        self._entries[name] = Entry(name, description, model)

    @property
    def names(self) -> tuple[str, ...]:
        """The registered names, in registration order."""
        return tuple(self._entries)

    def entry(self, name: str) -> Entry[T]:
        """The entry of ``name``; :class:`InputError` naming the known models otherwise."""
        try:
            return self._entries[name]
        except (KeyError, TypeError):
            raise InputError(self.field, name, f"one of {', '.join(self.names)}") from None

    def check(self, name: str) -> str:
        """``name`` if it is registered (for validators); :class:`InputError` otherwise."""
        return self.entry(name).name

    def __getitem__(self, name: str) -> T:
        return self.entry(name).model

    def __contains__(self, name: object) -> bool:
        return isinstance(name, str) and name in self._entries

    def __iter__(self) -> Iterator[str]:
        return iter(self._entries)

    def __len__(self) -> int:
        return len(self._entries)

    def describe(self) -> Mapping[str, str]:
        """name → description of every model, for help texts and reports."""
        return {name: e.description for name, e in self._entries.items()}
