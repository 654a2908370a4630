"""Profile readers: CSV/text with units, ISO 25178-71/BCR SDF (ASCII and binary), bad files."""

from __future__ import annotations

import struct
from pathlib import Path

import numpy as np
import pytest

from ballscrew.errors import InputError
from ballscrew.surface import (
    Profile,
    fractal_parameters,
    read_profile,
    weierstrass_mandelbrot_profile,
    write_sdf,
    write_text_profile,
)

# The example of the NIST SDF page (values shortened), header keys and values split over lines.
NIST_STYLE = """aBCR-1.0
ManufacID = Sine
CreateDate = 031019971457
ModDate =
031019971457
NumPoints =
16
NumProfiles = 1
Xscale
= 0.5e-6
Yscale = 0
Zscale = 1.0e-10
Zresolution = 0
Compression = 0
DataType = 5
CheckType = 0
*
0
79
157
236
314
393 471 550
628 550 471 393
314 236 157 79
*
"""


def write(path: Path, text: str) -> Path:
    path.write_text(text, encoding="utf-8")
    return path


def csv_rows(n: int = 20) -> str:
    return "\n".join(f"{0.5 * i:g}, {10.0 * ((-1) ** i) + i:g}" for i in range(n))


# ------------------------------------------------------------------------------------ text


def test_csv_header_units_are_converted(tmp_path: Path) -> None:
    path = write(tmp_path / "p.csv", "x [um], z [nm]\n" + csv_rows())
    p = read_profile(path)
    assert p.spacing == pytest.approx(0.5e-6)
    expected = np.array([10.0 * ((-1) ** i) + i for i in range(20)]) * 1e-9
    np.testing.assert_allclose(p.heights, expected, rtol=1e-12)
    assert p.metadata["x_unit"] == "um" and p.metadata["z_unit"] == "nm"
    assert p.source == str(path)


def test_semicolon_parentheses_micro_sign_and_comments(tmp_path: Path) -> None:
    body = "\n".join(f"{0.002 * i:.3f}; {0.1 * i:.1f}" for i in range(32))
    text = "# instrument = stylus\n% exported\nposition (mm); height (µm)\n" + body
    p = read_profile(write(tmp_path / "p.txt", text))
    assert p.spacing == pytest.approx(2e-6)
    assert p.heights[-1] == pytest.approx(3.1e-6)
    assert p.metadata["instrument"] == "stylus"


def test_whitespace_columns_without_header_are_si(tmp_path: Path) -> None:
    body = "\n".join(f"{1e-6 * i:.6e}\t{1e-8 * np.sin(i):.8e}" for i in range(40))
    p = read_profile(write(tmp_path / "p.dat", body))
    assert p.spacing == pytest.approx(1e-6)
    assert p.heights[3] == pytest.approx(1e-8 * np.sin(3), rel=1e-7)


def test_blank_separated_header_with_units(tmp_path: Path) -> None:
    body = "\n".join(f"{2 * i}  {i}" for i in range(20))
    p = read_profile(write(tmp_path / "p.txt", "x [nm]   z [Å]\n" + body))
    assert p.spacing == pytest.approx(2e-9)
    assert p.heights[5] == pytest.approx(5e-10)


def test_decreasing_x_is_reversed(tmp_path: Path) -> None:
    body = "\n".join(f"{0.5 * (19 - i):g}, {i:g}" for i in range(20))
    p = read_profile(write(tmp_path / "p.csv", "x [um], z [nm]\n" + body))
    assert p.heights[0] == pytest.approx(19e-9)


def test_one_column_with_spacing_comment_or_argument(tmp_path: Path) -> None:
    heights = "\n".join(f"{i * 0.01:g}" for i in range(20))
    p = read_profile(write(tmp_path / "a.txt", "# spacing = 0.25 um\nz [um]\n" + heights))
    assert p.spacing == pytest.approx(0.25e-6)
    assert p.heights[19] == pytest.approx(0.19e-6)
    q = read_profile(write(tmp_path / "b.txt", heights), spacing="2 mm", z_unit="nm")
    assert q.spacing == pytest.approx(2e-3)
    assert q.heights[19] == pytest.approx(0.19e-9)
    r = read_profile(write(tmp_path / "c.txt", "# dx = 3\n# x_unit = um\n" + heights))
    assert r.spacing == pytest.approx(3e-6)


