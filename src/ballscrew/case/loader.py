"""Reading, overriding and validating case files."""

from __future__ import annotations

import copy
import math
import os
import stat
import sys
import tomllib
import warnings
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from types import UnionType
from typing import Annotated, Any, Union, get_args, get_origin

from pydantic import BaseModel, ValidationError

from ballscrew.case.base import nearest_hint
from ballscrew.case.models import Case
from ballscrew.errors import BallscrewError
from ballscrew.units import parse_quantity, to_si


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
    if not isinstance(path, str | os.PathLike):
        raise CaseError([f"path = {path!r}: expected the path of a case file (str or Path)"])
    path = Path(path)
    raw = read_toml(path, "case file")
    raw.setdefault("name", path.stem)
    return case_from_dict(raw, overrides, source=str(path))


#: Largest TOML file read (a case is a few kB).
MAX_FILE_BYTES = 1 << 20

#: Deepest nesting of tables and arrays in a TOML file (a case needs about 5).
MAX_NESTING = 32

_BOMS = {b"\xff\xfe": "UTF-16", b"\xfe\xff": "UTF-16"}


def read_toml(path: str | Path, what: str = "case file") -> dict[str, Any]:
    """The tables of the TOML file ``path``; one-line :class:`CaseError` naming it if unreadable.

    The file must be a regular file of at most :data:`MAX_FILE_BYTES` in UTF-8 (a leading byte
    order mark is skipped) nested at most :data:`MAX_NESTING` levels deep.
    """
    path = Path(path)
    try:
        if not stat.S_ISREG(os.stat(path).st_mode):  # a FIFO or device could block or never end
            raise CaseError([f"the {what} is not a regular file"], str(path))
        with path.open("rb") as file:
            data = file.read(MAX_FILE_BYTES + 1)
    except OSError as exc:
        raise CaseError([f"cannot read the {what} ({exc.strerror})"], str(path)) from None
    if len(data) > MAX_FILE_BYTES:
        raise CaseError([f"the {what} is larger than {MAX_FILE_BYTES} bytes"], str(path))
    return _parse_toml(_decode(data, path, what), path, what)


def _decode(data: bytes, path: Path, what: str) -> str:
    """``data`` as UTF-8 text without a byte order mark."""
    if data[:2] in _BOMS:
        raise CaseError([f"the {what} is UTF-16 text; save it as UTF-8"], str(path))
    try:
        return data.decode("utf-8").removeprefix("\ufeff")
    except UnicodeDecodeError as exc:
        problem = f"the {what} is not UTF-8 text (byte {exc.start + 1}); save it as UTF-8"
        raise CaseError([problem], str(path)) from None


def _parse_toml(text: str, path: Path, what: str) -> dict[str, Any]:
    """Parse TOML ``text``, refusing syntax errors and too deep nesting."""
    too_deep = CaseError([f"the {what} is nested deeper than {MAX_NESTING} levels"], str(path))
    try:
        raw = tomllib.loads(text)
    except ValueError as exc:  # a syntax error, or an integer of more than 4300 digits
        raise CaseError([f"TOML syntax error: {exc}"], str(path)) from None
    except RecursionError:
        raise too_deep from None
    if _depth(raw) > MAX_NESTING:
        raise too_deep
    return raw


def _depth(value: Any) -> int:
    """Nesting depth of dicts and lists in ``value`` (0 for a scalar), without recursion."""
    deepest, stack = 0, [(value, 0)]
    while stack:
        node, depth = stack.pop()
        children = (
            node.values() if isinstance(node, dict) else node if isinstance(node, list) else None
        )
        if children is not None:
            deepest = max(deepest, depth + 1)
            if depth + 1 <= MAX_NESTING:
                stack.extend((child, depth + 1) for child in children)
    return deepest


