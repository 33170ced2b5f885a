"""The touchdown-plane network builder on the catalogue QJ202, its options and its errors."""

import math

import numpy as np
import pytest

from auxbearing import get_bearing
from auxbearing.analysis.thermal import (
    BALLS,
    HOUSING,
    INNER_RACE,
    JOURNAL,
    NODE_NAMES,
    OUTER_RACE,
    build_network,
    natural_convection_coefficient,
    rotating_cylinder_coefficient,
)
from auxbearing.bearings.materials import Material, get_material
from auxbearing.common.errors import InputError
from auxbearing.core import bearing_friction as bf

QJ202 = get_bearing("QJ202")  # 15 x 35 x 11 mm, 11 balls of 6 mm, 42CrMo rings, GCr15 balls


def net(**kw):
    kw.setdefault("contact_load", 100.0)
    return build_network(QJ202, 7.4e-3, **kw)


def test_qj202_masses_and_capacities():
    """Masses stated by hand from the envelope (densities 7810 GCr15, 7850 42CrMo, 7854 steel).

    balls 11 x rho pi D^3/6 = 9.72 g; inner ring pi (9.75^2 - 7.5^2) 11 mm^3 = 10.53 g; outer ring
    pi (17.5^2 - 15.75^2) 11 mm^3 = 15.78 g; journal pi 7.4^2 11 mm^3 = 14.86 g; default housing
    pi (27.5^2 - 17.5^2) 11 mm^3 = 122.1 g. Rings and balls together, 36 g, sit below a real 202-size
    bearing's mass because the lands are left out (module docstring).
    """
    n = net()
    assert n.node_names == NODE_NAMES
    grams = n.masses * 1e3
    assert grams[BALLS] == pytest.approx(11 * 7810 * math.pi * 6e-3**3 / 6 * 1e3, rel=1e-12)
    assert grams[INNER_RACE] == pytest.approx(7850 * math.pi * (9.75**2 - 7.5**2) * 11 * 1e-9 * 1e3, rel=1e-12)
    assert grams[OUTER_RACE] == pytest.approx(7850 * math.pi * (17.5**2 - 15.75**2) * 11 * 1e-9 * 1e3, rel=1e-12)
    assert grams[JOURNAL] == pytest.approx(7854 * math.pi * 7.4**2 * 11 * 1e-9 * 1e3, rel=1e-12)
    assert grams[HOUSING] == pytest.approx(122.1, abs=0.1)
    assert 30.0 < grams[INNER_RACE] + grams[BALLS] + grams[OUTER_RACE] < 45.0
    assert np.all(n.capacities > 0.0)
    assert n.capacities[BALLS] == pytest.approx(n.masses[BALLS] * 475.0)


def test_conductances_are_positive_where_a_path_exists():
    n = net(rotor_speed=1000.0)
    for a, b in ((BALLS, INNER_RACE), (BALLS, OUTER_RACE), (OUTER_RACE, HOUSING)):
        assert n.conductances[a, b] > 0.0
    assert n.conductances[JOURNAL, INNER_RACE] == 0.0
    assert n.ambient_conductances[JOURNAL] > 0.0 and n.ambient_conductances[HOUSING] > 0.0
    assert set(n.paths) == {"balls-inner_race", "balls-outer_race", "outer_race-housing", "journal-inner_race",
                            "housing-ambient", "journal-ambient"}


def test_unloaded_bearing_has_no_ball_path_and_loads_can_be_updated():
    idle = build_network(QJ202, 7.4e-3)
    assert idle.conductances[BALLS, INNER_RACE] == 0.0
    loaded = idle.with_contact_loads([200.0, 150.0], [200.0, 150.0])
    assert loaded.conductances[BALLS, INNER_RACE] > 0.0
    assert loaded.conductances[INNER_RACE, BALLS] == loaded.conductances[BALLS, INNER_RACE]
    assert idle.conductances[BALLS, INNER_RACE] == 0.0  # the original is untouched


