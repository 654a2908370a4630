"""Sweeps that scale: one-thread pools in the workers, equal results on 1 and 2 workers."""

from __future__ import annotations

import os
import sys

import cloudpickle
import numpy as np

from ballscrew.analyses.screw_tcr import tcr_scalars
from ballscrew.case import with_overrides
from ballscrew.sweep import grid_points, parse_axis, run_point, run_sweep, warm_workers
from ballscrew.sweep.cluster import close_clients, shared_client

# Workers are separate processes that cannot import this test module: ship it by value.
cloudpickle.register_pickle_by_value(sys.modules[__name__])


def pool_threads(case):
    """The widest BLAS/OpenMP pool and the FFT threads that a point sees on its worker."""
    from threadpoolctl import threadpool_info

    from ballscrew.backend import fft_threads

    pools = max(pool["num_threads"] for pool in threadpool_info())
    return {"pool_threads": (pools, ""), "fft_threads": (fft_threads(2**24), "")}


def environment(key):
    """``key`` in the environment of the process that runs this."""
    return os.environ.get(key)


def profiling():
    """Whether the Dask worker that runs this samples its threads' stacks."""
    import dask

    return dask.config.get("distributed.worker.profile.enabled")


def test_workers_run_their_pools_on_one_thread(tmp_path, coarse_case, monkeypatch):
    # Pools as wide as the machine in this process's environment must not reach the points.
    close_clients()
    monkeypatch.setenv("OPENBLAS_NUM_THREADS", "2")
    monkeypatch.setenv("OMP_NUM_THREADS", "2")
    axes = [parse_axis("operating.axial_load=0:1000:4")]
    ds, _ = run_sweep(coarse_case, axes, pool_threads, "threads", tmp_path, workers=2)
    assert not ds["failed"].any()
    np.testing.assert_array_equal(ds["pool_threads"], 1)
    np.testing.assert_array_equal(ds["fft_threads"], 1)
    client = shared_client(None, 2)
    assert sum(client.nthreads().values()) == 2  # one task thread per worker
    fft_env = client.run(environment, "BALLSCREW_FFT_THREADS")
    assert set(fft_env.values()) == {"1"}
    assert set(client.run(profiling).values()) == {False}


def test_one_worker_two_workers_serial_and_warm_workers_agree(tmp_path, coarse_case):
    axes = [parse_axis("surface.D=1.45,1.55"), parse_axis("operating.axial_load=0,700,1400")]

    def sweep(store, workers):
        ds, computed = run_sweep(
            coarse_case, axes, tcr_scalars, "tcr", tmp_path / store, workers=workers
        )
        assert computed == 6 and not ds["failed"].any()
        return ds["resistance"].values

    cold = sweep("cold", 2)
    seconds = warm_workers(tcr_scalars, coarse_case, workers=2)
    assert len(seconds) == 2 and min(seconds.values()) > 0
    warm = sweep("warm", 2)
    one = sweep("one", 1)
    serial = [
        run_point(tcr_scalars, with_overrides(coarse_case, p), p).results["resistance"][0]
        for p in grid_points(axes)
    ]
    np.testing.assert_array_equal(warm, cold)
    np.testing.assert_array_equal(one, cold)
    np.testing.assert_array_equal(np.reshape(serial, (2, 3)), cold)