def case_from_dict(
    raw: Mapping[str, Any],
    overrides: Mapping[str, Any] | None = None,
    source: str = "case",
    known: Sequence[str] = (),
) -> Case:
    """Validate a case given as nested dictionaries (as read from TOML); warn about each
    implausible value (:mod:`ballscrew.case.plausibility`) not among the ``known`` messages."""
    if not isinstance(raw, Mapping):
        raise CaseError([f"expected tables of keys, not {type(raw).__name__}"], source)
    data = apply_overrides(raw, overrides or {}, source)
    check_assumed_keys(data, source)
    if overrides and isinstance(data.get("assumed"), dict):  # a value written now is chosen
        data["assumed"] = {
            key: why
            for key, why in data["assumed"].items()
            if not any(key == k or key.startswith(f"{k}.") for k in map(str, overrides))
        }
    try:
        case = Case.model_validate(data)
    except ValidationError as exc:
        raise CaseError(describe_errors(exc), source) from None
    from ballscrew.case.plausibility import ImplausibleValueWarning, implausible_values

    for message in implausible_values(case):
        if message not in known:
            warnings.warn(
                f"{source}: {message}", ImplausibleValueWarning, stacklevel=_caller_level()
            )
    return case


def _caller_level() -> int:
    """The ``stacklevel`` that attributes a warning of the calling function to the first frame
    outside the ballscrew package: the user's script or notebook cell, not the loader."""
    package = os.path.dirname(os.path.dirname(os.path.abspath(__file__))) + os.sep
    frame, level = sys._getframe(1), 1
    while frame is not None and os.path.abspath(frame.f_code.co_filename).startswith(package):
        frame, level = frame.f_back, level + 1
    return level


def with_overrides(case: Case, overrides: Mapping[str, Any]) -> Case:
    """A new validated case: ``case`` with dotted-key ``overrides`` applied.

    The fields ``case`` left at their defaults stay marked unset (``model_fields_set``) unless
    an override writes them, so the defaults that are guesses are still reported as such."""
    from ballscrew.case.plausibility import implausible_values

    # the case's own implausible values were warned about when it was read
    known = implausible_values(case)
    new = case_from_dict(case.model_dump(), overrides, source=case.name, known=known)
    _keep_unset(case, new, [str(key).split(".") for key in overrides])
    return new


def check_assumed_keys(data: Mapping[str, Any], source: str = "case") -> None:
    """Raise :class:`CaseError` unless the ``[assumed]`` table of the raw case ``data`` maps
    quoted dotted keys that name inputs of :class:`Case` (a list entry by an index that
    exists, ``duty.0.stroke``) to reasons in quotes."""
    declared = data.get("assumed", {})
    example = '"screw.lead" = "why"'
    if not isinstance(declared, Mapping):
        problem = f"assumed = {declared!r} is not allowed: a table of {example} lines"
        raise CaseError([problem], source)
    for key, why in declared.items():
        keys = str(key).split(".")
        where = f'assumed."{key}"'
        if isinstance(why, Mapping):
            problem = f"assumed.{key}: write the dotted key in quotes, e.g. {example}"
            raise CaseError([problem], source)
        if not all(keys):
            problem = f"{where}: name an input by its dotted key, e.g. {example}"
            raise CaseError([problem], source)
        if keys[0] == "assumed":
            raise CaseError([f"{where}: name an input, not the [assumed] table"], source)
        try:
            check_field_path(keys, source)
        except CaseError as exc:
            raise CaseError([f"{where}: {exc.problems[0]}"], source) from None
        _check_entries_exist(keys, data, where, source)
        if not (isinstance(why, str) and why.strip()):
            problem = f"{where} = {why!r} is not allowed: a reason in quotes, e.g. {example}"
            raise CaseError([problem], source)


def _no_entry(keys: list[str], depth: int, node: list[Any]) -> str:
    """'duty has no entry 7 (entries: 0 to 1)': the list ``keys[:depth]`` lacks ``keys[depth]``."""
    entries = f"0 to {len(node) - 1}" if node else "none"
    return f"{'.'.join(keys[:depth])} has no entry {keys[depth]} (entries: {entries})"


def _check_entries_exist(keys: list[str], data: Any, where: str, source: str) -> None:
    """Raise :class:`CaseError` when a list index of ``keys`` names no entry of ``data``."""
    node = data
    for depth, key in enumerate(keys):
        if isinstance(node, list):
            if int(key) >= len(node):
                raise CaseError([f"{where}: {_no_entry(keys, depth, node)}"], source)
            node = node[int(key)]
        elif isinstance(node, Mapping):
            node = node.get(key)
        else:
            return


