"""Sweeps: a bad scheduler is one line at once; sweep files are replaced atomically."""

from __future__ import annotations

import errno
import json
import os
import time

import numpy as np
import pytest
import xarray as xr
from typer.testing import CliRunner

from ballscrew.cli import app
from ballscrew.results import ResultsWriteError
from ballscrew.results.folder import MARKER_NAME, claim_output, prepare_sweep_folder
from ballscrew.results.sweep_report import write_sweep
from ballscrew.sweep import cluster as sweep_cluster
from ballscrew.sweep import runner as sweep_runner

cli = CliRunner()


@pytest.mark.parametrize("address", ["garbage", "foo://bar", "tcp://127.0.0.1:1"])
def test_a_bad_scheduler_is_one_line_at_once(tmp_path, gao_case_path, monkeypatch, address):
    monkeypatch.setattr(sweep_cluster, "CONNECT_TIMEOUT", "1s")
    out = tmp_path / "sweep"
    args = ["sweep", str(gao_case_path), "--vary", "operating.axial_load=0,1000"]
    start = time.perf_counter()
    result = cli.invoke(app, [*args, "--out", str(out), "--scheduler", address])
    # a refusal within the 1 s connect timeout plus Dask's client set-up, not distributed's
    # 30 s default; 10 s was once exceeded (10.06 s) with a loaded event loop in a full run
    assert time.perf_counter() - start < 20.0
    assert result.exit_code == 2, result.output
    assert "Traceback" not in result.output
    errors = [line for line in result.output.splitlines() if line.startswith("error:")]
    assert len(errors) == 1 and errors[0].startswith("error: --scheduler")
    assert list(tmp_path.iterdir()) == []  # nothing written, no empty folder


def _dataset(value: float) -> xr.Dataset:
    return xr.Dataset(
        {
            "R": (("F",), np.array([value, value]), {"units": "K/W"}),
            "error": (("F",), np.array(["", ""])),
            "failed": (("F",), np.array([False, False])),
        },
        coords={"F": ("F", np.array([0.0, 1.0]), {"units": "N"})},
        attrs={"analysis": "tcr", "case": "demo", "points": 2},
    )


def test_sweep_files_are_replaced_atomically(tmp_path, monkeypatch):
    out = tmp_path / "sweep"
    with claim_output(out, command="sweep"):
        prepare_sweep_folder(out)
        write_sweep(_dataset(1.0), out, 2)
    before = {p.name: p.read_bytes() for p in out.iterdir() if p.is_file()}
    assert {"sweep.nc", "summary.json", "report.html", "sweep_R.png", MARKER_NAME} <= set(before)

    def full(self, *args, **kwargs):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(xr.Dataset, "to_netcdf", full)
    with pytest.raises(ResultsWriteError, match="No space left"):
        write_sweep(_dataset(2.0), out, 0)
    after = {p.name: p.read_bytes() for p in out.iterdir() if p.is_file()}
    assert after == before
    assert json.loads((out / "summary.json").read_text())["computed_now"] == 2


def test_an_unreadable_point_is_computed_again(tmp_path):
    point = tmp_path / "0123.json"
    point.write_text('{"overrides": ')
    assert sweep_runner._needs_run(point, retry_failed=False)


def test_sweep_folder_states_its_inputs_and_failed_points(tmp_path, gao_case_path):
    """The sweep report has the writer's Inputs and Warnings sections; a failed point warns."""
    from ballscrew.case import load_case
    from ballscrew.sweep import parse_axis

    case = load_case(gao_case_path)
    data = _dataset(1.0)
    data["failed"] = (("F",), np.array([False, True]))
    data["error"] = (("F",), np.array(["", "InputError: boom"]))
    out = tmp_path / "sweep"
    with claim_output(out, command="sweep"):
        prepare_sweep_folder(out)
        write_sweep(data, out, 2, case, [parse_axis("operating.axial_load=0,1")])
    summary = json.loads((out / "summary.json").read_text())
    assert summary["warnings"] == ["point F=1 N failed: InputError: boom"]  # with its unit
    assert summary["inputs"]["analysis"] == "tcr"
    assert summary["inputs"]["axes"]["F"] == {"values": [0.0, 1.0], "unit": "N"}
    assert summary["inputs"]["case"]["operating"]["preload"]["unit"] == "N"
    assert summary["failed"] == 1 and summary["axes"]["F"]["unit"] == "N"  # as before
    report = (out / "report.html").read_text()
    assert "<h2>Inputs</h2>" in report and "operating.preload" in report
    assert "point F=1 N failed: InputError: boom" in report
