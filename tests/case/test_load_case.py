import math

import pytest

from ballscrew import load_case
from ballscrew.case import CaseError, with_overrides
from ballscrew.case.inputs import guessed_defaults


def test_reference_case_reads_in_si(gao_case_path):
    case = load_case(gao_case_path)
    assert case.name == "gao2019_tcr"
    assert case.screw.pitch_diameter == pytest.approx(0.040)
    assert case.screw.lead == pytest.approx(0.010)
    assert case.screw.contact_angle == pytest.approx(math.pi / 4)
    assert case.operating.speed == pytest.approx(1000 * 2 * math.pi / 60)
    assert case.surface.G == pytest.approx(9e-10)
    assert case.surface.ball is None  # smooth ball by default
    assert case.materials.screw.youngs_modulus == pytest.approx(206e9)


def test_wear_case_reads(wear_case_path):
    case = load_case(wear_case_path)
    assert case.screw.screw_conformity == 0.55
    assert case.operating.speed == pytest.approx(10 * math.pi / 3)


def test_contract_override_keys(gao_case_path):
    overrides = {
        "surface.D": 1.5,
        "surface.G": 1.38e-10,
        "operating.preload": 2000.0,
        "operating.axial_load": 3000.0,
        "operating.speed": 50.0,
    }
    case = load_case(gao_case_path, overrides)
    assert case.surface.D == 1.5
    assert case.surface.G == 1.38e-10
    assert case.operating.preload == 2000.0
    assert case.operating.axial_load == 3000.0
    assert case.operating.speed == 50.0


def test_override_accepts_unit_strings_and_returns_new_case(gao_case_path):
    case = load_case(gao_case_path)
    other = with_overrides(case, {"operating.speed": "800 rpm"})
    assert other.operating.speed == pytest.approx(800 * 2 * math.pi / 60)
    assert case.operating.speed == pytest.approx(1000 * 2 * math.pi / 60)


@pytest.mark.parametrize(
    ("key", "value", "expected"),
    [
        ("screw.lead", -0.01, "screw.lead = -0.01 is not allowed: allowed range is (0, 1] m"),
        ("screw.ball_diameter", 0.0, "screw.ball_diameter = 0.0 is not allowed"),
        (
            "screw.screw_conformity",
            0.5,
            "screw.screw_conformity = 0.5 is not allowed: allowed range is (0.5, 1)",
        ),
        ("screw.nut_conformity", 0.45, "screw.nut_conformity = 0.45"),
        (
            "screw.contact_angle",
            "0 deg",
            "screw.contact_angle = '0 deg' is not allowed: allowed range is (0, 1.5708) rad",
        ),
        ("screw.contact_angle", "90 deg", "allowed range is (0, 1.5708) rad"),
        (
            "screw.ball_diameter",
            "40 mm",
            "screw.ball_diameter = 0.04 m is not allowed: it must be "
            "smaller than pitch_diameter = 0.04 m",
        ),
        (
            "materials.nut.poissons_ratio",
            0.5,
            "materials.nut.poissons_ratio = 0.5 is not allowed: allowed range is (0, 0.5)",
        ),
        ("materials.ball.poissons_ratio", 0.0, "allowed range is (0, 0.5)"),
        ("operating.preload", -1500.0, "operating.preload = -1500.0 is not allowed"),
        ("operating.axial_load", -10.0, "operating.axial_load = -10.0 is not allowed"),
        ("surface.D", 2.0, "surface.D = 2.0 is not allowed: allowed range is (1, 2)"),
        ("surface.G", -1e-9, "surface.G = -1e-09 is not allowed: allowed range is (0, 0.001] m"),
        ("screw.lead", "10 kg", "screw.lead: '10 kg' is not a length (expected m)"),
        ("screw.nuts", 3, "screw.nuts = 3 is not allowed: it must be one of 1 or 2"),
        ("numerics.gap_model", "cubic", "numerics.gap_model = 'cubic'"),
        (
            "numerics.cells_across",
            64.5,
            "numerics.cells_across = 64.5: Input should be a valid integer, got a number with a "
            "fractional part; allowed range is [8, 4096]",
        ),
        (
            "numerics.cells",
            100000,
            "numerics.cells = 100000: Input should be a valid tuple (explicit grid [nx, ny] over "
            "the box, instead of cells_across)",
        ),
    ],
)
def test_bad_values_name_field_value_and_range(gao_case_path, key, value, expected):
    with pytest.raises(CaseError) as info:
        load_case(gao_case_path, {key: value})
    assert expected in str(info.value)
    assert len(info.value.problems) == 1


@pytest.mark.parametrize(
    ("key", "value", "expected"),
    [
        ("design.required_life", "1e20 h", "(0, 1e+11] s; in h: (0, 2.77778e+07]"),
        ("operating.speed", "1e9 rpm", "[0, 100000] rad/s (screw speed"),
        ("operating.speed", "1e9 rpm", "; in rpm: [0, 954930]"),
        ("screw.lead", "2 m", "(0, 1] m (lead"),
    ],
)
def test_a_range_is_also_given_in_the_unit_the_value_was_written_in(
    gao_case_path, key, value, expected
):
    """'design.required_life = 1e20 h … allowed range is (0, 1e+11] s' left the user to convert
    seconds to hours; a value written in SI (2 m) gets no second range."""
    with pytest.raises(CaseError) as info:
        load_case(gao_case_path, {key: value})
    assert expected in str(info.value)
    if value.endswith(" m"):
        assert "; in m:" not in str(info.value)


def test_unknown_key_is_an_error_with_suggestion(gao_case_path):
    with pytest.raises(CaseError, match=r"screw.leed: unknown key \(did you mean 'lead'\?\)"):
        load_case(gao_case_path, {"screw.leed": 0.01})


