"""Friction of a touchdown bearing and of the journal/race sliding contact, and where its heat goes (SI).

Two models of the bearing's own resisting torque (magnitudes; the caller applies them against the
relative rotation):

* Palmgren's M = M_0 + M_1 (Harris & Kotzalas, *Rolling Bearing Analysis*, 5th ed. 2007, Essential
  Concepts, Ch. 10, friction torque: M_0 from lubricant viscosity and speed, M_1 = f_1 P_1 d_m with
  f_1 = z (P_0/C_0)^y). The empirical formula is stated in catalogue units (viscosity in mm^2/s,
  speed in r/min, d_m in mm, torque in N mm); the functions here convert from and to SI.
* a constant rolling-resistance coefficient, M = mu F R (SKF, *Rolling bearings* catalogue, 2013,
  "Estimating the frictional moment": M = 0.5 mu P d with the bore d, Table 1 for mu).

The sliding contact between the journal and the inner race dissipates mu F_n |v_slip|; its share
per body follows the Blok/Jaeger fast-moving-source partition (Charron's effusivity split as the
equal-speed case).
"""

from __future__ import annotations

import math

from numba import njit

#: Constant friction coefficients of open (unsealed) ball bearings referred to the bore radius
#: (SKF, Rolling bearings catalogue 2013, "Estimating the frictional moment", Table 1; valid for
#: P/C about 0.1, good lubrication and normal operating conditions).
SKF_FRICTION_COEFFICIENT = {
    "deep_groove": 0.0015,
    "angular_contact": 0.0020,
    "four_point": 0.0024,
}

#: Palmgren's viscous term in catalogue units: M_0 = 1e-7 f_0 (nu n)^(2/3) d_m^3 [N mm] for
#: nu n >= 2000 (nu in mm^2/s, n in r/min, d_m in mm), else M_0 = 160e-7 f_0 d_m^3 (Harris &
#: Kotzalas 2007, Essential Concepts, Ch. 10).
PALMGREN_VISCOUS_SCALE = 1e-7
PALMGREN_LOW_SPEED_PRODUCT = 2000.0
PALMGREN_LOW_SPEED_SCALE = 160e-7

_M2S_TO_MM2S = 1e6  # kinematic viscosity m^2/s -> mm^2/s (cSt)
_RADS_TO_RPM = 30.0 / math.pi
_M_TO_MM = 1e3
_NMM_TO_NM = 1e-3


@njit(cache=True)
def palmgren_viscous_torque(kinematic_viscosity, speed, pitch_diameter, lubrication_factor):
    """Speed-dependent friction torque M_0 of a rolling bearing [N m] (Palmgren).

    M_0 = 1e-7 f_0 (nu n)^(2/3) d_m^3 for nu n >= 2000, 160e-7 f_0 d_m^3 below, in N mm with nu in
    mm^2/s, n in r/min and d_m in mm (Harris & Kotzalas 2007, Essential Concepts, Ch. 10). Harris
    tabulates f_0 by bearing type and lubrication method (roughly 0.7 to 4 for ball bearings). The
    low-speed branch does not vanish at n = 0: it is a running torque, not a breakaway model.

    Parameters
    ----------
    kinematic_viscosity : float
        nu of the oil (the base oil for grease) at operating temperature [m^2/s].
    speed : float
        Relative speed of the rings [rad/s]; the sign is ignored.
    pitch_diameter : float
        d_m [m].
    lubrication_factor : float
        f_0 [-].

    Returns
    -------
    float
        M_0 [N m], >= 0.

    Examples
    --------
    >>> round(palmgren_viscous_torque(32e-6, 1047.2, 25.5e-3, 2.0), 6)
    0.015515
    """
    product = kinematic_viscosity * _M2S_TO_MM2S * abs(speed) * _RADS_TO_RPM
    dm_cubed = (pitch_diameter * _M_TO_MM) ** 3
    if product >= PALMGREN_LOW_SPEED_PRODUCT:
        torque = PALMGREN_VISCOUS_SCALE * lubrication_factor * product ** (2.0 / 3.0) * dm_cubed
    else:
        torque = PALMGREN_LOW_SPEED_SCALE * lubrication_factor * dm_cubed
    return torque * _NMM_TO_NM


