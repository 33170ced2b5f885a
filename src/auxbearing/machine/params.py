"""Every input of a machine file: one :class:`~auxbearing.common.params.Param` row per key, with unit and source.

The tables of a machine TOML file are ``[machine]``, ``[rotor]``, one ``[[touchdown]]`` per plane and
``[drop]`` (how the run is made); the keys of ``[[touchdown]]`` that the source paper's drop also has
keep their meaning and units. Values the literature does not fix are marked "ours" with the reasoning.
"""

from __future__ import annotations

import math

from auxbearing.common.params import Param, by_key

G0 = 9.80665  #: standard gravity [m/s^2] (CGPM 1901)
#: What every ``position`` of a machine file is measured from and which way, for the help texts and the reference:
#: the kernels place each station by its distance from the mass centre along the spin axis, so that is the
#: origin a rigid rotor's file uses; a rotor of matrices keeps its model's coordinates (the reader subtracts the
#: mass centre's). +z is the direction a positive speed turns about by the right-hand rule, and up when vertical.
AXIAL_POSITION = ("from the rotor's mass centre along the spin axis z, positive towards +z (the end seen from which a "
                  "positive rotor.speed turns counter-clockwise; up on a vertical machine); with rotor.matrices or "
                  "rotor.ross_file, instead the axial coordinate of one of the matrices' nodes in the model's own "
                  "frame")

ROTOR: tuple[Param, ...] = (
    Param("rotor", "mass", "mass", None, "kg", "positive", "Rotor mass m", "required"),
    Param("rotor", "polar_inertia", "inertia", None, "kg*m**2", "positive",
          "Polar moment of inertia J_p about the spin axis; at most 2 x transverse_inertia (the perpendicular-axis "
          "theorem: no body has more, a flat disc exactly that)", "required"),
    Param("rotor", "transverse_inertia", "inertia", None, "kg*m**2", "optional_positive",
          "Moment of inertia J_t about a transverse axis through the mass centre", "required with two planes or more"),
    Param("rotor", "speed", "angular_speed", None, "rpm", "finite", "Spin speed at the drop", "required"),
    Param("rotor", "unbalance", "length", 0.0, "um", "nonnegative",
          "Static unbalance: offset of the mass centre from the journal axis", "ours: none unless given"),
    Param("rotor", "unbalance_phase", "angle", 0.0, "deg", "finite",
          "Direction of the mass-centre offset at the drop, from +x", "ours"),
    Param("rotor", "couple_unbalance", "angle", 0.0, "mrad", "nonnegative",
          "Couple unbalance: tilt of the principal axis from the journal axis", "ours: none unless given"),
    Param("rotor", "couple_unbalance_phase", "angle", 0.0, "deg", "finite",
          "Direction the principal axis leans towards at +z, relative to unbalance_phase's reference", "ours"),
    Param("rotor", "axial_force", "force", 0.0, "N", "finite", "Constant process thrust on the rotor along +z",
          "ours: none unless given"),
    Param("rotor", "side_force_x", "force", 0.0, "N", "finite", "Constant radial process force along x", "ours"),
    Param("rotor", "side_force_y", "force", 0.0, "N", "finite", "Constant radial process force along y", "ours"),
    Param("rotor", "start_x", "length", 0.0, "mm", "finite",
          "Journal-axis position at the drop, x; with a levitated [[scenario]] an offset from the levitated place, "
          "applied after the levitated machine is linearised (it must stay inside every touchdown clearance)",
          "ours: centred"),
    Param("rotor", "start_y", "length", 0.0, "mm", "finite",
          "Journal-axis position at the drop, y; with a levitated [[scenario]] an offset from the levitated place, "
          "applied after the levitated machine is linearised (it must stay inside every touchdown clearance)",
          "ours: centred"),
    Param("rotor", "max_mode_frequency", "frequency", 3000.0, "Hz", "positive",
          "With rotor.matrices: highest free-free natural frequency of the elastic modes kept (a mode's partner "
          "of equal frequency is kept with it)", "ours: above the drop's bounce and whirl content"),
    Param("rotor", "modal_damping", "dimensionless", 0.01, "", "unit_interval",
          "With rotor.matrices: viscous damping ratio added to each elastic mode (beside the matrices' own C)",
          "ours: between a solid steel shaft (about 0.002) and a built-up rotor (about 0.02)"),
)
#: ``[[unbalance]]``: one table per unbalance plane (balancing grade G of ISO 21940-11 gives e = G / Omega).
UNBALANCE: tuple[Param, ...] = (
    Param("unbalance", "position", "length", None, "mm", "finite", "Axial position of the plane, " + AXIAL_POSITION,
          "required"),
    Param("unbalance", "amount", "unbalance", None, "g*mm", "nonnegative", "Unbalance U = m e in the plane",
          "required"),
    Param("unbalance", "phase", "angle", 0.0, "deg", "finite", "Direction of the unbalance at the drop, from +x",
          "ours"),
)
#: Text keys of ``[rotor]``: ``matrices`` names a ``.npz`` file of the free-free rotor's matrices
#: (:func:`auxbearing.machine.structure.read_structure`), ``ross_file`` a rotor saved by ROSS (mass and inertias then
#: come from either); ``ross_bearings`` (``keep`` or ``drop``) goes with ``ross_file``, ``reduction``
#: (:data:`auxbearing.machine.model.REDUCTIONS`) with either. Every one is in the list an unknown key's message gives.
ROTOR_TEXT = ("matrices", "ross_file", "ross_bearings", "reduction")

