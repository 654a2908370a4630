"""Resource budgets: estimate memory and work before allocating, refuse what would not fit.

Every allocation-heavy path (contact grids, TCR re-binning, wear grids and time steps, thermal
meshes and time steps, measured data, sweep grids) estimates its memory in bytes and its work
(time steps, points) from the case *before* it allocates, and raises :class:`BudgetError`
(an :class:`~ballscrew.errors.InputError`) naming the case field, the estimate and the limit.
The estimates are rough upper bounds of the main arrays, not exact accounting.

Configuration (environment variables):

* ``BALLSCREW_MEMORY_BUDGET``: the most memory one run may plan to use, as bytes
  (``4000000000``) or with a unit (``"4 GiB"``, ``"500 MB"``; B, kB, MB, GB, TB, KiB, MiB, GiB,
  TiB). Default: half of the machine's physical memory (8 GiB when it cannot be read).
* ``BALLSCREW_MAX_STEPS``: the most time steps of a wear or thermal transient run and the most
  points of a sweep. Default: 1 000 000.
* ``BALLSCREW_MAX_WORK``: the most contact-grid cell solves of a wear run (grid cells × contact
  solves), which bounds its run time (about 3e4 to 1e5 cell solves per second and core). Default:
  100 000 000.
"""

from __future__ import annotations

import math
import os
import re

from ballscrew.errors import InputError

__all__ = [
    "CHECK_BYTES_PER_CELL",
    "CHECK_CELLS",
    "MEMORY_ENV",
    "STEPS_ENV",
    "BudgetError",
    "check_chunk",
    "check_count",
    "check_memory",
    "check_work",
    "contact_batch_bytes",
    "contact_grid_bytes",
    "format_bytes",
    "memory_budget",
    "parse_bytes",
    "step_limit",
    "work_limit",
]

MEMORY_ENV = "BALLSCREW_MEMORY_BUDGET"
STEPS_ENV = "BALLSCREW_MAX_STEPS"
WORK_ENV = "BALLSCREW_MAX_WORK"
RAM_SHARE = 0.5
"""Share of the physical memory a run may plan to use by default."""
FALLBACK_RAM = 16 * 2**30
"""Physical memory assumed when the system does not report it [bytes]."""
DEFAULT_MAX_STEPS = 1_000_000
DEFAULT_MAX_WORK = 100_000_000

_UNITS = {
    "": 1,
    "b": 1,
    "kb": 10**3,
    "mb": 10**6,
    "gb": 10**9,
    "tb": 10**12,
    "kib": 2**10,
    "mib": 2**20,
    "gib": 2**30,
    "tib": 2**40,
}
_SIZE = re.compile(r"^\s*(\d+(?:\.\d*)?(?:[eE][+-]?\d{1,3})?)\s*([A-Za-z]*)\s*$")


class BudgetError(InputError):
    """A case field asks for more memory or work than the budget allows."""


def parse_bytes(text: str) -> int:
    """Bytes of a size such as ``"4 GiB"``, ``"500 MB"`` or ``"123456"``; ValueError otherwise."""
    match = _SIZE.match(text)
    unit = match.group(2).lower() if match else ""
    if match is None or unit not in _UNITS:
        raise ValueError(f"cannot read {text!r} as a size such as '4 GiB' or a number of bytes")
    size = float(match.group(1)) * _UNITS[unit]
    if not (math.isfinite(size) and size >= 1):
        raise ValueError(f"{text!r} is not a size of at least 1 byte")
    return int(size)


def format_bytes(size: float) -> str:
    """``size`` bytes in binary units, e.g. ``"1.1 TiB"``."""
    for unit, scale in (("TiB", 2**40), ("GiB", 2**30), ("MiB", 2**20), ("KiB", 2**10)):
        if size >= scale:
            return f"{size / scale:.3g} {unit}"
    return f"{size:.0f} B"


def _physical_memory() -> int:
    try:
        return int(os.sysconf("SC_PHYS_PAGES")) * int(os.sysconf("SC_PAGE_SIZE"))
    except (AttributeError, ValueError, OSError):
        return FALLBACK_RAM


def memory_budget() -> int:
    """The memory budget in bytes (``BALLSCREW_MEMORY_BUDGET`` or a share of the RAM)."""
    text = os.environ.get(MEMORY_ENV, "").strip()
    if not text:
        return int(RAM_SHARE * _physical_memory())
    try:
        return parse_bytes(text)
    except ValueError as exc:
        raise InputError(MEMORY_ENV, text, str(exc)) from None