@njit(cache=True)
def palmgren_load_factor(scale, exponent, static_equivalent_load, static_load_rating):
    """Palmgren's load factor f_1 = z (P_0 / C_0)^y [-] (Harris & Kotzalas 2007, Essential Concepts, Ch. 10).

    Parameters
    ----------
    scale : float
        z [-], from Harris's table for the bearing type.
    exponent : float
        y [-], from the same table.
    static_equivalent_load : float
        P_0 [N], >= 0.
    static_load_rating : float
        C_0 [N], > 0.

    Returns
    -------
    float
        f_1 [-].

    Examples
    --------
    >>> round(palmgren_load_factor(0.001, 0.33, 300.0, 3000.0), 6)
    0.000468
    """
    return scale * (static_equivalent_load / static_load_rating) ** exponent


@njit(cache=True)
def palmgren_load_torque(load_factor, friction_load, pitch_diameter):
    """Load-dependent friction torque M_1 = f_1 P_1 d_m [N m] (Harris & Kotzalas 2007, Essential Concepts, Ch. 10).

    Parameters
    ----------
    load_factor : float
        f_1 [-] (:func:`palmgren_load_factor`).
    friction_load : float
        P_1 [N], the load combination Harris gives for the bearing type; the sign is ignored.
    pitch_diameter : float
        d_m [m].

    Returns
    -------
    float
        M_1 [N m].

    Examples
    --------
    >>> round(palmgren_load_torque(0.000468, 500.0, 25.5e-3), 6)
    0.005967
    """
    return load_factor * abs(friction_load) * pitch_diameter


@njit(cache=True)
def palmgren_torque(kinematic_viscosity, speed, pitch_diameter, lubrication_factor, load_factor, friction_load):
    """Total running friction torque M = M_0 + M_1 [N m] (Harris & Kotzalas 2007, Essential Concepts, Ch. 10).

    Parameters
    ----------
    kinematic_viscosity, speed, pitch_diameter, lubrication_factor
        As in :func:`palmgren_viscous_torque` ([m^2/s], [rad/s], [m], [-]).
    load_factor, friction_load
        As in :func:`palmgren_load_torque` ([-], [N]).

    Returns
    -------
    float
        M [N m].

    Examples
    --------
    >>> round(palmgren_torque(32e-6, 1047.2, 25.5e-3, 2.0, 0.000468, 500.0), 6)
    0.021482
    """
    return (palmgren_viscous_torque(kinematic_viscosity, speed, pitch_diameter, lubrication_factor)
            + palmgren_load_torque(load_factor, friction_load, pitch_diameter))


@njit(cache=True)
def rolling_resistance_torque(coefficient, load, radius):
    """Friction torque from a constant rolling-resistance coefficient, M = mu F R [N m].

    SKF's estimate M = 0.5 mu P d (Rolling bearings catalogue 2013, "Estimating the frictional
    moment") with R = d/2 the bore radius and mu from :data:`SKF_FRICTION_COEFFICIENT`.

    Parameters
    ----------
    coefficient : float
        mu [-].
    load : float
        Bearing load F [N] (radial, or the equivalent load P); the sign is ignored.
    radius : float
        R [m] the coefficient refers to (the bore radius for SKF's values).

    Returns
    -------
    float
        M [N m].

    Examples
    --------
    >>> round(rolling_resistance_torque(0.0024, 1000.0, 7.5e-3), 6)
    0.018
    """
    return coefficient * abs(load) * radius


@njit(cache=True)
def friction_power(torque, speed):
    """Power dissipated by a friction torque at a relative speed, |M omega| [W].

    Parameters
    ----------
    torque : float
        M [N m].
    speed : float
        Relative angular speed omega [rad/s].

    Returns
    -------
    float
        P [W].

    Examples
    --------
    >>> friction_power(0.02, -1000.0)
    20.0
    """
    return abs(torque * speed)


