"""``--out`` never loses a user's file: marker, refused locations, atomic swap, lock, disk full."""

from __future__ import annotations

import errno
import json
import os
import signal
from pathlib import Path

import pytest
import xarray as xr
from filelock import FileLock
from typer.testing import CliRunner

from ballscrew.cli import app
from ballscrew.errors import InputError
from ballscrew.results import (
    ResultsWriteError,
    check_output_folder,
    claim_output,
    results_folder,
    write_summary,
)
from ballscrew.results import folder as folder_module
from ballscrew.results.folder import MARKER_NAME, lock_path, prepare_sweep_folder

runner = CliRunner()
EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "gao2019_tcr.toml"


def _write(out: Path, run: int, command: str | None = None) -> None:
    with claim_output(out, command=command), results_folder(out) as scratch:
        write_summary(scratch / "summary.json", {"run": run})
        (scratch / "sub").mkdir()
        (scratch / "sub" / "data.txt").write_text(str(run))


def _run_of(out: Path) -> int:
    marker = json.loads((out / MARKER_NAME).read_text())
    assert sorted(marker["files"]) == ["sub/data.txt", "summary.json"]  # complete
    return json.loads((out / "summary.json").read_text())["run"]


def _one_line_error(result) -> str:
    assert result.exit_code == 2, result.output
    assert "Traceback" not in result.output
    lines = result.output.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: --out")
    return lines[0]


def test_a_foreign_file_in_out_survives(tmp_path, monkeypatch) -> None:
    """The reproduction: a summary.json alone does not make a folder ballscrew's."""
    monkeypatch.chdir(tmp_path)
    x = tmp_path / "x"
    x.mkdir()
    (x / "summary.json").write_text("{}")
    (x / "thesis.tex").write_text("my thesis")
    result = runner.invoke(app, ["contact", str(EXAMPLE), "--out", "x"])
    _one_line_error(result)
    assert sorted(p.name for p in x.iterdir()) == ["summary.json", "thesis.tex"]
    assert (x / "thesis.tex").read_text() == "my thesis"


def test_a_results_folder_with_an_added_file_is_refused_even_with_force(tmp_path) -> None:
    out = tmp_path / "run"
    _write(out, 1, "contact")
    (out / "sub" / "notes.md").write_text("mine")
    for force in (False, True):
        with pytest.raises(InputError, match=r"notes\.md"):
            check_output_folder(out, command="contact", force=force)
    assert (out / "sub" / "notes.md").read_text() == "mine"


def test_force_replaces_results_of_another_command(tmp_path) -> None:
    out = tmp_path / "run"
    _write(out, 1, "tcr")
    with pytest.raises(InputError, match="--force"):
        check_output_folder(out, command="contact")
    with claim_output(out, command="contact", force=True), results_folder(out) as scratch:
        write_summary(scratch / "summary.json", {"run": 2})
    assert json.loads((out / MARKER_NAME).read_text())["command"] == "contact"
    _write(out, 3, "contact")  # the same command again needs no --force
    assert _run_of(out) == 3


@pytest.mark.parametrize("where", [".", "", "case_folder", "case_grandparent"])
def test_refuses_the_current_folder_and_folders_holding_the_case(tmp_path, monkeypatch, where):
    work = tmp_path / "a" / "b"
    work.mkdir(parents=True)
    case = work / "case.toml"
    case.write_text(EXAMPLE.read_text())
    monkeypatch.chdir(work)
    (work / MARKER_NAME).write_text(json.dumps({"command": "contact", "files": ["case.toml"]}))
    out = {"case_folder": str(work), "case_grandparent": str(tmp_path / "a")}.get(where, where)
    before = sorted(tmp_path.rglob("*"))
    result = runner.invoke(app, ["contact", str(case), "--out", out, "--force"])
    _one_line_error(result)
    assert sorted(tmp_path.rglob("*")) == before
    assert case.read_text() == EXAMPLE.read_text()


def test_refuses_a_folder_holding_the_measured_file(tmp_path, wear_case_path) -> None:
    measured = tmp_path / "data" / "torque.csv"
    measured.parent.mkdir()
    measured.write_text("revolutions,friction_torque\n0,0.4\n1e5,0.39\n")
    args = ["calibrate", str(wear_case_path), "-m", str(measured), "--out", str(tmp_path)]
    assert "torque.csv" in _one_line_error(runner.invoke(app, args))


def test_checking_creates_nothing_and_a_failed_run_leaves_no_parents(tmp_path) -> None:
    out = tmp_path / "a" / "b" / "run"
    check_output_folder(out)
    with pytest.raises(RuntimeError), results_folder(out):
        raise RuntimeError("solver failed")
    assert list(tmp_path.iterdir()) == []


def test_a_second_writer_is_refused_at_once(tmp_path) -> None:
    out = tmp_path / "run"
    _write(out, 1, "contact")
    with FileLock(lock_path(out)):
        result = runner.invoke(app, ["contact", str(EXAMPLE), "--out", str(out)])
        assert "another run" in _one_line_error(result)
        assert lock_path(out).exists()  # the holder's lock file is left alone
    assert _run_of(out) == 1
    assert not any(tmp_path.glob(".run.partial-*"))