def test_unknown_key_in_file(tmp_path, gao_case_path):
    text = gao_case_path.read_text().replace("[numerics]", "[numerics]\ncell_across = 3")
    path = tmp_path / "typo.toml"
    path.write_text(text)
    with pytest.raises(CaseError, match=r"numerics\.cell_across: unknown key"):
        load_case(path)


def test_missing_key_names_the_field(tmp_path, gao_case_path):
    path = tmp_path / "missing.toml"
    path.write_text(gao_case_path.read_text().replace('lead = "10 mm"', ""))
    with pytest.raises(CaseError, match=r"screw.lead is missing \(lead L .* in m\)"):
        load_case(path)


def test_toml_syntax_error_gives_the_line(tmp_path, gao_case_path):
    path = tmp_path / "broken.toml"
    text = gao_case_path.read_text()
    path.write_text(text.replace('lead = "10 mm"', 'lead = "10 mm'))
    lines = text.splitlines()
    number = next(k for k, line in enumerate(lines, 1) if line.startswith('lead = "10 mm"'))
    with pytest.raises(CaseError, match=rf"TOML syntax error: .*line {number}\b"):
        load_case(path)


def test_missing_file(tmp_path):
    with pytest.raises(CaseError, match="cannot read the case file"):
        load_case(tmp_path / "nope.toml")


def test_load_that_lifts_every_ball_off(gao_case_path):
    with pytest.raises(CaseError, match="lifts every ball off"):
        load_case(gao_case_path, {"screw.nuts": 1, "operating.preload": 0.0})
    with pytest.raises(CaseError, match="a double nut needs a preload > 0 N"):
        load_case(gao_case_path, {"operating.preload": 0.0, "operating.axial_load": 100.0})


def test_single_nut_under_axial_load_alone_is_valid(gao_case_path):
    case = load_case(
        gao_case_path, {"screw.nuts": 1, "operating.preload": 0.0, "operating.axial_load": 500.0}
    )
    assert case.operating.axial_load == 500.0


def test_case_is_immutable(gao_case_path):
    case = load_case(gao_case_path)
    with pytest.raises(ValueError):
        case.screw.lead = 0.02


def test_errors_inside_a_table_array_name_the_entry(wear_case_path):
    bad_level = [{"axial_load": 2000.0, "speed": -1.0, "revolutions": 1e5}]
    with pytest.raises(CaseError, match=r"wear\.programme\.0\.speed = -1\.0 is not allowed"):
        load_case(wear_case_path, {"wear.programme": bad_level})
    typo = [{"axial_load": 2000.0, "speed": 1.0, "revolutions": 1e5, "sped": 1.0}]
    with pytest.raises(CaseError, match=r"wear\.programme\.0\.sped: unknown key"):
        load_case(wear_case_path, {"wear.programme": typo})


def test_a_preload_method_error_names_the_field_once(gao_case_path):
    with pytest.raises(CaseError) as info:
        load_case(gao_case_path, {"screw.nuts": 1, "screw.preload_method": "spacer"})
    message = str(info.value)
    assert "screw.preload_method = 'spacer' is not allowed with screw.nuts = 1" in message
    assert "screw.screw." not in message


def test_the_single_nut_preload_method_default_is_listed_as_a_guess(gao_case_path):
    """A single nut's preload method left out is a guess (oversized balls); a double nut's is
    not (only the spacer fits), nor a method the case gives."""
    single = load_case(gao_case_path, {"screw.nuts": 1})
    assert "GUESS" in guessed_defaults(single)["screw.preload_method"]
    assert "screw.preload_method" not in guessed_defaults(load_case(gao_case_path))
    given = load_case(gao_case_path, {"screw.nuts": 1, "screw.preload_method": "oversized_balls"})
    assert "screw.preload_method" not in guessed_defaults(given)


def test_an_offset_lead_nut_with_an_odd_ball_count_is_refused(gao_case_path):
    offset = {"screw.nuts": 1, "screw.preload_method": "offset_lead"}
    with pytest.raises(CaseError, match=r"balls_per_nut = 49 is not allowed .*an even number"):
        load_case(gao_case_path, offset | {"screw.balls_per_nut": 49})
    assert load_case(gao_case_path, offset | {"screw.balls_per_nut": 48}).screw.balls_per_nut == 48


def test_a_mistyped_lubricant_and_key_name_the_nearest_spelling(gao_case_path):
    """Both hints come from one helper (``case.base.nearest_hint``)."""
    with pytest.raises(CaseError, match=r"'ISO VG 66' .*\(did you mean 'iso_vg_68'\?\); known"):
        load_case(gao_case_path, {"kinematics.lubricant": "ISO VG 66"})
    with pytest.raises(CaseError, match=r"screw\.leed: unknown key \(did you mean 'lead'\?\)"):
        load_case(gao_case_path, {"screw.leed": "10 mm"})


@pytest.mark.parametrize("key", ["kinematics.mounting", "design.mounting"])
def test_mountings_are_those_the_shaft_formulas_know(gao_case_path, key):
    """Both mounting fields take every end fixity of the buckling and whirling formulas and
    nothing else (one list, ``design.MOUNTINGS``)."""
    from ballscrew.design.shaft import END_FIXITY, MOUNTINGS

    case = load_case(gao_case_path)
    for mounting in MOUNTINGS:
        assert mounting in END_FIXITY
        with_overrides(case, {key: mounting})
    with pytest.raises(CaseError, match=rf"{key} = 'fixed' is not allowed: .*'fixed-fixed'"):
        with_overrides(case, {key: "fixed"})