def _keep_unset(old: Any, new: Any, written: list[list[str]]) -> None:
    """Give each model of ``new`` (validated from the full dump of ``old``) the written fields
    of its counterpart in ``old`` plus those the ``written`` key paths end on; a path that ends
    on a section leaves that section as it was validated."""
    if isinstance(old, BaseModel) and type(old) is type(new):
        ends = {path[0] for path in written if len(path) == 1}
        fields = (set(old.model_fields_set) | ends) & set(type(new).model_fields)
        object.__setattr__(new, "__pydantic_fields_set__", fields)
        parts = [(name, getattr(old, name), getattr(new, name)) for name in type(new).model_fields]
    elif isinstance(old, list | tuple) and isinstance(new, list | tuple) and len(old) == len(new):
        ends = {path[0] for path in written if len(path) == 1}
        parts = [(str(k), a, b) for k, (a, b) in enumerate(zip(old, new, strict=True))]
    else:
        return
    for name, a, b in parts:
        if name not in ends:
            _keep_unset(a, b, [path[1:] for path in written if len(path) > 1 and path[0] == name])


def apply_overrides(
    raw: Mapping[str, Any], overrides: Mapping[str, Any], source: str = "case"
) -> dict[str, Any]:
    """Copy of ``raw`` with each dotted key of ``overrides`` set. The key must name a field; a
    list entry is named by its index (``duty.0.stroke``) and must exist."""
    if not isinstance(overrides, Mapping):
        problem = f"overrides must map dotted keys to values, not {type(overrides).__name__}"
        raise CaseError([problem], source)
    data = copy.deepcopy(dict(raw))
    for dotted, value in overrides.items():
        if not isinstance(dotted, str):
            raise CaseError([f"override key {dotted!r} is not a dotted key string"], source)
        keys = dotted.split(".")
        check_field_path(keys, source)
        node: Any = data
        for depth, key in enumerate(keys):
            if isinstance(node, list):
                if int(key) >= len(node):
                    raise CaseError([f"{dotted}: {_no_entry(keys, depth, node)}"], source)
                key = int(key)
            if depth == len(keys) - 1:
                node[key] = value
                break
            child = node[key] if isinstance(node, list) else node.get(key)
            if isinstance(child, tuple):
                child = list(child)
            if not isinstance(child, dict | list):
                child = {}
            node[key] = child
            node = child
    return data


def check_field_path(keys: list[str], source: str = "case") -> None:
    """Raise :class:`CaseError` unless ``keys`` walk down existing fields of :class:`Case`
    (an index after each list field)."""
    model: type[BaseModel] | None = Case
    listed = False
    for depth, key in enumerate(keys):
        where = ".".join(keys[:depth]) or "the case"
        if listed:
            listed = False
            if not (key.isascii() and key.isdigit()):
                problem = f"{'.'.join(keys)}: {where} is a list; name an entry, e.g. {where}.0"
                raise CaseError([problem], source)
            continue
        fields = model.model_fields if model is not None else {}
        if key not in fields:
            raise CaseError([unknown_key_message(".".join(keys), key, list(fields), where)], source)
        annotation = fields[key].annotation
        listed = any(get_origin(a) in (list, tuple) for a in _members(annotation))
        model = _submodel(annotation)


def _submodel(annotation: Any) -> type[BaseModel] | None:
    """The BaseModel class inside ``annotation`` (``X``, ``X | None``), if any."""
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return annotation
    for arg in getattr(annotation, "__args__", ()):
        found = _submodel(arg)
        if found is not None:
            return found
    return None


@dataclass(frozen=True)
class FieldSpec:
    """What the case model says about the value at one error location."""

    description: str = ""
    unit: str = ""
    kind: str = ""
    constraints: tuple[Any, ...] = ()
    dotted: str = ""
    annotation: Any = None


def _members(annotation: Any) -> list[Any]:
    """The non-None members of a union annotation (``[annotation]`` when it is no union)."""
    if get_origin(annotation) in (Union, UnionType):
        return [arg for arg in get_args(annotation) if arg is not type(None)]
    return [annotation]


def _pick_member(annotation: Any, tag: str) -> Any:
    """The member of a union that pydantic names ``tag`` in an error location."""
    members = _members(annotation)
    for member in members:
        origin = get_origin(member)
        if (origin in (tuple, list)) == tag.startswith(("tuple", "list")):
            return member
    return members[0]


def _element(annotation: Any, index: int) -> Any:
    """The annotation of item ``index`` of a tuple or list annotation."""
    for member in _members(annotation):
        args = get_args(member)
        if get_origin(member) is tuple and args:
            return args[-2 if args[-1] is Ellipsis else min(index, len(args) - 1)]
        if get_origin(member) is list and args:
            return args[0]
    return annotation


