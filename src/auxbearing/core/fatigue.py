"""Rolling-contact fatigue and permanent deformation of ball/raceway contacts (pure core, SI).

Four pieces, each with the source it follows:

* ISO 281:2007 basic dynamic radial load rating of radial and angular-contact ball bearings
  (6.1.1: b_m f_c (i cos alpha)^0.7 Z^(2/3) D_w^1.8 below D_w = 25.4 mm, 3.647 b_m f_c ... D_w^1.4
  above, D_w in mm, C in N; b_m from Table 1, f_c from Table 2 interpolated linearly) and the
  basic rating life L10 = (C/P)^3 [10^6 revolutions] with the equivalent load P = X Fr + Y Fa.
  ISO 281 does not cover four-point contact bearings (Roos & Hansen, Kaydon, "Not all thin-section
  bearings are created equal"); makers rate them as a double-row 35 deg bearing, i = 2 (MESYS
  manual, "Four-point bearing considered as radial bearing"), and take the ISO 281 double-row
  35 deg factors for P (SKF Rolling bearings, PUB BU/P1 17000/1 EN, 2018, p. 399).
* The Lundberg-Palmgren split of C into the dynamic capacities of the inner and outer raceway
  contacts, Q_ci and Q_ce: with the zero-clearance radial load zone (epsilon = 0.5) the rotating
  inner ring sees the cubic mean of the ball loads J_1 Q_max, the stationary outer ring the
  10/3-power mean J_2 Q_max, F_r = Z J_r Q_max cos(alpha), the ring lives L = (Q_c/Q_e)^3 combine
  as L^-e = L_i^-e + L_e^-e with e = 10/9, and Q_ci/Q_ce follows Lundberg-Palmgren's capacity
  formula (Harris & Kotzalas, Rolling Bearing Analysis, 5th ed., 2007, Essential Concepts Ch. 11).
  The ratio bracket below reproduces every entry of ISO 281 Table 2 to its printed 0.1 when the
  fc expression of ISO/TR 1281-1 is evaluated with it. Public ISO/TS 16281 codes split C the same
  way with the rounded J_r/J_1 = 0.407, J_r/J_2 = 0.389, J_2/J_1 = 1.044 (here exact; the
  standard's text was not retrieved).
* A stress-life law for one raceway point: N_f(S) = N_c (sigma_c/S)^9 over-rollings, where
  sigma_c is the Hertz stress of the contact at Q_c and N_c the over-rollings a raceway point takes
  in 10^6 revolutions. The exponent 9 is Lundberg-Palmgren's: life ~ Q^-3 and sigma ~ Q^(1/3)
  (Zaretsky, Poplawski & Root, NASA/TM-2008-214265: "an inverse 9th power relation between Hertz
  stress and fatigue life"; the same report gives 12 for post-1960 vacuum-processed steel).
  Miner's sum within a raceway point, Weibull sum (slope e) over points and rings, so a constant
  load reproduces N / L10 exactly (see :func:`ring_damage`).
* Palmgren's permanent deformation of a ball/raceway contact (Harris & Kotzalas 2007, Essential
  Concepts, Ch. 9: delta_p = 1.3e-7 Q^2 (rho_I1 + rho_II1)(rho_I2 + rho_II2)/D with delta, D in mm,
  Q in N, rho in 1/mm; the sum of ball and raceway set), and ISO 76's limit of 1e-4 D.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

#: ISO 281:2007 Table 2, column of single-row radial-contact and single/double-row angular-contact
#: groove ball bearings: f_c against D_w cos(alpha)/D_pw, read by linear interpolation as the
#: standard directs (it assumes groove radii of 0.52 D_w, ISO/TR 1281-1).
ISO281_FC_GAMMA = np.array([0.01, 0.02, 0.03, 0.04, 0.05, 0.06, 0.07, 0.08, 0.09, 0.10, 0.12, 0.14, 0.16,
                            0.18, 0.20, 0.22, 0.24, 0.26, 0.28, 0.30, 0.32, 0.34, 0.36, 0.38, 0.40])
ISO281_FC = np.array([29.1, 35.8, 40.3, 43.8, 46.7, 49.1, 51.1, 52.8, 54.3, 55.5, 57.5, 58.8, 59.6,
                      59.9, 59.9, 59.6, 59.0, 58.2, 57.1, 56.0, 54.6, 53.2, 51.7, 50.0, 48.4])
#: ISO 281:2007 Table 1: b_m for radial ball bearings (material and manufacturing quality).
RADIAL_BALL_BM = 1.3
#: ISO 281:2007 6.1.1: the rating formula changes form above a 25.4 mm ball.
LARGE_BALL_DIAMETER = 25.4e-3
LARGE_BALL_FACTOR = 3.647
#: ISO 281 works in mm and N; ratings here take metres.
_MM = 1e3
#: L10 = (C/P)^p with p = 3 for ball bearings (ISO 281:2007, 7.1); one rating life unit.
BALL_LOAD_LIFE_EXPONENT = 3.0
RATING_REVOLUTIONS = 1e6
#: Lundberg-Palmgren Weibull slope for point contact (e = 10/9; Harris & Kotzalas 2007, Ch. 11).
WEIBULL_SLOPE = 10.0 / 9.0
#: Hertz stress-life exponent of Lundberg-Palmgren for ball bearings (NASA/TM-2008-214265).
STRESS_LIFE_EXPONENT = 9.0
#: Palmgren's permanent set, 1.3e-7 mm^4/N^2 in mm and N (Harris & Kotzalas 2007, Ch. 9), in SI.
PALMGREN_DENT_COEFFICIENT = 1.3e-7 * 1e-12
#: ISO 76:2006: at C0 the permanent set of ball and raceway is about 1e-4 of the ball diameter.
ISO76_DENT_RATIO = 1e-4
#: Equivalent-load factors (e, X1, Y1, X2, Y2): P = X1 Fr + Y1 Fa for Fa/Fr <= e, else X2, Y2.
#: Single-row angular contact, ISO 281:2007 Table 3 at 20-45 deg (as NSK Rolling Bearings CAT. No. E1102e reprints
#: it; a bearing takes the row of the nearest tabulated angle, the smaller one on a tie, whose Y is the larger);
#: four-point contact from SKF Rolling bearings 2018, p. 399 (the ISO 281 double-row 35 deg row).
ANGULAR_CONTACT_FACTORS = {20: (0.57, 1.0, 0.0, 0.43, 1.00), 25: (0.68, 1.0, 0.0, 0.41, 0.87),
                           30: (0.80, 1.0, 0.0, 0.39, 0.76), 35: (0.95, 1.0, 0.0, 0.37, 0.66),
                           40: (1.14, 1.0, 0.0, 0.35, 0.57), 45: (1.34, 1.0, 0.0, 0.33, 0.50)}
FOUR_POINT_FACTORS = (0.95, 1.0, 0.66, 0.6, 1.07)
#: A matched pair back-to-back or face-to-face: the double-row factors of ISO 281 Table 3 for the set's Fr and
#: Fa, as NSK CAT. No. E1102e lists them for DB and DF pairs (a tandem pair takes the single-row factors).
ANGULAR_CONTACT_PAIR_FACTORS = {20: (0.57, 1.0, 1.09, 0.70, 1.63), 25: (0.68, 1.0, 0.92, 0.67, 1.41),
                                30: (0.80, 1.0, 0.78, 0.63, 1.24), 35: (0.95, 1.0, 0.66, 0.60, 1.07),
                                40: (1.14, 1.0, 0.55, 0.57, 0.93), 45: (1.34, 1.0, 0.47, 0.54, 0.81)}


#: ISO 281:2007 Table 3, single-row radial deep-groove ball bearings: f0 Fa / C0, then e and Y for Fa / Fr > e
#: (X = 0.56 there; X = 1, Y = 0 at or below e). The same table stands in the makers' catalogues (SKF, NSK) beside
#: their deep-groove bearings. Between its rows linear interpolation, as ISO 281 allows; outside it the end rows.
DEEP_GROOVE_RELATIVE_AXIAL = (0.172, 0.345, 0.689, 1.03, 1.38, 2.07, 3.45, 5.17, 6.89)
DEEP_GROOVE_E = (0.19, 0.22, 0.26, 0.28, 0.30, 0.34, 0.38, 0.42, 0.44)
DEEP_GROOVE_Y = (2.30, 1.99, 1.71, 1.55, 1.45, 1.31, 1.15, 1.04, 1.00)


def deep_groove_factors(relative_axial: float) -> tuple[float, float, float, float, float]:
    """(e, X1, Y1, X2, Y2) of a single-row deep-groove ball bearing at f0 Fa / C0 (ISO 281:2007 Table 3).

    Examples
    --------
    >>> [round(v, 3) for v in deep_groove_factors(0.068)]   # below the table: its first row
    [0.19, 1.0, 0.0, 0.56, 2.3]
    >>> round(deep_groove_factors(0.5)[4], 3)                # between 0.345 (1.99) and 0.689 (1.71)
    1.864
    """
    x = float(np.clip(relative_axial, DEEP_GROOVE_RELATIVE_AXIAL[0], DEEP_GROOVE_RELATIVE_AXIAL[-1]))
    e = float(np.interp(x, DEEP_GROOVE_RELATIVE_AXIAL, DEEP_GROOVE_E))
    y = float(np.interp(x, DEEP_GROOVE_RELATIVE_AXIAL, DEEP_GROOVE_Y))
    return e, 1.0, 0.0, 0.56, y


def iso281_fc(gamma):
    """ISO 281:2007 Table 2 factor f_c [-] at gamma = D_w cos(alpha)/D_pw, linear interpolation.

    Parameters
    ----------
    gamma : float
        D_w cos(alpha) / D_pw [-], within the table's 0.01 to 0.40.

    Examples
    --------
    >>> round(iso281_fc(0.11), 2), iso281_fc(0.2)
    (56.5, 59.9)
    """
    if not ISO281_FC_GAMMA[0] <= gamma <= ISO281_FC_GAMMA[-1]:
        raise ValueError(f"D_w cos(alpha)/D_pw = {gamma:.4g}: outside ISO 281 Table 2 (0.01 to 0.40)")
    return float(np.interp(gamma, ISO281_FC_GAMMA, ISO281_FC))


def dynamic_load_rating(ball_diameter, pitch_diameter, ball_count, contact_angle, rows=1, bm=RADIAL_BALL_BM):
    """Basic dynamic radial load rating C_r [N] of a radial or angular-contact ball bearing.

    ISO 281:2007, 6.1.1, both ball-size forms, with f_c from :func:`iso281_fc`.

    Parameters
    ----------
    ball_diameter : float
        D_w [m].
    pitch_diameter : float
        D_pw [m].
    ball_count : int
        Z, balls per row [-].
    contact_angle : float
        Nominal contact angle alpha [rad].
    rows : int
        i [-]; 2 for a four-point contact bearing as makers rate it.
    bm : float
        Rating factor b_m [-] (ISO 281 Table 1).

    Examples
    --------
    >>> round(dynamic_load_rating(12.7e-3, 65e-3, 9, 0.0))  # the 209 of Harris & Kotzalas
    32687
    """
    gamma = ball_diameter * math.cos(contact_angle) / pitch_diameter
    common = bm * iso281_fc(gamma) * (rows * math.cos(contact_angle)) ** 0.7 * ball_count ** (2.0 / 3.0)
    if ball_diameter <= LARGE_BALL_DIAMETER:
        return common * (ball_diameter * _MM) ** 1.8
    return LARGE_BALL_FACTOR * common * (ball_diameter * _MM) ** 1.4


def rating_life(dynamic_rating, equivalent_load):
    """Basic rating life L10 = (C/P)^3 [10^6 revolutions] (ISO 281:2007, 7.1, ball bearings).

    Examples
    --------
    >>> rating_life(20e3, 10e3)
    8.0
    """
    return (dynamic_rating / equivalent_load) ** BALL_LOAD_LIFE_EXPONENT


def equivalent_dynamic_load(radial, axial, factors):
    """Dynamic equivalent radial load P = X Fr + Y Fa [N] (ISO 281:2007, 6.2).

    Parameters
    ----------
    radial, axial : float
        Fr, Fa [N], >= 0.
    factors : tuple
        (e, X1, Y1, X2, Y2): X1, Y1 apply for Fa/Fr <= e, X2, Y2 above; see
        :data:`ANGULAR_CONTACT_FACTORS` and :data:`FOUR_POINT_FACTORS`.

    Examples
    --------
    >>> equivalent_dynamic_load(1000.0, 2000.0, ANGULAR_CONTACT_FACTORS[40])
    1490.0
    """
    e, x1, y1, x2, y2 = factors
    if axial <= e * radial:
        return x1 * radial + y1 * axial
    return x2 * radial + y2 * axial


def load_zone_integrals():
    """Lundberg-Palmgren load integrals J_r, J_1, J_2 [-] of the epsilon = 0.5 radial load zone.

    Zero clearance gives Q(psi) = Q_max cos(psi)^1.5 over |psi| < 90 deg (Stribeck; Harris &
    Kotzalas 2007, Ch. 7), so J_r = <cos^2.5>, J_1 = <cos^4.5>^(1/3), J_2 = <cos^5>^(3/10), the
    averages over the whole circle, in closed form through the Beta function. Harris tabulates them
    as 0.2288, 0.5625 and 0.5875; 1/J_r is Stribeck's 4.37.

    Examples
    --------
    >>> [round(j, 4) for j in load_zone_integrals()]
    [0.2288, 0.5625, 0.5874]
    """
    def mean_cos_power(n):
        return math.gamma(0.5 * (n + 1.0)) / (2.0 * math.sqrt(math.pi) * math.gamma(0.5 * n + 1.0))
    return mean_cos_power(2.5), mean_cos_power(4.5) ** (1.0 / 3.0), mean_cos_power(5.0) ** 0.3


def raceway_capacity_loads(rating_per_row, ball_count, contact_angle, gamma, inner_groove_ratio,
                           outer_groove_ratio):
    """Dynamic capacities Q_ci, Q_ce [N] of one ball's inner and outer raceway contacts.

    The ball load at which the rotating inner (stationary outer) raceway alone reaches L10 = 10^6
    revolutions, split from the row's rating C so that the epsilon = 0.5 load zone with
    F_r = C gives exactly 10^6 revolutions (see the module notes): Q_ci = J_1 Q_max (1 + B^(10/3))^0.3,
    Q_ce = J_2 Q_max (1 + B^(-10/3))^0.3, Q_max = C/(Z J_r cos(alpha)), B = (J_2 Q_ci)/(J_1 Q_ce) with
    Lundberg-Palmgren's Q_ci/Q_ce = [f_i (2 f_e - 1)/(f_e (2 f_i - 1))]^0.41 ((1 - gamma)/(1 + gamma))^1.72.

    Parameters
    ----------
    rating_per_row : float
        C of one row [N] (for a four-point bearing the rating with i = 1).
    ball_count : int
        Z [-].
    contact_angle : float
        alpha [rad].
    gamma : float
        D cos(alpha)/d_m [-].
    inner_groove_ratio, outer_groove_ratio : float
        f_i, f_e [-].

    Examples
    --------
    >>> qi, qe = raceway_capacity_loads(32687.0, 9, 0.0, 0.1954, 0.52, 0.52)
    >>> round(qi), round(qe)
    (9235, 18246)
    """
    j_r, j_1, j_2 = load_zone_integrals()
    q_max = rating_per_row / (ball_count * j_r * math.cos(contact_angle))
    fi, fe = inner_groove_ratio, outer_groove_ratio
    ratio = (fi * (2.0 * fe - 1.0) / (fe * (2.0 * fi - 1.0))) ** 0.41 * ((1.0 - gamma) / (1.0 + gamma)) ** 1.72
    bracket = j_2 / j_1 * ratio
    q_ci = j_1 * q_max * (1.0 + bracket ** (10.0 / 3.0)) ** 0.3
    q_ce = j_2 * q_max * (1.0 + bracket ** (-10.0 / 3.0)) ** 0.3
    return q_ci, q_ce


def overrolls_per_revolution(ball_count, gamma):
    """Ball passes over one raceway point per inner-ring revolution, outer ring fixed [-].

    Kinematic (no-slip) cage speed omega_c = omega_i (1 - gamma)/2 (Harris & Kotzalas 2007,
    Essential Concepts, Ch. 10): a point of the inner raceway meets Z (1 + gamma)/2 balls per
    revolution, a point of the outer raceway Z (1 - gamma)/2.

    Examples
    --------
    >>> overrolls_per_revolution(10, 0.2)
    (6.0, 4.0)
    """
    return 0.5 * ball_count * (1.0 + gamma), 0.5 * ball_count * (1.0 - gamma)


def cycle_damage(stress, capacity_stress, capacity_cycles, exponent=STRESS_LIFE_EXPONENT):
    """Miner damage [-] of one stress cycle of amplitude ``stress`` at a raceway point.

    1/N_f with N_f = N_c (sigma_c / S)^n: ``capacity_cycles`` over-rollings at ``capacity_stress``
    fail the point at the L10 reliability; n = 9 is Lundberg-Palmgren's (module notes).

    Parameters
    ----------
    stress : float or array
        Cycle stress S [Pa], >= 0.
    capacity_stress : float
        sigma_c [Pa], Hertz stress of the contact at its dynamic capacity Q_c.
    capacity_cycles : float
        N_c [-], over-rollings of a raceway point in 10^6 revolutions.
    exponent : float
        n [-].

    Examples
    --------
    >>> float(cycle_damage(4e9, 4e9, 5e6)) * 5e6
    1.0
    """
    return (np.asarray(stress, float) / capacity_stress) ** exponent / capacity_cycles


def ring_damage(point_damage, slope=WEIBULL_SLOPE):
    """Damage of a ring [-] from the Miner damage of its raceway points, shape (..., tracks, points).

    The survival of a ring is the product over its material: ln(1/S) ~ sum of (point damage)^e,
    each point standing for an equal share of a track (Lundberg-Palmgren), so
    D_ring = (sum over tracks of the mean over points of D^e)^(1/e). A uniform D on one track gives
    D; the stationary ring of the epsilon = 0.5 zone gives its J_2 life (Harris & Kotzalas 2007,
    Ch. 11, the rotating ring its J_1 life).

    Examples
    --------
    >>> round(float(ring_damage(np.array([[0.5, 0.5]]))), 12)
    0.5
    """
    d = np.asarray(point_damage, float)
    return np.sum(np.mean(d ** slope, axis=-1), axis=-1) ** (1.0 / slope)


def bearing_damage(inner, outer, slope=WEIBULL_SLOPE):
    """Bearing damage [-] from its rings', D = (D_i^e + D_e^e)^(1/e) (Lundberg-Palmgren ring lives).

    Examples
    --------
    >>> round(float(bearing_damage(1.0, 0.0)), 12)
    1.0
    """
    return (np.asarray(inner, float) ** slope + np.asarray(outer, float) ** slope) ** (1.0 / slope)


def palmgren_dent_depth(load, ball_diameter, curvature_sum_1, curvature_sum_2):
    """Permanent set of ball and raceway together [m] after a contact load (Palmgren).

    delta_p = 1.3e-7 Q^2 (rho_I1 + rho_II1)(rho_I2 + rho_II2)/D in mm and N (Harris & Kotzalas 2007,
    Essential Concepts, Ch. 9), here in SI: 1.3e-19 m^4/N^2.

    Parameters
    ----------
    load : float or array
        Contact load Q [N].
    ball_diameter : float
        D [m].
    curvature_sum_1, curvature_sum_2 : float
        Ball plus raceway curvature in each principal plane [1/m] (concave negative).

    Examples
    --------
    >>> f"{float(palmgren_dent_depth(1000.0, 10e-3, 250.0, 10.0)):.3g}"
    '3.25e-08'
    """
    q = np.asarray(load, float)
    return PALMGREN_DENT_COEFFICIENT * q * q * curvature_sum_1 * curvature_sum_2 / ball_diameter


def dwell_width_ratio(exponent=STRESS_LIFE_EXPONENT, slope=WEIBULL_SLOPE):
    """Width of raceway a standing contact damages, over its semi-minor axis b [-].

    Under a contact that loads and unloads in place, the surface pressure at x along the track is
    sigma sqrt(1 - (x/b)^2) (Hertz, Harris & Kotzalas 2007, Ch. 6), so by the stress-life law and
    the Weibull sum the strip contributes int (1 - x^2/b^2)^(n e/2) dx = b B(1/2, n e/2 + 1): the
    same as a strip of this width at the full stress. One raceway point per such width lets the
    point under a standing ball carry the contact's damage unreduced.

    Examples
    --------
    >>> round(dwell_width_ratio(), 4)
    0.7388
    """
    power = 0.5 * exponent * slope
    return math.sqrt(math.pi) * math.gamma(power + 1.0) / math.gamma(power + 1.5)


@njit(cache=True)
def _visit(position, stress, n_elements, out_elem, out_ball, out_value, fill):
    """One pass over the samples: count (``fill`` False) or write the raceway-point events."""
    n_time, n_ball = position.shape
    count = 0
    for n in range(n_time):
        for j in range(n_ball):
            u1, s1 = position[n, j], stress[n, j]
            u0, s0 = (u1, 0.0) if n == 0 else (position[n - 1, j], stress[n - 1, j])
            m0 = math.floor(u0 + 0.5)
            m1 = math.floor(u1 + 0.5)
            for m in range(min(m0, m1), max(m0, m1) + 1):
                was = m == m0 and s0 > 0.0
                now = m == m1 and s1 > 0.0
                crossing = 0.0
                crosses = (u0 - m) * (u1 - m) < 0.0
                if crosses:
                    crossing = s0 + (m - u0) / (u1 - u0) * (s1 - s0)
                    crosses = crossing > 0.0
                if not (was or now or crosses):
                    continue
                closes = (not now) or n == n_time - 1
                if fill:
                    k = ((m % n_elements) + n_elements) % n_elements
                    values = (-1.0 if was else 0.0, crossing if crosses else -1.0, s1 if now else -1.0,
                              0.0 if closes else -1.0)
                    for v in values:
                        if v >= 0.0:
                            out_elem[count] = k
                            out_ball[count] = j
                            out_value[count] = v
                            count += 1
                else:
                    count += (not was) + crosses + now + closes
    return count


def overrolling_events(position, stress, n_elements):
    """Stress history of every raceway point of one track, as chronological events.

    The track is cut into ``n_elements`` points, centred at the whole numbers of ``position``. A
    point carries the stress of the ball whose contact centre is nearest to it (within half a
    pitch); a ball that passes a point between two samples loads it with the stress interpolated
    at the moment it crosses the point's centre. Every loading starts and ends with a zero, so each
    point's history is a train of pulses (one per over-rolling or standing load) whose peaks are
    the contact stresses, ready for cycle counting.

    Parameters
    ----------
    position : array (time, ball)
        Contact centre along the track in point pitches [-], unwrapped (continuous).
    stress : array (time, ball)
        Contact max stress [Pa], >= 0.
    n_elements : int
        Raceway points around the track.

    Returns
    -------
    element, ball : int arrays
        Raceway point and ball of each event, in the order the events happen.
    value : float array
        Stress at the point [Pa].

    Examples
    --------
    >>> e, b, v = overrolling_events(np.array([[0.0], [2.2]]), np.full((2, 1), 1e9), 8)
    >>> [e.tolist(), (v / 1e9).tolist()]
    [[0, 0, 0, 1, 1, 1, 2, 2, 2, 2], [0.0, 1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 0.0]]
    """
    args = (np.ascontiguousarray(position, dtype=float), np.ascontiguousarray(stress, dtype=float),
            int(n_elements))
    size = _visit(*args, np.empty(0, np.int64), np.empty(0, np.int64), np.empty(0), False)
    element = np.empty(size, np.int64)
    ball = np.empty(size, np.int64)
    value = np.empty(size)
    _visit(*args, element, ball, value, True)
    return element, ball, value


@njit(cache=True)
def rainflow_turning_points(x):
    """Rainflow cycles of a history of turning points (ASTM E1049-85, 5.4.4), in the order they close.

    ``x`` must alternate (each point a reversal; the first and last taken as reversals). The three-point
    rule of the standard on a stack: with X the range of the two newest points and Y the one before it,
    X < Y reads the next point; otherwise Y is counted, as a half cycle when it holds the history's first
    point still on the stack (which is then dropped), else as a whole cycle (both its points dropped).
    What is left at the end counts as half cycles, oldest first. The same counting and order as the
    ``rainflow`` package (which the tests hold it to), without a Python object per cycle: a coast-down's
    drop window has over a million of them.

    Returns
    -------
    ndarray, shape (cycles, 5)
        range, mean, count (1 or 0.5), index of its first and of its second point in ``x``.

    Examples
    --------
    >>> import numpy as np
    >>> c = rainflow_turning_points(np.array([-2.0, 1.0, -3.0, 5.0, -1.0, 3.0, -4.0, 4.0, -2.0]))
    >>> c[:, 0].tolist(), c[:, 2].tolist()
    ([3.0, 4.0, 4.0, 8.0, 9.0, 8.0, 6.0], [0.5, 0.5, 1.0, 0.5, 0.5, 0.5, 0.5])
    """
    n = x.size
    out = np.empty((max(n - 1, 0), 5))
    stack = np.empty(n, np.int64)
    bottom = 0  # the oldest point still on the stack
    top = 0  # one past the newest
    m = 0
    for i in range(n):
        stack[top] = i
        top += 1
        while top - bottom >= 3:
            i1, i2, i3 = stack[top - 3], stack[top - 2], stack[top - 1]
            if abs(x[i3] - x[i2]) < abs(x[i2] - x[i1]):
                break
            if top - bottom == 3:  # Y holds the first point: half a cycle, the first point dropped
                a, b, count = stack[bottom], stack[bottom + 1], 0.5
                bottom += 1
            else:  # a whole cycle: its two points dropped, the newest kept
                a, b, count = i1, i2, 1.0
                stack[top - 3] = i3
                top -= 2
            out[m, 0] = abs(x[a] - x[b])
            out[m, 1] = 0.5 * (x[a] + x[b])
            out[m, 2] = count
            out[m, 3] = a
            out[m, 4] = b
            m += 1
    for j in range(bottom, top - 1):
        a, b = stack[j], stack[j + 1]
        out[m, 0] = abs(x[a] - x[b])
        out[m, 1] = 0.5 * (x[a] + x[b])
        out[m, 2] = 0.5
        out[m, 3] = a
        out[m, 4] = b
        m += 1
    return out[:m]
