"""Sweeps from Python: one analysis per store, a script's entry point, the user's own scheduler,
and errors that name the Python arguments."""

from __future__ import annotations

import json
import logging
import os
import subprocess
import sys
import time
from pathlib import Path

import cloudpickle
import pytest

from ballscrew import load_case
from ballscrew.errors import InputError
from ballscrew.sweep import cluster as sweep_cluster
from ballscrew.sweep import parse_axis, run_sweep
from ballscrew.sweep.entry_guard import is_guarded
from ballscrew.sweep.registry import get_analysis, resolve_analysis

cloudpickle.register_pickle_by_value(sys.modules[__name__])

SRC = Path(__file__).resolve().parents[2] / "src"
DEAD = "tcp://127.0.0.1:1"  # nothing listens there: a sweep that reached it would fail on it
AXES = [parse_axis("operating.axial_load=0:2000:2")]


def load_in_kn(case):
    """A user's analysis: the axial load in kN (cheap)."""
    return {"load": (case.operating.axial_load / 1e3, "kN")}


def twice_the_load(case):
    """Another user's analysis."""
    return {"load": (2.0 * case.operating.axial_load, "N")}


def test_sweep_refuses_an_analysis_name_that_is_not_the_analysis(gao_case_path, tmp_path):
    """The thermal-network analysis under the name 'tcr' was stored and labelled tcr; a real
    tcr sweep into that store then computed 0 points (researcher's walkthrough, session 24)."""
    ref = load_case(gao_case_path)
    with pytest.raises(InputError, match=r"^analysis_name = 'tcr' is not allowed: 'thermal-netw"):
        run_sweep(ref, AXES, get_analysis("thermal-network"), "tcr", tmp_path, scheduler=DEAD)
    with pytest.raises(InputError, match=r"^analysis_name = 'tcr' is not allowed: a name other"):
        run_sweep(ref, AXES, load_in_kn, "tcr", tmp_path, scheduler=DEAD)
    with pytest.raises(InputError, match=r"^analysis = 'tcp' is not allowed: one of contact, tcr"):
        run_sweep(ref, AXES, "tcp", None, tmp_path, scheduler=DEAD)


def test_the_analysis_is_named_by_itself():
    tcr = get_analysis("tcr")
    assert resolve_analysis("tcr") == (tcr, "tcr", "tcr")
    assert resolve_analysis(tcr, None) == (tcr, "tcr", "tcr")
    assert resolve_analysis(tcr, "tcr") == (tcr, "tcr", "tcr")
    function, name, identity = resolve_analysis(load_in_kn)
    assert function is load_in_kn and name == identity == f"{__name__}.load_in_kn"
    assert resolve_analysis(load_in_kn, "load")[1:] == ("load", identity)


def _stored(store: Path, analysis: str, function: str) -> None:
    """A store with one point of ``analysis`` (``function``) and an unreadable one."""
    (store / "points").mkdir(parents=True)
    record = {"overrides": {}, "results": {}, "error": None, "seconds": 0.0}
    text = json.dumps({**record, "analysis": analysis, "function": function})
    (store / "points" / "0123456789abcdef0123.json").write_text(text, encoding="utf-8")
    (store / "points" / "00000000000000000000.json").write_text("{", encoding="utf-8")


def test_a_store_of_another_analysis_is_refused_before_the_scheduler(gao_case_path, tmp_path):
    ref = load_case(gao_case_path)
    _stored(tmp_path, "thermal-network", "thermal-network")
    start = time.perf_counter()
    with pytest.raises(InputError) as refused:
        run_sweep(ref, AXES, "tcr", None, tmp_path, scheduler=DEAD)
    assert time.perf_counter() - start < 1.0  # no connection was tried
    assert str(refused.value) == (
        f"analysis of the sweep store {tmp_path} = 'tcr' is not allowed: 'thermal-network', "
        "the analysis its points were computed with (use another store)"
    )
    other = tmp_path / "other"
    _stored(other, "load", f"{__name__}.twice_the_load")
    with pytest.raises(InputError, match=r"load \(.*load_in_kn\)' is not allowed: '.*twice_the"):
        run_sweep(ref, AXES, load_in_kn, "load", other, scheduler=DEAD)


def test_points_stored_before_the_analysis_was_recorded_are_passed_over(tmp_path):
    """A store of older points (no analysis recorded) resumes with any analysis; among them, one
    point that records another analysis still refuses the store, wherever it lies."""
    from ballscrew.sweep.runner import check_store

    folder = tmp_path / "points"
    folder.mkdir()
    old = {"overrides": {}, "results": {}, "error": None, "seconds": 0.0}
    for k in range(20):
        (folder / f"{k:020d}.json").write_text(json.dumps(old), encoding="utf-8")
    check_store(folder, "tcr", "tcr", tmp_path)
    _stored(tmp_path / "mixed", "thermal-network", "thermal-network")
    mixed = tmp_path / "mixed" / "points"
    for k in range(20):
        (mixed / f"{k + 1:020d}.json").write_text(json.dumps(old), encoding="utf-8")
    with pytest.raises(InputError, match=r"= 'tcr' is not allowed: 'thermal-network'"):
        check_store(mixed, "tcr", "tcr", tmp_path / "mixed")


