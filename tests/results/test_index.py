import json

import pytest

from ballscrew.errors import InputError
from ballscrew.results.index import write_index


def make_folder(root, name, summary):
    folder = root / name
    folder.mkdir()
    (folder / "summary.json").write_text(json.dumps(summary))
    (folder / "report.html").write_text("<html></html>")
    return folder


def test_index_lists_each_results_folder_with_its_key_numbers(tmp_path):
    make_folder(
        tmp_path,
        "tcr",
        {"analysis": "tcr", "case": "c", "resistance": {"value": 0.0195, "unit": "K/W"}},
    )
    make_folder(
        tmp_path,
        "wear",
        {"analysis": "wear", "case": "w", "final_preload": {"value": 244.3, "unit": "N"}},
    )
    (tmp_path / "not_results").mkdir()
    text = write_index(tmp_path).read_text()
    assert "resistance = 0.0195 K/W" in text
    assert "final_preload = 244.3 N" in text
    assert '<a href="wear/report.html">' in text
    assert "not_results" not in text


def test_index_needs_results_folders(tmp_path):
    with pytest.raises(InputError, match="folder"):
        write_index(tmp_path)