def test_csv_round_trip(tmp_path: Path) -> None:
    p = weierstrass_mandelbrot_profile(1.59, 9e-10, 1e-3, 0.5e-6, seed=1)
    path = write_text_profile(tmp_path / "wm.csv", p, x_unit="mm", z_unit="um")
    q = read_profile(path)
    assert q.spacing == pytest.approx(p.spacing, rel=1e-10)
    np.testing.assert_allclose(q.heights, p.heights, rtol=1e-10, atol=1e-20)


# ------------------------------------------------------------------------------------- SDF


def test_sdf_in_the_nist_layout(tmp_path: Path) -> None:
    p = read_profile(write(tmp_path / "sine.sdf", NIST_STYLE))
    assert p.n_profiles == 1 and p.heights.shape == (16,)
    assert p.spacing == pytest.approx(0.5e-6)
    assert p.y_spacing is None
    np.testing.assert_allclose(p.heights[:6], np.array([0, 79, 157, 236, 314, 393]) * 1e-10)
    assert p.metadata["ManufacID"] == "Sine"
    assert p.metadata["ModDate"] == "031019971457"
    assert p.metadata["version"] == "aBCR-1.0"


def test_sdf_found_by_magic_whatever_the_extension(tmp_path: Path) -> None:
    p = read_profile(write(tmp_path / "export.xyz", NIST_STYLE))
    assert p.metadata["format"] == "sdf-ascii"


def test_areal_sdf_with_bad_points(tmp_path: Path) -> None:
    rows = ["1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16", "BAD " * 16, "16 " * 16]
    text = NIST_STYLE.split("*")[0].replace("NumProfiles = 1", "NumProfiles = 3")
    text = text.replace("Yscale = 0", "Yscale = 2e-6")
    p = read_profile(write(tmp_path / "areal.sdf", text + "*\n" + "\n".join(rows) + "\n*\n"))
    assert p.heights.shape == (3, 16)
    assert p.y_spacing == pytest.approx(2e-6)
    assert np.all(np.isnan(p.heights[1]))
    assert p.heights[0, 15] == pytest.approx(16e-10)


@pytest.mark.parametrize(("data_type", "z_scale", "rtol"), [(7, 1e-9, 1e-11), (6, 1e-13, 1e-4)])
def test_sdf_round_trip(tmp_path: Path, data_type: int, z_scale: float, rtol: float) -> None:
    p = weierstrass_mandelbrot_profile(1.5, 1e-10, 1e-3, 1e-6, seed=2, profiles=3)
    p = Profile(p.heights, p.spacing, 5e-6, {}, "synthetic")
    path = write_sdf(tmp_path / "wm.sdf", p, z_scale=z_scale, data_type=data_type)
    q = read_profile(path)
    assert q.heights.shape == (3, 1000)
    assert q.spacing == pytest.approx(1e-6) and q.y_spacing == pytest.approx(5e-6)
    np.testing.assert_allclose(q.heights, p.heights, rtol=rtol, atol=z_scale)


def test_fit_of_an_areal_sdf(tmp_path: Path) -> None:
    D, G = 1.59, 9e-10
    p = weierstrass_mandelbrot_profile(D, G, 2**13 * 0.5e-6, 0.5e-6, seed=9, profiles=12)
    result = fractal_parameters(read_profile(write_sdf(tmp_path / "a.sdf", p)))
    assert result.psd.profiles == 12
    assert result.D == pytest.approx(D, rel=0.02)
    assert result.G == pytest.approx(G, rel=0.10)


