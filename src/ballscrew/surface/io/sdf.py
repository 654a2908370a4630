"""ISO 25178-71 / BCR Surface Data File (``.sdf``), the interchange format of areal data.

Exported by WYKO/Veeco Vision (the WYKO NT1100 of the paper), Bruker, Zygo MetroPro, Digital Surf
MountainsMap, Taylor Hobson and others. ASCII layout (record 1 header, record 2 data, record 3
optional trailer, each closed by a line with a single ``*``)::

    aBCR-1.0                  (or aISO-1.0, aISO-2.0)
    ManufacID   = WYKO
    CreateDate  = 250520231200
    ModDate     = 250520231200
    NumPoints   = 640          points per profile (x)
    NumProfiles = 480          profiles (y)
    Xscale      = 8.2e-07      x spacing, m
    Yscale      = 8.2e-07      y spacing, m
    Zscale      = 1e-09        height of one data unit, m
    Zresolution = -1
    Compression = 0
    DataType    = 5            0 uchar, 1 uint16, 2 uint32, 3 float, 4 schar, 5 int16, 6 int32,
                               7 double
    CheckType   = 0
    *
    z values, profile after profile (x fastest), separated by blanks or line breaks;
    BAD marks a non-measured point
    *
    optional trailer
    *

Heights are value × Zscale in metres, the spacing is Xscale in metres. Binary files (version
string ``bBCR-1.0``/``bISO-1.0``) have the same fields as an 81-byte packed little-endian header
(8, 10, 12, 12 characters; uint16 NumPoints, NumProfiles; four float64 scales; three uint8),
then the data in the type DataType. Compression and checksums are not supported.

Sources: Stout, K. J. et al. (1993), *The development of methods for the characterisation of
roughness in three dimensions*, Report EUR 15178 EN (the BCR format); ISO 25178-71:2017
(softgauges, file format); NIST Surface Metrology, "SDF Format" (physics.nist.gov/VSC).
"""

from __future__ import annotations

import math
import re
import struct
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

import numpy as np

from ballscrew.errors import InputError
from ballscrew.surface.io._common import checked_profile, file_error, file_path
from ballscrew.surface.profile import Profile, sampling_range

__all__ = ["SDF_MAGIC", "read_sdf", "write_sdf"]

#: First bytes of an SDF file (ASCII 'a…' or binary 'b…').
SDF_MAGIC = (b"aBCR", b"aISO", b"bBCR", b"bISO")

_DTYPES = {
    0: np.dtype("u1"),
    1: np.dtype("<u2"),
    2: np.dtype("<u4"),
    3: np.dtype("<f4"),
    4: np.dtype("i1"),
    5: np.dtype("<i2"),
    6: np.dtype("<i4"),
    7: np.dtype("<f8"),
}
_BINARY_HEADER = struct.Struct("<8s10s12s12sHHddddBBB")
_REQUIRED = ("NumPoints", "NumProfiles", "Xscale", "Zscale")
_KEY_SPLIT = re.compile(r"(?:^|\s)([A-Za-z]\w*)\s*=\s*")


def _int_field(path: Path, header: dict[str, str], key: str, least: int) -> int:
    """Header ``key`` as an integer ≥ ``least``; NaN, ±inf, fractions and words are refused."""
    text = header[key]
    try:
        number = float(text)
    except ValueError:
        number = math.nan
    if not (math.isfinite(number) and number.is_integer() and number >= least):
        raise file_error(path, key, text, f"an integer >= {least}")
    return int(number)


def _float_field(path: Path, header: dict[str, str], key: str, positive: bool) -> float:
    text = header[key]
    try:
        value = float(text)
    except ValueError:
        raise file_error(path, key, text, "a number") from None
    if not math.isfinite(value) or (positive and value <= 0.0) or value == 0.0:
        raise file_error(path, key, text, "a finite number > 0" if positive else "non-zero")
    return value


def _parse_ascii_header(path: Path, lines: list[str]) -> dict[str, str]:
    """``Key = value`` pairs; a key, its '=' and its value may be split over lines."""
    parts = _KEY_SPLIT.split(" ".join(line.strip() for line in lines))
    if parts[0].strip():
        raise file_error(path, "header", parts[0].strip()[:60], "'Key = value' pairs before '*'")
    return {key: value.strip() for key, value in zip(parts[1::2], parts[2::2], strict=True)}


