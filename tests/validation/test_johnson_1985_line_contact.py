"""Validation of the journal-in-bore contact at light load against Hertz's line contact.

Source: Johnson, K. L., *Contact Mechanics*, Cambridge University Press (1985), Sec. 4.3: two cylinders with
parallel axes, half-width a = sqrt(4 P R / (pi E*)) (Eq. 4.43) and peak pressure p0 = 2 P / (pi a) (Eq. 4.45),
with 1/R = 1/R1 + 1/R2; a journal of radius R1 in a bore of radius R2 = R1 + dR is the conformal case,
R = R1 R2 / dR. The contact half-angle is a / R1.

Tolerance: Hertz's half-space solution is the small-angle limit of the conformal one; their difference
grows as eps^2 (13 eps^2 / 24 in the load at a given angle), so at 2 degrees 0.1 %,.
"""

import math

import pytest

from auxbearing.core.hertz import journal_contact

STEEL = 2.0 * (1.0 - 0.3**2) / 207e9  # (1 - nu^2)/E of journal and race, both steel


def _hertz(force: float, length: float, clearance: float, radius: float) -> tuple[float, float]:
    load = force / length
    relative = radius * (radius + clearance) / clearance
    a = math.sqrt(4.0 * load * relative * STEEL / math.pi)
    return a / radius, 2.0 * load / (math.pi * a)


@pytest.mark.parametrize("force", [1.0, 10.0, 50.0])
def test_light_load_is_hertz_line_contact(force):
    length, clearance, radius = 18e-3, 0.15e-3, 20e-3
    eps, p_max = journal_contact(force, length, STEEL, clearance, radius)
    eps_h, p0_h = _hertz(force, length, clearance, radius)
    assert math.degrees(eps) < 2.0
    # the bore radius R2 = R1 + dR enters Hertz's R but not the conformal form (dR << R): a further s/R = 0.75 %
    assert eps == pytest.approx(eps_h, rel=1e-3 + clearance / radius)
    assert p_max == pytest.approx(p0_h, rel=1e-3 + clearance / radius)

