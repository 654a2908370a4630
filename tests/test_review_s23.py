"""Review of the session-23 changes: failing tests of the bugs found (each names the behaviour
the code should have; they fail on the reviewed commit and pass once the bug is fixed)."""

from __future__ import annotations

import json
import threading
import tomllib
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

import ballscrew
from ballscrew import backend
from ballscrew.case import CaseError, case_from_dict, load_case
from ballscrew.case.inputs import guessed_defaults
from ballscrew.cli import app
from ballscrew.errors import InputError

runner = CliRunner()


def _not_run(case: object) -> object:
    raise AssertionError("the names must be checked before the model runs")


@pytest.mark.parametrize("bad", [3, None])
def test_a_non_string_fit_name_is_an_input_error_not_an_attribute_error(wear_case_path, bad):
    """Before split_list, ``fit=["wear_coefficient", 3]`` was ``InputError: --fit = 3 …``;
    split_list calls ``.strip()`` on every item and raises AttributeError (a traceback)."""
    case = ballscrew.load_case(wear_case_path)
    measured = np.array([[0.0, 1.0], [1e6, 1.1], [2e6, 1.2]])
    with pytest.raises(InputError, match=rf"^--fit = {bad}"):
        ballscrew.calibrate(case, measured, fit=["wear_coefficient", bad], model=_not_run)


def _with_assumed(tmp_path: Path, table: str) -> Path:
    path = tmp_path / "case.toml"
    text = Path("examples/gao2019_tcr.toml").read_text(encoding="utf-8")
    path.write_text(text + "\n[assumed]\n" + table, encoding="utf-8")
    return path


def test_an_override_at_load_drops_its_assumed_key_like_with_overrides(tmp_path):
    """``with_overrides`` drops an [assumed] key whose value the override writes; the same
    override given to ``load_case`` (the CLI's ``--set``, a sweep file's fixed values) keeps it,
    so the report calls the value the user just wrote an assumption."""
    path = _with_assumed(tmp_path, '"operating.preload" = "a typical preload"\n')
    case = load_case(path, {"operating.preload": 2000.0})
    assert "operating.preload" not in guessed_defaults(case)


def test_cli_set_drops_its_assumed_key(tmp_path):
    path = _with_assumed(tmp_path, '"operating.preload" = "a typical preload"\n')
    out = tmp_path / "out"
    args = ["check", str(path), "--out", str(out), "--set", "operating.preload=2 kN"]
    result = runner.invoke(app, args)
    assert result.exit_code == 0, result.output
    summary = json.loads((out / "summary.json").read_text(encoding="utf-8"))
    assert "operating.preload" not in summary["guessed_defaults"]


def test_an_assumed_key_naming_a_missing_list_entry_is_refused(tmp_path):
    """``duty.7.stroke`` in a case with two duty segments is accepted and listed as the
    assumed input ``duty[7].stroke``, which does not exist (an override of the same key is a
    one-line error: 'the entry must exist')."""
    path = _with_assumed(tmp_path, '"duty.7.stroke" = "why"\n')
    with pytest.raises(CaseError, match=r'assumed\."duty\.7\.stroke"'):
        load_case(path)


def test_init_with_a_given_nut_length_does_not_call_it_assumed():
    """``init --nut-length 80`` writes the given 80 mm but still lists thermal.nut_length in
    [assumed] with the reason of the computed default ('the loaded turns plus one lead')."""
    sheet = ["--d0", "40", "--lead", "10", "--ball", "6.35", "--turns", "2.5x2"]
    result = runner.invoke(app, ["init", *sheet, "--nut-length", "80"])
    assert result.exit_code == 0, result.output
    raw = tomllib.loads(result.stdout)
    assert "thermal.nut_length" not in raw["assumed"]
    assert "thermal.nut_length" not in guessed_defaults(case_from_dict(raw))


def test_a_nested_map_chunks_with_explicit_threads_does_not_deadlock(monkeypatch):
    """map_chunks is public; a run that itself calls map_chunks with threads > 1 waits on the
    pool it occupies: with every worker holding an outer run, the inner runs never start. (The
    test uses a private pool and frees it afterwards, so a deadlock cannot hang the session.)"""
    pool = ThreadPoolExecutor(2, thread_name_prefix="review-fft")
    monkeypatch.setattr(backend, "fft_pool", lambda: pool)
    barrier = threading.Barrier(2, timeout=5)

    def outer(rows: slice) -> list[slice]:
        barrier.wait()  # both workers now hold an outer run
        return backend.map_chunks(lambda inner: inner, 4, 2)

    done: list[object] = []
    caller = threading.Thread(target=lambda: done.append(backend.map_chunks(outer, 2, 2)))
    caller.daemon = True
    caller.start()
    caller.join(3.0)
    deadlocked = caller.is_alive()
    while deadlocked and caller.is_alive():  # free the pool: run the queued inner runs here
        try:
            item = pool._work_queue.get(timeout=0.1)
        except Exception:  # queue.Empty
            continue
        if item is not None:
            item.run()
    caller.join()
    pool.shutdown()
    assert not deadlocked


def test_more_circuits_than_balls_is_one_line_exit_2(tmp_path):
    """``friction.circuits`` above ``screw.balls_per_nut`` ran silently and gave the return push
    a mean force above its ramp's maximum ((n_l + 1)/(2 n_l) > 1 for n_l < 1)."""
    out = tmp_path / "out"
    args = ["operating-point", "examples/gao2019_tcr.toml", "--out", str(out)]
    result = runner.invoke(app, [*args, "--set", "friction.circuits=64"])
    assert result.exit_code == 2 and result.output.count("\n") == 1
    assert "friction.circuits = 64 is not allowed: 1 to screw.balls_per_nut = 54" in result.output
    assert not out.exists()