def _check_header(path: Path, header: dict[str, str]) -> dict[str, Any]:
    missing = [k for k in _REQUIRED if k not in header or header[k] == ""]
    if missing:
        raise file_error(path, missing[0], None, "present in the SDF header (record 1)")
    out: dict[str, Any] = {
        "NumPoints": _int_field(path, header, "NumPoints", 2),
        "NumProfiles": _int_field(path, header, "NumProfiles", 1),
        "Xscale": _float_field(path, header, "Xscale", positive=True),
        "Zscale": _float_field(path, header, "Zscale", positive=False),
    }
    for key in ("Compression", "CheckType"):
        out[key] = _int_field(path, header, key, 0) if header.get(key, "") != "" else 0
    if out["Compression"] != 0:
        raise file_error(path, "Compression", out["Compression"], "0 (uncompressed)")
    dtype = _int_field(path, header, "DataType", 0) if header.get("DataType", "") != "" else 7
    if dtype not in _DTYPES:
        raise file_error(path, "DataType", dtype, "0 … 7")
    out["DataType"] = dtype
    try:
        y_scale = float(header.get("Yscale", "0") or 0.0)
    except ValueError:
        raise file_error(path, "Yscale", header["Yscale"], "a number") from None
    out["Yscale"] = y_scale if math.isfinite(y_scale) and y_scale > 0.0 else None
    return out


def _read_ascii(path: Path, raw: bytes) -> tuple[dict[str, str], np.ndarray]:
    lines = raw.decode("latin-1").splitlines()
    version = lines[0].strip()
    stars = [i for i, line in enumerate(lines) if line.strip() == "*"]
    if not stars:
        raise file_error(path, "header", "no '*' line", "a header record closed by a '*' line")
    header = _parse_ascii_header(path, lines[1 : stars[0]])
    header["version"] = version
    end = stars[1] if len(stars) > 1 else len(lines)
    tokens = " ".join(lines[stars[0] + 1 : end]).replace(",", " ").split()
    try:
        values = np.array(
            [math.nan if t.upper() == "BAD" else float(t) for t in tokens], dtype=np.float64
        )
    except ValueError:
        bad = next(t for t in tokens if t.upper() != "BAD" and not _is_float(t))
        raise file_error(path, "data", bad, "numbers or BAD in the data record") from None
    if len(stars) > 2:
        header["trailer"] = "\n".join(lines[stars[1] + 1 : stars[2]]).strip()
    return header, values


def _is_float(token: str) -> bool:
    try:
        float(token)
    except ValueError:
        return False
    return True


def _read_binary(path: Path, raw: bytes) -> tuple[dict[str, str], np.ndarray]:
    if len(raw) < _BINARY_HEADER.size:
        raise file_error(path, "header", f"{len(raw)} bytes", "an 81-byte binary SDF header")
    fields = _BINARY_HEADER.unpack_from(raw)
    names = (
        "version",
        "ManufacID",
        "CreateDate",
        "ModDate",
        "NumPoints",
        "NumProfiles",
        "Xscale",
        "Yscale",
        "Zscale",
        "Zresolution",
        "Compression",
        "DataType",
        "CheckType",
    )
    header = {
        k: (v.decode("latin-1").rstrip("\x00 ") if isinstance(v, bytes) else repr(v))
        for k, v in zip(names, fields, strict=True)
    }
    checked = _check_header(path, header)
    dtype = _DTYPES[checked["DataType"]]
    count = checked["NumPoints"] * checked["NumProfiles"]
    body = raw[_BINARY_HEADER.size :]
    if len(body) < count * dtype.itemsize:
        raise file_error(
            path,
            "data",
            f"{len(body) // dtype.itemsize} values",
            f"NumPoints × NumProfiles = {count} values of DataType {checked['DataType']}",
        )
    values = np.frombuffer(body, dtype=dtype, count=count).astype(np.float64)
    return header, values


