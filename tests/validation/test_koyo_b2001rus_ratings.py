"""Validation of the ISO 281:2007 basic dynamic load rating against KOYO's catalogue.

Source: KOYO, Standard ball & roller bearings, CAT. NO. B2001RUS (KOYO Deutschland, 2008), single-row
deep groove ball bearings, C [kN]: 6203 9.55, 6205 14.0, 6206 19.5, 6209 32.7.

Internal geometry (makers do not print it; each source named):

* 6205 and 6203: the SKF 6205-2RS JEM and 6203-2RS JEM of the Case Western Reserve University Bearing
  Data Center: 9 balls of 0.3126 in on a 1.537 in pitch circle and 8 balls of 0.2656 in on 1.122 in
  (Smith & Randall, Mech. Syst. Signal Process. 64-65 (2015); the ball counts also follow from CWRU's
  published fault-frequency multiples, BPFI + BPFO = Z).
* 6209: the 209 bearing of Harris & Kotzalas, Rolling Bearing Analysis, 5th ed. (2007): 9 balls of
  12.7 mm on 65 mm (catalogue "209").
* 6206: 9 balls of 9.525 mm on 46.0 mm (eng-tools.dev 6206 example, docs/validation_sources.md H2).

Tolerance: 1 %. The ratings are printed to 3 digits and the ball sets are those of another maker's
bearing of the same standard design (observed <= 0.3 %).
"""

import pytest

from auxbearing import get_bearing
from auxbearing.analysis.life import dynamic_load_rating
from auxbearing.core.fatigue import dynamic_load_rating as iso281_rating

INCH = 25.4e-3
# (name, ball diameter [m], pitch diameter [m], Z, KOYO C [N])
DEEP_GROOVE = [
    ("6203", 0.2656 * INCH, 1.122 * INCH, 8, 9.55e3),
    ("6205", 0.3126 * INCH, 1.537 * INCH, 9, 14.0e3),
    ("6206", 9.525e-3, 46.0e-3, 9, 19.5e3),
    ("6209", 12.7e-3, 65.0e-3, 9, 32.7e3),
]


@pytest.mark.parametrize(("name", "ball", "pitch", "z", "koyo"), DEEP_GROOVE)
def test_deep_groove_against_koyo(name, ball, pitch, z, koyo):
    assert iso281_rating(ball, pitch, z, 0.0) == pytest.approx(koyo, rel=0.01)


def test_catalogue_209_is_harris_geometry_of_the_6209():
    assert dynamic_load_rating(get_bearing("209")) == pytest.approx(32.7e3, rel=0.01)
