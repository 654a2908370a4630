"""Engineering units and readable names at the edge: reports, plots and the sweep figures."""

from __future__ import annotations

import math

import numpy as np
import pytest
import xarray as xr

from ballscrew.plotting import line_styles, zero_noise
from ballscrew.results.about import ABOUT, theory_link
from ballscrew.results.display import engineering, engineering_array, readable
from ballscrew.results.report import inputs_warnings_sections
from ballscrew.results.sweep_report import plot_nut_forces, plot_variable
from ballscrew.units import format_quantity


@pytest.mark.parametrize(
    ("value", "unit", "key", "expected"),
    [
        (0.04, "m", "screw.pitch_diameter", (40.0, "mm")),
        (2.43e-6, "m", "max_wear_depth", (2.43, "µm")),
        (9.633e8, "Pa", "p0", (963.3, "MPa")),
        (2.06e11, "Pa", "E", (206.0, "GPa")),
        (2.1e7, "Pa", "yield", (21.0, "MPa")),
        (157.07963267948966, "rad/s", "operating.speed", (1500.0, "rpm")),
        (math.pi / 4, "rad", "contact_angle", (45.0, "°")),
        (1.41e9, "N/m", "catalogue_rigidity", (1410.0, "N/µm")),
        (293.15, "K", "operating.ambient_temperature", (20.0, "°C")),
        (12.5, "K", "max_temperature_rise", (12.5, "K")),
        (0.42, "N*m", "torque", (0.42, "N·m")),
        (28800.0, "s", "duration", (8.0, "h")),
        (2.43e-6, "m", "wear_depth", (2.43, "µm")),
        (1.37e-7, "m^2*K/W", "resistance_per_area", (0.137, "mm²·K/W")),
    ],
)
def test_engineering_units(value, unit, key, expected):
    shown, shown_unit = engineering(value, unit, key)
    assert shown_unit == expected[1]
    assert shown == pytest.approx(expected[0], rel=1e-12)


def test_one_spelling_per_unit():
    from ballscrew.results.display import spelling

    assert [spelling(u) for u in ("N m", "N*m", "kg/m^3", "J/(kg*K)", "um", "1")] == [
        "N·m",
        "N·m",
        "kg/m³",
        "J/(kg·K)",
        "µm",
        "",
    ]


def test_arrays_share_one_unit_and_headlines_keep_four_figures():
    values, unit = engineering_array(np.array([1e-7, 2.4e-6]), "m")
    assert unit == "µm" and values == pytest.approx([0.1, 2.4])
    assert format_quantity(9.633e8, "Pa") == "963.3 MPa"
    assert format_quantity(4.652 * math.pi / 30, "rad/s") == "4.652 rpm"


def test_readable_names_have_no_dots_or_underscores():
    assert readable("nut1.orbital_speed") == "nut 1: orbital speed"
    assert readable("operating.axial_load") == "axial load"
    assert readable("nut2_resistance") == "nut 2 resistance"


def test_solver_noise_is_zero_and_many_curves_look_different():
    assert zero_noise(np.array([1e-15, -3e-13, 0.2]), 1e-9).tolist() == [0.0, 0.0, 0.2]
    styles = line_styles(13)
    assert len({(str(s["color"]), s["linestyle"], s["marker"]) for s in styles}) == 13


def test_every_report_starts_with_inputs_in_engineering_units_warnings_and_the_theory():
    inputs = {
        "screw": {"lead": {"value": 0.01, "unit": "m"}},
        "operating": {"speed": {"value": 50 * math.pi, "unit": "rad/s"}},
    }
    sections = inputs_warnings_sections(inputs, [], "thermal")
    assert [s.title for s in sections] == ["Inputs", "Warnings", "What was computed and how"]
    rows = sections[0].tables[0][1]
    assert rows[0] == ["screw.lead", pytest.approx(10.0), "mm"]
    assert rows[1] == ["operating.speed", pytest.approx(1500.0), "rpm"]
    assert sections[1].paragraphs == ["No warnings."]
    text, url = sections[2].links[0]
    assert "thermal" in text and url.endswith(
        ("theory/thermal/", "thermal/index.html", "thermal.md")
    )