@njit(cache=True)
def sliding_friction_power(friction_coefficient, normal_force, slip_speed):
    """Heat generated by Coulomb sliding, mu F_n |v_slip| [W] (frictional work rate).

    Parameters
    ----------
    friction_coefficient : float
        mu [-].
    normal_force : float
        F_n [N], >= 0.
    slip_speed : float
        Relative surface speed at the contact [m/s].

    Returns
    -------
    float
        P [W].

    Examples
    --------
    >>> round(sliding_friction_power(0.2, 500.0, 12.5), 9)
    1250.0
    """
    return friction_coefficient * normal_force * abs(slip_speed)


@njit(cache=True)
def effusivity(conductivity, density, specific_heat):
    """Thermal effusivity e = sqrt(k rho c) [W s^(1/2)/(m^2 K)] (Incropera et al. 2007, Sec. 5.7).

    Parameters
    ----------
    conductivity : float
        k [W/(m K)].
    density : float
        rho [kg/m^3].
    specific_heat : float
        c [J/(kg K)].

    Returns
    -------
    float
        e.

    Examples
    --------
    >>> round(effusivity(46.6, 7810.0, 475.0))
    13148
    """
    return math.sqrt(conductivity * density * specific_heat)


@njit(cache=True)
def heat_partition(effusivity_1, surface_speed_1, effusivity_2, surface_speed_2):
    """Share of sliding friction heat that enters body 1 [-], Blok/Jaeger fast-source partition.

    When both surfaces move through the contact fast (Peclet numbers V a / (2 kappa) above about 5),
    the mean flash temperature of body i is proportional to q_i / (e_i sqrt(V_i)) (Jaeger, "Moving
    sources of heat and the temperature at sliding contacts", Proc. Roy. Soc. N.S.W. 76, 1942, 203-224;
    Blok, Proc. General Discussion on Lubrication, IMechE 1937, vol. 2, 222-235). Equal mean
    temperatures give share_1 = e_1 sqrt(V_1) / (e_1 sqrt(V_1) + e_2 sqrt(V_2)). With equal speeds, or
    both at rest, it is Charron's effusivity partition e_1 / (e_1 + e_2) (Charron, "Partage de la
    chaleur entre deux corps frottants", Publ. Sci. Tech. Ministere de l'Air 182, 1943).
    A body nearly at rest (Peclet below about 1) is outside the fast-source range: there this form
    gives it too small a share.

    Parameters
    ----------
    effusivity_1, effusivity_2 : float
        e = sqrt(k rho c) of the two bodies (:func:`effusivity`).
    surface_speed_1, surface_speed_2 : float
        Speed of each surface relative to the contact [m/s]; the sign is ignored.

    Returns
    -------
    float
        Share of the heat into body 1, in [0, 1]; body 2 takes the rest.

    Examples
    --------
    >>> heat_partition(13000.0, 0.0, 13000.0, 0.0)
    0.5
    >>> round(heat_partition(13000.0, 100.0, 13000.0, 25.0), 4)
    0.6667
    """
    w1 = effusivity_1 * math.sqrt(abs(surface_speed_1))
    w2 = effusivity_2 * math.sqrt(abs(surface_speed_2))
    if w1 + w2 <= 0.0:
        return effusivity_1 / (effusivity_1 + effusivity_2)
    return w1 / (w1 + w2)


@njit(cache=True)
def peclet_number(surface_speed, half_width, diffusivity):
    """Peclet number L = V a / (2 kappa) of a moving heat source [-] (Jaeger 1942's parameter).

    Parameters
    ----------
    surface_speed : float
        V [m/s].
    half_width : float
        Contact half-width a along the motion [m].
    diffusivity : float
        kappa = k / (rho c) [m^2/s].

    Returns
    -------
    float
        L [-].

    Examples
    --------
    >>> round(peclet_number(50.0, 1e-4, 12.6e-6), 1)
    198.4
    """
    return abs(surface_speed) * half_width / (2.0 * diffusivity)
