"""Run a parameter sweep on Dask and collect it into one labelled xarray Dataset.

Each point runs ``analysis(case) -> {name: (value, unit)}`` on a Dask worker: a local cluster
by default, or any running scheduler given by address; the client is shared by every sweep of
the process (:mod:`ballscrew.sweep.cluster`). Points go in chunks of several per task that
shrink towards the end of the sweep, each mixing points from across the grid
(:func:`chunk_indices`), the analysis once to each worker; a chunk runs with the worker's BLAS
and OpenMP pools and its FFTs on one thread. A point that raises is recorded with its error and
does not stop the sweep. Finished points are stored one JSON file each under
``points/``, so re-running into the same folder computes only what is missing.
"""

from __future__ import annotations

import hashlib
import json
import logging
import math
import time
import traceback
from collections.abc import Callable, Iterator, Sequence
from contextlib import closing
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr

from ballscrew.backend import limited_fft_threads, single_thread_pools
from ballscrew.case import Case
from ballscrew.errors import InputError
from ballscrew.files import atomic_file
from ballscrew.sweep.axes import SweepAxis, grid_points, validate_points
from ballscrew.sweep.cluster import sweep_client
from ballscrew.sweep.spec import check_sweep_size
from ballscrew.thread_warnings import record_warnings

log = logging.getLogger(__name__)

#: An analysis maps a validated case to named scalars with their SI units.
Analysis = Callable[[Case], dict[str, tuple[float, str]]]


@dataclass(frozen=True)
class PointRecord:
    """What one sweep point produced: its results or its error."""

    overrides: dict[str, float]
    results: dict[str, tuple[float, str]] | None
    error: str | None
    seconds: float
    warnings: tuple[str, ...] = ()
    """The warnings the analysis gave at this point (d·n above its limit, …), each once."""


def run_point(analysis: Analysis, case: Case, overrides: dict[str, float]) -> PointRecord:
    """Run one point, catching any exception into the record (runs on a worker).

    FFTs run single-threaded: the sweep's parallelism is its workers, one per core.
    """
    start = time.perf_counter()
    with record_warnings() as caught:  # this point's own, with other points in other threads
        try:
            with limited_fft_threads(1):
                results = {k: (float(v), u) for k, (v, u) in analysis(case).items()}
            error = None
        except Exception as exc:  # a failed point must not kill the sweep
            results, error = None, f"{type(exc).__name__}: {exc}"
            log.debug("point %s failed:\n%s", overrides, traceback.format_exc())
    messages = tuple(dict.fromkeys(str(w.message) for w in caught))
    return PointRecord(overrides, results, error, time.perf_counter() - start, messages)


def run_chunk(
    analysis: Analysis, cases: Sequence[Case], points: Sequence[dict[str, float]]
) -> list[PointRecord]:
    """Run several points in one task (runs on a worker); each point fails on its own.

    The worker's BLAS and OpenMP pools run one thread meanwhile, whatever its environment set:
    a worker started elsewhere (``--scheduler``) may have pools as wide as its machine.
    """
    with single_thread_pools():
        return [run_point(analysis, c, p) for c, p in zip(cases, points, strict=True)]


#: Share of the points still to send that the next chunk takes: 1 / (this × worker threads).
#: The first chunks are large, so the scheduler's per-task cost (some ms) stays small beside
#: the points' own; the last ones hold a single point, so the workers finish together.
TASKS_PER_THREAD = 4

_GOLDEN = (math.sqrt(5.0) - 1.0) / 2.0


def spread_order(todo: Sequence[int]) -> list[int]:
    """``todo`` in the order of the fractional parts of ``k·φ`` (φ the golden ratio, k its place).

    Neighbours in this order lie far apart in ``todo`` (steps of Fibonacci numbers), so any run
    of it samples the whole grid: a chunk holds cheap and costly points alike (Weyl's
    equidistributed sequence; Knuth 1998, *The Art of Computer Programming* 3, §6.4).
    """
    return [todo[k] for k in sorted(range(len(todo)), key=lambda k: (k * _GOLDEN) % 1.0)]


