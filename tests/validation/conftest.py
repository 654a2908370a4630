"""Validation suite: the ``validation`` recorder and the generated table ``docs/validation.md``.

Each test compares one model prediction with one published number (a measurement, or a maker's
worked example or formula, then called a *verification*) through ``validation.check(...)``. The
recorder computes the error, asserts it is within the stated tolerance, and keeps the record.
A case the current model is known to miss is declared with ``known_miss=True``: the test is then
marked ``xfail(strict=True)`` with the measured error in the reason, so the miss stays visible
(and a miss that starts to pass fails the run until the flag is removed). Data without a model
that can predict them are recorded with ``validation.not_compared(...)`` and the test is skipped.

At the end of a session in which every test of this directory ran, the records are written to
``docs/validation.md``.
"""

from __future__ import annotations

import copy
import dataclasses
import math
import re
import tomllib
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import pytest

HERE = Path(__file__).resolve().parent
DATA = HERE / "data"
ROOT = HERE.parents[1]
DOC = ROOT / "docs" / "validation.md"
EXAMPLES = ROOT / "examples"


@dataclass(frozen=True)
class Record:
    """One comparison of a prediction with published data."""

    id: str
    model: str
    source: str
    reference: dict[str, Any]
    quantity: str
    unit: str
    measured: float
    assumptions: tuple[str, ...]
    predicted: float | None = None
    tolerance: float | None = None
    relative: bool = True
    tolerance_basis: str = ""
    kind: str = "validation"
    status: str = ""
    note: str = ""

    @property
    def error(self) -> float | None:
        """Predicted − measured, relative to the measured value where the tolerance is."""
        if self.predicted is None:
            return None
        diff = self.predicted - self.measured
        return diff / abs(self.measured) if self.relative else diff


@dataclass
class _Session:
    records: dict[str, list[Record]] = field(default_factory=dict)
    selected: list[str] = field(default_factory=list)
    outcomes: dict[str, str] = field(default_factory=dict)
    deselected: bool = False


_SESSION = pytest.StashKey[_Session]()


def _in_suite(path: Path) -> bool:
    return HERE in Path(path).resolve().parents


def _fmt(value: float | None) -> str:
    return "—" if value is None else f"{value:.4g}"


def _fmt_error(record: Record) -> str:
    err = record.error
    if err is None:
        return "—"
    if not record.relative:
        return f"{err:+.3g} {record.unit}"
    return f"{err:+.1%}" if abs(err) >= 1e-3 or err == 0.0 else f"{err:+.1e}"


def _fmt_tolerance(record: Record) -> str:
    tol = record.tolerance
    if tol is None:
        return "—"
    if not record.relative:
        return f"±{tol:.3g} {record.unit}"
    return f"±{tol:.1%}" if tol >= 1e-3 else f"±{tol:.0e} (relative)"


class Validation:
    """The recorder a validation test calls (fixture ``validation``)."""

    def __init__(self, request: pytest.FixtureRequest) -> None:
        self._node = request.node
        self._store = request.config.stash[_SESSION].records.setdefault(request.node.nodeid, [])

    def check(
        self,
        id: str,
        *,
        model: str,
        source: str,
        reference: dict[str, Any],
        quantity: str,
        unit: str,
        measured: float,
        predicted: float,
        tolerance: float,
        relative: bool,
        tolerance_basis: str,
        assumptions: Sequence[str],
        kind: str = "validation",
        known_miss: bool = False,
    ) -> Record:
        """Record a comparison and assert |error| ≤ tolerance (relative: of the measured value).

        ``known_miss``: the current model is known to miss this case; the test becomes a strict
        xfail whose reason carries the error (a pass then fails the run).
        """
        probe = Record(
            id=id,
            model=model,
            source=source,
            reference=reference,
            quantity=quantity,
            unit=unit,
            measured=float(measured),
            predicted=float(predicted),
            tolerance=float(tolerance),
            relative=relative,
            tolerance_basis=tolerance_basis,
            assumptions=tuple(assumptions),
            kind=kind,
        )
        error = probe.error
        assert error is not None and math.isfinite(error), f"{id}: prediction {predicted!r}"
        within = abs(error) <= tolerance
        status = "PASS" if within else ("FAIL (known miss)" if known_miss else "FAIL")
        record = dataclasses.replace(probe, status=status)
        self._store.append(record)
        summary = (
            f"{id}: predicted {_fmt(record.predicted)} vs measured {_fmt(record.measured)} "
            f"{unit}, error {_fmt_error(record)}, tolerance {_fmt_tolerance(record)}"
        )
        if known_miss:
            self._node.add_marker(
                pytest.mark.xfail(strict=True, reason=f"known miss of the model: {summary}")
            )
        assert within, summary
        return record

    def not_compared(
        self,
        id: str,
        *,
        model: str,
        source: str,
        reference: dict[str, Any],
        quantity: str,
        unit: str,
        measured: float,
        assumptions: Sequence[str],
        reason: str,
    ) -> None:
        """Record published data that no current model can predict honestly, and skip."""
        self._store.append(
            Record(
                id=id,
                model=model,
                source=source,
                reference=reference,
                quantity=quantity,
                unit=unit,
                measured=float(measured),
                assumptions=tuple(assumptions),
                status="NOT COMPARED",
                note=reason,
            )
        )
        pytest.skip(f"{id}: not compared — {reason}")


@pytest.fixture
def validation(request: pytest.FixtureRequest) -> Validation:
    """Recorder of one validation test (see the module docstring)."""
    return Validation(request)


@pytest.fixture(scope="session")
def dataset() -> Callable[[str, str], dict[str, Any]]:
    """``dataset(file, key)``: one entry of ``tests/validation/data/<file>.toml``."""

    def load(file: str, key: str) -> dict[str, Any]:
        with (DATA / f"{file}.toml").open("rb") as fh:
            return tomllib.load(fh)[key]

    return load