def _metadata(annotation: Any) -> list[Any]:
    """Constraint and FieldInfo objects inside ``annotation`` (through ``X | None``)."""
    members = _members(annotation)
    if len(members) != 1:
        return []
    if get_origin(members[0]) is Annotated:
        base, *meta = get_args(members[0])
        found = []
        for item in meta:
            found += [item, *getattr(item, "metadata", ())]
        return found + _metadata(base)
    return []


def field_spec(loc: tuple[Any, ...] | list[Any]) -> FieldSpec:
    """Description, unit, kind and constraints of the field at an error location ``loc``.

    ``loc`` may hold list or tuple indices and pydantic's union member tags; ``dotted`` is the
    field as the user wrote it (tags left out). An unknown key gives a spec with ``dotted`` only.
    """
    info, annotation, keys = None, Case, []
    for key in loc:
        model = _submodel(annotation)
        if isinstance(key, int):
            annotation = _element(annotation, key)
        elif model is not None and key in model.model_fields:
            info = model.model_fields[key]
            annotation = info.annotation
        elif len(_members(annotation)) > 1:
            annotation = _pick_member(annotation, str(key))
            continue
        else:
            info, annotation = None, None
        keys.append(str(key))
    if info is None:
        return FieldSpec(dotted=".".join(keys), annotation=annotation)
    found = [info, *info.metadata, *_metadata(annotation)]
    extra: dict[str, Any] = {}
    for item in found:
        if isinstance(getattr(item, "json_schema_extra", None), dict):
            extra = {**item.json_schema_extra, **extra}
    return FieldSpec(
        description=info.description or "",
        unit=str(extra.get("unit", "")),
        kind=str(extra.get("kind", "")),
        constraints=tuple(item for item in found if _bound_attrs(item)),
        dotted=".".join(keys),
        annotation=annotation,
    )


def unknown_key_message(dotted: str, key: str, allowed: list[str], where: str) -> str:
    """'unknown key' line with the nearest allowed spelling."""
    hint = nearest_hint(key, allowed)
    return f"{dotted}: unknown key{hint}; allowed in {where}: {', '.join(allowed)}"


_BOUNDS = {"greater_than", "greater_than_equal", "less_than", "less_than_equal", "finite_number"}


def _bound_attrs(item: Any) -> dict[str, float]:
    """The bounds (gt, ge, lt, le) that one constraint object sets."""
    return {
        a: getattr(item, a) for a in ("gt", "ge", "lt", "le") if getattr(item, a, None) is not None
    }


def _allowed_range(loc: tuple[Any, ...], unit: float = 1.0) -> str:
    """The interval a numeric field accepts, from its constraints, e.g. ``(0, 1.5708)``; in
    multiples of ``unit`` (its size in SI)."""
    low, high = "(-inf", "inf)"
    for constraint in field_spec(loc).constraints:
        bounds = _bound_attrs(constraint)
        for attr, fmt in (("gt", "({:.6g}"), ("ge", "[{:.6g}")):
            if attr in bounds:
                low = fmt.format(bounds[attr] / unit)
        for attr, fmt in (("lt", "{:.6g})"), ("le", "{:.6g}]")):
            if attr in bounds:
                high = fmt.format(bounds[attr] / unit)
    return f"{low}, {high}"


_TYPE_ERRORS = ("_type", "_parsing")

#: Most problems listed in one error (the rest are counted).
MAX_PROBLEMS = 20


def _prefixes(dotted: str) -> list[str]:
    """``dotted`` and each of its parents: ``a.b.c``, ``a.b``, ``a``."""
    parts = dotted.split(".")
    return [".".join(parts[:n]) for n in range(len(parts), 0, -1)]


def _union_duplicates(errors: list[dict[str, Any]]) -> set[int]:
    """Indices of type errors of one union member when another error of that field says more.

    Kept instead: any other kind of error of the field or one of its items, else the first
    type error.
    """
    fields = [field_spec(tuple(err["loc"])).dotted for err in errors]
    is_type = [err["type"].endswith(_TYPE_ERRORS) for err in errors]
    better = {p for f, t in zip(fields, is_type, strict=True) if not t for p in _prefixes(f)}
    skip, seen = set(), set()
    for i, field in enumerate(fields):
        if is_type[i]:
            if field in better or field in seen:
                skip.add(i)
            seen.update(_prefixes(field))
    return skip