def chunk_indices(todo: Sequence[int], threads: int) -> list[list[int]]:
    """Split ``todo`` into chunks that shrink towards the end, each spread over the grid.

    Guided self-scheduling (Polychronopoulos & Kuck 1987): the next chunk takes
    ``ceil(R / (TASKS_PER_THREAD × threads))`` of the ``R`` points left, so the last chunks
    hold one point and no worker is left with a long task while the others idle. The points
    are taken in :func:`spread_order`, so costly regions of the grid do not gather in one chunk.
    """
    order = spread_order(todo)
    share = TASKS_PER_THREAD * max(threads, 1)
    chunks, start = [], 0
    while start < len(order):
        size = math.ceil((len(order) - start) / share)
        chunks.append(order[start : start + size])
        start += size
    return chunks


def point_key(analysis_name: str, case: Case) -> str:
    """Stable identity of a point: the analysis and every value of its case."""
    text = json.dumps([analysis_name, case.model_dump(mode="json")], sort_keys=True)
    return hashlib.sha256(text.encode()).hexdigest()[:20]


def _save(path: Path, record: PointRecord, name: str, identity: str) -> None:
    with atomic_file(path) as scratch:
        scratch.write_text(json.dumps({**record.__dict__, "analysis": name, "function": identity}))


def _load(path: Path) -> PointRecord:
    raw = json.loads(path.read_text())
    results = {k: (v[0], v[1]) for k, v in raw["results"].items()} if raw["results"] else None
    found = tuple(raw.get("warnings", ()))  # points stored before warnings were kept have none
    return PointRecord(raw["overrides"], results, raw["error"], raw["seconds"], found)


def _needs_run(path: Path, retry_failed: bool) -> bool:
    if not path.is_file():
        return True
    try:
        record = _load(path)
    except (OSError, ValueError, KeyError, TypeError, IndexError):
        return True  # unreadable: computed again
    return retry_failed and record.error is not None