TOUCHDOWN: tuple[Param, ...] = (
    Param("touchdown", "position", "length", 0.0, "mm", "finite", "Axial position of the plane, " + AXIAL_POSITION,
          "required with two planes or more"),
    Param("touchdown", "radial_clearance", "length", None, "mm", "positive",
          "Radial clearance s between journal and inner-race bore", "required"),
    Param("touchdown", "axial_clearance", "length", None, "mm", "optional_positive",
          "Clearance between the rotor collar and the race face; absent: the plane does not catch axially",
          "ours: no axial touchdown unless given"),
    Param("touchdown", "journal_radius", "length", None, "mm", "optional_positive",
          "Journal radius r; default bore/2 - radial_clearance", "paper_notes item 6"),
    Param("touchdown", "race_mass", "mass", None, "kg", "optional_positive",
          "Inner race mass; default from bore, inner raceway diameter, width and ring density",
          "ours: the ring as a hollow cylinder from the bore to the groove bottom"),
    Param("touchdown", "race_inertia", "inertia", None, "kg*m**2", "optional_positive",
          "Inner race polar moment of inertia; default from the same hollow cylinder", "ours"),
    Param("touchdown", "line_stiffness", "line_stiffness", None, "N/m**(10/9)", "optional_positive",
          "Journal/race line-contact constant K_l; default Palmgren with the bearing width", "Palmgren (Eq. 19)"),
    Param("touchdown", "journal_pressure_limit", "pressure", 4000e6, "MPa", "positive",
          "Peak pressure of the journal/race contact (conformal, Persson's pin in a hole) that the journal and race "
          "surfaces carry without permanent set; a run past it stops",
          "ISO 76:2006: 4000 MPa for hardened bearing steel in line contact; a journal that is not hardened yields "
          "first at about 1.67 x its yield strength (Johnson 1985, Sec. 6.2, Tresca)"),
    Param("touchdown", "line_damping", "damping", 1000.0, "N*s/m", "nonnegative",
          "Journal/race contact damping C_l", "source paper Table II"),
    Param("touchdown", "ball_damping", "damping", 500.0, "N*s/m", "nonnegative",
          "Ball-set damping C_b on the race velocity", "source paper Table II"),
    Param("touchdown", "ball_constant", "ball_constant", None, "N/m**1.5", "optional_positive",
          "Override of the ball contact constant K_b; default Hertz (Eq. 15)", "source paper Eq. 15"),
    Param("touchdown", "sliding_friction", "dimensionless", 0.2, "", "unit_interval",
          "Journal/race sliding friction coefficient mu_1", "source paper Table II"),
    Param("touchdown", "rolling_friction", "dimensionless", 0.01, "", "unit_interval",
          "Rolling resistance coefficient of the race mu_2", "source paper Table II"),
    Param("touchdown", "slip_velocity", "velocity", 1e-2, "mm/s", "positive",
          "Regularisation v_eps of sign(slip), tanh(v/v_eps)", "ours: results insensitive (tests)"),
    Param("touchdown", "mount_stiffness", "stiffness", None, "N/m", "optional_positive",
          "Radial stiffness of the outer-ring mount; absent: rigid housing", "ours: rigid unless given"),
    Param("touchdown", "mount_damping", "damping", 0.0, "N*s/m", "nonnegative", "Radial damping of the mount",
          "ours"),
    Param("touchdown", "mount_mass", "mass", None, "kg", "optional_positive",
          "Mass moving with the outer ring in the mount; default the outer ring's", "ours: ring as a hollow cylinder"),
    Param("touchdown", "mount_deadband", "length", 0.0, "um", "nonnegative",
          "Radial travel of the outer ring before the mount spring engages", "ours"),
    Param("touchdown", "mount_stop", "length", None, "um", "optional_positive",
          "Radial travel to a hard stop; absent: none", "Hawkins et al. GT2007-28290 (flexible support, hard stop)"),
    Param("touchdown", "stop_stiffness", "stiffness", None, "N/m", "optional_positive",
          "Hard-stop stiffness; default 100 x mount_stiffness", "ours"),
    Param("touchdown", "stop_damping", "damping", 0.0, "N*s/m", "nonnegative", "Hard-stop damping", "ours"),
    Param("touchdown", "mount_travel", "length", None, "mm", "optional_positive",
          "Largest radial travel the mount allows before the run stops; default 2 x the stop, or 10 x the clearance "
          "(at least 2 x the dead band)",
          "ours"),
    Param("touchdown", "misalignment_x", "length", 0.0, "um", "finite", "Bearing centre offset along x", "ours"),
    Param("touchdown", "misalignment_y", "length", 0.0, "um", "finite", "Bearing centre offset along y", "ours"),
    Param("touchdown", "face_stiffness", "stiffness", None, "N/m", "optional_positive",
          "Axial stiffness of the collar on the race face; default the race ring as an axial column E A / B",
          "ours"),
    Param("touchdown", "face_damping", "damping", 1000.0, "N*s/m", "nonnegative", "Axial face contact damping",
          "ours: as C_l, an assumption; over the blower's first 10 s its drive end's drop damage moves -3 % at "
          "300 and +15 % at 10 000 N*s/m, its coast-down damage by at most 0.5 %"),
    Param("touchdown", "face_friction", "dimensionless", None, "", "unit_interval",
          "Friction coefficient of the collar on the race face; default sliding_friction",
          "Wilkes et al. GT2013-94594 (face friction drives forward whirl)"),
    Param("touchdown", "face_radius", "length", None, "mm", "optional_positive",
          "Mean radius of the collar/race-face annulus; default midway between bore and groove bottom", "ours"),
    Param("touchdown", "shoulder_height", "length", None, "mm", "optional_positive",
          "Groove shoulder height above the groove bottom (both rings); default 0.25 x ball diameter",
          "ours: an assumption; give the maker's value"),
    Param("touchdown", "axial_room", "length", None, "mm", "optional_positive",
          "Axial length the seat offers a touchdown bearing; default the bearing's own width. A verify candidate "
          "wider than it (a duplex pair in place of one bearing) does not fit",
          "ours: the machine's drawing"),
    Param("touchdown", "lubricant_viscosity", "kinematic_viscosity", 0.0, "mm**2/s", "nonnegative",
          "Kinematic viscosity of the bearing's oil (base oil of a grease) for Palmgren's load-free torque, held at "
          "this value over the whole run: give it at the bearing's running temperature (a value at 40 degC overstates "
          "a hot bearing's torque and heat, on the safe side for its temperature)",
          "Harris & Kotzalas 2007, Essential Concepts Ch. 10; 0: no load-free torque"),
    Param("touchdown", "viscous_factor", "dimensionless", 0.0, "", "nonnegative",
          "Palmgren's f_0 of the load-free torque M_0 = 1e-7 f_0 (nu n)^(2/3) d_m^3 of one bearing (about 0.7-4 for "
          "ball bearings; a matched pair turns two bearings' oil, 2 M_0)",
          "Harris & Kotzalas 2007, Essential Concepts Ch. 10; 0: no load-free torque"),
    Param("touchdown", "housing_mass", "mass", None, "kg", "optional_positive",
          "Mass of the housing lumped with the outer ring in the thermal network; default a steel ring around it",
          "ours (auxbearing.analysis.thermal.build_network)"),
    Param("touchdown", "housing_to_ambient", "thermal_conductance", None, "W/K", "optional_nonnegative",
          "Conductance from the housing to ambient; default natural convection of its outside (none in vacuum)",
          "Churchill & Chu correlation (auxbearing.analysis.thermal)"),
    Param("touchdown", "journal_to_ambient", "thermal_conductance", None, "W/K", "optional_nonnegative",
          "Conductance from the journal to the rest of the rotor and ambient; default conduction along the shaft "
          "to the mass centre (the rotor body held at ambient)", "ours: Fourier conduction k A / L"),
    Param("touchdown", "emissivity", "dimensionless", 0.0, "", "unit_interval",
          "Emissivity of the housing for radiation to ambient", "ours: none unless given"),
)
#: Keys of ``[[touchdown]]`` that are text, not quantities. ``axial_direction`` (with ``axial_clearance``) says which
#: way the collar meets the race face: ``both`` (the default: the rotor is caught moving either way), ``+z`` (only
#: moving towards +z) or ``-z`` (only towards -z), as at the two ends of a rotor that each catch one way.
TOUCHDOWN_TEXT = ("name", "bearing", "axial_direction", "preload")
AXIAL_DIRECTIONS = ("both", "+z", "-z")

