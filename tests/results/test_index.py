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
    assert "final preload = 244.3 N" in text
    assert '<a href="wear/report.html">' in text
    assert "not_results" not in text


def test_index_needs_results_folders(tmp_path):
    with pytest.raises(InputError, match="folder"):
        write_index(tmp_path)


def _png(path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=(1, 1))
    fig.savefig(path)
    plt.close(fig)


def test_index_shows_the_headlines_and_key_figure_of_each_descriptor(tmp_path):
    """Headlines and figures come from the analysis descriptors (thermal-network had none)."""
    from ballscrew.analyses.catalog import ANALYSES

    summary = {
        "analysis": "thermal-network",
        "case": "n",
        "points": 7,
        "steady": {"max_temperature_rise": {"value": 12.5, "unit": "K"}},
    }
    make_folder(tmp_path, "net", summary)
    sweep = make_folder(
        tmp_path, "sw", {"analysis": "tcr", "case": "c", "axes": {"F": {}}, "points": 3}
    )
    for name in ("sweep_a.png", "sweep_resistance_per_area.png"):
        _png(sweep / name)
    assert ANALYSES["thermal-network"].headlines[0] == "steady.max_temperature_rise"
    text = write_index(tmp_path).read_text()
    assert "max temperature rise = 12.5 K" in text
    assert "points = 7" not in text  # only the descriptor's headlines
    assert "points = 3" in text  # a sweep's headlines
    assert "sw: sweep_resistance_per_area" in text  # the sweep's key figure, not its first PNG


def test_index_is_replaced_atomically(tmp_path, monkeypatch):
    from ballscrew.results import index as index_module

    make_folder(tmp_path, "a", {"analysis": "tcr", "case": "c"})
    page = write_index(tmp_path)
    before = page.read_bytes()

    def fail(path, folders):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(index_module, "_link_reports", fail)
    with pytest.raises(InputError, match="writable"):
        write_index(tmp_path)
    assert page.read_bytes() == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a", "index.html"]
