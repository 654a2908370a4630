"""The report's picture of the 3-D temperature field: a section through the axis and the screw
surface unrolled, drawn from a coarse 3-D solution."""

from __future__ import annotations

from types import SimpleNamespace

import matplotlib.axes
import numpy as np

from ballscrew.analyses.thermal_report import field_3d
from ballscrew.thermal.simulate import simulate
from ballscrew.thermal.threed import build_threed

from . import test_network as ref


def test_the_3d_field_is_drawn_in_celsius_on_both_bodies(tmp_path, monkeypatch):
    problem = ref.engine_problem()
    solution = simulate(build_threed(problem, 0.04, 8, 1), None)
    result = SimpleNamespace(
        solution=solution, problem=problem, ambient_temperature=293.15, case_name="engine"
    )
    drawn = []
    original = matplotlib.axes.Axes.tricontourf
    monkeypatch.setattr(
        matplotlib.axes.Axes,
        "tricontourf",
        lambda self, tri, values, **kw: (
            drawn.append((tri, values)) or original(self, tri, values, **kw)
        ),
    )
    path = field_3d(result, tmp_path / "field.png")
    assert path.stat().st_size > 10_000
    (section, t_section), (surface, t_surface) = drawn
    rise = solution.steady.max()
    assert np.isfinite(t_section).all() and np.isfinite(t_surface).all()
    assert max(t_section.max(), t_surface.max()) <= 20.0 + rise + 1e-9  # °C, ambient 20 °C
    assert t_section.min() >= 20.0 - 1e-9
    assert section.y.max() > problem.shaft_radius * 1e3  # the nut is in the section [mm]
    assert np.ptp(surface.y) > 300.0  # the whole circumference [°]
    assert (~section.mask).sum() > 0.5 * section.triangles.shape[0]
