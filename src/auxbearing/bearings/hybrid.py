"""Hybrid bearings: silicon-nitride balls in steel rings, any bearing type.

A hybrid is the steel bearing with its ball material swapped (catalogue material ``Si3N4``), so
everything that reads the ball material follows on its own: the Hertz constants and stresses
(the contact compliance, source paper Eq. 3), the ball mass (density) and the thermal network
(specific heat, conductivity, expansion). The ratings follow :mod:`auxbearing.bearings.ratings`:
C as the steel bearing's (DIN ISO 281 Bbl. 5 / ISO 20056-1), C0 at 4200 MPa with the ceramic
contact (lower; ISO 20056-2's slightly higher permissible stress was not retrievable).
"""

from __future__ import annotations

from auxbearing.bearings.geometry import BearingGeometry
from auxbearing.bearings.materials import Material, get_material

#: The ceramic of hybrid bearings (catalogue entry with its source in catalog/materials.toml).
HYBRID_BALL_MATERIAL = "Si3N4"


def hybrid(bearing: BearingGeometry, ball_material: str | Material = HYBRID_BALL_MATERIAL) -> BearingGeometry:
    """The bearing with ceramic balls, named '<name> hybrid'.

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> h = hybrid(get_bearing("QJ208"))
    >>> h.name, h.ball_material.name, round(h.ball_mass / get_bearing("QJ208").ball_mass, 3)
    ('QJ208 hybrid', 'Si3N4', 0.41)
    """
    material = get_material(ball_material) if isinstance(ball_material, str) else ball_material
    if bearing.ball_material == material:
        return bearing
    name = bearing.name if bearing.name.endswith(" hybrid") else f"{bearing.name} hybrid"
    source = (f"{bearing.source} Hybrid: balls of {material.name} ({material.source.split('.')[0]}).")
    return bearing.with_changes(ball_material=material, name=name, source=source)
