"""Figures are written in one drawing pass (``savefig`` draws a constrained-layout figure twice),
with the pixels ``savefig`` gives."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from ballscrew.plotting import DPI, pyplot, save_figure


def _figure() -> Figure:
    fig, ax = pyplot().subplots(figsize=(4.0, 3.0), layout="constrained")
    image = ax.imshow(np.arange(12.0).reshape(3, 4))
    fig.colorbar(image, ax=ax, label="pressure [GPa]")
    ax.set_title("screw contact A")
    ax.set_xlabel("y, across the groove [µm]")
    return fig


def test_a_figure_is_drawn_once_with_the_pixels_of_savefig(tmp_path, monkeypatch):
    reference = _figure()
    reference.savefig(tmp_path / "savefig.png", dpi=DPI)
    pyplot().close(reference)
    draws: list[Figure] = []
    draw = Figure.draw
    monkeypatch.setattr(
        Figure, "draw", lambda fig, renderer: draws.append(fig) or draw(fig, renderer)
    )
    fig = _figure()
    assert save_figure(fig, tmp_path / "once.png") == tmp_path / "once.png"
    assert draws == [fig]
    assert not pyplot().fignum_exists(fig.number)  # closed
    imread = pyplot().imread
    np.testing.assert_array_equal(imread(tmp_path / "once.png"), imread(tmp_path / "savefig.png"))