def test_fewer_loaded_balls_conduct_less():
    assert net(loaded_balls=3).conductances[BALLS, OUTER_RACE] < net().conductances[BALLS, OUTER_RACE]


def test_overrides():
    n = net(housing_mass=0.5, inner_race_mass=0.012, outer_race_mass=0.018, housing_to_ambient=0.7,
            journal_to_ambient=0.3, convection_coefficient=0.0)
    assert n.masses[HOUSING] == 0.5 and n.masses[INNER_RACE] == 0.012 and n.masses[OUTER_RACE] == 0.018
    assert n.ambient_conductances[HOUSING] == 0.7
    assert n.ambient_conductances[JOURNAL] == pytest.approx(0.3)
    assert net(journal_race_conductance=0.2).conductances[JOURNAL, INNER_RACE] == 0.2


def test_faster_rotor_convects_more():
    assert net(rotor_speed=3000.0).ambient_conductances[JOURNAL] > net(rotor_speed=300.0).ambient_conductances[JOURNAL]
    assert rotating_cylinder_coefficient(0.015, 0.0) == 0.0
    assert natural_convection_coefficient(0.05, 40.0) > natural_convection_coefficient(0.05, 5.0)


def test_heat_inputs_conserve_power_and_follow_the_partition():
    n = net()
    q = n.heat_inputs(40.0, 6.0)
    assert q.sum() == pytest.approx(46.0)
    assert q[JOURNAL] == pytest.approx(40.0 * n.journal_heat_share)
    assert 0.5 < n.journal_heat_share < 0.56  # plain steel journal is a little more effusive than 42CrMo
    assert n.heat_inputs(40.0, 0.0, journal_share=1.0)[INNER_RACE] == 0.0


def test_steady_state_and_step():
    n = net(rotor_speed=1000.0, housing_to_ambient=1.0, journal_to_ambient=0.5)
    q = n.heat_inputs(10.0, 1.0)
    steady = n.steady_state(q)
    assert np.all(steady > n.ambient_temperature)
    assert n.step(steady, q, 10.0) == pytest.approx(steady, rel=1e-12)
    radial, diametral = n.clearance_changes(steady)
    assert math.isfinite(radial) and math.isfinite(diametral)


def test_kernel_tuples():
    n = net()
    c, g, ga, ta = n.kernel_args()
    assert c.shape == (5,) and g.shape == (5, 5) and ga.shape == (5,) and ta == pytest.approx(293.15)
    growth = n.growth_args()
    assert growth.shape == (9,)
    assert growth[5] == pytest.approx(7.5e-3) and growth[8] == pytest.approx(6e-3)


def test_errors():
    with pytest.raises(InputError, match="journal_radius"):
        build_network(QJ202, 8e-3)
    with pytest.raises(InputError, match="width is not given"):
        build_network(QJ202.with_changes(width=None), 7.4e-3)
    bare = Material(207e9, 0.3, "bare")
    with pytest.raises(InputError, match="density is not given"):
        build_network(QJ202.with_changes(ring_material=bare), 7.4e-3)
    with pytest.raises(InputError, match="emissivity"):
        net(emissivity=1.5)
    with pytest.raises(InputError, match="no conductive path"):
        build_network(QJ202, 7.4e-3, vacuum=True).steady_state(np.ones(5))


def test_materials_carry_thermal_data():
    for name in ("GCr15", "42CrMo", "M50", "Si3N4", "steel"):
        m = get_material(name)
        assert m.has_thermal_data
        assert 1e-6 < m.thermal_expansion < 2e-5 and 2000 < m.density < 9000
    assert get_material("Si3N4").thermal_expansion < 0.4 * get_material("GCr15").thermal_expansion


def test_friction_coefficients_cover_the_bearing_types():
    from auxbearing.bearings.geometry import BEARING_TYPES
    assert set(bf.SKF_FRICTION_COEFFICIENT) == set(BEARING_TYPES)
    assert bf.sliding_friction_power(0.3, 100.0, -20.0) == pytest.approx(600.0)