@pytest.fixture(scope="session")
def _gao_raw() -> dict[str, Any]:
    with (EXAMPLES / "gao2019_tcr.toml").open("rb") as fh:
        return tomllib.load(fh)


@pytest.fixture
def base_raw(_gao_raw: dict[str, Any]) -> dict[str, Any]:
    """A fresh copy of ``examples/gao2019_tcr.toml`` as nested dictionaries."""
    return copy.deepcopy(_gao_raw)


def _anchor(heading: str) -> str:
    """The anchor GitHub and MkDocs give a ``## heading`` (punctuation but ``-``, ``_`` dropped)."""
    return re.sub(r"[^\w-]", "", heading.lower())


# --- hooks: marker, completeness and the generated table --------------------------------------


_CURRENT: list[_Session] = []
"""The session state of the running session (the log-report hook gets no config)."""


def pytest_configure(config: pytest.Config) -> None:
    state = _Session()
    config.stash[_SESSION] = state
    _CURRENT[:] = [state]


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    state = config.stash[_SESSION]
    for item in items:
        if _in_suite(item.path):
            item.add_marker(pytest.mark.validation)
            state.selected.append(item.nodeid)


def pytest_deselected(items: Sequence[pytest.Item]) -> None:
    for item in items:
        if _in_suite(item.path):
            item.config.stash[_SESSION].deselected = True


def pytest_runtest_logreport(report: pytest.TestReport) -> None:
    if _CURRENT and _in_suite(Path(str(report.fspath)).resolve()):
        if report.when == "call" or (report.when == "setup" and not report.passed):
            xfail = getattr(report, "wasxfail", None)
            outcome = f"FAIL (known miss): {xfail}" if xfail else f"{report.outcome}"
            _CURRENT[-1].outcomes[report.nodeid] = outcome


def _complete(state: _Session) -> bool:
    """Every test file of the suite collected, nothing deselected, every selected test run."""
    files = {p.resolve() for p in HERE.glob("test_*.py")}
    seen = {(ROOT / nodeid.split("::")[0]).resolve() for nodeid in state.selected}
    ran = all(nodeid in state.outcomes for nodeid in state.selected)
    return bool(state.selected) and files <= seen and not state.deselected and ran


def pytest_sessionfinish(session: pytest.Session, exitstatus: int) -> None:
    state = session.config.stash[_SESSION]
    if _complete(state):
        DOC.write_text(render(state), encoding="utf-8")


def render(state: _Session) -> str:
    """The Markdown of ``docs/validation.md``."""
    records = [r for nodeid in state.selected for r in state.records.get(nodeid, [])]
    unrecorded = [
        n for n in state.selected if not state.records.get(n) and state.outcomes[n] != "passed"
    ]
    lines = [
        "# Validation against published data",
        "",
        "<!-- Generated by tests/validation/conftest.py; do not edit by hand. -->",
        "",
        "**Generated file.** Regenerate with `pytest tests/validation` (the file is written only",
        "when every test of `tests/validation` ran). Each row compares one model prediction with",
        "one published number; the data, with citation, quote and `verified` flag, are in",
        "`tests/validation/data/*.toml`.",
        "",
        "* *validation*: against a measurement; *verification*: against a maker's worked",
        "  example or formula (a calculation, not a measurement).",
        "* error = (predicted − measured)/|measured| for a relative tolerance, predicted −",
        "  measured for an absolute one.",
        "* PASS: within tolerance. FAIL (known miss): outside tolerance; the test is a strict",
        "  xfail that reports this number (never tuned away). FAIL: outside tolerance, not yet",
        "  triaged. NOT COMPARED: published data recorded, but no current model can predict",
        "  them honestly (the reason is in the section).",
        "",
        "| id | kind | model | source | quantity | measured | predicted | error | tolerance "
        "| status |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for r in records:
        unit = f" [{r.unit}]" if r.unit else ""
        lines.append(
            f"| [{r.id}](#{_anchor(r.id)}) | {r.kind} | {r.model} | {r.source} | "
            f"{r.quantity}{unit} | {_fmt(r.measured)} | {_fmt(r.predicted)} | {_fmt_error(r)} | "
            f"{_fmt_tolerance(r)} | {r.status} |"
        )
    for nodeid in unrecorded:
        lines.append(f"| `{nodeid}` | | | | | | | | | {state.outcomes[nodeid]} (no row recorded) |")
    for r in records:
        lines += _section(r)
    return "\n".join(lines) + "\n"


def _section(r: Record) -> list[str]:
    ref = r.reference
    verified = "yes" if ref.get("verified") else "no (unverified)"
    out = [
        "",
        f"## {r.id}",
        "",
        f"* **Model:** {r.model} ({r.kind}); **status:** {r.status}.",
        f"* **Source:** {ref['citation']}; {ref['location']}. Read from: {ref['retrieved_via']}.",
        f"  Numbers verified in the source text: {verified}.",
        f"* **Quote:** “{ref['quote']}”",
        f"* **Quantity:** {r.quantity} [{r.unit}]: measured {_fmt(r.measured)}, predicted "
        f"{_fmt(r.predicted)}, error {_fmt_error(r)}, tolerance {_fmt_tolerance(r)}.",
    ]
    if r.tolerance_basis:
        out.append(f"* **Tolerance basis:** {r.tolerance_basis}")
    if r.note:
        out.append(f"* **Not compared because:** {r.note}")
    out.append("* **Inputs and assumptions** (ASSUMED: not in the source; GUESS: a default only):")
    out += [f"  * {a}" for a in r.assumptions]
    return out
