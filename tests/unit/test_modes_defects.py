"""The review of ``modes`` (analysis.modes): thrust bearing, frequency-dependent controllers, the ball set in contact,
growing modes.

Each test's expected numbers are worked by hand in its docstring from the machine file's data.
"""

import cmath
import copy
import math

import numpy as np
import pytest

from auxbearing.analysis import modes
from auxbearing.analysis.modes import campbell, contact_stiffness, linear_matrices
from auxbearing.machine.files import machine_table
from auxbearing.machine.model import machine_from_mapping


def _machine(name, change=None):
    data, _, base = machine_table(name)
    data = copy.deepcopy(data)
    if change is not None:
        change(data)
    return machine_from_mapping(data, name, base)


def _rigid_blower(*supports):
    """The blower's rigid rotor (10 kg, J_t 0.2 kg m^2, J_p 0.015 kg m^2) on linear supports alone."""
    def change(data):
        for key in ("criteria", "candidate", "amb", "scenario"):
            data.pop(key)
        data["linear_support"] = list(supports)
    return _machine("blower", change)


def test_the_thrust_bearing_is_no_radial_spring():
    """Free at rest, the blower is held by its two radial AMBs only (defect A).

    Each radial AMB (collocated): k = k_i k_p - k_s = 100 * 6000 - 2e5 = 4e5 N/m, c = k_i k_d = 100 * 12 = 1200 N s/m,
    at a = +-0.1 m. Symmetric about the mass centre, translation and tilt decouple:
    translation m s^2 + 2c s + 2k: w_d^2 = 2k/m - (2c/2m)^2 = 8e4 - 120^2 = 65600, w_d = 256.12 rad/s = 40.763 Hz;
    tilt J_t s^2 + 2c a^2 s + 2k a^2: w_d^2 = 8000/0.2 - (24/0.4)^2 = 36400, w_d = 190.79 rad/s = 30.365 Hz.
    The thrust AMB at -120 mm (k 150 * 6000 - 3e5 = 6e5 N/m) gave 34.8 / 59.7 Hz when counted as a radial spring.
    The translation does not couple with the spin: 1x crosses it at 60 * 40.763 = 2445.8 rpm.
    """
    blower = _machine("blower")
    d = campbell(blower, "0, 18000 rpm")
    assert d.frequencies[0] == pytest.approx([30.365, 30.365, 40.763, 40.763], abs=1e-3)
    _, _, _, stiff, _ = linear_matrices(blower, "free")
    assert stiff[0, 0] == pytest.approx(2 * 4e5)  # x: the two radial bearings, nothing from the thrust bearing
    assert stiff[2, 2] == pytest.approx(2 * 4e5 * 0.1 ** 2)
    crit = sorted(c["speed_rpm"] for c in d.critical_speeds())
    assert min(abs(c - 2445.8) for c in crit) < 0.5


KP, KI, KD, WF = 6000.0, 1e5, 12.0, 2 * math.pi * 2000.0


def _filtered_blower():
    """The blower with ``derivative_bandwidth = "2 kHz"`` on its radial AMBs, the controller written out by hand.

    C(s) = kp + ki / s + kd s / (1 + s / w_f) = kp + kd w_f + ki / s - kd w_f^2 / (s + w_f): states z1' = x
    (the integral) and z2' = -w_f z2 + x (the filter), A = diag(0, -w_f), B = (1, 1), C = (ki, -kd w_f^2),
    D = kp + kd w_f; what the file's derivative_bandwidth builds through python-control, without its import
    (a second of this test's time).
    """
    import dataclasses

    blower = _machine("blower")
    controller = (((0.0, 0.0), (0.0, -WF)), (1.0, 1.0), (KI, -KD * WF * WF), KP + KD * WF)
    stations = tuple(dataclasses.replace(s, controller=controller) if s.KIND == "amb" and not s.axial else s
                     for s in blower.stations)
    return dataclasses.replace(blower, stations=stations)