def test_a_sweep_folder_is_not_replaced_by_another_command(tmp_path) -> None:
    out = tmp_path / "sweep"
    with claim_output(out, command="sweep"):
        prepare_sweep_folder(out)
        (out / "points" / "0123.json").write_text("{}")
    result = runner.invoke(app, ["contact", str(EXAMPLE), "--out", str(out)])
    assert "sweep" in _one_line_error(result)
    assert (out / "points" / "0123.json").is_file()


def test_a_failed_swap_step_keeps_the_old_folder(tmp_path, monkeypatch) -> None:
    out = tmp_path / "run"
    _write(out, 1)
    monkeypatch.setattr(folder_module, "_exchange", lambda a, b: False)  # no renameat2
    real_rename, calls = Path.rename, []

    def rename(self, target):
        calls.append(target)
        if len(calls) == 2:  # the new folder into place
            raise OSError(errno.EIO, "I/O error")
        return real_rename(self, target)

    monkeypatch.setattr(Path, "rename", rename)
    with pytest.raises(ResultsWriteError, match="I/O error"):
        _write(out, 2)
    assert _run_of(out) == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == ["run"]


def test_leftovers_of_a_killed_swap_are_tidied(tmp_path) -> None:
    out = tmp_path / "run"
    _write(out, 1)
    out.rename(tmp_path / ".run.old-abc")  # killed after setting the old folder aside
    (tmp_path / ".run.partial-def").mkdir()
    (tmp_path / ".run.partial-def" / "summary.json").write_text("{}")
    (tmp_path / ".run.wear-state.npz.ghi.tmp").write_bytes(b"PK")  # a checkpoint half-written
    (tmp_path / "other.partial-x").mkdir()  # not ours
    with claim_output(out):
        assert _run_of(out) == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == ["other.partial-x", "run"]


def _killed_writer(out: Path, where: str) -> None:
    """In a child process: start replacing ``out`` and die by SIGKILL at ``where``."""

    def die(*args, **kwargs):
        os.kill(os.getpid(), signal.SIGKILL)

    if where == "after_swap":
        folder_module.shutil.rmtree = die
    with results_folder(out) as scratch:
        write_summary(scratch / "summary.json", {"run": 2})
        (scratch / "sub").mkdir()
        (scratch / "sub" / "data.txt").write_text("2")
        if where == "while_writing":
            die()


@pytest.mark.parametrize(("where", "run"), [("while_writing", 1), ("after_swap", 2)])
def test_a_run_killed_while_replacing_leaves_a_complete_folder(tmp_path, where, run) -> None:
    out = tmp_path / "run"
    _write(out, 1)
    pid = os.fork()
    if pid == 0:  # pragma: no cover - the child never returns
        try:
            _killed_writer(out, where)
        finally:
            os._exit(1)
    _, status = os.waitpid(pid, 0)
    assert os.WIFSIGNALED(status) and os.WTERMSIG(status) == signal.SIGKILL
    assert _run_of(out) == run
    _write(out, 3)  # the next run tidies what the killed one left
    assert sorted(p.name for p in tmp_path.iterdir()) == ["run"]


def test_disk_full_is_one_line_and_leaves_nothing(tmp_path, monkeypatch) -> None:
    def full(self, *args, **kwargs):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(xr.Dataset, "to_netcdf", full)
    out = tmp_path / "deep" / "run"
    result = runner.invoke(app, ["contact", str(EXAMPLE), "--out", str(out)])
    assert result.exit_code == 2, result.output
    assert (
        result.output.strip() == f"error: cannot write the results {out}: No space left on device"
    )
    assert list(tmp_path.iterdir()) == []


def test_disk_full_keeps_the_previous_results(tmp_path) -> None:
    out = tmp_path / "run"
    _write(out, 1)
    with pytest.raises(ResultsWriteError, match="No space left"), results_folder(out) as scratch:
        (scratch / "summary.json").write_text("{")
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
    assert _run_of(out) == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == ["run"]


def test_index_never_replaces_an_index_html_of_your_own(tmp_path) -> None:
    _write(tmp_path / "run", 1, "contact")
    assert runner.invoke(app, ["index", str(tmp_path)]).exit_code == 0
    assert runner.invoke(app, ["index", str(tmp_path)]).exit_code == 0  # its own page again
    (tmp_path / "index.html").write_text("<h1>my page</h1>")
    result = runner.invoke(app, ["index", str(tmp_path)])
    assert result.exit_code == 2 and "index.html of your own" in result.output
    assert (tmp_path / "index.html").read_text() == "<h1>my page</h1>"


def test_a_large_netcdf_is_not_started_without_room(tmp_path, monkeypatch) -> None:
    from collections import namedtuple

    usage = namedtuple("usage", "total used free")
    monkeypatch.setattr(folder_module, "IN_MEMORY_BYTES", 0)
    monkeypatch.setattr(folder_module.shutil, "disk_usage", lambda path: usage(1, 1, 10))
    dataset = xr.Dataset({"p": (("x",), [1.0, 2.0])})
    with (
        pytest.raises(ResultsWriteError, match="No space left"),
        results_folder(tmp_path / "r") as f,
    ):
        folder_module.write_netcdf(dataset, f / "fields.nc")
    assert list(tmp_path.iterdir()) == []
