"""Sweeps on a real local Dask cluster: coordinates, failures recorded, resumption."""

from __future__ import annotations

import sys

import cloudpickle
import numpy as np
import pytest

from ballscrew.analyses.screw_tcr import tcr_scalars
from ballscrew.case import CaseError, with_overrides
from ballscrew.sweep import parse_axis, run_point, run_sweep
from ballscrew.sweep.runner import chunk_indices, run_chunk

# Workers are separate processes that cannot import this test module: ship it by value.
cloudpickle.register_pickle_by_value(sys.modules[__name__])

FAILING_POINT = (1.5, 1000.0)


def tcr_with_one_failure(case):
    """tcr_scalars, except that one chosen point raises (an injected failure)."""
    if (case.surface.D, case.operating.axial_load) == FAILING_POINT:
        raise RuntimeError("injected failure")
    return tcr_scalars(case)


def _sweep_with_one_failure(store, case, workers):
    """The 3 × 2 sweep of D and axial load with one failing point: (Dataset, computed, progress)."""
    axes = [parse_axis("surface.D=1.45:1.55:3"), parse_axis("operating.axial_load=0,1000")]
    seen = []
    ds, computed = run_sweep(
        case,
        axes,
        tcr_with_one_failure,
        "tcr-test",
        store,
        workers=workers,
        progress=lambda done, total: seen.append((done, total)),
    )
    return axes, ds, computed, seen


def test_sweep_on_local_dask_cluster(tmp_path, coarse_case):
    axes, ds, computed, seen = _sweep_with_one_failure(tmp_path, coarse_case, workers=2)
    assert computed == 6
    assert seen[-1] == (6, 6)
    assert list(ds.dims) == ["surface.D", "operating.axial_load"]
    np.testing.assert_allclose(ds["surface.D"], [1.45, 1.5, 1.55])
    np.testing.assert_allclose(ds["operating.axial_load"], [0.0, 1000.0])
    assert ds["operating.axial_load"].attrs["units"] == "N"
    assert ds["resistance"].attrs["units"] == "K/W"

    failed = ds["failed"].sel({"surface.D": 1.5, "operating.axial_load": 1000.0})
    assert bool(failed)
    assert int(ds["failed"].sum()) == 1
    assert "injected failure" in str(
        ds["error"].sel({"surface.D": 1.5, "operating.axial_load": 1000.0}).values
    )
    assert np.isnan(ds["resistance"].sel({"surface.D": 1.5, "operating.axial_load": 1000.0}))
    good = ds["resistance"].where(~ds["failed"])
    assert int(np.isfinite(good).sum()) == 5
    # Physics through the sweep: R falls with D (Gao et al. 2019) at either load.
    assert float(good.isel({"operating.axial_load": 0}).diff("surface.D").max()) < 0
    # F1 − F2 = F_a at every good point (P1).
    np.testing.assert_allclose(
        (ds["F1"] - ds["F2"]).where(~ds["failed"]).isel({"surface.D": 0}),
        [0.0, 1000.0],
        atol=1e-9,
    )

    ds_again, computed_again = run_sweep(
        coarse_case, axes, tcr_with_one_failure, "tcr-test", tmp_path, workers=2
    )
    assert computed_again == 0
    np.testing.assert_array_equal(ds_again["resistance"].values, ds["resistance"].values)


def test_bad_sweep_axes_are_refused_before_any_work(coarse_case, tmp_path):
    with pytest.raises(CaseError, match="unknown key"):
        parse_axis("surface.X=1:2:3")
    with pytest.raises(CaseError, match="empty"):
        parse_axis("surface.D=1.4:1.6:0")
    with pytest.raises(CaseError, match="expected KEY=START:STOP:NUM"):
        parse_axis("surface.D")
    with pytest.raises(
        CaseError, match=r"surface.D = 2.1 is not allowed: allowed range is \(1, 2\)"
    ):
        run_sweep(coarse_case, [parse_axis("surface.D=1.5,2.1")], tcr_scalars, "tcr", tmp_path)
    assert not (tmp_path / "points").exists()


def test_sweeps_of_one_process_share_one_cluster(tmp_path, coarse_case):
    from ballscrew.sweep.cluster import close_clients, shared_client

    axes = [parse_axis("surface.D=1.45,1.5")]
    run_sweep(coarse_case, axes, tcr_scalars, "tcr", tmp_path / "a", workers=1)
    client = shared_client(None, 1)
    assert client.status == "running"  # kept for the next sweep
    run_sweep(coarse_case, axes, tcr_scalars, "tcr", tmp_path / "b", workers=1)
    assert shared_client(None, 1) is client
    close_clients()
    assert client.status == "closed"
    assert shared_client(None, 1) is not client  # a closed client is replaced
    close_clients()


def test_chunks_cover_every_point_once_and_keep_both_workers_busy():
    todo = list(range(3, 103))
    chunks = chunk_indices(todo, threads=2)
    assert sorted(i for chunk in chunks for i in chunk) == todo
    sizes = [len(chunk) for chunk in chunks]
    # Guided: each chunk takes 1/8 of the points left (4 tasks per worker thread), down to one.
    assert sizes[:8] == [13, 11, 10, 9, 8, 7, 6, 5]
    assert sizes == sorted(sizes, reverse=True) and sizes[-8:] == [1] * 8
    # Each chunk of several points reaches into both the first and the last third of the grid.
    for chunk in chunks[:8]:
        assert min(chunk) < 3 + 100 / 3 and max(chunk) > 3 + 200 / 3
    assert chunk_indices([5], threads=2) == [[5]]
    assert sorted(chunk_indices(list(range(3)), threads=4)) == [[0], [1], [2]]


def test_a_failed_point_in_a_chunk_keeps_the_others_and_reports_every_point(tmp_path, coarse_case):
    # Six points on one worker go as five chunks (2, 1, 1, 1, 1).
    _, ds, computed, seen = _sweep_with_one_failure(tmp_path, coarse_case, workers=1)
    assert computed == 6
    assert seen == [(n, 6) for n in range(7)]  # every point reported once
    assert int(ds["failed"].sum()) == 1
    assert int(np.isfinite(ds["resistance"]).sum()) == 5
    assert len(list((tmp_path / "points").glob("*.json"))) == 6
    # In one chunk with the failing point, a point equals the sweep's and the point run alone.
    failing = dict(zip(["surface.D", "operating.axial_load"], FAILING_POINT, strict=True))
    partner = {"surface.D": 1.5, "operating.axial_load": 0.0}
    cases = [with_overrides(coarse_case, p) for p in (failing, partner)]
    bad, good = run_chunk(tcr_with_one_failure, cases, [failing, partner])
    assert "injected failure" in bad.error and good.error is None
    alone = run_point(tcr_scalars, cases[1], partner)
    assert good.results == alone.results
    assert float(ds["resistance"].sel(partner)) == alone.results["resistance"][0]
