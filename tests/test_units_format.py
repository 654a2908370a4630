"""Engineering units at the edges: one formatter for the console, reports and plot axes."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew.units import DISPLAY_UNITS, format_number, format_quantity, to_display, to_si


@pytest.mark.parametrize(
    ("value", "kind", "text"),
    [
        (9.633e8, "pressure", "963.3 MPa"),
        (206e9, "Pa", "206 GPa"),
        (74.2371e-6, "displacement", "74.24 µm"),
        (0.04, "length", "40 mm"),
        (2.43e-6, "m", "2.43 µm"),
        (293.15, "temperature", "20 °C"),
        (17.5, "K", "17.5 K"),
        (1500 * math.pi / 30, "angular_velocity", "1500 rpm"),
        (4.652, "rad/s", "44.42 rpm"),
        (2000.0, "force", "2 kN"),
        (68.69, "N", "68.69 N"),
        (0.42314, "N*m", "0.4231 N·m"),
        (1.716e8, "N/m", "171.6 N/µm"),
        (28800.0, "time", "8 h"),
        (1.44e6, "revolutions", "1.44×10⁶ rev"),
        (12345.0, "angular_velocity", "117900 rpm"),  # 117 886 rpm to four figures
        (-3.2e-5, "length", "-32 µm"),
        (0.963, "", "0.963"),
    ],
)
def test_values_read_in_engineering_units_with_four_significant_figures(value, kind, text):
    assert format_quantity(value, kind) == text


@pytest.mark.parametrize(
    ("value", "kind"), [(1e-15, "rad/s"), (-3e-17, "angular_velocity"), (2e-16, "m")]
)
def test_solver_noise_reads_as_zero(value, kind):
    assert format_quantity(value, kind).startswith("0 ")
    assert format_quantity(1e-6, kind, zero_below=1e-5).startswith("0 ")
    assert not format_quantity(1e-3, kind).startswith("0 ")


def test_the_shown_number_reads_back_as_the_value_to_four_figures():
    """The text is a quantity ballscrew reads: the formatter and the reader agree on units."""
    for kind, value in (("pressure", 9.6334e8), ("length", 6.35e-3), ("force", 1234.5)):
        text = format_quantity(value, kind).replace("µ", "u")
        assert to_si(text, kind) == pytest.approx(value, rel=5e-4)


def test_one_spelling_of_each_unit():
    symbols = [s for units in DISPLAY_UNITS.values() for s, _ in units]
    assert "µm" in symbols and "N·m" in symbols
    assert not {"um", "N m", "N*m", "Nm", "degC"} & set(symbols)


@pytest.mark.parametrize(
    ("value", "text"),
    [(74.2371, "74.24"), (12000.0, "12000"), (0.11984, "0.1198"), (9.99996, "10"),
     (123456789.0, "1.235×10⁸"), (1.5e-5, "1.5×10⁻⁵"), (0.0, "0")],
)  # fmt: skip
def test_format_number(value, text):
    assert format_number(value) == text


def test_plot_axes_get_values_and_the_unit_symbol():
    values, symbol = to_display(np.array([0.0, 1e-5, 5e-5]), "length")
    assert symbol == "µm" and values == pytest.approx([0, 10, 50])
    celsius, symbol = to_display([293.15, 303.15], "temperature")
    assert symbol == "°C" and celsius == pytest.approx([20, 30])


def test_a_zero_length_reads_in_millimetres():
    """A zero stroke or rarefaction length was shown as '0 nm' in the report's inputs."""
    assert to_display(0.0, "length")[1] == "mm"
    assert format_quantity(0.0, "length") == "0 mm"
    assert to_display(np.array([0.0, 2e-3]), "length")[1] == "mm"  # nonzero: as before
    assert format_quantity(0.0, "force") == "0 N"


def test_flows_and_kinematic_viscosities_read_in_their_engineering_units():
    """A coolant flow read '3.333×10⁻⁵ m³/s' and an air viscosity '1.589×10⁻⁵ m²/s'."""
    assert format_quantity(2e-3 / 60.0, "m^3/s") == "2 L/min"
    assert format_quantity(1.589e-5, "m^2/s") == "15.89 mm²/s"
