"""The local cluster started in the background while the command line reads its case."""

from __future__ import annotations

import subprocess
import sys

import pytest

from ballscrew.errors import InputError
from ballscrew.sweep import cluster


class _Client:
    status = "running"

    def close(self) -> None:
        self.status = "closed"


def test_a_started_client_is_the_shared_one_and_starts_once(monkeypatch):
    opened = []

    def fake_open(scheduler, workers):
        opened.append(workers)
        return _Client(), None

    monkeypatch.setattr(cluster, "_open", fake_open)
    cluster.start_client(None, 3)
    cluster.start_client(None, 3)  # starting: not a second one
    client = cluster.shared_client(None, 3)
    cluster.start_client(None, 3)  # running: nothing started
    assert cluster.shared_client(None, 3) is client and opened == [3]
    cluster.close_clients()
    assert client.status == "closed"


def test_a_failed_start_is_raised_by_the_shared_client(monkeypatch):
    def refused(scheduler, workers):
        raise InputError("--workers", workers, "an integer ≥ 1")

    monkeypatch.setattr(cluster, "_open", refused)
    cluster.start_client(None, 0)
    with pytest.raises(InputError, match=r"^--workers = 0"):
        cluster.shared_client(None, 0)
    cluster.start_client(None, 0)
    cluster.close_clients()  # a failed start leaves nothing to close


def test_the_cluster_module_starts_without_the_runner():
    """``ballscrew.sweep.cluster`` loads no xarray or case models: the command starts the cluster
    before this process loads them (the workers' preload: ``test_sweep.py``)."""
    probe = "import sys, ballscrew.sweep.cluster; print({'xarray', 'ballscrew.case'} & set(sys.modules))"  # noqa: E501
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True)
    assert done.stdout.strip() == "set()"