def test_a_filtered_controller_is_evaluated_at_each_modes_own_frequency():
    """The blower's radial AMBs with a 2 kHz derivative filter: C(s) = kp + ki / s + kd s / (1 + s / w_f) (defect B).

    At a frequency w: Re C = kp + kd w^2 / w_f / (1 + (w/w_f)^2), Im C = kd w / (1 + (w/w_f)^2) - ki / w; the bearing
    is k(w) = k_i Re C - k_s, c(w) = k_i Im C / w. The translation mode's damped frequency solves
    w^2 = 2 k(w) / m - (c(w) / m)^2 (two bearings, 10 kg): at w = 2 pi 42.16 Hz = 264.9 rad/s, Re C = 6067.0 A/m,
    k = 4.067e5 N/m, Im C = 3177.4 - 377.5 = 2799.9 A/m, c = 1057 N s/m, so 2k/m - (c/m)^2 = 81340 - 11172 = 70168
    = 264.9^2: a fixed point near 42.16 Hz. Evaluated at the running speed (300 Hz, k = 7.3e5 N/m) it read 58.0 Hz.
    """
    blower = _filtered_blower()
    d = campbell(blower, [0.0])
    kp, ki, kd, wf, k_i, k_s, m = KP, KI, KD, WF, 100.0, 2e5, 10.0

    def translation(w):
        lag = 1.0 + (w / wf) ** 2
        k = k_i * (kp + kd * w * w / wf / lag) - k_s
        c = k_i * (kd * w / lag - ki / w) / w
        return math.sqrt(2 * k / m - (c / m) ** 2)

    w = 2 * math.pi * 40.0
    for _ in range(60):  # the fixed point by hand, iterated
        w = translation(w)
    assert w / (2 * math.pi) == pytest.approx(42.16, abs=0.01)
    assert d.frequencies[0, -1] == pytest.approx(w / (2 * math.pi), rel=1e-7)
    assert d.frequencies[0, -2] == pytest.approx(w / (2 * math.pi), rel=1e-7)  # the pair
    assert d.frequencies[0, 0] < 35.0 and d.unsettled == 0  # the tilt pair near 31 Hz, not 42
    # the plain PD (no filter) is frequency independent and gives the closed form of the test above
    assert campbell(_machine("blower"), [0.0]).frequencies[0, -1] == pytest.approx(40.763, abs=1e-3)


def test_in_contact_the_ball_set_is_linearised_under_its_share_of_the_weight():
    """Paper rig, two planes (defect C): 2.96 kg, planes at +-80 mm, J_t 0.01 kg m^2, QJ202 with no mount.

    Each plane carries W = 2.96 * 9.80665 / 2 = 14.514 N. A zero-clearance ball set follows F ~ delta^1.5, so its
    tangent stiffness is 1.5 W / delta with delta = radial_approach(W) = 0.7017 um: 3.103e7 N/m (the Jacobian gives
    3.106e7, the contact angle turning a little). The journal's line contact: delta_l = (W / K_l)^0.9 with
    K_l = 1.463e9, its tangent (10/9) W / delta_l; in series with the ball set: k_c = 2.772e7 N/m. Then along the
    weight the translation sqrt(2 k_c / m) = 4328 rad/s = 688.8 Hz and the tilt sqrt(2 k_c a^2 / J_t) = 5957 rad/s
    = 948.0 Hz (1131.5 / 1557.3 Hz with the ball set taken at 100 N).
    """
    from auxbearing.analysis.statics import radial_approach
    from auxbearing.bearings.ballset import ballset_params

    rig = _machine("paper_rig_two_planes")
    plane = rig.planes[0]
    weight = 0.5 * 2.96 * rig.simulation.gravity
    along, _ = modes.ball_set_stiffness(plane, weight)
    delta = radial_approach(ballset_params(plane.bearing, plane.ball_constant), weight)
    assert along == pytest.approx(1.5 * weight / delta, rel=2e-3)
    assert along == pytest.approx(3.10e7, rel=3e-3)
    line = 10.0 / 9.0 * weight / (weight / plane.line_stiffness) ** 0.9
    k_c = 1.0 / (1.0 / line + 1.0 / along)
    assert contact_stiffness(rig, 0) == pytest.approx(k_c, rel=1e-9)
    assert k_c == pytest.approx(2.772e7, rel=1e-3)
    d = campbell(rig, [0.0], "contact")
    assert d.frequencies[0, 2:] == pytest.approx([math.sqrt(2 * k_c / 2.96) / (2 * math.pi),
                                                 math.sqrt(2 * k_c * 0.08 ** 2 / 0.01) / (2 * math.pi)], rel=1e-6)
    assert d.frequencies[0, 2:] == pytest.approx([688.8, 948.0], abs=0.3)


