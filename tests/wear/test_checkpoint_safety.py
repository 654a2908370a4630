"""A broken or planted wear checkpoint never blocks a run and is never written through."""

from __future__ import annotations

import json
import os
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

import ballscrew
from ballscrew.analyses.wear import wear_life
from ballscrew.cli import app
from ballscrew.commands.wear import checkpoint_path
from ballscrew.wear.checkpoint import CheckpointWarning, load_checkpoint, save_checkpoint

from .conftest import REF_PATH, SPEED

runner = CliRunner()
QUANTITIES = ("revolutions", "max_wear_depth", "preload", "friction_torque", "profiles")


@pytest.fixture(scope="module")
def tiny_case():
    """Two levels of 4e4 rev on a 12 × 48 grid: a few steps, well under a second."""
    return ballscrew.load_case(
        REF_PATH,
        {
            "wear.grid": [12, 48],
            "wear.programme": [
                {"axial_load": load, "speed": SPEED, "revolutions": 4e4} for load in (2e3, 4e3)
            ],
            "wear.torque_sampling": 2e4,
            "wear.checkpoint_every": 1,
        },
    )


@pytest.fixture(scope="module")
def clean(tiny_case):
    return wear_life(tiny_case)


def _same(life, clean) -> None:
    for name in QUANTITIES:
        np.testing.assert_array_equal(getattr(life, name), getattr(clean, name))


def _valid(tiny_case, path: Path) -> None:
    wear_life(tiny_case, checkpoint=path, max_steps=2)


def _truncate(path: Path) -> None:
    path.write_bytes(path.read_bytes()[: path.stat().st_size // 2])


def _reshape(path: Path) -> None:
    loaded = load_checkpoint(path)
    assert loaded is not None
    meta, arrays = loaded
    arrays["depth"] = arrays["depth"][:, :-1]
    save_checkpoint(path, meta, arrays)


def _old_version(path: Path) -> None:
    loaded = load_checkpoint(path)
    assert loaded is not None
    meta, arrays = loaded
    save_checkpoint(path, {**meta, "version": 0}, arrays)


BREAKERS = {
    "empty": lambda path: path.write_bytes(b""),
    "garbage": lambda path: path.write_bytes(b"not a zip archive at all"),
    "truncated": _truncate,
    "no meta": lambda path: np.savez(path, depth=np.zeros(3)),
    "wrong shapes": _reshape,
    "old format": _old_version,
}


@pytest.mark.parametrize("breaker", BREAKERS.values(), ids=BREAKERS.keys())
def test_a_broken_checkpoint_gives_a_warning_and_a_fresh_start(tiny_case, clean, tmp_path, breaker):
    path = tmp_path / "state.npz"
    _valid(tiny_case, path)
    breaker(path)
    with pytest.warns(CheckpointWarning, match="starting afresh"):
        life = wear_life(tiny_case, checkpoint=path, resume=True)
    assert life.complete
    _same(life, clean)
    assert load_checkpoint(path) is not None  # replaced by a sound one


def test_a_planted_link_is_replaced_not_followed(tiny_case, clean, tmp_path):
    victim = tmp_path / "victim.txt"
    victim.write_text("precious")
    path = tmp_path / "state.npz"
    path.symlink_to(victim)
    (tmp_path / "state.npz.tmp.npz").symlink_to(victim)  # the fixed temp name of old versions
    with pytest.warns(CheckpointWarning, match="not a regular file"):
        life = wear_life(tiny_case, checkpoint=path, resume=True)
    _same(life, clean)
    assert victim.read_text() == "precious"
    assert not path.is_symlink() and load_checkpoint(path) is not None
    assert not [p for p in tmp_path.iterdir() if p.name.endswith(".tmp")]


def test_checkpoint_temp_files_are_unique(tmp_path, monkeypatch):
    made = []
    real = os.replace

    def replace(src, dst):
        made.append(Path(src).name)
        real(src, dst)

    monkeypatch.setattr(os, "replace", replace)
    path = tmp_path / "state.npz"
    for _ in range(2):
        save_checkpoint(path, {"version": 1}, {"depth": np.zeros(2)})
    assert len(set(made)) == 2 and all(name.startswith(".state.npz.") for name in made)


def test_wear_command_resumes_past_a_corrupt_checkpoint(tmp_path, clean):
    case = tmp_path / "case.toml"
    text = REF_PATH.read_text()
    case.write_text(
        text[: text.index("[wear]")]
        + "[wear]\ngrid = [12, 48]\ntorque_sampling = 2e4\n"
        + "".join(
            f'[[wear.programme]]\naxial_load = "{load} N"\nspeed = "100 rpm"\nrevolutions = 4e4\n'
            for load in (2000, 4000)
        )
    )
    out = tmp_path / "out"
    checkpoint_path(out).write_bytes(b"\0" * 10)
    result = runner.invoke(app, ["wear", str(case), "--out", str(out)])
    assert result.exit_code == 0, result.output
    assert "starting afresh" in result.output
    summary = json.loads((out / "summary.json").read_text())
    assert summary["complete"]
    assert summary["revolutions"] == pytest.approx(clean.revolutions[-1])
    assert not checkpoint_path(out).exists()


def test_disk_full_while_checkpointing_is_one_line(tmp_path, monkeypatch):
    import errno

    def full(*args, **kwargs):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(np, "savez", full)
    out = tmp_path / "results" / "out"
    result = runner.invoke(app, ["wear", str(REF_PATH), "--out", str(out)])
    assert result.exit_code == 2, result.output
    assert result.output.strip().splitlines()[-1] == (
        f"error: cannot write the results {out}: No space left on device"
    )
    assert list(tmp_path.iterdir()) == []