SIMULATION: tuple[Param, ...] = (
    Param("drop", "duration", "time", 0.2, "s", "positive", "Simulated time", "ours"),
    Param("drop", "output_step", "time", 1e-5, "us", "positive", "Uniform output interval", "ours"),
    Param("drop", "rtol", "dimensionless", 1e-6, "", "tolerance", "Relative tolerance of the integration",
          "ours (converged, tests)"),
    Param("drop", "atol", "dimensionless", 1e-6, "", "tolerance",
          "Absolute tolerance as a fraction of each state's scale", "ours"),
    Param("drop", "max_step", "time", 5e-5, "us", "positive", "Largest integration step", "ours"),
    Param("drop", "gravity", "acceleration", G0, "m/s**2", "nonnegative", "Gravitational acceleration",
          "standard gravity"),
    Param("drop", "max_steps", "dimensionless", 5e7, "", "count", "Step budget: the run stops with a verdict past it",
          "ours: about 5 min on this machine"),
    Param("drop", "max_wall_time", "time", 600.0, "s", "positive",
          "Wall-time guard of an interactive drop or coast-down (verify and campaigns bound their work by steps only)",
          "ours"),
    Param("drop", "max_output_points", "dimensionless", 4e5, "", "count",
          "Most output instants kept; a longer run is written at a coarser step (said in the result)",
          "ours: ~150 MB for two planes"),
    Param("drop", "whirl_window", "time", None, "ms", "optional_positive",
          "Length of the windows in which whirl is classified; default 3 spin periods at the drop, at least 5 ms",
          "ours: a whirl must turn half a revolution within a window to count"),
    Param("drop", "ball_stress_limit", "pressure", 6000e6, "MPa", "positive",
          "Ball contact stress beyond which elastic Hertz values mean nothing (the run stops)",
          "ours: Palmgren's dent grows as sigma^6, so 6000 MPa dents about 8.5x ISO 76's 1e-4 D"),
    Param("drop", "energy_tolerance", "dimensionless", 1e-3, "", "fraction",
          "Energy gain, relative to the energies in play, that stops a run as a numerical run-away", "ours"),
)