def test_binary_sdf_with_the_bcr_header(tmp_path: Path) -> None:
    values = np.arange(-8, 12, dtype="<i2")  # 4 points × 5 profiles
    header = struct.pack(
        "<8s10s12s12sHHddddBBB",
        b"bBCR-1.0",
        b"WYKO",
        b"010120201200",
        b"010120201200",
        4,
        5,
        0.82e-6,
        0.82e-6,
        2e-9,
        0.0,
        0,
        5,
        0,
    )
    path = tmp_path / "bin.sdf"
    path.write_bytes(header + values.tobytes())
    p = read_profile(path)
    assert p.heights.shape == (5, 4)
    np.testing.assert_allclose(p.heights.ravel(), values * 2e-9)
    assert p.spacing == pytest.approx(0.82e-6)
    assert p.metadata["ManufacID"] == "WYKO"


# ------------------------------------------------------------------------------ bad files


def error_of(path: Path, **kwargs) -> InputError:
    with pytest.raises(InputError) as err:
        read_profile(path, **kwargs)
    return err.value


@pytest.mark.parametrize("name", ["empty.csv", "empty.sdf", "empty.txt"])
def test_empty_file(tmp_path: Path, name: str) -> None:
    path = write(tmp_path / name, "\n  \n")
    err = error_of(path)
    assert name in str(err)
    assert "empty" in str(err)


def test_header_only_file(tmp_path: Path) -> None:
    err = error_of(write(tmp_path / "h.csv", "x [um], z [nm]\n"))
    assert "h.csv" in err.field and "no data rows" in str(err)


def test_missing_column(tmp_path: Path) -> None:
    lines = ["x [um], z [nm]", *csv_rows().splitlines()]
    lines[5] = "2.0"
    err = error_of(write(tmp_path / "m.csv", "\n".join(lines)))
    assert err.field == "m.csv: line 6"
    assert "1 column" in str(err)


def test_three_columns(tmp_path: Path) -> None:
    body = "\n".join(f"{i}, {i}, {i}" for i in range(20))
    assert error_of(write(tmp_path / "t.csv", body)).field == "t.csv: columns"


def test_non_uniform_spacing(tmp_path: Path) -> None:
    body = "\n".join(f"{0.5 * i + (0.2 if i == 7 else 0):g}, {i:g}" for i in range(20))
    err = error_of(write(tmp_path / "n.csv", "x [um], z [nm]\n" + body))
    assert err.field == "n.csv: column 'x' (spacing)"
    assert "non-uniform" in str(err)


def test_non_numeric_value(tmp_path: Path) -> None:
    lines = csv_rows().splitlines()
    lines[3] = "1.5, oops"
    err = error_of(write(tmp_path / "v.csv", "x [um], z [nm]\n" + "\n".join(lines)))
    assert err.field == "v.csv: line 5"


def test_unknown_unit(tmp_path: Path) -> None:
    err = error_of(write(tmp_path / "u.csv", "x [um], z [kg]\n" + csv_rows()))
    assert err.field == "u.csv: unit of column 'z'"


def test_missing_spacing_of_a_one_column_file(tmp_path: Path) -> None:
    err = error_of(write(tmp_path / "s.txt", "\n".join(str(i) for i in range(20))))
    assert err.field == "s.txt: spacing"


def test_unknown_binary_format(tmp_path: Path) -> None:
    path = tmp_path / "scan.opd"
    path.write_bytes(b"\x00\x01\x02binary" + bytes(range(256)))
    err = error_of(path)
    assert err.field == "scan.opd: format"


def test_missing_file(tmp_path: Path) -> None:
    assert "nothere.csv" in str(error_of(tmp_path / "nothere.csv"))


@pytest.mark.parametrize(
    ("old", "new", "field"),
    [
        ("NumPoints =\n16", "", "NumPoints"),
        ("NumPoints =\n16", "NumPoints = 17", "data"),
        ("Xscale\n= 0.5e-6", "Xscale = -1", "Xscale"),
        ("Compression = 0", "Compression = 1", "Compression"),
        ("DataType = 5", "DataType = 9", "DataType"),
        ("aBCR-1.0", "SDF-1.0", "version"),
        ("393 471 550", "393 x 550", "data"),
    ],
)
def test_bad_sdf(tmp_path: Path, old: str, new: str, field: str) -> None:
    assert old in NIST_STYLE
    err = error_of(write(tmp_path / "bad.sdf", NIST_STYLE.replace(old, new)))
    assert err.field == f"bad.sdf: {field}"