def test_python_errors_name_the_arguments_not_the_options(gao_case_path, tmp_path, monkeypatch):
    """A dead scheduler from Python was reported as '--scheduler = …', the command's option."""
    monkeypatch.setattr(sweep_cluster, "CONNECT_TIMEOUT", "1s")
    ref = load_case(gao_case_path)
    with pytest.raises(InputError, match=r"^scheduler = 'tcp://127.0.0.1:1' is not allowed: "):
        run_sweep(ref, AXES, load_in_kn, None, tmp_path, scheduler=DEAD)
    with pytest.raises(InputError, match=r"^workers = 0 is not allowed: an integer ≥ 1"):
        run_sweep(ref, AXES, load_in_kn, None, tmp_path / "w", workers=0)


SCRIPT = """\
import sys
import ballscrew
from ballscrew.sweep import parse_axis, run_sweep

{body}
"""


def test_is_guarded_finds_the_main_block():
    source = SCRIPT.format(
        body='run_sweep()\nif __name__ == "__main__":\n    run_sweep()\nelse:\n    run_sweep()\n'
        "def main():\n    run_sweep()\nif '__main__' == __name__:\n    main()\n"
        "try:\n    if __name__ == '__main__':\n        run_sweep()\nexcept ValueError:\n    pass\n"
    )
    calls = [n for n, line in enumerate(source.splitlines(), 1) if "run_sweep()" in line]
    guarded = [is_guarded(source, n) for n in calls]
    assert guarded == [False, True, False, True, True]
    assert is_guarded(source, source.splitlines().index("    main()") + 1)  # the second guard
    assert is_guarded("def (:", 1)  # unparsable: not refused


def test_an_unguarded_script_gets_one_error_and_starts_no_cluster(tmp_path):
    """A script calling run_sweep at its top level got pages of 'Nanny failed to start': each
    spawned worker ran the script again (researcher's walkthrough, session 24). The script here
    asks for the local cluster of run_sweep directly, to spare the case's imports."""
    script = tmp_path / "study.py"
    body = "from ballscrew.sweep.cluster import shared_client\n\nclient = shared_client(None, 1)\n"
    script.write_text(body, encoding="utf-8")
    env = {**os.environ, "PYTHONPATH": str(SRC)}
    done = subprocess.run(
        [sys.executable, str(script)], capture_output=True, text=True, env=env, timeout=60
    )
    assert done.returncode == 1
    assert "Nanny" not in done.stderr and "bootstrapping" not in done.stderr
    last = done.stderr.strip().splitlines()[-1]
    assert last.startswith(f"ballscrew.sweep.entry_guard.UnguardedScriptError: {script}:3 ")
    assert 'if __name__ == "__main__":' in last and "scheduler=" in last


class _Collect(logging.Handler):
    def __init__(self) -> None:
        super().__init__(logging.WARNING)
        self.records: list[logging.LogRecord] = []

    def emit(self, record: logging.LogRecord) -> None:
        self.records.append(record)


def test_the_users_cluster_closes_without_errors_after_a_sweep(gao_case_path, tmp_path):
    """The client of a user's scheduler outlived their LocalCluster: Dask logged 'lose scattered
    data' and 'Failed to reconnect' (researcher's walkthrough, session 24). Its client is now
    closed at the end of each sweep."""
    from distributed import LocalCluster

    ref = load_case(gao_case_path)
    collect = _Collect()
    logger = logging.getLogger("distributed")
    logger.addHandler(collect)
    try:
        with LocalCluster(n_workers=1, processes=False, dashboard_address=":0") as users:
            address = users.scheduler_address
            ds, computed = run_sweep(ref, AXES, load_in_kn, "load", tmp_path, scheduler=address)
            assert computed == 2 and ds.attrs["analysis"] == "load"
            assert list(ds["load"].values) == [0.0, 2.0]
            assert len(users.scheduler.clients) == 1  # the sweep's client has left
        time.sleep(2.0)  # a client left behind logs its lost connection within this
    finally:
        logger.removeHandler(collect)
    assert [r.getMessage() for r in collect.records if r.levelno >= logging.ERROR] == []
    for point in (tmp_path / "points").glob("*.json"):
        stored = json.loads(point.read_text(encoding="utf-8"))
        assert (stored["analysis"], stored["function"]) == ("load", f"{__name__}.load_in_kn")
    with pytest.raises(InputError, match=r"load \(.*twice_the_load\)' is not allowed: 'load \("):
        run_sweep(ref, AXES, twice_the_load, "load", tmp_path, scheduler=DEAD)


def test_the_command_refuses_a_folder_of_another_analysis(gao_case_path, tmp_path):
    from typer.testing import CliRunner

    from ballscrew.cli import app
    from ballscrew.results.folder import SWEEP_PATTERNS, write_marker

    out = tmp_path / "sweep"
    _stored(out, "thermal-network", "thermal-network")
    write_marker(out, "sweep", SWEEP_PATTERNS)  # the folder of an earlier, interrupted sweep
    args = ["sweep", str(gao_case_path), "--vary", "operating.axial_load=0,1000"]
    result = CliRunner().invoke(app, [*args, "--analysis", "tcr", "--out", str(out)])
    assert result.exit_code == 2, result.output
    errors = [line for line in result.output.splitlines() if line.startswith("error:")]
    assert errors == [
        f"error: analysis of the sweep store {out} = 'tcr' is not allowed: 'thermal-network', "
        "the analysis its points were computed with (use another store)"
    ]
