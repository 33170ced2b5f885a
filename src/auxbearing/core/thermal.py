"""Lumped thermal network of a touchdown plane, thermal growth and heat partition (SI, no units).

The network is linear: nodes with heat capacities C_i [J/K], a symmetric matrix of conductances
G_ij [W/K] between nodes (diagonal ignored), a conductance Ga_i [W/K] from each node to an ambient
held at T_a, and heat inputs Q_i [W]. Each node obeys the lumped-capacitance energy balance
(Incropera et al., *Fundamentals of Heat and Mass Transfer*, 6th ed. 2007, Sec. 5.1-5.3, Eq. 5.2
applied node by node, the thermal-circuit form of Sec. 3.1):

    C_i dT_i/dt = Q_i - sum_j G_ij (T_i - T_j) - Ga_i (T_i - T_a).

With theta = T - T_a and the weighted Laplacian L (L_ii = sum_j G_ij + Ga_i, L_ij = -G_ij) this is
C dtheta/dt = Q - L theta. For heat inputs held constant over a step the solution is exact: with
y = C^(1/2) theta the matrix A = C^(-1/2) L C^(-1/2) is symmetric positive semi-definite, A = V diag(lam)
V^T (numpy's eigh), and each mode relaxes as z(t) = z0 exp(-lam t) + q (1 - exp(-lam t)) / lam.

Growth relations: free thermal expansion of each part (alpha R dT), the journal/race radial
clearance and the bearing's diametral clearance from the raceway and ball diameters (Harris &
Kotzalas, *Rolling Bearing Analysis*, 5th ed. 2007, Essential Concepts, Ch. 3, "Differential
expansion").
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

#: Stefan-Boltzmann constant [W/(m^2 K^4)] (CODATA 2018, exact in the 2019 SI).
STEFAN_BOLTZMANN = 5.670374419e-8

#: Below this lam*dt the step factors use their Taylor series: the closed forms lose digits to
#: cancellation there, while three series terms are exact to below 1e-16 relative.
_SERIES_BELOW = 1e-4


@njit(cache=True)
def laplacian(conductances, ambient_conductances):
    """Weighted Laplacian L of the network [W/K] (Incropera et al. 2007, Sec. 3.1 thermal circuits).

    Parameters
    ----------
    conductances : ndarray, shape (n, n)
        Symmetric node-to-node conductances G_ij [W/K]; the diagonal is ignored.
    ambient_conductances : ndarray, shape (n,)
        Conductance of each node to ambient Ga_i [W/K].

    Returns
    -------
    ndarray, shape (n, n)
        L_ii = sum_j G_ij + Ga_i, L_ij = -G_ij [W/K].

    Examples
    --------
    >>> laplacian(np.array([[0.0, 2.0], [2.0, 0.0]]), np.array([1.0, 0.0]))
    array([[ 3., -2.],
           [-2.,  2.]])
    """
    n = ambient_conductances.shape[0]
    out = np.zeros((n, n))
    for i in range(n):
        out[i, i] = ambient_conductances[i]
        for j in range(n):
            if j != i:
                out[i, j] = -conductances[i, j]
                out[i, i] += conductances[i, j]
    return out


@njit(cache=True)
def temperature_rate(temperatures, capacities, conductances, ambient_conductances, heat, ambient_temperature):
    """Node temperature rates dT/dt [K/s] of the lumped network (module docstring equation).

    Parameters
    ----------
    temperatures : ndarray, shape (n,)
        Node temperatures T [K].
    capacities : ndarray, shape (n,)
        Heat capacities C [J/K], > 0.
    conductances, ambient_conductances : ndarray
        G (n, n) and Ga (n,) [W/K], as in :func:`laplacian`.
    heat : ndarray, shape (n,)
        Heat input Q [W].
    ambient_temperature : float
        T_a [K].

    Returns
    -------
    ndarray, shape (n,)
        dT/dt [K/s].

    Examples
    --------
    >>> temperature_rate(np.array([300.0]), np.array([10.0]), np.zeros((1, 1)), np.array([2.0]),
    ...                  np.array([5.0]), 295.0)
    array([-0.5])
    """
    lap = laplacian(conductances, ambient_conductances)
    theta = temperatures - ambient_temperature
    return (heat - lap @ theta) / capacities


@njit(cache=True)
def decompose(capacities, conductances, ambient_conductances):
    """Eigen-decomposition of A = C^(-1/2) L C^(-1/2) for :func:`step_decomposed`.

    Parameters
    ----------
    capacities, conductances, ambient_conductances : ndarray
        C [J/K], G [W/K], Ga [W/K] as in :func:`temperature_rate`.

    Returns
    -------
    rates : ndarray, shape (n,)
        Eigenvalues lam [1/s], >= 0 (clipped at 0 against round-off).
    modes : ndarray, shape (n, n)
        Orthonormal eigenvectors V (columns).
    root_capacities : ndarray, shape (n,)
        C^(1/2) [(J/K)^(1/2)].

    Examples
    --------
    >>> lam, v, rc = decompose(np.array([10.0]), np.zeros((1, 1)), np.array([2.0]))
    >>> round(float(lam[0]), 12)
    0.2
    """
    root = np.sqrt(capacities)
    lap = laplacian(conductances, ambient_conductances)
    sym = lap / np.outer(root, root)
    sym = 0.5 * (sym + sym.T)
    rates, modes = np.linalg.eigh(sym)
    return np.maximum(rates, 0.0), modes, root


@njit(cache=True)
def _step_factors(rate, dt):
    """(exp(-lam dt), (1 - exp(-lam dt))/lam, (dt - (1 - exp(-lam dt))/lam)/lam), with lam -> 0 limits."""
    x = rate * dt
    if x < _SERIES_BELOW:
        decay = 1.0 - x + 0.5 * x * x
        relax = dt * (1.0 - 0.5 * x + x * x / 6.0)
        lag = dt * dt * (0.5 - x / 6.0 + x * x / 24.0)
    else:
        decay = math.exp(-x)
        relax = -math.expm1(-x) / rate
        lag = (dt - relax) / rate
    return decay, relax, lag


@njit(cache=True)
def step_decomposed(temperatures, heat, ambient_temperature, dt, rates, modes, root_capacities):
    """Exact step of the network over dt with constant heat input, from a :func:`decompose` result.

    Parameters
    ----------
    temperatures : ndarray, shape (n,)
        T at the start [K].
    heat : ndarray, shape (n,)
        Q [W], constant over the step.
    ambient_temperature : float
        T_a [K].
    dt : float
        Step [s], >= 0.
    rates, modes, root_capacities
        From :func:`decompose`.

    Returns
    -------
    new_temperatures : ndarray, shape (n,)
        T at the end of the step [K].
    mean_temperatures : ndarray, shape (n,)
        Time average of T over the step [K]; Ga (T_mean - T_a) dt is the heat lost to ambient.

    Examples
    --------
    >>> lam, v, rc = decompose(np.array([10.0]), np.zeros((1, 1)), np.array([1.0]))
    >>> t, tm = step_decomposed(np.array([0.0]), np.array([1.0]), 0.0, 10.0, lam, v, rc)
    >>> round(float(t[0]), 6), round(float(tm[0]), 6)
    (0.632121, 0.367879)
    """
    z0 = modes.T @ ((temperatures - ambient_temperature) * root_capacities)
    q = modes.T @ (heat / root_capacities)
    z1 = np.empty_like(z0)
    zint = np.empty_like(z0)
    for k in range(z0.shape[0]):
        decay, relax, lag = _step_factors(rates[k], dt)
        z1[k] = z0[k] * decay + q[k] * relax
        zint[k] = z0[k] * relax + q[k] * lag
    new = ambient_temperature + (modes @ z1) / root_capacities
    if dt > 0.0:
        mean = ambient_temperature + (modes @ zint) / (root_capacities * dt)
    else:
        mean = new.copy()
    return new, mean


@njit(cache=True)
def exact_step(temperatures, capacities, conductances, ambient_conductances, heat, ambient_temperature, dt):
    """Exact step over dt for constant heat input (decomposes the network on every call).

    Parameters
    ----------
    temperatures, capacities, conductances, ambient_conductances, heat, ambient_temperature
        As in :func:`temperature_rate`.
    dt : float
        Step [s].

    Returns
    -------
    new_temperatures, mean_temperatures : ndarray
        As in :func:`step_decomposed` [K].

    Examples
    --------
    >>> t, _ = exact_step(np.array([293.15]), np.array([10.0]), np.zeros((1, 1)), np.array([1.0]),
    ...                   np.array([1.0]), 293.15, 1e9)
    >>> round(float(t[0]) - 293.15, 9)
    1.0
    """
    rates, modes, root = decompose(capacities, conductances, ambient_conductances)
    return step_decomposed(temperatures, heat, ambient_temperature, dt, rates, modes, root)


@njit(cache=True)
def steady_state(conductances, ambient_conductances, heat, ambient_temperature):
    """Steady temperatures T = T_a + L^(-1) Q [K] (module docstring equation with dT/dt = 0).

    Every node needs a conductive path to ambient, or L is singular and numpy raises.

    Parameters
    ----------
    conductances, ambient_conductances, heat, ambient_temperature
        G [W/K], Ga [W/K], Q [W], T_a [K] as in :func:`temperature_rate`.

    Returns
    -------
    ndarray, shape (n,)
        Steady T [K].

    Examples
    --------
    >>> steady_state(np.array([[0.0, 2.0], [2.0, 0.0]]), np.array([1.0, 0.0]), np.array([0.0, 4.0]), 300.0)
    array([304., 306.])
    """
    return ambient_temperature + np.linalg.solve(laplacian(conductances, ambient_conductances), heat)


@njit(cache=True)
def radial_growth(expansion, radius, temperature_rise):
    """Free radial growth of a ring or shaft at uniform temperature, alpha R dT [m].

    Linear thermal strain alpha dT of an unconstrained isotropic body (Incropera et al. 2007 define
    alpha in Sec. 2.2; Harris & Kotzalas 2007, Essential Concepts Ch. 3 use it for ring growth).

    Parameters
    ----------
    expansion, radius, temperature_rise : float
        alpha [1/K], R [m], dT [K].

    Examples
    --------
    >>> round(radial_growth(11.9e-6, 7.5e-3, 100.0) * 1e6, 4)
    8.925
    """
    return expansion * radius * temperature_rise


@njit(cache=True)
def journal_clearance_change(ring_expansion, bore_radius, ring_rise, journal_expansion, journal_radius, journal_rise):
    """Change of the journal/inner-race radial clearance c = R_bore - R_journal [m].

    dc = alpha_ring R_bore dT_ring - alpha_journal R_journal dT_journal: the free ring's bore and the
    journal both grow as in :func:`radial_growth` (Harris & Kotzalas 2007, Essential Concepts, Ch. 3,
    differential expansion).

    Parameters
    ----------
    ring_expansion, bore_radius, ring_rise : float
        Inner ring: alpha [1/K], bore radius [m], temperature rise [K].
    journal_expansion, journal_radius, journal_rise : float
        Journal: alpha [1/K], radius [m], temperature rise [K].

    Examples
    --------
    >>> round(journal_clearance_change(12.3e-6, 7.5e-3, 20.0, 11.5e-6, 7.3e-3, 80.0) * 1e6, 3)
    -4.871
    """
    return ring_expansion * bore_radius * ring_rise - journal_expansion * journal_radius * journal_rise


@njit(cache=True)
def diametral_clearance_change(
    inner_expansion, inner_raceway_diameter, inner_rise,
    outer_expansion, outer_raceway_diameter, outer_rise,
    ball_expansion, ball_diameter, ball_rise,
):
    """Change of the diametral clearance Pd = d_o - d_i - 2 D from free thermal growth [m].

    dPd = alpha_o d_o dT_o - alpha_i d_i dT_i - 2 alpha_b D dT_b (Harris & Kotzalas 2007, Essential
    Concepts, Ch. 3, differential expansion, with each raceway and ball growing freely). With one
    alpha for all parts and the inner ring and balls at one temperature it reduces to
    -alpha d_o (dT_i - dT_o) + alpha Pd dT_i, the catalogue rule "reduction = alpha dt x outer-ring
    bore" (IKO, Needle Roller Bearings catalogue, Eq. 29).

    Parameters
    ----------
    inner_expansion, outer_expansion, ball_expansion : float
        alpha of inner ring, outer ring, balls [1/K].
    inner_raceway_diameter, outer_raceway_diameter : float
        d_i, d_o groove-bottom diameters [m].
    ball_diameter : float
        D [m].
    inner_rise, outer_rise, ball_rise : float
        Temperature rises [K].

    Returns
    -------
    float
        dPd [m]; negative when the clearance closes (towards preload).

    Examples
    --------
    >>> round(diametral_clearance_change(11.9e-6, 19.5e-3, 30.0, 11.9e-6, 31.5e-3, 10.0,
    ...                                  11.9e-6, 6e-3, 30.0) * 1e6, 3)
    -7.497
    """
    return (outer_expansion * outer_raceway_diameter * outer_rise
            - inner_expansion * inner_raceway_diameter * inner_rise
            - 2.0 * ball_expansion * ball_diameter * ball_rise)


@njit(cache=True)
def _elliptic_k_of_ratio(ratio):
    """K(e) with e^2 = 1 - ratio^2 by the arithmetic-geometric mean, K = pi / (2 AGM(1, ratio)).

    Abramowitz & Stegun (1964) 17.6; fed the axis ratio b/a directly so thin ellipses keep digits.
    """
    a = 1.0
    b = ratio
    for _ in range(60):
        if abs(a - b) <= 1e-15 * a:
            break
        a, b = 0.5 * (a + b), math.sqrt(a * b)
    return 0.5 * math.pi / a


@njit(cache=True)
def constriction_resistance(semi_major, semi_minor, conductivity):
    """Constriction resistance of an isothermal elliptic contact spot on a half-space [K/W].

    R = K(e) / (2 pi k a), e^2 = 1 - (b/a)^2, K the complete elliptic integral of the first kind
    (Yovanovich & Marotta, "Thermal spreading and contact resistances", in Bejan & Kraus (eds.),
    *Heat Transfer Handbook*, Wiley 2003, Ch. 4, elliptic contact areas on a half-space). For a
    circle K = pi/2 and R = 1/(4 k a), Holm's result (Holm, *Electric Contacts*, 4th ed. 1967, Sec. 4).
    Each body of a Hertz contact adds its own R; see :func:`contact_conductance`.

    Parameters
    ----------
    semi_major : float
        a [m], > 0.
    semi_minor : float
        b [m], 0 < b <= a.
    conductivity : float
        k of the body [W/(m K)].

    Examples
    --------
    >>> round(constriction_resistance(1e-3, 1e-3, 50.0), 6)
    5.0
    """
    return _elliptic_k_of_ratio(semi_minor / semi_major) / (2.0 * math.pi * conductivity * semi_major)


@njit(cache=True)
def contact_conductance(semi_major, semi_minor, conductivity_1, conductivity_2):
    """Conductance of one Hertz contact between two bodies, 1/(R_1 + R_2) [W/K].

    Series sum of the two half-space constriction resistances of :func:`constriction_resistance`
    (Yovanovich & Marotta 2003, Ch. 4); an unloaded contact (a = 0) conducts nothing.

    Parameters
    ----------
    semi_major, semi_minor : float
        Contact ellipse semi-axes a >= b [m].
    conductivity_1, conductivity_2 : float
        k of the two bodies [W/(m K)].

    Examples
    --------
    >>> round(contact_conductance(2e-4, 1e-4, 46.6, 42.6), 5)
    0.01297
    """
    if semi_major <= 0.0 or semi_minor <= 0.0:
        return 0.0
    return 1.0 / (constriction_resistance(semi_major, semi_minor, conductivity_1)
                  + constriction_resistance(semi_major, semi_minor, conductivity_2))


@njit(cache=True)
def shell_resistance(inner_radius, outer_radius, length, conductivity):
    """Radial conduction resistance of a cylindrical shell, ln(r2/r1) / (2 pi k L) [K/W].

    Incropera et al. (2007) Eq. 3.28 (Table 3.3, cylindrical wall).

    Parameters
    ----------
    inner_radius, outer_radius, length : float
        r1 <= r2 and L [m].
    conductivity : float
        k [W/(m K)].

    Examples
    --------
    >>> round(shell_resistance(7.5e-3, 9.75e-3, 11e-3, 42.6), 5)
    0.08911
    """
    return math.log(outer_radius / inner_radius) / (2.0 * math.pi * conductivity * length)
