"""Bearing model, catalogue and TOML input: every impossible value gets a one-line error."""

import math
from pathlib import Path

import pytest

from auxbearing import InputError, get_bearing, load_bearing
from auxbearing.bearings.geometry import bearing_from_mapping, bearing_names
from auxbearing.bearings.materials import get_material, material_names

EXAMPLE = Path(__file__).parents[2] / "examples" / "my_bearing.toml"

BASE = {
    "name": "t", "type": "four_point", "ball_diameter": "6 mm", "pitch_diameter": "25.5 mm",
    "ball_count": 11, "inner_groove_ratio": 0.52, "outer_groove_ratio": 0.52, "contact_angle": "35 deg",
    "diametral_clearance": "0 mm",
    "ball_material": {"elastic_modulus": "207 GPa", "poisson_ratio": 0.3},
    "ring_material": {"elastic_modulus": "207 GPa", "poisson_ratio": 0.3},
}


def with_(**changes):
    table = {**BASE, **changes}
    return {k: v for k, v in table.items() if v is not None}


def test_example_file_reads_as_table_i_bearing():
    b = load_bearing(EXAMPLE)
    ref = get_bearing("QJ202")
    assert b.ball_diameter == pytest.approx(6e-3)
    assert b.contact_angle == pytest.approx(ref.contact_angle)
    assert b.gamma == pytest.approx(6 * math.cos(math.radians(35)) / 25.5)
    assert b.curvature_centre_distance == pytest.approx(0.04 * 6e-3)


def test_catalogue_has_the_papers_bearings_with_sources():
    assert {"QJ202", "7202", "7202-40"} <= set(bearing_names())
    for name in bearing_names():
        b = get_bearing(name)
        assert b.source
    assert get_bearing("7202-40").contact_angle == pytest.approx(math.radians(40))
    assert get_bearing("QJ202").pairs_per_ball == 2
    assert get_bearing("7202").pairs_per_ball == 1


def test_materials_catalogue():
    assert {"GCr15", "42CrMo", "M50", "Si3N4"} <= set(material_names())
    assert get_material("AISI 52100").name == "GCr15"
    assert get_material("silicon nitride").elastic_modulus > 300e9


@pytest.mark.parametrize(
    ("changes", "fragment"),
    [
        ({"inner_groove_ratio": 0.5}, "bearing.inner_groove_ratio = 0.5: must be > 0.5"),
        ({"outer_groove_ratio": 0.45}, "bearing.outer_groove_ratio = 0.45: must be > 0.5"),
        ({"ball_count": 14}, "bearing.ball_count = 14: balls overlap on the pitch circle"),
        ({"ball_count": 2}, "bearing.ball_count = 2: must be a whole number >= 3"),
        ({"ball_count": 11.5}, "bearing.ball_count = 11.5: must be a whole number >= 3"),
        ({"contact_angle": "90 deg"}, "bearing.contact_angle = '90 deg': must lie in [0, 90) deg"),
        ({"contact_angle": "-5 deg"}, "bearing.contact_angle = '-5 deg': must lie in [0, 90) deg"),
        ({"ball_diameter": "0 mm"}, "bearing.ball_diameter = '0 mm': must be a positive finite number"),
        ({"ball_diameter": "-6 mm"}, "bearing.ball_diameter = '-6 mm': must be a positive finite number"),
        ({"ball_diameter": "nan mm"}, "bearing.ball_diameter = 'nan mm': must be a finite number"),
        ({"ball_diameter": "6 kg"}, "bearing.ball_diameter = '6 kg': unit kilogram is not a length"),
        ({"ball_diameter": 6}, "bearing.ball_diameter = 6: needs a unit, e.g. '6 mm'"),
        ({"ball_diameter": "six mm"}, "bearing.ball_diameter = 'six mm': cannot read it"),
        ({"ball_diameter": None}, "bearing.ball_diameter: missing"),
        ({"colour": "red"}, "bearing.colour = 'red': unknown key; allowed keys: type, ball_diameter"),
        ({"type": "tapered"}, "bearing.type = 'tapered': must be one of four_point, angular_contact, deep_groove"),
        ({"ball_material": "brass"}, "bearing.ball_material = 'brass': unknown; catalogue names are GCr15"),
        ({"ring_material": {"elastic_modulus": "-1 GPa", "poisson_ratio": 0.3}},
         "bearing.ring_material.elastic_modulus = '-1 GPa': must be a positive finite number"),
        ({"ring_material": {"elastic_modulus": "207 GPa", "poisson_ratio": 0.5}},
         "bearing.ring_material.poisson_ratio = 0.5: must lie in (-1, 0.5)"),
        ({"ring_material": {"elastic_modulus": "207 GPa"}}, "bearing.ring_material.poisson_ratio: missing"),
        ({"diametral_clearance": "-1 um"}, "bearing.diametral_clearance = '-1 um': must be >= 0 m"),
        ({"pitch_diameter": "5 mm"}, "bearing.pitch_diameter = '5 mm': must exceed ball_diameter"),
    ],
)
def test_impossible_values_get_one_line_errors(changes, fragment):
    with pytest.raises(InputError) as info:
        bearing_from_mapping(with_(**changes))
    message = str(info.value)
    assert fragment in message
    assert "\n" not in message