def _pair(name):
    def change(data):
        for table in data["touchdown"]:
            table["bearing"] = name
    return change


def test_a_matched_pair_in_contact_is_both_rows_with_their_preload():
    """The blower with a 7208 pair in each plane (defect C).

    A heavy DF pair (4 % of C0 preload) is stiff at zero load: both rows' Jacobian at the clamped state,
    -sum M_k^T J_k M_k = 2.90e8 N/m (duplex_statics.set_reaction); a tandem pair has no preload and zero clearance:
    nothing at zero load. Under the blower's W = 10 * 9.80665 / 2 = 49.0 N the preloaded pair stays far stiffer than
    the tandem one, so the contact modes differ (they were equal, 286.6 / 304.0 Hz, with one row at 100 N).
    The plane's spring is the line contact, the ball set and the 2e7 N/m mount in series.
    """
    from auxbearing.bearings.duplex_statics import set_reaction

    heavy, tandem = _machine("blower", _pair("7208 DF heavy")), _machine("blower", _pair("7208 DT"))
    _, jac, _ = set_reaction(heavy.planes[0].bearing_set, np.zeros(5))
    assert modes.ball_set_stiffness(heavy.planes[0], 0.0)[0] == pytest.approx(-jac[1, 1], rel=1e-9)
    assert -jac[1, 1] == pytest.approx(2.90e8, rel=1e-2)
    assert modes.ball_set_stiffness(tandem.planes[0], 0.0) == (0.0, 0.0)
    weight = 0.5 * 10.0 * heavy.simulation.gravity
    k_heavy, k_tandem = (modes.ball_set_stiffness(m.planes[0], weight)[0] for m in (heavy, tandem))
    assert k_heavy > 1.5 * k_tandem > 0.0
    plane = heavy.planes[0]
    line = 10.0 / 9.0 * weight / (weight / plane.line_stiffness) ** 0.9
    expected = 1.0 / (1.0 / line + 1.0 / k_heavy + 1.0 / plane.mount.mount_stiffness)
    assert contact_stiffness(heavy, 0) == pytest.approx(expected, rel=1e-9)
    f_heavy = campbell(heavy, [0.0], "contact").frequencies[0]
    f_tandem = campbell(tandem, [0.0], "contact").frequencies[0]
    assert f_heavy[-1] > f_tandem[-1] + 1.0


def test_a_cross_coupled_support_shows_a_growing_mode():
    """A rigid rotor whose translation a cross-coupled seal destabilises (defect D).

    Supports k = 1e6 N/m at +-0.15 m and at the mass centre a seal kxy = 5e5, kyx = -5e5 N/m with cxx = cyy =
    200 N s/m. With z = x + i y the translation is m z'' + c z' + (2k - i q) z = 0, roots
    s = (-c +- sqrt(c^2 - 4 m (2k - i q))) / (2 m); the forward one grows at about q / (2 m w) - c / (2 m)
    = 5e5 / (2 * 10 * 447) - 10 = 46 1/s. The tilt (the seal has no arm) is undamped and neutral.
    """
    seal = {"position": "0 mm", "kxy": "5e5 N/m", "kyx": "-5e5 N/m", "cxx": "200 N*s/m", "cyy": "200 N*s/m"}
    rotor = _rigid_blower(*({"position": f"{s * 0.15} m", "kxx": "1e6 N/m", "kyy": "1e6 N/m"} for s in (-1, 1)), seal)
    m, c, k2, q = 10.0, 200.0, 2e6, 5e5
    roots = [(-c + sign * cmath.sqrt(c * c - 4 * m * (k2 - 1j * q))) / (2 * m) for sign in (1, -1)]
    growing = max(roots, key=lambda s: s.real)
    assert growing.real == pytest.approx(46.0, abs=1.0)
    d = campbell(rotor, [0.0])
    unstable = d.unstable()
    assert len(unstable) == 1
    assert unstable[0]["growth_rate_per_s"] == pytest.approx(growing.real, rel=1e-9)
    assert unstable[0]["frequency_Hz"] == pytest.approx(abs(growing.imag) / (2 * math.pi), rel=1e-9)
    assert unstable[0]["damping_ratio"] == pytest.approx(-growing.real / abs(growing), rel=1e-9)
    assert d.as_dict()["unstable"] == unstable


