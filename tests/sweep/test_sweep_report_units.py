"""The sweep's report and summary speak engineering units and carry the points' warnings
(written from hand-made point records: no Dask cluster)."""

from __future__ import annotations

import json
import math
import warnings

import pytest

from ballscrew.results.sweep_report import write_sweep
from ballscrew.sweep import PointRecord, assemble, parse_axis, run_point

RPM = math.pi / 30.0


def _fast_warns(case):
    """A stand-in analysis: warns above 2000 rpm, fails above 2500 rpm."""
    if case.operating.speed > 2000 * RPM:
        warnings.warn(f"too fast: {case.operating.speed / RPM:.0f} rpm", UserWarning, stacklevel=1)
    if case.operating.speed > 2500 * RPM:
        raise ValueError("far too fast")
    return {"heat": (case.operating.speed, "W")}


def test_a_point_keeps_its_warnings_even_when_it_fails(coarse_case):
    from ballscrew.case import with_overrides

    slow = run_point(_fast_warns, coarse_case, {})
    assert slow.warnings == () and slow.error is None
    fast = with_overrides(coarse_case, {"operating.speed": 2200 * RPM})
    record = run_point(_fast_warns, fast, {"operating.speed": 2200 * RPM})
    assert record.warnings == ("too fast: 2200 rpm",) and record.error is None
    failed = with_overrides(coarse_case, {"operating.speed": 3000 * RPM})
    record = run_point(_fast_warns, failed, {"operating.speed": 3000 * RPM})
    assert record.warnings == ("too fast: 3000 rpm",) and "far too fast" in record.error


@pytest.mark.filterwarnings("ignore::UserWarning")
def test_report_and_summary_read_in_rpm_with_the_points_warnings(coarse_case, tmp_path):
    """The inputs table showed '[52.35987755982988, 183.25957145940458, …] rad/s', a failed
    point as 'operating.speed=314.2', and the points' warnings were lost."""
    from ballscrew.case import with_overrides

    axis = parse_axis("operating.speed=500 rpm:3000 rpm:3")
    records = [
        run_point(_fast_warns, with_overrides(coarse_case, {axis.key: v}), {axis.key: v})
        for v in axis.values
    ]
    records[1] = PointRecord(records[1].overrides, records[1].results, None, 0.0, ("d·n high",))
    ds = assemble([axis], records, "test", coarse_case)
    (tmp_path / "sweep").mkdir()
    folder = write_sweep(ds, tmp_path / "sweep", 3, coarse_case, [axis])
    summary = json.loads((folder / "summary.json").read_text(encoding="utf-8"))
    assert summary["warnings"] == [
        "point operating.speed=3000 rpm failed: ValueError: far too fast",
        "point operating.speed=1750 rpm: d·n high",
        "point operating.speed=3000 rpm: too fast: 3000 rpm",
    ]
    assert summary["inputs"]["axes"][axis.key]["unit"] == "rad/s"  # SI kept in the summary
    report = (folder / "report.html").read_text(encoding="utf-8")
    assert "<td>500, 1750, 3000</td><td>rpm</td>" in report
    assert "52.359" not in report and "d·n high" in report
    assert "sweep_warnings.png" not in {p.name for p in folder.iterdir()}


def _two_speeds(case, tmp_path):
    """The folder of a 500/1000 rpm sweep of the stand-in analysis."""
    axis = parse_axis("operating.speed=500 rpm,1000 rpm")
    records = [run_point(_fast_warns, case, {axis.key: v}) for v in axis.values]
    (tmp_path / "sweep").mkdir()
    return write_sweep(assemble([axis], records, "test", case), tmp_path / "sweep", 2, case, [axis])


def test_the_sweep_reports_the_guessed_defaults_of_its_case(coarse_case, tmp_path):
    folder = _two_speeds(coarse_case, tmp_path)
    summary = json.loads((folder / "summary.json").read_text(encoding="utf-8"))
    assert "case.friction.circuits" in summary["guessed_defaults"]
    assert "<td>case.friction.circuits</td>" in (folder / "report.html").read_text("utf-8")


def test_the_report_tabulates_every_point_in_engineering_units(coarse_case, tmp_path):
    """The sweep report had plots only: no number of any point could be read from it."""
    report = (_two_speeds(coarse_case, tmp_path) / "report.html").read_text("utf-8")
    assert "<h2>Values at every point</h2>" in report
    assert "<th>speed [rpm]</th><th>heat [W]</th>" in report
    assert "<td>1000</td><td>104.7</td>" in report  # the stand-in's heat is ω in W


def test_a_swept_guess_is_no_guess(coarse_case, tmp_path):
    """The sweep listed the base case's guessed defaults, the swept one among them: its default
    is never used, every point writes its own value."""
    axis = parse_axis("friction.hysteresis=0.001:0.01:2")
    records = [PointRecord({axis.key: v}, {"heat": (v, "W")}, None, 0.0) for v in axis.values]
    ds = assemble([axis], records, "test", coarse_case)
    (tmp_path / "sweep").mkdir()
    folder = write_sweep(ds, tmp_path / "sweep", 2, coarse_case, [axis])
    guessed = json.loads((folder / "summary.json").read_text(encoding="utf-8"))["guessed_defaults"]
    assert "case.friction.seal_force" in guessed
    assert "case.friction.hysteresis" not in guessed


def test_points_run_in_threads_keep_their_own_warnings(coarse_case):
    """A worker with several threads (``--scheduler`` at a ``dask worker --nthreads 2``) runs
    points at once: ``warnings.catch_warnings`` swaps the process's warning hook, so one point's
    warnings landed in the other's record and the other's were lost."""
    import threading

    both = threading.Barrier(2)

    def named(name):
        def analysis(case):
            both.wait(timeout=5)  # both points inside their capture
            warnings.warn(f"from {name}", UserWarning, stacklevel=1)
            both.wait(timeout=5)
            return {"heat": (1.0, "W")}

        return analysis

    records = {}

    def run(name):
        records[name] = run_point(named(name), coarse_case, {})

    threads = [threading.Thread(target=run, args=(name,)) for name in ("a", "b")]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert records["a"].warnings == ("from a",) and records["b"].warnings == ("from b",)