COASTDOWN: tuple[Param, ...] = (
    Param("coastdown", "drag_torque", "moment", 0.0, "N*m", "nonnegative",
          "Constant drag torque T0 on the rotor (seals, motor cogging)", "ours: none unless given"),
    Param("coastdown", "viscous_drag", "torque_per_speed", 0.0, "N*m*s", "nonnegative",
          "Viscous drag c1 of T = T0 + c1 Omega + c2 Omega^2", "ours: none unless given"),
    Param("coastdown", "windage_drag", "torque_per_speed2", 0.0, "N*m*s**2", "nonnegative",
          "Windage drag c2 of T = T0 + c1 Omega + c2 Omega^2", "ours: none unless given"),
    Param("coastdown", "process_torque", "moment", 0.0, "N*m", "finite",
          "Constant torque the process puts on the rotor (positive drives it)", "ours: none unless given"),
    Param("coastdown", "ambient_temperature", "temperature", 293.15, "degC", "service_temperature",
          "Ambient (and initial) temperature, -73 to 350 degC and below max_temperature",
          "ISO 1 reference temperature, 20 degC"),
    Param("coastdown", "max_time", "time", 3600.0, "s", "positive",
          "Longest simulated coast-down: a run to standstill that reaches it first ends with verdict time_budget, "
          "not checked in a verification; a campaign's coast-downs take it as their horizon", "ours: one hour"),
    Param("coastdown", "stop_speed", "angular_speed", math.pi / 30.0, "rpm", "positive",
          "Rotor speed counted as standstill", "ours"),
    Param("coastdown", "max_temperature", "temperature", 423.15, "degC", "service_temperature",
          "Temperature of any bearing part that ends the run (thermal run-away), -73 to 350 degC and above "
          "ambient_temperature",
          "ours: 150 degC, the usual dimensional-stabilisation limit of through-hardened bearing steel"),
    Param("coastdown", "speed_step", "dimensionless", 0.1, "", "fraction",
          "Relative speed change of one reduced-model stretch before full dynamics checks again; where the "
          "windows find steady states (no rattle or swing) it doubles, up to four times (at most half the speed), "
          "while the windows after each stretch find the torques it held unchanged",
          "ours: the reduced/full agreement test holds within 2 % with it"),
    Param("coastdown", "max_steps", "dimensionless", 3e7, "", "count",
          "Step budget of the coast-down's full dynamics: past it the run stops, its outcome not checked",
          "ours: a tenth of the drop's rate of steps per simulated second kept up for an hour of coast-down"),
    Param("coastdown", "check_window", "time", 0.01, "ms", "positive",
          "Length of the full-dynamics windows that check the motion is settled and measure the losses and the "
          "over-rolling load (the cube mean of the bearing load over each: the damage does not depend on this "
          "length); a window is never shorter than one whirl window (drop.whirl_window, three spin periods at the "
          "drop speed), which its states are judged on; where a steady motion's losses repeat slower than a "
          "window, the coast-down doubles it, up to four times", "ours"),
    Param("coastdown", "tail_temperature_rise", "temperature", 0.05, "K", "temperature_rise",
          "A run to standstill ends once the spin energy left, all of it made heat in the smallest part, would warm "
          "that part by less than this and its revolutions could add less than 0.1 % to any damage; the time left "
          "to standstill is then extrapolated at the last deceleration (0: simulate down to stop_speed)",
          "ours: 0.05 K, below what the temperature criteria resolve"),
    Param("coastdown", "settle_time", "time", 0.0, "ms", "nonnegative",
          "Full dynamics after each reduced stretch that is run and booked but not judged for the next one: a "
          "stretch resumes the motion as it was, which then follows the new speed and clearances only in the "
          "windows, and where it changes slowly the load the first windows measure lags full dynamics'. "
          "Whatever it is, a stretch that carried a rattling journal is followed by at least 100 ms of full "
          "dynamics before the next (the time a rattle takes to forget the handover; those windows are judged)",
          "ours, measured over 30 s against full dynamics with 0 ms: damage per drop within 2 % on the blower, "
          "its 7208, 6208 and hybrid candidates, the compressor and the vertical machine, -3.3 / -5.6 % on the "
          "7208 DB pair against full dynamics converged in its tolerances (its small rattle turns unstable over "
          "seconds, which a stretch freezes; settling does not change it); 150 ms brought the blower "
          "family and the vertical machine within 1 % at 2.5 times the computing before stretches were charged "
          "by the trapezoidal rule"),
)
#: Keys of ``[coastdown]`` that are no quantity: ``vacuum`` (true or false, default false) runs the machine in vacuum,
#: where no air carries heat off the housings (no natural convection; radiation and conduction stay).
COASTDOWN_TEXT = ("vacuum",)
LIFE: tuple[Param, ...] = (
    Param("life", "required_drops", "dimensionless", 10.0, "", "count",
          "Drops (each with its coast-down) the touchdown bearings must survive",
          "an assumption of auxbearing, not a standard's clause: give the purchaser's figure"),
)