def test_every_analysis_links_an_existing_theory_page(monkeypatch):
    from quick_cases import REPO

    for _, page in ABOUT.values():
        assert (REPO / "docs" / "theory" / page).is_file(), page
    monkeypatch.setenv("BALLSCREW_DOCS_URL", "https://example.org/ballscrew/")
    assert theory_link("wear.md") == "https://example.org/ballscrew/theory/wear/"


def _sweep_2d() -> xr.Dataset:
    d = np.linspace(1.4, 1.7, 4)
    f = np.linspace(0.0, 6000.0, 5)
    return xr.Dataset(
        {
            "resistance_per_area": (
                ("surface.D", "operating.axial_load"),
                np.outer(d, 1.0 + f / 6000.0) * 1e-7,
                {"units": "m^2*K/W"},
            )
        },
        coords={
            "surface.D": d,
            "operating.axial_load": ("operating.axial_load", f, {"units": "N"}),
        },
    )


def spy(monkeypatch, method: str, keep) -> list:
    """Record ``keep(*args)`` of every call of ``Axes.<method>``; the call still draws."""
    import matplotlib.axes

    seen = []
    original = getattr(matplotlib.axes.Axes, method)

    def wrapper(self, *args, **kwargs):
        seen.append(keep(*args))
        return original(self, *args, **kwargs)

    monkeypatch.setattr(matplotlib.axes.Axes, method, wrapper)
    return seen


def test_a_2d_sweep_is_a_contour_map_with_readable_axes(tmp_path, monkeypatch):
    labels = spy(monkeypatch, "set_ylabel", lambda text, *a: text)
    drawn = spy(monkeypatch, "contourf", lambda *a: a[2].shape)
    path = plot_variable(_sweep_2d(), "resistance_per_area", tmp_path / "map.png")
    assert path.stat().st_size > 0
    assert drawn == [(5, 4)]  # (axial loads, D values): a map, not 4 lines
    assert "axial load [kN]" in labels and "resistance per area [mm²·K/W]" in labels


def test_a_swept_spin_of_round_off_is_plotted_as_zero(tmp_path, monkeypatch):
    plotted = spy(monkeypatch, "plot", lambda x, y, *a: np.asarray(y))
    speed = np.linspace(10.0, 200.0, 4)
    spin = ("operating.speed", [1e-15, -2e-15, 3e-16, 0.0], {"units": "rad/s"})
    ds = xr.Dataset(
        {"nuts.nut1.spin_nut": spin},
        coords={"operating.speed": ("operating.speed", speed, {"units": "rad/s"})},
    )
    plot_variable(ds, "nuts.nut1.spin_nut", tmp_path / "spin.png")
    assert plotted[0].tolist() == [0.0, 0.0, 0.0, 0.0]


def test_the_nut_forces_mark_the_lift_off(tmp_path, monkeypatch):
    lines = spy(monkeypatch, "axvline", lambda x=0, *a: x)
    load = np.linspace(0.0, 6000.0, 7)
    f2 = np.clip(1500.0 - 0.4 * load, 0.0, None)
    ds = xr.Dataset(
        {"F1": ("operating.axial_load", load + f2), "F2": ("operating.axial_load", f2)},
        coords={"operating.axial_load": ("operating.axial_load", load, {"units": "N"})},
    )
    plot_nut_forces(ds, tmp_path / "forces.png")
    assert lines == [4.0]  # kN, the axis unit


def test_a_margin_ratio_reads_as_a_margin():
    """The check's headline read 'speed: ratio'."""
    assert readable("margins.speed.ratio") == "speed margin (capacity/demand)"


def test_a_revolution_axis_has_its_power_in_the_label():
    """The wear plots' x axis read 'screw revolutions' with a bare '1e6' beside it."""
    from ballscrew.plotting import revolutions_axis

    assert revolutions_axis(np.array([0.0, 1.44e6])) == (1e6, "screw revolutions [10⁶ rev]")
    assert revolutions_axis(np.array([0.0, 5e4])) == (1e3, "screw revolutions [10³ rev]")
    assert revolutions_axis(np.array([0.0, 2000.0])) == (1.0, "screw revolutions")