def _range_text(loc: tuple[Any, ...], spec: FieldSpec) -> str:
    """'allowed range is … unit (description)' for a numeric field."""
    unit_text = f" {spec.unit}" if spec.unit else ""
    meaning = f" ({spec.description})" if spec.description else ""
    return f"allowed range is {_allowed_range(loc)}{unit_text}{meaning}"


def _range_in_given_unit(loc: tuple[Any, ...], spec: FieldSpec, given: Any) -> str:
    """For a value given with a unit other than the SI one (``'1e20 h'``): the allowed range in
    that unit, ``; in h: (0, 2.77778e+07]`` (none for temperatures, whose units are offset)."""
    if not isinstance(given, str) or not spec.kind or spec.kind == "temperature":
        return ""
    try:
        _, unit = parse_quantity(given)
        factor = to_si(f"1 {unit:~}", spec.kind) if unit is not None else 1.0
    except (ValueError, TypeError):
        return ""
    if unit is None or factor <= 0.0 or math.isclose(factor, 1.0):
        return ""
    return f"; in {unit:~}: {_allowed_range(loc, factor)}"


def _unit_hint(loc: tuple[Any, ...], spec: FieldSpec, given: Any) -> str:
    """For a number given without a unit: the unit in which it would be in range, if any."""
    from ballscrew.case.plausibility import unit_hint

    if isinstance(given, bool) or not isinstance(given, int | float) or not spec.kind:
        return ""
    bounds = [_bound_attrs(c) for c in field_spec(loc).constraints]

    def in_range(value: float) -> bool:
        return all(
            value > b.get("gt", -math.inf)
            and value >= b.get("ge", -math.inf)
            and value < b.get("lt", math.inf)
            and value <= b.get("le", math.inf)
            for b in bounds
        )

    return unit_hint(float(given), spec.kind, in_range)


def _describe(err: dict[str, Any]) -> str:
    """One readable line for one pydantic error."""
    loc = tuple(k for k in err["loc"] if not isinstance(k, int) or k >= 0)
    spec = field_spec(loc)
    dotted = spec.dotted or ".".join(str(k) for k in loc)
    kind = err["type"]
    if kind == "missing":
        unit = f", in {spec.unit}" if spec.unit else ""
        what = f" ({spec.description}{unit})" if spec.description else ""
        return f"{dotted} is missing{what}"
    if kind == "extra_forbidden":
        parent = field_spec(loc[:-1])
        model = _submodel(parent.annotation)
        allowed = list(model.model_fields) if model else []
        return unknown_key_message(dotted, str(loc[-1]), allowed, parent.dotted or "the case")
    if kind in _BOUNDS:
        hint = _unit_hint(loc, spec, err["input"]) + _range_in_given_unit(loc, spec, err["input"])
        return f"{dotted} = {err['input']!r} is not allowed: {_range_text(loc, spec)}{hint}"
    if kind == "literal_error":
        expected = err["ctx"]["expected"]
        return f"{dotted} = {err['input']!r} is not allowed: it must be one of {expected}"
    if kind == "value_error":
        message = str(err["ctx"]["error"])
        if " = " in message:  # a model validator naming its own field
            return f"{dotted}.{message}" if dotted else message
        if message.startswith("is not allowed"):  # a validator of the value itself
            return f"{dotted} = {err['input']!r} {message}"
        if spec.constraints or spec.kind:
            return f"{dotted}: {message}; {_range_text(loc, spec)}"
        return f"{dotted}: {message}"
    value = f" = {err['input']!r}" if "input" in err and loc else ""
    if spec.constraints:
        allowed = f"; {_range_text(loc, spec)}"
    else:  # no range to state: say what the field is
        allowed = f" ({spec.description})" if spec.description else ""
    return f"{dotted or 'case'}{value}: {err['msg']}{allowed}"


def describe_errors(exc: ValidationError) -> list[str]:
    """One readable line per pydantic error: field, value and allowed range."""
    errors = list(exc.errors())
    skip = _union_duplicates(errors)
    kept = [err for i, err in enumerate(errors) if i not in skip]
    lines = [_describe(err) for err in kept[:MAX_PROBLEMS]]
    if len(kept) > MAX_PROBLEMS:
        lines.append(f"... and {len(kept) - MAX_PROBLEMS} more problems")
    return lines