def test_a_divergent_root_is_reported_not_dropped():
    """A negative net stiffness (defect D): supports 1e6 N/m at +-0.15 m and -5e6 N/m at the mass centre.

    Translation: m s^2 + (2e6 - 5e6) = 0, s = +-sqrt(3e6 / 10) = +-547.7 1/s, in x and in y: two roots that diverge
    without oscillating. The tilt is untouched (no arm): sqrt(2 k a^2 / J_t) = sqrt(2e6 * 0.0225 / 0.2) = 474.3 rad/s
    = 75.49 Hz, a pair. Four entries, as many as the stable rotor has (only the two tilts were shown before).
    """
    rotor = _rigid_blower(*({"position": f"{s * 0.15} m", "kxx": "1e6 N/m", "kyy": "1e6 N/m"} for s in (-1, 1)),
                          {"position": "0 mm", "kxx": "-5e6 N/m", "kyy": "-5e6 N/m"})
    d = campbell(rotor, [0.0])
    assert d.frequencies.shape == (1, 4)
    assert list(d.whirl[0, :2]) == ["none", "none"]
    assert d.growth_rates[0, :2] == pytest.approx([math.sqrt(3e5)] * 2, rel=1e-9)
    assert d.damping_ratios[0, :2] == pytest.approx([-1.0, -1.0])
    assert d.frequencies[0, 2:] == pytest.approx([math.sqrt(2e6 * 0.0225 / 0.2) / (2 * math.pi)] * 2, rel=1e-9)
    assert len(d.unstable()) == 2 and not d.critical_speeds()  # a divergence has no frequency for 1x to meet


def _labelled_points(fig, label):
    """The (speed, frequency) points of the figure's scatter drawn with ``label``."""
    ax = fig.axes[0]
    return [c.get_offsets().tolist() for c in ax.collections if c.get_label() == label]


def test_the_campbell_diagram_marks_what_grows_and_what_diverges():
    from auxbearing.plots.modes import plot_campbell

    seal = {"position": "0 mm", "kxy": "5e5 N/m", "kyx": "-5e5 N/m", "cxx": "200 N*s/m", "cyy": "200 N*s/m"}
    sealed = _rigid_blower(*({"position": f"{s * 0.15} m", "kxx": "1e6 N/m", "kyy": "1e6 N/m"} for s in (-1, 1)), seal)
    d = campbell(sealed, [0.0])
    (grows,) = _labelled_points(plot_campbell([d], 0.0), "growing (unstable)")
    assert grows == [[0.0, pytest.approx(d.unstable()[0]["frequency_Hz"])]]
    soft = _rigid_blower(*({"position": f"{s * 0.15} m", "kxx": "1e6 N/m", "kyy": "1e6 N/m"} for s in (-1, 1)),
                         {"position": "0 mm", "kxx": "-5e6 N/m", "kyy": "-5e6 N/m"})
    (diverges,) = _labelled_points(plot_campbell([campbell(soft, [0.0])], 0.0), "diverging without oscillating (0 Hz)")
    assert diverges == [[0.0, 0.0], [0.0, 0.0]]  # the two translations, at 0 Hz on the speed axis