def read_sdf(path: str | Path) -> Profile:
    """Read an SDF file (ASCII, or binary with the BCR header) into a :class:`Profile`.

    One profile (NumProfiles = 1) gives 1-D heights; an areal file gives rows
    (NumProfiles × NumPoints), row i at y = i · Yscale. Heights = value × Zscale (m),
    spacing = Xscale (m); ``BAD`` points are NaN. The header goes to the metadata.

    Raises:
        InputError: naming the file and the field (a missing or invalid header key, a data
            count that is not NumPoints × NumProfiles, compressed data, a non-numeric value).
    """
    path = file_path(path)
    try:
        raw = path.read_bytes()
    except OSError as exc:
        raise file_error(path, "", str(path), f"a readable file ({exc.strerror})") from None
    if not raw.strip():
        raise file_error(path, "", "an empty file", "an SDF file with a header and data")
    if not raw.startswith(SDF_MAGIC):
        head = raw[:8].decode("latin-1", errors="replace")
        raise file_error(path, "version", head, "aBCR-1.0, aISO-1.0, aISO-2.0 or bBCR-1.0")
    if raw.startswith(b"b"):
        header, values = _read_binary(path, raw)
        header["format"] = "sdf-binary"
    else:
        header, values = _read_ascii(path, raw)
        header["format"] = "sdf-ascii"
    checked = _check_header(path, header)
    n_points, n_profiles = checked["NumPoints"], checked["NumProfiles"]
    if values.size != n_points * n_profiles:
        raise file_error(
            path,
            "data",
            f"{values.size} values",
            f"NumPoints × NumProfiles = {n_points} × {n_profiles} = {n_points * n_profiles}",
        )
    with np.errstate(over="ignore"):
        heights = values.reshape(n_profiles, n_points) * checked["Zscale"]
    if np.isinf(heights).any():
        raise file_error(
            path, "data", "an infinite height", "finite values × Zscale (numbers or BAD)"
        )
    allowed = sampling_range(checked["Xscale"], n_points)  # once the data match NumPoints
    if allowed is not None:
        raise file_error(path, "Xscale", checked["Xscale"], allowed)
    if n_profiles == 1:
        heights = heights[0]
    metadata: dict[str, Any] = dict(header)
    metadata.update({k: checked[k] for k in ("NumPoints", "NumProfiles", "DataType")})
    return Profile(heights, checked["Xscale"], checked["Yscale"], metadata, str(path))


def write_sdf(
    path: str | Path,
    profile: Profile,
    *,
    z_scale: float = 1e-9,
    data_type: int = 7,
    manufacturer: str = "ballscrew",
    version: str = "aBCR-1.0",
) -> Path:
    """Write a :class:`Profile` as an ASCII SDF file (one profile or rows).

    Args:
        path: the file to write (``.sdf``).
        profile: heights in m; NaN is written as ``BAD``.
        z_scale: metres per data unit (Zscale); values written are heights / z_scale.
        data_type: 7 (double, ``%.12g``) or an integer type 5 (int16) / 6 (int32), for which
            the values are rounded to integers (quantised to ``z_scale``).
        manufacturer: ManufacID (at most 10 characters kept).
        version: ``aBCR-1.0`` or ``aISO-1.0``.
    """
    path, profile = file_path(path), checked_profile(profile)
    if data_type not in (3, 5, 6, 7):
        raise InputError("data_type", data_type, "3 (float), 5 (int16), 6 (int32) or 7 (double)")
    if version not in ("aBCR-1.0", "aISO-1.0"):
        raise InputError("version", version, "'aBCR-1.0' or 'aISO-1.0'")
    if not (math.isfinite(z_scale) and z_scale > 0.0):
        raise InputError("z_scale", z_scale, "a finite number > 0 (m per data unit)")
    rows = profile.rows / z_scale
    if data_type in (5, 6):
        limit = 32767 if data_type == 5 else 2147483647
        finite = rows[np.isfinite(rows)]
        if finite.size and np.abs(finite).max() > limit:
            raise InputError("z_scale", z_scale, f"large enough that |z|/z_scale ≤ {limit}")
    stamp = datetime.now(UTC).strftime("%d%m%Y%H%M")
    y_scale = profile.y_spacing if profile.y_spacing is not None else 0.0
    header = [
        version,
        f"ManufacID   = {manufacturer[:10]}",
        f"CreateDate  = {stamp}",
        f"ModDate     = {stamp}",
        f"NumPoints   = {profile.n_points}",
        f"NumProfiles = {profile.n_profiles}",
        f"Xscale      = {profile.spacing:.12g}",
        f"Yscale      = {y_scale:.12g}",
        f"Zscale      = {z_scale:.12g}",
        f"Zresolution = {-1 if data_type in (3, 7) else z_scale:.12g}",
        "Compression = 0",
        f"DataType    = {data_type}",
        "CheckType   = 0",
        "*",
    ]

    def fmt(v: float) -> str:
        if not math.isfinite(v):
            return "BAD"
        return f"{round(v)}" if data_type in (5, 6) else f"{v:.12g}"

    body = [" ".join(fmt(v) for v in row) for row in rows]
    path.write_text("\n".join([*header, *body, "*", ""]), encoding="ascii")
    return path
