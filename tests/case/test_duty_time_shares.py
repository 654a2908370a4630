"""A ``[[duty]]`` list whose segments lack their durations is one clear error."""

from __future__ import annotations

import tomllib

import pytest

from ballscrew.case import CaseError, case_from_dict


def test_segments_without_duration_are_one_line(gao_case_path) -> None:
    raw = tomllib.loads(gao_case_path.read_text())
    raw["duty"] = [{"speed": "1000 rpm", "axial_load": "2 kN"}, {"speed": 0}]
    with pytest.raises(CaseError) as info:
        case_from_dict(raw)
    message = str(info.value)
    assert "\n" not in message
    assert "duty = 2 segment(s) without a duration is not allowed" in message
    assert message.endswith("missing in duty.0, duty.1")
