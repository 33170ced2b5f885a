"""Validation of the ISO 281:2007 basic dynamic load rating against makers' catalogue values.

Catalogue ratings C (kN):

* KOYO, Standard ball & roller bearings, CAT. NO. B2001RUS (KOYO Deutschland, 2008), single-row
  deep groove ball bearings: 6203 9.55, 6205 14.0, 6206 19.5, 6209 32.7 (printed to 3 digits).
* SKF, Rolling bearings, PUB BU/P1 17000/1 EN (2018): 6203 9.95, 6205 14.8, 6206 20.3, 6209 35.1;
  7202 BEP (40 deg) 8.32; QJ 202 N2MA (four-point, 35 deg) 12.7. SKF states that its Explorer
  bearings' ratings follow ISO 281 "with adjusted factors" (skf.com, Load ratings), so they stand
  above the plain standard.

Internal geometry (makers do not print it; each source named):

* 6205 and 6203: the SKF 6205-2RS JEM and 6203-2RS JEM of the Case Western Reserve University
  Bearing Data Center: ball 0.3126 in on a 1.537 in pitch circle, and 0.2656 in on 1.122 in; 9 and
  8 balls (Smith & Randall, Mech. Syst. Signal Process. 64-65 (2015); the ball counts also follow
  from CWRU's published fault-frequency multiples, BPFI + BPFO = Z).
* 6209: the 209 bearing of Harris & Kotzalas (2007): 9 balls of 12.7 mm on 65 mm (catalogue "209").
* 6206: 9 balls of 9.525 mm on 46.0 mm (eng-tools.dev 6206 example, docs/validation_sources.md H2).
* 7202 and QJ 202: the source paper's Table I geometry (11 balls of 6 mm on 25.5 mm; catalogue
  "7202-40" at 40 deg, "QJ202" at 35 deg). Inferred, not the makers' own.

Tolerances: 1 % against KOYO (3-digit print, and the ball sets are those of another maker's
bearing of the same standard design; observed <= 0.3 %); SKF's Explorer ratings 3 to 8 % above
ours (observed 4.0 to 6.9 %); 6 % for the 7202 and 10 % for the QJ 202, whose ball sets are
inferred. The QJ 202 case also checks how a four-point bearing is rated: as a double-row 35 deg
bearing (i = 2, MESYS manual "Four-point bearing considered as radial bearing": "as usually done
in bearing catalogues"); the single-row rating (i = 1) misses SKF's value by a third.
"""

import math

import pytest

from auxbearing import get_bearing
from auxbearing.core.fatigue import dynamic_load_rating as iso281_rating
from auxbearing.life import dynamic_load_rating

INCH = 25.4e-3
# (name, ball diameter [m], pitch diameter [m], Z, KOYO C [N], SKF C [N])
DEEP_GROOVE = [
    ("6203", 0.2656 * INCH, 1.122 * INCH, 8, 9.55e3, 9.95e3),
    ("6205", 0.3126 * INCH, 1.537 * INCH, 9, 14.0e3, 14.8e3),
    ("6206", 9.525e-3, 46.0e-3, 9, 19.5e3, 20.3e3),
    ("6209", 12.7e-3, 65.0e-3, 9, 32.7e3, 35.1e3),
]


@pytest.mark.parametrize(("name", "ball", "pitch", "z", "koyo", "skf"), DEEP_GROOVE)
def test_deep_groove_against_koyo(name, ball, pitch, z, koyo, skf):
    assert iso281_rating(ball, pitch, z, 0.0) == pytest.approx(koyo, rel=0.01)


@pytest.mark.parametrize(("name", "ball", "pitch", "z", "koyo", "skf"), DEEP_GROOVE)
def test_deep_groove_below_skf_explorer(name, ball, pitch, z, koyo, skf):
    assert 1.03 <= skf / iso281_rating(ball, pitch, z, 0.0) <= 1.08


def test_catalogue_209_is_harris_geometry_of_the_6209():
    assert dynamic_load_rating(get_bearing("209")) == pytest.approx(32.7e3, rel=0.01)


def test_angular_contact_7202_bep():
    assert dynamic_load_rating(get_bearing("7202-40")) == pytest.approx(8.32e3, rel=0.06)


def test_four_point_qj202_is_rated_as_double_row():
    qj = get_bearing("QJ202")
    assert dynamic_load_rating(qj) == pytest.approx(12.7e3, rel=0.10)
    single_row = iso281_rating(qj.ball_diameter, qj.pitch_diameter, qj.ball_count, qj.contact_angle, rows=1)
    assert single_row / 12.7e3 < 0.7
    assert dynamic_load_rating(qj) / single_row == pytest.approx(2.0**0.7, rel=1e-12)
    assert qj.contact_angle == pytest.approx(math.radians(35.0))
