"""A bearing engineer's review of the bearing data and ratings: each find refused or computed as the rule says."""

import pytest
from click.testing import CliRunner

from auxbearing.analysis.coastdown_life import _factors, equivalent_load
from auxbearing.bearings.catalogue import get_bearing, load_bearing
from auxbearing.bearings.geometry import bearing_from_mapping
from auxbearing.bearings.ratings import dynamic_load_rating, static_load_rating
from auxbearing.cli.main import cli
from auxbearing.common.errors import InputError
from auxbearing.common.units import to_si


@pytest.mark.parametrize("name", ["6208-2ZC3", "6208ZZC3", "6208LLUC3", "6208-2RSC3", "6208 MC3", "6208 ZZ C3",
                                  "6208-2Z/C4"])
def test_a_clearance_group_glued_to_a_seal_or_cage_code_is_refused(name):
    """Read before as the normal clearance (13 um for the 6208), while C3 is about twice that."""
    with pytest.raises(InputError, match=r"internal clearance group C[34] is not in the catalogue's geometry"):
        get_bearing(name)


@pytest.mark.parametrize("name", ["6208/HC", "7208 BECBP/HCP4A"])
def test_skf_s_hc_suffix_is_not_read_as_steel_balls(name):
    with pytest.raises(InputError, match="a ball material is not read from a maker's suffix"):
        get_bearing(name)


def test_maker_codes_without_a_clearance_group_still_read():
    for name in ("7208 BECBP", "7208 BECBM", "QJ208 N2MA", "6208-2RS1", "6208/HC5"):
        get_bearing(name)
    assert get_bearing("6208/HC5").ball_material.name == "Si3N4"


@pytest.mark.parametrize("thrust", [50.0, 500.0, 2000.0, 8000.0])
def test_a_hybrid_deep_groove_bearing_reads_iso_281_table_3_as_the_steel_one(thrust):
    """f0 Fa / C0 is Fa over Z D_w^2: the hybrid's lowered C0 made it 41 % higher, its Y and P lower."""
    assert _factors(get_bearing("6208 hybrid"), thrust) == pytest.approx(_factors(get_bearing("6208"), thrust))
    assert equivalent_load(get_bearing("6208 hybrid"), 1000.0, thrust) == pytest.approx(
        equivalent_load(get_bearing("6208"), 1000.0, thrust))


def test_a_hybrid_pair_s_preload_class_is_the_steel_pair_s():
    """The class was a share of the hybrid's lowered C0: 171 N light against the steel pair's 241 N."""
    for preload in ("light", "medium", "heavy"):
        steel, hybrid = get_bearing(f"7208 DB {preload}"), get_bearing(f"7208 hybrid DB {preload}")
        assert hybrid.preload_force == pytest.approx(steel.preload_force, rel=1e-9)


def _odd_bearing(tmp_path):
    path = tmp_path / "odd.toml"
    path.write_text('[bearing]\ntype = "angular_contact"\nball_diameter = "20 mm"\npitch_diameter = "30 mm"\n'
                    'bore = "8 mm"\noutside_diameter = "52 mm"\nwidth = "10 mm"\nball_count = 4\n'
                    'contact_angle = "25 deg"\ninner_groove_ratio = 0.52\nouter_groove_ratio = 0.53\n'
                    'diametral_clearance = "0 um"\nball_material = "GCr15"\nring_material = "GCr15"\n')
    return path


def test_a_ball_set_outside_the_rating_tables_is_bad_input(tmp_path):
    """D_w cos(alpha) / D_pw = 0.604: a ValueError from the kernels' tables, a traceback on the command line."""
    bearing = load_bearing(str(_odd_bearing(tmp_path)))
    for rating in (static_load_rating, dynamic_load_rating):
        with pytest.raises(InputError, match=r"^ball_diameter = '20 mm': .* D_w cos\(alpha\)/D_pw = 0.604 lies "
                                             r"outside the tables of ISO 281"):
            rating(bearing)
    machine = tmp_path / "m.toml"
    row = _odd_bearing(tmp_path).read_text().split("\n", 1)[1].strip().replace("\n", ", ")
    machine.write_text('[machine]\nname = "odd"\norientation = "horizontal"\n[rotor]\nmass = "1.48 kg"\n'
                       'polar_inertia = "3.88e-4 kg*m^2"\nspeed = "6000 rpm"\n[[touchdown]]\n'
                       f'bearing = {{ {row}, arrangement = "DB" }}\nradial_clearance = "0.1 mm"\n')
    result = CliRunner().invoke(cli, ["drop", "--machine", str(machine), "--duration", "1 ms",
                                      "--out", str(tmp_path / "out")])
    assert result.exit_code == 2 and "D_w cos(alpha)/D_pw = 0.604" in result.stderr, result.output
    assert "Traceback" not in result.output and not (tmp_path / "out").exists()


