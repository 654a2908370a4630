"""Shared settings of the lubrication tests."""

from __future__ import annotations

import pytest


@pytest.fixture(autouse=True)
def _one_fft_thread(monkeypatch):
    """One FFT thread for the contact solves (see tests/kinematics/conftest.py)."""
    monkeypatch.setenv("BALLSCREW_FFT_THREADS", "1")
