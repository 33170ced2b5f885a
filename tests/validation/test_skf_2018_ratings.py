"""Validation of the basic load ratings (ISO 281 C, ISO 76 C0) against SKF's published ratings.

Source: SKF, Rolling bearings, PUB BU/P1 17000/1 EN (2018), product tables, C and C0 [kN] as
catalog/series.toml holds them (6203 9.95/4.75, 6205 14.8/7.8, 6206 20.3/11.2, 6209 35.1/21.6, ...;
7202 BEP 8.32; QJ 202 N2MA 12.7); SKF 7308 BEGAPH data sheet (skf.com, 2022-06-14): 50/32.5; SKF
7208 BECBP as issue 26 quotes it: 34.5/24. SKF states that its Explorer ratings follow ISO 281
"with adjusted factors" (skf.com, Load ratings), so plain ISO 281 stands below them.

What is independent and what is calibrated (auxbearing.bearings.series):

* Published ball sets (CWRU's measured SKF 6203 and 6205, eng-tools.dev's 6206; see
  test_koyo_b2001rus_ratings.py): ISO 76 C0 from them is independent of SKF's tables and meets SKF's
  C0 within 1 %; ISO 281 C times SKF's factor meets SKF's C within 1 % (the factor, 1.047, is the mean
  over these three, so C is partly fitted here). Plain ISO 281 C lies 4 to 6 % below SKF's.
* The rule that fits a ball set to a maker's C and C0 recovers those three published ball sets:
  Z exactly, D_w within 0.3 % (independent: the rule sees only SKF's two ratings).
* Catalogue entries fitted to their published pair (every 60/62/63 size, 7208, 7308): C and C0 within
  2 % by construction (two numbers, two unknowns; only the whole ball count leaves an error, at most
  0.9 %). This checks the calibration, not the model.
* Out of sample: the 7202 B built by the rule for unrated angular sizes (ball of the 6202, spacing of
  7208/7308) against SKF's 7202 BEP C = 8.32 kN: +7 %, tolerance 10 %.
* The source paper's QJ202 and 7202-40 ball sets (inferred, not SKF's) against SKF: 10 % and 6 %.

Tolerances: 2 % where the issue asks for it; as stated above elsewhere.
"""

import math

import pytest

from auxbearing import get_bearing
from auxbearing.analysis.life import dynamic_load_rating
from auxbearing.bearings.ratings import static_load_rating, static_load_rating_si
from auxbearing.bearings.series import SKF_RATING_FACTOR, fit_ball_set, published_ratings, series_entries
from auxbearing.core.fatigue import dynamic_load_rating as iso281_rating

INCH = 25.4e-3
# (name, d, D [m], ball diameter [m], pitch diameter [m], Z, SKF C, SKF C0 [N]): published ball sets
PUBLISHED_BALL_SETS = [
    ("6203", 17e-3, 40e-3, 0.2656 * INCH, 1.122 * INCH, 8, 9.95e3, 4.75e3),
    ("6205", 25e-3, 52e-3, 0.3126 * INCH, 1.537 * INCH, 9, 14.8e3, 7.8e3),
    ("6206", 30e-3, 62e-3, 9.525e-3, 46.0e-3, 9, 20.3e3, 11.2e3),
]
#: At least ten catalogue bearings with SKF's C and C0, over the three families' sizes 15 to 100 mm.
RATED = ["6002", "6004", "6008", "6010", "6020", "6202", "6205", "6208", "6210", "6215", "6220", "6305",
         "6308", "6310", "6315", "6320", "7208", "7308"]


@pytest.mark.parametrize(("name", "d", "big_d", "ball", "pitch", "z", "skf_c", "skf_c0"), PUBLISHED_BALL_SETS)
def test_published_ball_sets_meet_skf(name, d, big_d, ball, pitch, z, skf_c, skf_c0):
    assert static_load_rating_si(ball, pitch, z, 0.0) == pytest.approx(skf_c0, rel=0.01)
    assert SKF_RATING_FACTOR * iso281_rating(ball, pitch, z, 0.0) == pytest.approx(skf_c, rel=0.01)
    assert 1.03 <= skf_c / iso281_rating(ball, pitch, z, 0.0) <= 1.06  # plain ISO 281 below the Explorer rating


@pytest.mark.parametrize(("name", "d", "big_d", "ball", "pitch", "z", "skf_c", "skf_c0"), PUBLISHED_BALL_SETS)
def test_fit_recovers_published_ball_sets(name, d, big_d, ball, pitch, z, skf_c, skf_c0):
    z_fit, ball_fit, _ = fit_ball_set(d, big_d, 0.0, skf_c, skf_c0)
    assert z_fit == z
    assert ball_fit == pytest.approx(ball, rel=0.003)


def test_skf_factor_is_the_mean_over_the_published_ball_sets():
    ratios = [skf / iso281_rating(ball, pitch, z, 0.0) for _, _, _, ball, pitch, z, skf, _ in PUBLISHED_BALL_SETS]
    assert SKF_RATING_FACTOR == pytest.approx(math.prod(ratios) ** (1 / 3), abs=5e-4)


@pytest.mark.parametrize("name", RATED)
def test_catalogue_ratings_within_two_percent_of_skf(name):
    c, c0, _ = published_ratings(name)
    bearing = get_bearing(name)
    assert dynamic_load_rating(bearing) == pytest.approx(c, rel=0.02)
    assert static_load_rating(bearing) == pytest.approx(c0, rel=0.02)


def test_every_series_entry_with_a_published_pair_is_within_two_percent():
    checked = 0
    for name, entry in series_entries().items():
        if "C" in entry.published and "C0" in entry.published:
            assert dynamic_load_rating(entry.bearing) == pytest.approx(entry.published["C"][0], rel=0.02), name
            assert static_load_rating(entry.bearing) == pytest.approx(entry.published["C0"][0], rel=0.02), name
            checked += 1
    assert checked >= 10


def test_rule_built_7202_b_against_skf_7202_bep():
    rule_7202 = series_entries()["7202"].bearing  # ball of the 6202, spacing of the 7208/7308
    assert dynamic_load_rating(rule_7202) == pytest.approx(8.32e3, rel=0.10)


def test_angular_contact_7202_bep():
    assert dynamic_load_rating(get_bearing("7202-40")) == pytest.approx(8.32e3, rel=0.06)


def test_four_point_qj202_is_rated_as_double_row():
    qj = get_bearing("QJ202")
    assert dynamic_load_rating(qj) == pytest.approx(12.7e3, rel=0.10)
    single_row = iso281_rating(qj.ball_diameter, qj.pitch_diameter, qj.ball_count, qj.contact_angle, rows=1)
    assert single_row / 12.7e3 < 0.7