@pytest.mark.parametrize(("text", "field"), [("13 um 2", "diametral_clearance"), ("12 mm 2", "ball_diameter"),
                                             ("±5 um", "diametral_clearance")])
def test_a_number_after_the_unit_or_a_tolerance_is_refused(text, field):
    """pint multiplied the trailing number (26 um) and read ± as +."""
    with pytest.raises(InputError, match="one number with a decimal point and its unit"):
        to_si(field, text, "length")


@pytest.mark.parametrize("name", ["7208 DB 5 um 3", "7208 DB 500 N 2", "7208 DB 2 500 N", "7208 DB ±5 um"])
def test_a_preload_in_the_name_is_one_number_and_its_unit(name):
    """'500 N 2' was a 1000 N preload, '5 um 3' a 15 um offset."""
    with pytest.raises(InputError, match="one number and its unit"):
        get_bearing(name)


@pytest.mark.parametrize("ratio", [52, 0.9, 0.61])
def test_a_groove_ratio_beyond_any_ball_bearing_s_is_refused(ratio):
    """'52' for 0.52 made a flat race and printed its 4457 MPa as a result."""
    table = {"type": "deep_groove", "ball_diameter": "12 mm", "pitch_diameter": "60 mm", "ball_count": 9,
             "inner_groove_ratio": ratio, "outer_groove_ratio": 0.53, "contact_angle": "0 deg",
             "diametral_clearance": "10 um", "ball_material": "GCr15", "ring_material": "GCr15"}
    with pytest.raises(InputError, match=rf"inner_groove_ratio = {ratio}: must be at most 0.6"):
        bearing_from_mapping(table)


def test_the_listing_names_the_7208_s_source_whole():
    """The source's text was cut at its first comma: 'as the maker publishes it: C = 34.5 kN.', C0 lost."""
    result = CliRunner().invoke(cli, ["bearings", "--bore", "40"], terminal_width=200)
    assert result.exit_code == 0
    text = " ".join(result.stdout.split())
    assert "C = 34.5 kN, C0 = 24 kN from SKF 7208 BECBP as the maker publishes it." in text


@pytest.mark.parametrize(("name", "expected"), [("7202", 1690.0), ("7202 DB", 2740.0), ("7208", 1490.0),
                                                ("7208 DB", 2430.0), ("QJ208", 2740.0)])
def test_a_35_deg_bearing_takes_iso_281_table_3_s_35_deg_row(name, expected):
    """Fr 1 kN, Fa 2 kN. The 35 deg 7202 took the 30 deg row (1910 N single, 3110 N as a DB pair): ISO 281 Table 3
    gives e 0.95, X 0.37, Y 0.66 single row and X 0.60, Y 1.07 double row at 35 deg, 0.35 / 0.57 and 0.57 / 0.93
    at 40 deg (hand: 0.37 x 1000 + 0.66 x 2000 = 1690 N)."""
    assert equivalent_load(get_bearing(name), 1000.0, 2000.0) == pytest.approx(expected)


def test_a_preload_that_alone_loads_a_row_past_its_static_rating_is_refused():
    """0.29 mm was a 124 kN preload a row, five times the 7208's C0 of 24.1 kN, accepted (ISO 76: P0 = 0.26 Fa at
    40 deg, so s0 = 24.1 / (0.26 x 123.8) = 0.75)."""
    for name in ("7208 DB 0.29 mm", "7208 DB 100 kN"):
        with pytest.raises(InputError, match=r"past its static rating on its own \(ISO 76: s0 = C0 / \(Y0 Fa\)"):
            get_bearing(name)
    assert get_bearing("7208 DB 20 kN").preload_force == pytest.approx(20e3)  # s0 4.6


@pytest.mark.parametrize(("key", "value", "rule"), [("name", {"a": 1}, "must be text in quotes"),
                                                    ("source", 5, "must be text in quotes"),
                                                    ("estimated", 5, "must list the keys whose values are estimated")])
def test_a_bearing_table_s_text_keys_take_text(key, value, rule):
    table = {"type": "deep_groove", "ball_diameter": "12 mm", "pitch_diameter": "60 mm", "ball_count": 9,
             "inner_groove_ratio": 0.52, "outer_groove_ratio": 0.53, "contact_angle": "0 deg",
             "diametral_clearance": "10 um", "ball_material": "GCr15", "ring_material": "GCr15", key: value}
    with pytest.raises(InputError, match=rf"^bearing.{key} = .*: {rule}"):
        bearing_from_mapping(table)
