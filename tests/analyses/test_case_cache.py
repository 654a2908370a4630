"""The module-level result caches of the composer: complete keys, safe under threads."""

from __future__ import annotations

import sys
import threading
import time
import warnings
from types import SimpleNamespace

import pytest

import ballscrew
from ballscrew.analyses import thermal_setup
from ballscrew.analyses.screw_tcr import ScrewTCR, screw_tcr
from ballscrew.case import with_overrides

QUICK = {"numerics.cells_across": 16}
RPM = 0.10471975511965977  # rad/s


def _resistances(tcr: ScrewTCR) -> list[float]:
    """The headline R, R″ and every nut's R by every model."""
    by_model = [r for m in tcr.models.values() for r in m.nut_resistances.values()]
    return [tcr.resistance, tcr.resistance_per_area, *(n.resistance for n in tcr.nuts), *by_model]


@pytest.fixture
def tcr_cache():
    """The TCR cache, empty before and after the test."""
    thermal_setup._cached_tcr.clear()
    yield thermal_setup._cached_tcr
    thermal_setup._cached_tcr.clear()


def test_the_tcr_cache_reuses_the_contacts_at_a_new_speed_and_oil(gao_case_path, tcr_cache):
    """Without a film path the TCR reads neither the speed nor the oil's viscosity: cases that
    differ only there share the first one's result, and it is each one's own (to 1e-12)."""
    first = ballscrew.load_case(gao_case_path, QUICK | {"operating.speed": 300 * RPM})
    other = with_overrides(
        first,
        {
            "operating.speed": 2700 * RPM,
            "medium.viscosity": 0.011,
            "medium.pressure_viscosity": 1.2e-8,
        },
    )
    shared = tcr_cache(first)
    assert tcr_cache(other) is shared
    for case in (first, other):
        assert _resistances(shared) == pytest.approx(_resistances(screw_tcr(case)), rel=1e-12)


def test_the_meniscus_film_path_re_solves_at_a_new_speed(gao_case_path, tcr_cache):
    """The meniscus film path takes the EHL film at the case's speed: another speed is another
    result, each equal to a fresh solve, and the film paths differ."""
    slow = ballscrew.load_case(
        gao_case_path, QUICK | {"tcr.film_path": "meniscus", "operating.speed": 300 * RPM}
    )
    fast = with_overrides(slow, {"operating.speed": 3000 * RPM})
    a, b = tcr_cache(slow), tcr_cache(fast)
    assert a is not b
    assert b.ball_path_with_film == pytest.approx(screw_tcr(fast).ball_path_with_film, rel=1e-12)
    assert a.ball_path_with_film != pytest.approx(b.ball_path_with_film, rel=1e-6)


@pytest.mark.parametrize(
    ("field", "value"),
    [
        ("operating.preload", 3000.0),
        ("operating.axial_load", 1500.0),
        ("surface.G", 2e-9),
        ("medium.thermal_conductivity", 0.03),
    ],
)
def test_the_tcr_cache_re_solves_what_the_tcr_reads(gao_case_path, tcr_cache, field, value):
    """A change in a field the TCR reads is a new solve, equal to a fresh one and different."""
    base = ballscrew.load_case(gao_case_path, QUICK)
    changed = with_overrides(base, {field: value})
    before, after = tcr_cache(base), tcr_cache(changed)
    assert after is not before
    assert _resistances(after) == pytest.approx(_resistances(screw_tcr(changed)), rel=1e-12)
    assert after.resistance != pytest.approx(before.resistance, rel=1e-6)


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
        operating = SimpleNamespace(coupled=False)
        tcr = SimpleNamespace(film_path="none")

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


def test_a_coupled_tcr_is_keyed_on_the_thermal_model(gao_case_path, tcr_cache):
    """Coupled, the medium is the oil at the operating point's contact temperature, which the
    ambient moves: 20 → 40 °C ambient is another R (0.2083 → 0.2088 K/W at 16 cells; the old
    key, without ``[thermal]``, handed the 20 °C result on)."""
    cool = ballscrew.load_case(
        gao_case_path,
        QUICK
        | {
            "medium.viscosity": None,
            "medium.pressure_viscosity": None,
            "kinematics.lubricant": "iso_vg_68",
            "operating.coupled": True,
        },
    )
    warm = with_overrides(cool, {"thermal.ambient_temperature": 313.15})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the operating point's film warnings
        a, b = tcr_cache(cool), tcr_cache(warm)
        fresh = screw_tcr(warm)
    assert b.resistance == pytest.approx(fresh.resistance, rel=1e-12)
    assert b.resistance != pytest.approx(a.resistance, rel=1e-4)
