"""Headline numbers of a summary in engineering units, as the console, report and index show."""

from __future__ import annotations

import pytest

from ballscrew.results.display import readable
from ballscrew.results.headlines import format_entry, headline_keys, headline_rows


@pytest.mark.parametrize(
    ("key", "entry", "text"),
    [
        ("max_wear_depth", {"value": 1.737e-7, "unit": "m"}, "0.1737 µm"),
        ("steady.elongation", {"value": 7.424e-5, "unit": "m"}, "74.24 µm"),
        ("nut_temperature", {"value": 298.27, "unit": "K"}, "25.12 °C"),
        ("steady.max_temperature_rise", {"value": 17.53, "unit": "K"}, "17.53 K"),
        ("nuts.nut1.orbital_speed", {"value": 4.652, "unit": "rad/s"}, "44.42 rpm"),
        ("nuts.nut1.spin_screw", {"value": 1e-15, "unit": "rad/s"}, "0 rpm"),
        ("contacts.screw.numerical.peak_pressure", {"value": 9.633e8, "unit": "Pa"}, "963.3 MPa"),
        ("rating_life", {"value": 7.615e9, "unit": ""}, "7.615×10⁹ rev"),
        ("points", 7, "7"),
        ("model", "network", None),
    ],
)
def test_summary_entries_read_in_engineering_units(key, entry, text):
    assert format_entry(key, entry) == text


@pytest.mark.parametrize(
    ("key", "label"),
    [
        ("contacts.screw.numerical.peak_pressure", "screw: peak pressure"),
        ("nuts.nut1.orbital_speed", "nut 1: orbital speed"),
        ("heat_balance.heat_input", "heat input"),
        ("drag_torque.ball_model", "drag torque: ball model"),
        ("recommended.D", "D"),
        ("ball_load", "ball load"),
    ],
)
def test_labels_leave_out_the_grouping_keys(key, label):
    assert readable(key) == label


def test_headlines_and_plots_spell_a_name_alike():
    """One spelling of a name on the console, the report, the index page and the plot axes."""
    summary = {"nuts": {"nut1": {"orbital_speed": {"value": 4.652, "unit": "rad/s"}}}}
    [(label, _)] = headline_rows(summary, ["nuts.nut1.orbital_speed"])
    assert label == readable("nut1.orbital_speed") == "nut 1: orbital speed"


def test_rows_follow_the_declared_headlines():
    summary = {
        "analysis": "operating-point",
        "friction_torque": {"value": 0.42314, "unit": "N*m"},
        "heat": {"value": 44.31, "unit": "W"},
        "nut_temperature": {"value": 298.27, "unit": "K"},
        "screw_temperature": {"value": 302.9, "unit": "K"},
        "viscosity": {"value": 0.05, "unit": "Pa*s"},
    }
    rows = headline_rows(summary, headline_keys("operating-point"))
    assert rows == [
        ("friction torque", "0.4231 N·m"),
        ("heat", "44.31 W"),
        ("nut temperature", "25.12 °C"),
        ("screw temperature", "29.75 °C"),
        ("viscosity", "50 mPa·s"),
    ]
    assert headline_keys("no such analysis") == ()


def test_label_of_is_kept_as_readable():
    """``label_of`` stays a public name of this module: the same words as ``readable``."""
    from ballscrew.results import headlines
    from ballscrew.results.headlines import label_of

    assert "label_of" in headlines.__all__
    for key in ("contacts.screw.numerical.peak_pressure", "nuts.nut1.orbital_speed", "F1"):
        assert label_of(key) == readable(key)


def test_a_relative_difference_reads_in_percent():
    """The contact headline read 'relative difference to hertz: peak pressure  0.001316'."""
    entry = {"value": 0.001316, "unit": ""}
    key = "contacts.screw.relative_difference_to_hertz.peak_pressure"
    assert format_entry(key, entry) == "0.1316 %"
    assert format_entry("static_safety_factor", {"value": 28.91, "unit": ""}) == "28.91"
