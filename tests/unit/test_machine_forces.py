"""Forces of the machine right-hand side by free-body sketch (source paper Eq. 17-26 as NOTES.md corrects them).

The paper rig is the one-plane machine; its state is indexed through the names of auxbearing.core.machine.
"""

import math

import numpy as np
import pytest

from auxbearing import get_bearing
from auxbearing.core import machine as cm
from auxbearing.core.probes import plane_diagnostics
from auxbearing.machine.pack import pack
from auxbearing.planar.params import DropCase, Rotor
from auxbearing.planar.rig import planar_machine

QJ202 = get_bearing("QJ202")
P0 = cm.N_ROTOR  # first state of plane 0


def _kernel(rotor=None, **case):
    return pack(planar_machine(QJ202, rotor or Rotor(eccentricity=0.0), DropCase(**case)))


def _state(km, **values):
    y = km.y0.copy()
    names = {"x": cm.X, "y": cm.Y, "vx": cm.VX, "vy": cm.VY, "spin": cm.OMEGA, "race_x": P0 + cm.RX,
             "race_y": P0 + cm.RY, "race_speed": P0 + cm.ROMEGA}
    for key, value in values.items():
        y[names[key]] = value
    return y


def _rhs(km, y):
    out = np.zeros(y.size)
    cm.rhs(0.0, y, km.machine, out)
    return out


@pytest.mark.parametrize("angle_deg", [-150.0, -90.0, -30.0, 0.0, 45.0, 100.0, 179.0, 225.0])
def test_contact_pushes_rotor_back_toward_race_centre_in_every_quadrant(angle_deg):
    """NOTES item 2: the normal force on the journal points from the contact to the race centre."""
    km = _kernel(gravity=0.0, sliding_friction=0.0, rolling_friction=0.0, line_damping=0.0, ball_damping=0.0)
    a = math.radians(angle_deg)
    dist = 2e-4 + 2e-6
    y = _state(km, x=dist * math.cos(a), y=dist * math.sin(a), spin=0.0)
    out = _rhs(km, y)
    acc = out[[cm.VX, cm.VY]]
    np.testing.assert_allclose(acc / np.linalg.norm(acc), [-math.cos(a), -math.sin(a)], atol=1e-12)
    race = out[[P0 + cm.RVX, P0 + cm.RVY]]
    np.testing.assert_allclose(race / np.linalg.norm(race), [math.cos(a), math.sin(a)], atol=1e-12)
    diag = plane_diagnostics(y, km.machine, 0)
    assert diag[cm.D_PEN] == pytest.approx(2e-6)
    assert diag[cm.D_FN] == pytest.approx(km.machine.planes.line_stiffness[0] * 2e-6 ** (10 / 9))


def test_normal_force_never_pulls():
    """Eq. 19 clipped: a separating journal with large damping feels no (negative) force."""
    km = _kernel()
    diag = plane_diagnostics(_state(km, y=-(2e-4 + 1e-8), vy=1.0), km.machine, 0)
    assert diag[cm.D_PEN] > 0 and diag[cm.D_FN] == 0.0


def test_friction_slows_rotor_spins_race_up_and_acts_against_slip():
    """NOTES item 3, at the bottom: rotor CCW, race at rest -> the rotor slows, the race spins up, and the
    friction on the journal points along -x (against its surface motion there)."""
    km = _kernel(gravity=0.0, line_damping=0.0, rolling_friction=0.0)
    y = _state(km, y=-(2e-4 + 2e-6), spin=628.0)
    out = _rhs(km, y)
    assert out[cm.OMEGA] < 0.0 and out[P0 + cm.ROMEGA] > 0.0 and out[cm.VX] < 0.0
    diag = plane_diagnostics(y, km.machine, 0)
    assert diag[cm.D_SLIP] == pytest.approx(628.0 * 7.3e-3)
    assert diag[cm.D_FT] == pytest.approx(-0.2 * diag[cm.D_FN], rel=1e-9)  # full Coulomb far from zero slip


def test_friction_vanishes_at_zero_slip():
    km = _kernel(gravity=0.0)
    r, s = 7.3e-3, 2e-4
    diag = plane_diagnostics(_state(km, y=-(s + 2e-6), spin=628.0, race_speed=628.0 * r / (r + s)), km.machine, 0)
    assert diag[cm.D_FN] > 0 and abs(diag[cm.D_SLIP]) < 1e-12 and abs(diag[cm.D_FT]) < 1e-9


def test_rolling_resistance_brakes_the_race_and_stops_at_rest():
    km = _kernel(ball_damping=0.0)
    assert _rhs(km, _state(km, race_y=-2e-6, race_speed=300.0, spin=0.0))[P0 + cm.ROMEGA] < 0.0
    assert _rhs(km, _state(km, race_y=-2e-6, spin=0.0))[P0 + cm.ROMEGA] == 0.0


def test_ball_set_force_on_the_race_is_the_shared_kernel():
    """The race feels exactly the resultant of the one ball-set kernel (Eq. 22, NOTES item 4)."""
    from auxbearing.bearings.ballset import ballset_state

    km = _kernel(gravity=0.0, ball_damping=0.0, rolling_friction=0.0)
    for xb, yb in ((3e-6, -4e-6), (-1e-6, 2e-6), (0.0, -1e-5)):
        out = _rhs(km, _state(km, race_x=xb, race_y=yb, spin=0.0))
        force = ballset_state([0.0, xb, yb, 0.0, 0.0], km.machine.ballsets[0]).force
        np.testing.assert_allclose(out[[P0 + cm.RVX, P0 + cm.RVY]] * 0.0125, force[1:3], rtol=1e-12)


def test_free_fall_of_the_journal():
    km = _kernel()
    out = _rhs(km, km.y0)
    assert out[cm.VY] == pytest.approx(-9.80665) and out[cm.VX] == 0.0


def test_gyroscopic_terms_do_no_work():
    """The tilt equations' J_p Omega terms are orthogonal to the tilt rates (Friswell et al. 2010 Eq. 3.63)."""
    from auxbearing.machine.files import read_machine

    km = pack(read_machine("paper_rig_two_planes").with_simulation(gravity=0.0))
    y = km.y0.copy()
    y[cm.WX], y[cm.WY] = 0.3, -0.2
    out = _rhs(km, y)
    jt = km.machine.rotor.transverse_inertia
    power = jt * (y[cm.WX] * out[cm.WX] + y[cm.WY] * out[cm.WY])
    scale = km.machine.rotor.polar_inertia * abs(y[cm.OMEGA]) * (y[cm.WX] ** 2 + y[cm.WY] ** 2)
    assert out[cm.WX] != 0.0 and abs(power) <= 1e-12 * scale
