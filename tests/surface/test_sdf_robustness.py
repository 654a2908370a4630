"""Bad numbers in SDF headers and profile files end in one line naming the field."""

from __future__ import annotations

import struct
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from ballscrew.cli import app
from ballscrew.errors import InputError
from ballscrew.surface import read_profile

HEADER = """aBCR-1.0
ManufacID = test
NumPoints = {points}
NumProfiles = {profiles}
Xscale = {xscale}
Yscale = 0
Zscale = {zscale}
Compression = {compression}
DataType = {dtype}
CheckType = 0
*
{data}
*
"""
GOOD = {
    "points": "16",
    "profiles": "1",
    "xscale": "0.5e-6",
    "zscale": "1e-9",
    "compression": "0",
    "dtype": "5",
    "data": " ".join(str((-1) ** i * i) for i in range(16)),
}


def sdf(tmp_path: Path, **changes: str) -> Path:
    path = tmp_path / "bad.sdf"
    path.write_text(HEADER.format(**{**GOOD, **changes}), encoding="ascii")
    return path


def test_the_good_file_reads(tmp_path):
    assert read_profile(sdf(tmp_path)).n_points == 16


@pytest.mark.parametrize(
    ("key", "value", "field"),
    [
        ("points", "inf", "NumPoints"),
        ("points", "-inf", "NumPoints"),
        ("points", "1e400", "NumPoints"),
        ("points", "nan", "NumPoints"),
        ("points", "-16", "NumPoints"),
        ("points", "16.5", "NumPoints"),
        ("points", "sixteen", "NumPoints"),
        ("points", "1e30", "data"),
        ("points", "15", "data"),
        ("profiles", "inf", "NumProfiles"),
        ("profiles", "0", "NumProfiles"),
        ("profiles", "2", "data"),
        ("compression", "inf", "Compression"),
        ("dtype", "inf", "DataType"),
        ("dtype", "5.5", "DataType"),
        ("xscale", "inf", "Xscale"),
        ("xscale", "nan", "Xscale"),
        ("xscale", "0", "Xscale"),
        ("zscale", "nan", "Zscale"),
        ("zscale", "1e308", "data"),
        ("data", "1 2 3 inf 5 6 7 8 9 10 11 12 13 14 15 16", "data"),
    ],
)
def test_bad_header_number_is_one_line_naming_the_field(tmp_path, key, value, field):
    path = sdf(tmp_path, **{key: value})
    with pytest.raises(InputError) as info:
        read_profile(path)
    assert info.value.field == f"bad.sdf: {field}"
    result = CliRunner().invoke(app, ["surface", str(path), "--out", str(tmp_path / "out")])
    assert result.exit_code == 2, result.output
    assert f"bad.sdf: {field}" in result.output
    assert "Traceback" not in result.output


def test_a_spacing_no_instrument_samples_is_refused_as_in_text_files(tmp_path):
    """Xscale = 1e30 m was refused from a text profile but read from an SDF file."""
    with pytest.raises(InputError, match=r"bad.sdf: Xscale = 1e\+30 is not allowed: a sampling"):
        read_profile(sdf(tmp_path, xscale="1e30"))


def test_binary_header_with_infinite_scale(tmp_path):
    header = struct.pack(
        "<8s10s12s12sHHddddBBB", b"bBCR-1.0", b"x", b"", b"", 4, 1, np.inf, 0, 1e-9, 0, 0, 5, 0
    )
    path = tmp_path / "bin.sdf"
    path.write_bytes(header + np.arange(4, dtype="<i2").tobytes())
    with pytest.raises(InputError, match="Xscale"):
        read_profile(path)


def text_file(tmp_path: Path, body: str) -> Path:
    path = tmp_path / "p.csv"
    path.write_text(body, encoding="utf-8")
    return path


@pytest.mark.parametrize(
    ("kwargs", "field"),
    [
        ({"x_unit": 5}, "p.csv: unit of column 'x'"),
        ({"z_unit": ["um"]}, "p.csv: unit of column 'z'"),
        ({"format": 5}, "p.csv: format"),
    ],
)
def test_non_string_options_are_refused(tmp_path, kwargs, field):
    path = text_file(tmp_path, "\n".join(f"{i}, {i % 3}" for i in range(20)))
    with pytest.raises(InputError) as info:
        read_profile(path, **kwargs)
    assert info.value.field == field


@pytest.mark.parametrize("spacing", [True, 1e-6 + 1e-6j, np.complex128(1e-6)])
def test_spacing_must_be_a_real_number(tmp_path, spacing):
    path = text_file(tmp_path, "\n".join(str(i % 3) for i in range(20)))
    with pytest.raises(InputError, match="spacing"):
        read_profile(path, spacing=spacing)


def test_infinite_height_in_a_text_file(tmp_path):
    rows = [f"{i}, {i % 3}" for i in range(20)]
    rows[4] = "4, 1e400"
    with pytest.raises(InputError, match="infinite height"):
        read_profile(text_file(tmp_path, "\n".join(rows)))
