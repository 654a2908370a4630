"""Headline numbers of a summary in engineering units, as the console, report and index show."""

from __future__ import annotations

import pytest

from ballscrew.results.headlines import format_entry, headline_keys, headline_rows, label_of


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


def test_labels_leave_out_the_grouping_keys():
    assert label_of("contacts.screw.numerical.peak_pressure") == "screw peak pressure"
    assert label_of("nuts.nut1.orbital_speed") == "nut1 orbital speed"
    assert label_of("ball_load") == "ball load"


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
    ]
    assert headline_keys("no such analysis") == ()
