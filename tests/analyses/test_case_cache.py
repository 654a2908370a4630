"""The module-level result caches of the composer: complete keys, safe under threads."""

from __future__ import annotations

import sys
import threading
import time

import pytest

import ballscrew
from ballscrew.analyses import thermal_setup
from ballscrew.analyses.screw_tcr import screw_tcr

QUICK = {"numerics.cells_across": 16}


def test_the_thermal_tcr_cache_sees_the_load_distribution(gao_case_path):
    """A uniform run first must not hand its R to an elastic run with a lead error (which
    loads nut 1's balls unevenly and lowers its R: 0.0297 against 0.0375 K/W, V2)."""
    uniform = ballscrew.load_case(gao_case_path, QUICK)
    elastic = ballscrew.load_case(
        gao_case_path,
        QUICK | {"loads.distribution": "elastic", "loads.lead_error": [2e-6, 0, 0, 0, 0, 0]},
    )
    thermal_setup._cached_tcr(uniform)
    cached = thermal_setup._cached_tcr(elastic).models["V2"].nut_resistances
    fresh = screw_tcr(elastic).models["V2"].nut_resistances
    assert cached[1] == pytest.approx(fresh[1], rel=1e-12)
    assert cached[1] < 0.9 * cached[2]  # the lead error shows


def test_the_tcr_cache_evicts_safely_under_threads(monkeypatch):
    """Threads filling the cache with more cases than it holds: no KeyError or "dictionary
    changed size" from another thread's eviction in between."""

    class Fake:
        def __init__(self, i: int) -> None:
            self.i = i

        def model_dump_json(self, **_: object) -> str:
            return str(self.i)

    def slow(case: Fake) -> int:
        time.sleep(1e-5)  # lets the threads interleave
        return case.i

    monkeypatch.setattr(thermal_setup._cached_tcr, "compute", slow)
    interval = sys.getswitchinterval()
    sys.setswitchinterval(1e-6)  # switch threads often, inside the cache's own lines too
    errors: list[BaseException] = []

    def work(start: int) -> None:
        try:
            for i in range(start, start + 1500):
                assert thermal_setup._cached_tcr(Fake(i % 97)) == i % 97  # type: ignore[arg-type]
        except BaseException as exc:
            errors.append(exc)

    threads = [threading.Thread(target=work, args=(13 * k,)) for k in range(8)]
    try:
        for t in threads:
            t.start()
        for t in threads:
            t.join()
    finally:
        sys.setswitchinterval(interval)
        thermal_setup._cached_tcr.clear()
    assert not errors, errors[0]
