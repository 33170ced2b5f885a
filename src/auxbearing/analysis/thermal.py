"""Lumped thermal network of one touchdown plane, built from a bearing's geometry and materials.

Nodes (:data:`NODE_NAMES`): the rotor journal under the bearing, inner race, all balls together,
outer race and housing; ambient is held at a fixed temperature. Heat paths:

* ball/raceway: the loaded Hertz contacts, each two half-space constriction resistances of an
  elliptic spot (:func:`auxbearing.core.thermal.contact_conductance`), in series with half the
  ring's radial shell resistance. The contact size follows the load, so this path is rebuilt with
  :meth:`ThermalNetwork.with_contact_loads` as the loads change;
* outer race/housing: half shell of each in series with the fit interface's contact resistance
  (:data:`FIT_CONTACT_RESISTANCE`);
* journal/inner race: nothing by default (they touch only intermittently; the sliding heat is split
  between them by :func:`auxbearing.core.bearing_friction.heat_partition`);
* housing and journal to ambient: natural convection (Churchill & Chu), the rotating-cylinder
  correlation for the journal, optional linearised radiation, user conductances; no convection in
  vacuum. The ring faces inside the machine are not given an ambient path.

Ring masses are the rectangular sections bore-to-groove-bottom (inner) and groove-bottom-to-outside
(outer) over the full width: lands above the groove bottom are left out, so ring masses are low by
roughly the land volume; pass ``inner_race_mass`` / ``outer_race_mass`` from a catalogue to replace
them. Kernels: :mod:`auxbearing.core.thermal`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from auxbearing.analysis.contact import raceway_contact
from auxbearing.bearings.geometry import BearingGeometry
from auxbearing.bearings.materials import Material, check_positive, get_material
from auxbearing.common.errors import InputError
from auxbearing.core import thermal as kernel
from auxbearing.core.bearing_friction import effusivity, heat_partition

NODE_NAMES = ("journal", "inner_race", "balls", "outer_race", "housing")
JOURNAL, INNER_RACE, BALLS, OUTER_RACE, HOUSING = range(5)

# Dry air at 300 K and 1 atm (Incropera et al., Fundamentals of Heat and Mass Transfer, 6th ed.
# 2007, Table A.4): conductivity [W/(m K)], kinematic viscosity and diffusivity [m^2/s], Prandtl [-].
AIR_CONDUCTIVITY = 0.0263
AIR_KINEMATIC_VISCOSITY = 15.89e-6
AIR_DIFFUSIVITY = 22.5e-6
AIR_PRANDTL = 0.707
#: Standard acceleration of gravity [m/s^2] (3rd CGPM, 1901).
STANDARD_GRAVITY = 9.80665
#: Rotating cylinder in still air, Nu_D = 0.133 Re_D^(2/3) Pr^(1/3), Re_D = omega D^2 / nu below 4.3e5
#: (correlation of Kays & Bjorklund, Trans. ASME 80, 1958, 70-78, in the form quoted by Incropera et
#: al. 2007 among the Ch. 7 problems).
ROTATING_CYLINDER_COEFFICIENT = 0.133
ROTATING_CYLINDER_REYNOLDS_LIMIT = 4.3e5
#: Thermal contact resistance of a metal fit interface [m^2 K/W]: middle of the range 6-25e-4 for
#: stainless steel at 100 kPa contact pressure in vacuum (Incropera et al. 2007, Table 3.1a); a
#: low-pressure, poor-conductor value, so it errs towards a hot bearing.
FIT_CONTACT_RESISTANCE = 15.5e-4
#: Ambient default: 20 degC, the ISO 1 reference temperature for dimensional measurements [K].
REFERENCE_AMBIENT = 293.15
#: Surface-to-ambient temperature difference at which the nonlinear convection and radiation
#: coefficients are linearised [K]; a modelling choice, not a measured value (h varies as dT^(1/4)
#: or weaker, so a factor 2 error in dT moves h by under 20 %).
LINEARISATION_RISE = 20.0


def natural_convection_coefficient(diameter: float, temperature_rise: float,
                                   ambient_temperature: float = REFERENCE_AMBIENT) -> float:
    """Natural convection from a horizontal cylinder in air [W/(m^2 K)], Churchill & Chu.

    Nu_D = {0.60 + 0.387 Ra_D^(1/6) / [1 + (0.559/Pr)^(9/16)]^(8/27)}^2 for Ra_D <= 1e12 (Incropera
    et al. 2007, Eq. 9.34), Ra_D = g beta dT D^3 / (nu alpha), beta = 1/T_film for an ideal gas.

    Parameters
    ----------
    diameter, temperature_rise, ambient_temperature : float
        D [m], surface minus ambient [K] (>= 0), T_a [K].

    Examples
    --------
    >>> round(natural_convection_coefficient(0.055, 20.0), 2)
    4.99
    """
    film = ambient_temperature + 0.5 * temperature_rise
    rayleigh = (STANDARD_GRAVITY * abs(temperature_rise) / film * diameter**3
                / (AIR_KINEMATIC_VISCOSITY * AIR_DIFFUSIVITY))
    shape = (1.0 + (0.559 / AIR_PRANDTL) ** (9.0 / 16.0)) ** (8.0 / 27.0)
    nusselt = (0.60 + 0.387 * rayleigh ** (1.0 / 6.0) / shape) ** 2
    return nusselt * AIR_CONDUCTIVITY / diameter


def rotating_cylinder_coefficient(diameter: float, speed: float) -> float:
    """Convection from a cylinder spinning in still air [W/(m^2 K)] (:data:`ROTATING_CYLINDER_COEFFICIENT`).

    Above Re_D = 4.3e5 the correlation is used at its limit (the coefficient is then an underestimate).

    Parameters
    ----------
    diameter, speed : float
        D [m], spin speed omega [rad/s].

    Examples
    --------
    >>> round(rotating_cylinder_coefficient(0.015, 1047.2), 1)
    125.4
    """
    reynolds = min(abs(speed) * diameter**2 / AIR_KINEMATIC_VISCOSITY, ROTATING_CYLINDER_REYNOLDS_LIMIT)
    nusselt = ROTATING_CYLINDER_COEFFICIENT * reynolds ** (2.0 / 3.0) * AIR_PRANDTL ** (1.0 / 3.0)
    return nusselt * AIR_CONDUCTIVITY / diameter


def radiation_coefficient(emissivity: float, surface_temperature: float, ambient_temperature: float) -> float:
    """Linearised radiation coefficient eps sigma (T_s + T_a)(T_s^2 + T_a^2) [W/(m^2 K)] (Incropera Eq. 1.9).

    Parameters
    ----------
    emissivity : float
        eps of the surface [-], in [0, 1]; the surroundings are large and black.
    surface_temperature, ambient_temperature : float
        T_s, T_a [K].

    Examples
    --------
    >>> round(radiation_coefficient(0.8, 313.15, 293.15), 2)
    5.06
    """
    ts, ta = surface_temperature, ambient_temperature
    return emissivity * kernel.STEFAN_BOLTZMANN * (ts + ta) * (ts * ts + ta * ta)


def ball_race_conductance(bearing: BearingGeometry, contact_loads, race: str) -> float:
    """Summed conductance of the ball/raceway contacts of one race [W/K] (contacts in parallel).

    Each contact's ellipse comes from the Hertz solution at its load (source paper Eq. 4-5) and
    conducts :func:`auxbearing.core.thermal.contact_conductance`; unloaded contacts conduct nothing.

    Parameters
    ----------
    bearing : BearingGeometry
    contact_loads : array_like
        Load on each ball/raceway contact of this race [N], >= 0.
    race : {"inner", "outer"}

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> round(ball_race_conductance(get_bearing("QJ202"), [100.0] * 22, "inner"), 3)
    0.473
    """
    loads = np.atleast_1d(np.asarray(contact_loads, float))
    ring = bearing.ring_material.thermal_conductivity
    ball = bearing.ball_material.thermal_conductivity
    contact = raceway_contact(bearing, loads, race)
    return float(sum(kernel.contact_conductance(a, b, ball, ring)
                     for a, b in zip(np.ravel(contact.semi_major), np.ravel(contact.semi_minor), strict=True)))


@dataclass(frozen=True)
class ThermalNetwork:
    """A touchdown plane's thermal network and its thermal-growth data (all SI).

    ``capacities`` C [J/K], ``masses`` [kg], ``conductances`` G [W/K] (symmetric, zero diagonal),
    ``ambient_conductances`` [W/K] and ``expansion`` alpha [1/K] are indexed by :data:`NODE_NAMES`.
    ``paths`` names each conductance for reports. ``journal_heat_share`` is the Charron share of the
    sliding heat that enters the journal (equal surface speeds).

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> net = build_network(get_bearing("QJ202"), 7.4e-3, contact_load=100.0, housing_to_ambient=1.0,
    ...                     journal_to_ambient=0.5)
    >>> q = net.heat_inputs(sliding_power=20.0, bearing_power=2.0)
    >>> rise = net.steady_state(q) - net.ambient_temperature
    >>> [round(float(x), 1) for x in rise]
    [21.2, 70.1, 48.9, 26.6, 11.3]
    >>> [round(x * 1e6, 2) for x in net.clearance_changes(net.ambient_temperature + rise)]
    [4.66, -13.48]
    """

    capacities: np.ndarray
    masses: np.ndarray
    conductances: np.ndarray
    ambient_conductances: np.ndarray
    expansion: np.ndarray
    ambient_temperature: float
    journal_radius: float
    bore_radius: float
    inner_raceway_diameter: float
    outer_raceway_diameter: float
    ball_diameter: float
    journal_effusivity: float
    race_effusivity: float
    ball_heat_share: float
    vacuum: bool
    bearing: BearingGeometry = field(repr=False)
    inner_shell_resistance: float = 0.0
    outer_shell_resistance: float = 0.0
    paths: dict = field(default_factory=dict)
    node_names: tuple = NODE_NAMES

    @property
    def journal_heat_share(self) -> float:
        """Charron partition e_journal / (e_journal + e_race) [-] (core heat_partition, equal speeds)."""
        return heat_partition(self.journal_effusivity, 0.0, self.race_effusivity, 0.0)

    def kernel_args(self) -> tuple:
        """(C, G, Ga, T_a) for :mod:`auxbearing.core.thermal`."""
        return self.capacities, self.conductances, self.ambient_conductances, self.ambient_temperature

    def growth_args(self) -> np.ndarray:
        """[alpha_journal, alpha_inner, alpha_balls, alpha_outer, R_journal, R_bore, d_i, d_o, D] (SI)."""
        a = self.expansion
        return np.array([a[JOURNAL], a[INNER_RACE], a[BALLS], a[OUTER_RACE], self.journal_radius,
                         self.bore_radius, self.inner_raceway_diameter, self.outer_raceway_diameter,
                         self.ball_diameter])

    def clearance_changes(self, temperatures, reference_temperature: float | None = None) -> tuple[float, float]:
        """(change of journal/race radial clearance, change of diametral clearance) [m] at ``temperatures``.

        Rises are taken from ``reference_temperature`` (default: ambient), at which the clearances
        have their nominal values.
        """
        rise = np.asarray(temperatures, float) - (self.ambient_temperature if reference_temperature is None
                                                  else reference_temperature)
        a = self.expansion
        radial = kernel.journal_clearance_change(a[INNER_RACE], self.bore_radius, rise[INNER_RACE],
                                                 a[JOURNAL], self.journal_radius, rise[JOURNAL])
        diametral = kernel.diametral_clearance_change(
            a[INNER_RACE], self.inner_raceway_diameter, rise[INNER_RACE],
            a[OUTER_RACE], self.outer_raceway_diameter, rise[OUTER_RACE],
            a[BALLS], self.ball_diameter, rise[BALLS])
        return float(radial), float(diametral)

    def heat_inputs(self, sliding_power: float, bearing_power: float, journal_share: float | None = None) -> np.ndarray:
        """Heat input per node [W] from the sliding contact and the bearing's own friction.

        Sliding heat goes to journal and inner race by ``journal_share`` (default
        :attr:`journal_heat_share`). Bearing friction heat is taken half at the inner and half at
        the outer raceway contacts, each half split between ball and race by Charron's effusivity
        partition (:attr:`ball_heat_share`).
        """
        share = self.journal_heat_share if journal_share is None else journal_share
        q = np.zeros(len(NODE_NAMES))
        q[JOURNAL] = share * sliding_power
        q[INNER_RACE] = (1.0 - share) * sliding_power + 0.5 * (1.0 - self.ball_heat_share) * bearing_power
        q[OUTER_RACE] = 0.5 * (1.0 - self.ball_heat_share) * bearing_power
        q[BALLS] = self.ball_heat_share * bearing_power
        return q

    def steady_state(self, heat) -> np.ndarray:
        """Steady node temperatures [K] under constant heat input [W]; every node needs a path to ambient."""
        cut_off = [NODE_NAMES[i] for i in np.flatnonzero(~self._reaches_ambient())]
        if cut_off:
            raise InputError(f"no steady state: {', '.join(cut_off)} has no conductive path to ambient "
                             "(vacuum with no radiation, or an unloaded bearing); give housing_to_ambient, "
                             "journal_to_ambient, an emissivity or a contact load")
        return kernel.steady_state(self.conductances, self.ambient_conductances,
                                   np.asarray(heat, float), self.ambient_temperature)

    def _reaches_ambient(self) -> np.ndarray:
        reached = self.ambient_conductances > 0.0
        for _ in NODE_NAMES:
            reached = reached | ((self.conductances > 0.0) & reached[None, :]).any(axis=1)
        return reached

    def step(self, temperatures, heat, dt: float) -> np.ndarray:
        """Node temperatures [K] after an exact step dt [s] with constant heat input [W]."""
        new, _ = kernel.exact_step(np.asarray(temperatures, float), self.capacities, self.conductances,
                                   self.ambient_conductances, np.asarray(heat, float), self.ambient_temperature, dt)
        return new

    def with_contact_loads(self, inner_loads, outer_loads) -> ThermalNetwork:
        """A copy whose ball/raceway paths follow the given contact loads [N] (one entry per contact)."""
        g = self.conductances.copy()
        paths = dict(self.paths)
        for race, loads, node, shell in (("inner", inner_loads, INNER_RACE, self.inner_shell_resistance),
                                         ("outer", outer_loads, OUTER_RACE, self.outer_shell_resistance)):
            contacts = ball_race_conductance(self.bearing, loads, race)
            value = 1.0 / (1.0 / contacts + shell) if contacts > 0.0 else 0.0
            g[node, BALLS] = g[BALLS, node] = value
            paths[f"balls-{race}_race"] = value
        return replace(self, conductances=g, paths=paths)


def _thermal_material(value: Material | str, purpose: str) -> Material:
    material = get_material(value) if isinstance(value, str) else value
    material.require_thermal(purpose)
    return material


def _annulus_volume(inner_radius: float, outer_radius: float, length: float) -> float:
    return math.pi * (outer_radius**2 - inner_radius**2) * length


def build_network(
    bearing: BearingGeometry,
    journal_radius: float,
    *,
    contact_load: float = 0.0,
    loaded_balls: int | None = None,
    journal_material: Material | str = "steel",
    journal_length: float | None = None,
    journal_bore_radius: float = 0.0,
    housing_material: Material | str = "steel",
    housing_outer_diameter: float | None = None,
    housing_length: float | None = None,
    housing_mass: float | None = None,
    inner_race_mass: float | None = None,
    outer_race_mass: float | None = None,
    housing_to_ambient: float | None = None,
    journal_to_ambient: float = 0.0,
    convection_coefficient: float | None = None,
    vacuum: bool = False,
    emissivity: float = 0.0,
    rotor_speed: float = 0.0,
    ambient_temperature: float = REFERENCE_AMBIENT,
    fit_contact_resistance: float = FIT_CONTACT_RESISTANCE,
    journal_race_conductance: float = 0.0,
    rows: int = 1,
    set_width: float | None = None,
) -> ThermalNetwork:
    """Build the lumped network of one touchdown plane (module docstring lists the paths).

    Parameters
    ----------
    bearing : BearingGeometry
        Needs bore, outside_diameter, width and thermal data of both materials.
    journal_radius : float
        Rotor journal radius [m], at most the bore radius.
    contact_load, loaded_balls : float, int
        Load [N] on each ball/raceway contact of ``loaded_balls`` balls (default all; ``pairs_per_ball``
        contacts per race each) sizing the contact ellipses; 0 N leaves the balls without a path.
    journal_material, housing_material : Material or str
        Default the catalogue ``steel``.
    journal_length, journal_bore_radius : float
        Rotor length lumped into the journal node (default the bearing width) and bore of a hollow rotor [m].
    housing_outer_diameter, housing_length : float, optional
        Default housing: a ring around the bearing with a wall as thick as the bearing section
        ((outside diameter - bore) / 2) and as wide as the bearing [m].
    housing_mass, inner_race_mass, outer_race_mass : float, optional
        Replace the envelope masses [kg].
    housing_to_ambient, journal_to_ambient : float
        Housing conductance to ambient replacing convection and radiation; extra journal conductance
        to ambient, e.g. into the rest of the rotor [W/K].
    convection_coefficient : float, optional
        h for journal and housing instead of the correlations [W/(m^2 K)]; ignored in vacuum.
    vacuum : bool
        No convection at all.
    emissivity : float
        Surface emissivity for radiation to ambient [-]; 0 turns radiation off.
    rotor_speed : float
        Spin speed for the journal's convection coefficient [rad/s].
    ambient_temperature : float
        [K].
    fit_contact_resistance : float
        Outer ring/housing interface resistance [m^2 K/W].
    journal_race_conductance : float
        Journal/inner-race conductance [W/K].
    rows, set_width : int, float
        A matched set of ``rows`` of ``bearing`` side by side, ``set_width`` wide [m] (spacer included): its rings
        are lumped as one ring of that width, its balls as one node of every row's balls, and every row's
        contacts carry heat between them (default one bearing, its own width).

    Returns
    -------
    ThermalNetwork

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> net = build_network(get_bearing("QJ202"), 7.4e-3, contact_load=100.0)
    >>> [round(float(m) * 1e3, 1) for m in net.masses]
    [14.9, 10.5, 9.7, 15.8, 122.1]
    """
    for key in ("bore", "outside_diameter", "width"):
        if getattr(bearing, key) is None:
            raise InputError(f"bearing {bearing.name}: {key} is not given but the thermal network needs it")
    check_positive("journal_radius", journal_radius)
    bore_r = 0.5 * bearing.bore
    if journal_radius > bore_r:
        raise InputError.for_field("journal_radius", journal_radius, f"must not exceed the bore radius {bore_r:g} m")
    if not 0.0 <= journal_bore_radius < journal_radius:
        raise InputError.for_field("journal_bore_radius", journal_bore_radius, "must lie in [0, journal_radius)")
    if not 0.0 <= emissivity <= 1.0:
        raise InputError.for_field("emissivity", emissivity, "must lie in [0, 1]")
    if contact_load < 0.0:
        raise InputError.for_field("contact_load", contact_load, "must be >= 0 N")
    ring = _thermal_material(bearing.ring_material, "the thermal network")
    ball = _thermal_material(bearing.ball_material, "the thermal network")
    shaft = _thermal_material(journal_material, "the journal node")
    frame = _thermal_material(housing_material, "the housing node")

    width = bearing.width if set_width is None else set_width
    r_i, r_o = 0.5 * bearing.inner_raceway_diameter, 0.5 * bearing.outer_raceway_diameter
    r_od = 0.5 * bearing.outside_diameter
    j_len = width if journal_length is None else journal_length
    h_diam = bearing.outside_diameter + (bearing.outside_diameter - bearing.bore) if housing_outer_diameter is None \
        else housing_outer_diameter
    h_len = width if housing_length is None else housing_length
    if h_diam <= bearing.outside_diameter:
        raise InputError.for_field("housing_outer_diameter", h_diam, "must exceed the bearing outside diameter")

    masses = np.array([
        shaft.density * _annulus_volume(journal_bore_radius, journal_radius, j_len),
        ring.density * _annulus_volume(bore_r, r_i, width) if inner_race_mass is None else inner_race_mass,
        rows * bearing.ball_count * ball.density * math.pi * bearing.ball_diameter**3 / 6.0,
        ring.density * _annulus_volume(r_o, r_od, width) if outer_race_mass is None else outer_race_mass,
        frame.density * _annulus_volume(r_od, 0.5 * h_diam, h_len) if housing_mass is None else housing_mass,
    ])
    heat = np.array([shaft.specific_heat, ring.specific_heat, ball.specific_heat, ring.specific_heat,
                     frame.specific_heat])

    # each node sits where it splits its shell's resistance in two, so half a shell lies on each side
    inner_half = 0.5 * kernel.shell_resistance(bore_r, r_i, width, ring.thermal_conductivity)
    outer_half = 0.5 * kernel.shell_resistance(r_o, r_od, width, ring.thermal_conductivity)
    housing_half = 0.5 * kernel.shell_resistance(r_od, 0.5 * h_diam, h_len, frame.thermal_conductivity)
    fit = fit_contact_resistance / (math.pi * bearing.outside_diameter * width)
    g = np.zeros((5, 5))
    g[OUTER_RACE, HOUSING] = g[HOUSING, OUTER_RACE] = 1.0 / (outer_half + fit + housing_half)
    g[JOURNAL, INNER_RACE] = g[INNER_RACE, JOURNAL] = journal_race_conductance

    rise_temperature = ambient_temperature + LINEARISATION_RISE
    h_rad = radiation_coefficient(emissivity, rise_temperature, ambient_temperature) if emissivity > 0.0 else 0.0
    j_diam = 2.0 * journal_radius
    if vacuum:
        h_housing = h_journal = 0.0
    elif convection_coefficient is not None:
        h_housing = h_journal = convection_coefficient
    else:
        h_housing = natural_convection_coefficient(h_diam, LINEARISATION_RISE, ambient_temperature)
        h_journal = max(rotating_cylinder_coefficient(j_diam, rotor_speed),
                        natural_convection_coefficient(j_diam, LINEARISATION_RISE, ambient_temperature))
    housing_area = math.pi * h_diam * h_len + 2.0 * 0.25 * math.pi * (h_diam**2 - bearing.outside_diameter**2)
    ga = np.zeros(5)
    ga[HOUSING] = (h_housing + h_rad) * housing_area if housing_to_ambient is None else housing_to_ambient
    ga[JOURNAL] = (h_journal + h_rad) * math.pi * j_diam * j_len + journal_to_ambient

    network = ThermalNetwork(
        capacities=masses * heat, masses=masses, conductances=g, ambient_conductances=ga,
        expansion=np.array([shaft.thermal_expansion, ring.thermal_expansion, ball.thermal_expansion,
                            ring.thermal_expansion, frame.thermal_expansion]),
        ambient_temperature=ambient_temperature, journal_radius=journal_radius, bore_radius=bore_r,
        # groove bottoms placed so that d_o - d_i - 2 D = Pd (Harris & Kotzalas 2007, Essential Concepts, Ch. 2)
        inner_raceway_diameter=bearing.inner_raceway_diameter - 0.5 * bearing.diametral_clearance,
        outer_raceway_diameter=bearing.outer_raceway_diameter + 0.5 * bearing.diametral_clearance,
        ball_diameter=bearing.ball_diameter,
        journal_effusivity=effusivity(shaft.thermal_conductivity, shaft.density, shaft.specific_heat),
        race_effusivity=effusivity(ring.thermal_conductivity, ring.density, ring.specific_heat),
        ball_heat_share=heat_partition(effusivity(ball.thermal_conductivity, ball.density, ball.specific_heat), 0.0,
                                       effusivity(ring.thermal_conductivity, ring.density, ring.specific_heat), 0.0),
        vacuum=vacuum, bearing=bearing, inner_shell_resistance=inner_half, outer_shell_resistance=outer_half,
        paths={"outer_race-housing": g[OUTER_RACE, HOUSING], "journal-inner_race": journal_race_conductance,
               "housing-ambient": ga[HOUSING], "journal-ambient": ga[JOURNAL]},
    )
    n_contacts = (rows * bearing.ball_count if loaded_balls is None else loaded_balls) * bearing.pairs_per_ball
    loads = np.full(n_contacts, float(contact_load))
    return network.with_contact_loads(loads, loads)