TABLES = {"rotor": by_key(ROTOR, "rotor"), "touchdown": by_key(TOUCHDOWN, "touchdown"),
          "drop": by_key(SIMULATION, "drop"), "coastdown": by_key(COASTDOWN, "coastdown"),
          "life": by_key(LIFE, "life"), "unbalance": by_key(UNBALANCE, "unbalance")}


def default(section: str, key: str) -> float | None:
    """The SI default of a row."""
    return TABLES[section][key].default


def steel_column_stiffness(modulus: float, area: float, length: float) -> float:
    """Axial stiffness of a prismatic bar E A / L [N/m] (Timoshenko & Gere, Mechanics of Materials, Eq. 2.3).

    >>> round(steel_column_stiffness(207e9, 1e-4, 0.01) / 1e9, 2)
    2.07
    """
    return modulus * area / length


def hollow_cylinder(density: float, inner: float, outer: float, width: float) -> tuple[float, float]:
    """Mass [kg] and polar moment of inertia [kg m^2] of a hollow cylinder, m (r_i^2 + r_o^2) / 2.

    >>> m, j = hollow_cylinder(7810.0, 0.0075, 0.00975, 0.011)
    >>> round(m * 1e3, 2), f"{j:.3e}"
    (10.48, '7.925e-07')
    """
    mass = density * math.pi * (outer**2 - inner**2) * width
    return mass, 0.5 * mass * (inner**2 + outer**2)

#: How the dents of successive drops add up: ``same_spot``, every drop's largest dent on one spot of each race,
#: depths added (conservative; right for the stationary outer ring, which a horizontal rotor always strikes
#: at the bottom); ``spread``, the rotating inner race meets the drop at a random angle, so its dents fall on
#: spots spread uniformly around the raceway (one spot a contact-ellipse width long) and a spot reaches the
#: limit only when enough drops land on it; the outer race keeps ``same_spot``.
DENT_ACCUMULATION = ("same_spot", "spread")