def test_unknown_catalogue_name():
    with pytest.raises(InputError, match="bearing = 'QJ999': unknown; catalogue names are QJ202"):
        load_bearing("QJ999")


def test_missing_file_and_bad_toml(tmp_path):
    with pytest.raises(InputError, match="not found"):
        load_bearing(tmp_path / "nope.toml")
    bad = tmp_path / "bad.toml"
    bad.write_text("[bearing\n")
    with pytest.raises(InputError, match="is not valid TOML"):
        load_bearing(bad)
    empty = tmp_path / "empty.toml"
    empty.write_text("[rotor]\n")
    with pytest.raises(InputError, match=r"has no \[bearing\] table"):
        load_bearing(empty)


def test_deep_groove_free_contact_angle_from_clearance():
    b = get_bearing("209")
    a = b.curvature_centre_distance
    assert b.free_contact_angle == pytest.approx(math.acos(1 - b.diametral_clearance / (2 * a)))
    with pytest.raises(InputError, match="deep_groove bearing has contact_angle 0 deg"):
        b.with_changes(contact_angle=0.3)


# -- names as makers write them, hybrids, duplex sets, the catalogue listing (issue 26) ---------------
@pytest.mark.parametrize(("name", "expected", "kind", "z"), [
    ("6205", "6205", "deep_groove", 9), ("6305", "6305", "deep_groove", 7), ("6305-2RS1", "6305", "deep_groove", 7),
    ("7208", "7208", "angular_contact", 15), ("7208 BECBP", "7208", "angular_contact", 15),
    ("QJ208", "QJ208", "four_point", 11), ("QJ 208 N2MA", "QJ208", "four_point", 11),
    ("qj 308", "QJ308", "four_point", 9), ("7202 BEP", "7202-40", "angular_contact", 11),
])
def test_maker_names(name, expected, kind, z):
    b = get_bearing(name)
    assert (b.name, b.type, b.ball_count) == (expected, kind, z)


def test_7208_is_the_40_deg_b_design_and_sizes_cover_15_to_100():
    assert get_bearing("7208").contact_angle == pytest.approx(math.radians(40))
    for name in ("6002", "6020", "6202", "6220", "6302", "6320", "7203", "7320", "QJ203", "QJ320"):
        assert 15e-3 <= get_bearing(name).bore <= 100e-3


@pytest.mark.parametrize(("name", "fragment"), [
    ("7208 AC", "only the 40 deg B design"), ("6221", "bore code outside"), ("6205 DB", "needs an angular-contact row"),
    ("DB", "names no bearing"), ("7208 DT heavy", "cannot be preloaded"),
    # a suffix that would change the physics is refused, not ignored as maker codes are
    ("QJ208hybrid", "write the word 'hybrid' apart.*'QJ208 hybrid'"), ("QJ208 ceramic", "ball material"),
    ("QJ208 Si3N4", "ball material"), ("6208 hybird", "ball material"), ("6208 C3", "clearance group C3"),
    ("6305-2RS1 C4", "clearance group C4"), ("6208/C2", "clearance group C2"),
])
def test_bad_names(name, fragment):
    with pytest.raises(InputError, match=fragment):
        get_bearing(name)