def check_store(folder: Path, name: str, identity: str, store: str | Path) -> None:
    """Refuse to resume a store whose points another analysis computed.

    Each point file names its analysis; the first readable one that does speaks for the store
    (a store holds one analysis). Points stored before the analysis was recorded are passed
    over, so a store of only such points is taken as this analysis's.
    """
    for path in folder.glob("*.json"):
        try:
            raw = json.loads(path.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            continue
        if not isinstance(raw, dict) or "function" not in raw:
            continue
        held, held_identity = str(raw.get("analysis")), str(raw["function"])
        if held_identity != identity:
            given = name if name == identity else f"{name} ({identity})"
            found = held if held == held_identity else f"{held} ({held_identity})"
            raise InputError(
                f"analysis of the sweep store {store}",
                given,
                f"{found!r}, the analysis its points were computed with (use another store)",
            )
        return


def run_sweep(
    base: Case,
    axes: Sequence[SweepAxis],
    analysis: Analysis | str,
    analysis_name: str | None,
    store: str | Path,
    scheduler: str | None = None,
    workers: int | None = None,
    progress: Callable[[int, int], None] | None = None,
    retry_failed: bool = False,
) -> tuple[xr.Dataset, int]:
    """Run every point of the grid not already in ``store/points`` and assemble the Dataset.

    ``analysis`` is a sweepable analysis's name (``"tcr"``), its function, or a function of the
    user's; ``analysis_name`` labels a user's function and may be ``None`` (its qualified name),
    and for a built-in analysis must be ``None`` or its own name
    (:func:`ballscrew.sweep.registry.resolve_analysis`). A store holds one analysis: resuming
    it with another is refused before any cluster is reached. Points that failed earlier count
    as done unless ``retry_failed``. Returns the Dataset and the number of points computed in
    this call (0 when all were done).
    """
    from ballscrew.sweep.registry import resolve_analysis  # it imports every analysis

    check_sweep_size(axes)
    points = grid_points(axes)
    cases = validate_points(base, points)
    function, name, identity = resolve_analysis(analysis, analysis_name)
    folder = Path(store) / "points"
    check_store(folder, name, identity, store)
    folder.mkdir(parents=True, exist_ok=True)
    keys = [point_key(name, case) for case in cases]
    todo = [i for i, key in enumerate(keys) if _needs_run(folder / f"{key}.json", retry_failed)]
    done = len(points) - len(todo)
    if progress:
        progress(done, len(points))
    if todo:
        with (
            sweep_client(scheduler, workers) as client,
            closing(_run_chunks(client, function, cases, points, todo)) as finished,
        ):
            for i, record in finished:
                _save(folder / f"{keys[i]}.json", record, name, identity)
                done += 1
                if progress:
                    progress(done, len(points))
    records = [_load(folder / f"{key}.json") for key in keys]
    return assemble(axes, records, name, base), len(todo)


def _run_chunks(
    client: Any,
    analysis: Analysis,
    cases: Sequence[Case],
    points: Sequence[dict[str, float]],
    todo: Sequence[int],
) -> Iterator[tuple[int, PointRecord]]:
    """Each point of ``todo`` with its record, as the chunks finish on ``client``'s workers.

    The analysis is scattered once; on any exit the unfinished chunks are cancelled and the
    scattered analysis released, so an interrupted sweep leaves no work or data behind.
    """
    from distributed import as_completed

    chunks = chunk_indices(todo, sum(client.nthreads().values()))
    [shipped] = client.scatter([analysis], broadcast=True, hash=False)  # sent once
    futures = {
        client.submit(
            run_chunk,
            shipped,
            [cases[i] for i in chunk],
            [points[i] for i in chunk],
            pure=False,
        ): chunk
        for chunk in chunks
    }
    try:
        for future in as_completed(futures, loop=client.loop):
            yield from zip(futures[future], future.result(), strict=True)
    finally:
        client.cancel([*futures, shipped])


def warm_workers(
    analysis: Analysis | str, case: Case, scheduler: str | None = None, workers: int | None = None
) -> dict[str, float]:
    """Run ``case`` once on every worker of the sweep's client and discard the result.

    A worker's first point imports the physics and builds its FFT plans and caches; a timed
    sweep (points per second) starts after this. The results of later points do not change.
    ``analysis`` is a name or a function, as in :func:`run_sweep`. Returns each worker's
    seconds for its point.
    """
    from ballscrew.sweep.registry import resolve_analysis

    function = resolve_analysis(analysis)[0]
    with sweep_client(scheduler, workers) as client:
        futures = {
            worker: client.submit(
                run_chunk,
                function,
                [case],
                [{}],
                workers=[worker],
                allow_other_workers=False,
                pure=False,
            )
            for worker in client.nthreads()
        }
        return {worker: future.result()[0].seconds for worker, future in futures.items()}


def assemble(
    axes: Sequence[SweepAxis], records: Sequence[PointRecord], analysis_name: str, base: Case
) -> xr.Dataset:
    """Records (in grid order) → Dataset with the swept keys as coordinates."""
    shape = tuple(len(axis.values) for axis in axes)
    dims = [axis.key for axis in axes]
    names: dict[str, str] = {}
    for record in records:
        for name, (_, unit) in (record.results or {}).items():
            names.setdefault(name, unit)
    data = {name: np.full(len(records), np.nan) for name in names}
    errors = np.array([r.error or "" for r in records], dtype=object)
    for n, record in enumerate(records):
        for name, (val, _) in (record.results or {}).items():
            data[name][n] = val
    variables = {
        name: (dims, data[name].reshape(shape), {"units": unit}) for name, unit in names.items()
    }
    variables["error"] = (
        dims,
        errors.reshape(shape).astype(str),
        {"long_name": "error of a failed point"},
    )
    variables["failed"] = (dims, (errors != "").reshape(shape), {"long_name": "point failed"})
    said = np.array(["\n".join(r.warnings) for r in records], dtype=object)
    variables["warnings"] = (
        dims,
        said.reshape(shape).astype(str),
        {"long_name": "warnings of the point, one a line"},
    )
    coords = {
        axis.key: (
            axis.key,
            np.array(axis.values),
            {"units": axis.unit, "long_name": axis.description},
        )
        for axis in axes
    }
    return xr.Dataset(
        variables,
        coords=coords,
        attrs={"analysis": analysis_name, "case": base.name, "points": len(records)},
    )
