"""The wear reference screw (examples/wear_step_stress.toml) and helpers to vary its case."""

from __future__ import annotations

import math
from typing import Any

import pytest

from ballscrew.case import load_case
from ballscrew.geometry import ScrewGeometry

OMEGA = 10.0 * math.pi / 3.0  # 100 rpm, the test's screw speed
RPM = 2.0 * math.pi / 60.0


@pytest.fixture
def ref_geometry() -> ScrewGeometry:
    return ScrewGeometry(0.040, 0.010, 6.35e-3, 0.55, 0.55, math.pi / 4)


@pytest.fixture
def ref_case(wear_case_path):
    """The reference case at preload 1500 N and no external load (so F_1 = F_2 = 1500 N)."""
    return updated(load_case(wear_case_path), operating={"axial_load": 0.0})


def updated(case: Any, **sections: dict) -> Any:
    """A copy of ``case`` with some fields of some sections replaced (validated models)."""
    changes = {}
    for name, fields in sections.items():
        section = getattr(case, name)
        changes[name] = section.model_validate(section.model_dump() | fields)
    return case.model_copy(update=changes)


@pytest.fixture(autouse=True)
def _one_fft_thread(monkeypatch):
    """One FFT thread: with the cores shared (parallel test runs), two-thread pyFFTW plans of the
    contact solver were measured 100–1000× slower (41 s instead of 0.03 s for a 64 × 256 solve)."""
    monkeypatch.setenv("BALLSCREW_FFT_THREADS", "1")