def test_hybrid_and_duplex_names():
    h = get_bearing("QJ208 hybrid")
    assert h.ball_material.name == "Si3N4" and h.ring_material.name == "GCr15" and h.name == "QJ208 hybrid"
    pair = get_bearing("7208 DB medium")
    assert (pair.arrangement, pair.preload, pair.row.name) == ("DB", "medium", "7208")
    assert get_bearing("7208 BECBP/DF").arrangement == "DF"
    assert get_bearing("7208 DT").preload_offset == 0.0
    hybrid_pair = get_bearing("7208 hybrid DB")
    assert hybrid_pair.row.ball_material.name == "Si3N4"


def test_single_bearing_analyses_refuse_a_pair_by_name():
    with pytest.raises(InputError, match="is a matched set"):
        load_bearing("7208 DB")
    assert load_bearing("7208 DB", sets=True).arrangement == "DB"


def test_rating_factor_round_trip_and_validation():
    b = get_bearing("6205")
    assert b.rating_factor > 1.0
    assert bearing_from_mapping(b.to_table(), name=b.name) == b
    with pytest.raises(InputError, match="rating_factor"):
        bearing_from_mapping(with_(rating_factor=-1.0))


def test_duplex_set_from_force_offset_and_spacer():
    from auxbearing.bearings.duplex import duplex_set

    row = get_bearing("7208")
    assert duplex_set(row, "DB", preload="800 N").preload_force == pytest.approx(800.0, rel=1e-9)
    assert duplex_set(row, "DB", preload=800).preload_force == pytest.approx(800.0, rel=1e-9)
    pair = duplex_set(row, "DF", preload="6 um", spacer="4 mm")
    assert pair.preload_offset == pytest.approx(6e-6) and pair.row_spacing == pytest.approx(22e-3)
    with pytest.raises(InputError, match="preload"):
        duplex_set(row, "DB", preload="3 kg")
    with pytest.raises(InputError, match="arrangement"):
        duplex_set(row, "XX")


def test_bearings_command_filters(tmp_path):
    import json

    from click.testing import CliRunner

    from auxbearing.cli.main import cli

    result = CliRunner().invoke(cli, ["bearings", "--type", "angular", "--bore", "40", "--json"])
    assert result.exit_code == 0, result.output
    rows = json.loads(result.output)["bearings"]
    assert [r["name"] for r in rows] == ["7208", "7308"]
    seven = rows[0]
    assert seven["C_published_N"] == 34.5e3 and "ball_count" in seven["estimated"] and seven["published"]
    result = CliRunner().invoke(cli, ["bearings", "--type", "deep_groove", "--bore", "30-60", "--json"])
    names = {r["name"] for r in json.loads(result.output)["bearings"]}
    assert {"6006", "6206", "6306", "6012", "6212", "6312", "209"} <= names and "6005" not in names
    bad = CliRunner().invoke(cli, ["bearings", "--type", "tapered"])
    assert bad.exit_code == 2 and "--type = 'tapered'" in bad.output


@pytest.mark.parametrize("bore", ["-5", "0", "30-", "1-2-3", "abc", "-30-60"])
def test_a_bore_filter_that_is_not_a_bore_or_a_range_is_refused(bore):
    # issue: '-5' and '0' listed nothing with exit 0, and '30-' was read as 30 mm
    from click.testing import CliRunner

    from auxbearing.cli.main import cli

    bad = CliRunner().invoke(cli, ["bearings", "--bore", bore])
    assert bad.exit_code == 2
    assert f"--bore = '{bore}': must be a bore or a range, each above 0" in bad.output


def test_a_pair_takes_its_preload_as_a_force_or_an_offset_in_its_name():
    # issue: '7208 DB 8 um' was read as a bearing '7208 8 um' and refused for not being the 40 deg B design
    assert get_bearing("7208 DB 8 um").preload_offset == pytest.approx(8e-6)
    assert get_bearing("7208 DB 500 N").preload_force == pytest.approx(500.0)
    with pytest.raises(InputError, match=r"^bearing = '7208 DB ultra': its preload 'ultra': cannot read it"):
        get_bearing("7208 DB ultra")
