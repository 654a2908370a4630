"""Dask clients of the sweeps: one local cluster per worker count, kept for the process.

Starting a local cluster costs seconds (worker processes import numpy, scipy and ballscrew); a
notebook or script that runs several sweeps pays it once. The local clients are closed when the
interpreter exits, or by :func:`close_clients`. A scheduler given by address belongs to the
user: its client lives for one sweep (:func:`sweep_client`), so none outlives the user's
cluster.

A local worker runs one task thread, and its BLAS, OpenMP and FFT pools one thread each
(:data:`WORKER_ENV`): the sweep's parallelism is its workers, one per core, and a second pool
thread per worker only competes for the same cores.
"""

from __future__ import annotations

import atexit
import logging
import os
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

from ballscrew.budget import check_memory
from ballscrew.errors import InputError
from ballscrew.sweep.entry_guard import check_entry_guard
from ballscrew.validation import integer_at_least

log = logging.getLogger(__name__)

#: Memory of one local worker process with numpy, scipy, Dask and ballscrew loaded [bytes]
#: (about what the command line itself takes, 0.25 GB; GUESS for the points' own arrays).
WORKER_BYTES = 0.3e9

#: How long connecting to a scheduler given by address may take.
CONNECT_TIMEOUT = "5s"

#: Thread pools of a local worker: set before its process starts (BLAS and OpenMP read them when
#: they load) and in the worker (the FFT threads, :func:`ballscrew.backend.fft_threads`).
WORKER_ENV = {
    "OMP_NUM_THREADS": "1",
    "OPENBLAS_NUM_THREADS": "1",
    "MKL_NUM_THREADS": "1",
    "BALLSCREW_FFT_THREADS": "1",
}

#: Dask settings of a local worker.
WORKER_CONFIG = {"distributed.worker.profile.enabled": False}

_CLIENTS: dict[int | None, tuple[Any, Any]] = {}


def _quiet_dask() -> None:
    # Worker processes read their log level from the environment when they import distributed.
    quiet = "DEBUG" if log.isEnabledFor(logging.DEBUG) else "ERROR"
    os.environ.setdefault("DASK_LOGGING__DISTRIBUTED", quiet.lower())
    import dask

    dask.config.set({"logging.distributed": quiet.lower()})
    logging.getLogger("distributed").setLevel(quiet)


def _connect(scheduler: str) -> Any:
    from distributed import Client

    try:  # not the default client: a failed one would stay registered as the default
        return Client(scheduler, timeout=CONNECT_TIMEOUT, set_as_default=False)
    except Exception as exc:  # any failure to reach it is the address's
        reason = (str(exc).splitlines() or [type(exc).__name__])[0][:200]
        raise InputError(
            "scheduler",
            scheduler,
            f"the address of a running Dask scheduler, e.g. tcp://host:8786 ({reason})",
        ) from None


def check_workers(workers: int | None, field: str = "--workers") -> None:
    """Refuse a local worker count below 1 or whose processes exceed the memory budget.

    ``field`` names the count in the message: the command's option, or ``workers`` from Python.
    """
    if workers is not None:
        integer_at_least(field, workers, 1)
        check_memory(field, workers, workers * WORKER_BYTES, f"{workers} local workers")


def _local(workers: int | None) -> tuple[Any, Any]:
    import dask
    from distributed import Client, LocalCluster

    # The nanny sets the pre-spawn variables in this process too: not the FFT threads.
    pools = {k: v for k, v in WORKER_ENV.items() if k != "BALLSCREW_FFT_THREADS"}
    pre_spawn = {**dask.config.get("distributed.nanny.pre-spawn-environ", {}), **pools}
    # The workers' statistical profiler samples every thread's stack 100 times a second; a
    # sweep does not read it, and it takes CPU from the points on the shared cores.
    settings = {"distributed.nanny.pre-spawn-environ": pre_spawn, **WORKER_CONFIG}
    with dask.config.set(settings):
        cluster = LocalCluster(
            n_workers=workers,
            threads_per_worker=1,
            processes=True,
            env=WORKER_ENV,
            host="127.0.0.1",  # the local cluster listens on the loopback interface only
            dashboard_address="127.0.0.1:0",  # its HTTP server on loopback, any free port
        )
    return Client(cluster, set_as_default=False), cluster


def shared_client(scheduler: str | None = None, workers: int | None = None) -> Any:
    """The process's client of a local cluster of ``workers``, or a new client of ``scheduler``.

    The local client is kept for later sweeps (a closed one is replaced); a client of a scheduler
    given by address is the caller's to close (:func:`sweep_client` does). Such a scheduler is
    trusted: Dask exchanges pickled functions and results with it.
    """
    _quiet_dask()
    if scheduler:
        return _connect(scheduler)
    cached = _CLIENTS.get(workers)
    if cached is not None and cached[0].status == "running":
        return cached[0]
    check_workers(workers, "workers")
    check_entry_guard()
    _CLIENTS[workers] = _local(workers)
    return _CLIENTS[workers][0]


@contextmanager
def sweep_client(scheduler: str | None = None, workers: int | None = None) -> Iterator[Any]:
    """:func:`shared_client` for one sweep: a client of ``scheduler`` is closed at the end.

    Closing it releases what the sweep scattered and stops its heartbeats, so the user may then
    close their own cluster without Dask logging the lost client's reconnection attempts.
    """
    client = shared_client(scheduler, workers)
    try:
        yield client
    finally:
        if scheduler:
            client.close()


@atexit.register
def close_clients() -> None:
    """Close every shared client and the local clusters behind them."""
    while _CLIENTS:
        _, (client, cluster) = _CLIENTS.popitem()
        client.close()
        cluster.close()