def _limit(env: str, default: int) -> int:
    text = os.environ.get(env, "").strip()
    if not text:
        return default
    try:
        limit = int(float(text))
    except (ValueError, OverflowError):
        limit = 0
    if limit < 1:
        raise InputError(env, text, "a whole number ≥ 1")
    return limit


def step_limit() -> int:
    """The most time steps (or sweep points) of one run (``BALLSCREW_MAX_STEPS``)."""
    return _limit(STEPS_ENV, DEFAULT_MAX_STEPS)


def work_limit() -> int:
    """The most contact-grid cell solves of one wear run (``BALLSCREW_MAX_WORK``)."""
    return _limit(WORK_ENV, DEFAULT_MAX_WORK)


def check_memory(field: str, value: object, estimate: float, what: str) -> None:
    """Raise :class:`BudgetError` when ``estimate`` bytes (of ``what``) exceed the budget."""
    budget = memory_budget()
    if not estimate <= budget:  # also refuses NaN and inf
        raise BudgetError(
            field,
            value,
            f"{what} needs about {format_bytes(estimate)} of memory, more than the budget of "
            f"{format_bytes(budget)} (set {MEMORY_ENV} to change it)",
        )


def _check_limit(field: str, value: object, count: float, what: str, env: str, limit: int) -> None:
    if not count <= limit:
        raise BudgetError(
            field,
            value,
            f"{what}: about {count:.3g}, more than the limit of {limit} (set {env} to change it)",
        )


def check_count(field: str, value: object, count: float, what: str) -> None:
    """Raise :class:`BudgetError` when ``count`` steps (or points) exceed :func:`step_limit`."""
    _check_limit(field, value, count, what, STEPS_ENV, step_limit())


def check_work(field: str, value: object, work: float, what: str) -> None:
    """Raise :class:`BudgetError` when ``work`` cell solves exceed :func:`work_limit`."""
    _check_limit(field, value, work, what, WORK_ENV, work_limit())


def contact_grid_bytes(nx: float, ny: float) -> float:
    """Working memory of one normal contact solve on an nx × ny grid [bytes].

    About twenty nx × ny float arrays (gap, pressure, displacement, residual, direction, its
    preconditioned form and spectrum, masks, initial guess, the coarse grids of the nested start)
    and the DC-FFT buffers on the 2nx × 2ny padded grid (the wrap-around kernel, its spectrum
    stored as float pairs, one padded input and its spectrum). Measured: 1.23 GB peak for the
    preconditioned solve of a 2048 × 2048 grid (this estimate: 1.21 GB).
    """
    cells = float(nx) * float(ny)
    return 8.0 * cells * (20.0 + 4.0 * 4.0)


CHECK_CELLS = 2**20
"""Grid cells whose whole-grid window check (u + h outside each contact's window) is taken at
once: a batch is checked in runs of :func:`check_chunk` contacts (GUESS: 2²⁰ cells keep the
check's temporaries near 25 MB, while a run of many small grids stays one vectorised step)."""
CHECK_BYTES_PER_CELL = 24.0
"""Temporaries of the window check per cell of a run [bytes]: u + h (float64), the contacts' rows
of u, h and p gathered when the windowed contacts are not consecutive (float64 each, u's and
h's freed once summed) and two boolean masks (window, contact set)."""


def check_chunk(nx: int, ny: int) -> int:
    """Contacts of nx × ny grids whose window check runs at once: CHECK_CELLS / (nx·ny), ≥ 1."""
    return max(1, CHECK_CELLS // (int(nx) * int(ny)))


def contact_batch_bytes(count: int, nx: float, ny: float) -> float:
    """Working memory of ``count`` normal contacts solved together on nx × ny grids [bytes].

    ``count`` × :func:`contact_grid_bytes` and the whole-grid window check of the batch, which
    holds :data:`CHECK_BYTES_PER_CELL` per cell of at most :func:`check_chunk` contacts at once.
    """
    run = min(int(count), check_chunk(int(nx), int(ny)))
    return count * contact_grid_bytes(nx, ny) + CHECK_BYTES_PER_CELL * run * float(nx) * float(ny)
