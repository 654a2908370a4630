import json

import pytest

from ballscrew.errors import InputError
from ballscrew.results import results_folder, write_summary


def test_folder_appears_only_when_complete(tmp_path):
    out = tmp_path / "run"
    with results_folder(out) as scratch:
        write_summary(scratch / "summary.json", {"x": 1})
        assert not out.exists()
    assert json.loads((out / "summary.json").read_text()) == {"x": 1}
    assert [p.name for p in tmp_path.iterdir()] == ["run"]


def test_failed_run_leaves_nothing(tmp_path):
    out = tmp_path / "run"
    with pytest.raises(RuntimeError), results_folder(out) as scratch:
        (scratch / "summary.json").write_text("{}")
        raise RuntimeError("solver failed")
    assert list(tmp_path.iterdir()) == []


def test_failed_rerun_keeps_the_previous_results(tmp_path):
    out = tmp_path / "run"
    with results_folder(out) as scratch:
        write_summary(scratch / "summary.json", {"run": 1})
    with pytest.raises(RuntimeError), results_folder(out) as scratch:
        raise RuntimeError
    assert json.loads((out / "summary.json").read_text()) == {"run": 1}


def test_refuses_a_folder_that_is_not_a_results_folder(tmp_path):
    (tmp_path / "precious.txt").write_text("keep me")
    with pytest.raises(InputError, match="--out"), results_folder(tmp_path):
        pass
    assert (tmp_path / "precious.txt").exists()


def test_refuses_a_file(tmp_path):
    target = tmp_path / "file"
    target.write_text("")
    with pytest.raises(InputError, match="not an existing file"), results_folder(target):
        pass


def test_unwritable_location(tmp_path):
    locked = tmp_path / "locked"
    locked.mkdir()
    locked.chmod(0o500)
    try:
        import os

        if os.access(locked, os.W_OK):  # running as root: permissions are not enforced
            pytest.skip("permissions are not enforced for this user")
        with pytest.raises(InputError, match="--out"), results_folder(locked / "run"):
            pass
    finally:
        locked.chmod(0o700)


def test_summary_replaces_non_finite_numbers_with_null(tmp_path):
    import math

    import numpy as np

    path = write_summary(
        tmp_path / "s.json", {"a": np.float64(2.0), "b": math.nan, "c": [np.int64(3)]}
    )
    assert json.loads(path.read_text()) == {"a": 2.0, "b": None, "c": [3]}
