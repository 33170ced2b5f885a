"""A machine for a touchdown run: rotor, touchdown planes, mounts, run settings (validated, SI).

Read from a machine TOML file (:func:`read_machine`, keys and units in
:mod:`auxbearing.machine.params`) or a catalogue name (:func:`machine_names`), or built from the
source paper's planar inputs (:func:`planar_machine`). :meth:`Machine.kernel` packs it into the
NamedTuples of :mod:`auxbearing.core.machine` with the initial state and tolerances
(:mod:`auxbearing.machine.pack`).
"""

from __future__ import annotations

import copy
import math
from dataclasses import dataclass, field, replace
from functools import cached_property
from pathlib import Path

from auxbearing.bearings.duplex import DuplexSet
from auxbearing.bearings.geometry import BearingGeometry, bearing_from_mapping
from auxbearing.common.errors import InputError
from auxbearing.common.params import accept, as_typed, display_value, read_table, unknown
from auxbearing.core.hertz import line_contact_constant
from auxbearing.machine.params import (
    AXIAL_DIRECTIONS,
    COASTDOWN,
    COASTDOWN_TEXT,
    DENT_ACCUMULATION,
    G0,
    LIFE,
    ROTOR_TEXT,
    SIMULATION,
    TABLES,
    TOUCHDOWN_TEXT,
    default,
    hollow_cylinder,
    steel_column_stiffness,
)
from auxbearing.machine.scenario import read_scenarios
from auxbearing.machine.stations import TABLES as STATION_TABLES
from auxbearing.machine.stations import kinds as station_kinds
from auxbearing.machine.stations import of_kind
from auxbearing.machine.structure import ModalRotor, RotorStructure, check_spinning, modal_rotor, read_structure

#: (1 - nu^2)/E of the journal: steel, E = 207 GPa, nu = 0.3 (the paper names no rotor material).
JOURNAL_COMPLIANCE = (1.0 - 0.3**2) / 207e9
#: Density used for a ring whose material gives none [kg/m^3] (through-hardened bearing steel).
STEEL_DENSITY = 7810.0
#: Default shoulder height of the raceway grooves as a fraction of the ball diameter (an assumption).
SHOULDER_FRACTION = 0.25
ORIENTATIONS = ("horizontal", "vertical")
#: ``rotor.reduction``: the kept modes with the static correction at the stations (default), or the modes alone
REDUCTIONS = ("static_correction", "modes")
#: Keys of ``[machine]``.
MACHINE_KEYS = ("name", "orientation", "source")
#: Tables of a machine file that other commands read and check (verify's criteria and candidates, a
#: campaign's definition); a drop or coast-down leaves them alone.
OTHER_TABLES = ("criteria", "candidate", "verify", "campaign")
#: Speed below which the constant drag torque T0 is regularised as T0 tanh(Omega / scale) [rad/s], like
#: Coulomb friction near zero slip (a constant torque has no direction at standstill).
DRAG_SPEED_SCALE = 0.1


@dataclass(frozen=True)
class Mount:
    """The outer ring's support: a spring with a dead band, a damper, an optional hard stop (SI)."""

    mount_stiffness: float
    mount_damping: float = 0.0
    mount_mass: float = 0.0
    mount_deadband: float = 0.0
    mount_stop: float | None = None
    stop_stiffness: float | None = None
    stop_damping: float = 0.0
    mount_travel: float | None = None


@dataclass(frozen=True)
class TouchdownPlane:
    """One touchdown bearing with its journal, race, contact laws and mount (SI, every value resolved)."""

    name: str
    bearing: BearingGeometry
    position: float
    radial_clearance: float
    journal_radius: float
    race_mass: float
    race_inertia: float
    line_stiffness: float
    line_damping: float
    ball_damping: float
    ball_constant: float | None
    sliding_friction: float
    rolling_friction: float
    slip_velocity: float
    axial_clearance: float | None = None
    axial_direction: str = "both"
    face_stiffness: float = 0.0
    face_damping: float = 0.0
    face_friction: float = 0.0
    face_radius: float = 0.0
    mount: Mount | None = None
    misalignment: tuple[float, float] = (0.0, 0.0)
    shoulder_height: float = 0.0
    lubricant_viscosity: float = 0.0
    viscous_factor: float = 0.0
    housing_mass: float | None = None
    housing_to_ambient: float | None = None
    journal_to_ambient: float | None = None
    emissivity: float = 0.0
    journal_pressure_limit: float = 4000e6
    defaults: tuple[str, ...] = ()  #: keys filled from geometry or defaults, for the report
    #: a matched pair (duplex set) in the plane; ``bearing`` is then one of its two identical rows
    bearing_set: DuplexSet | None = None
    axial_room: float | None = None  #: axial length of the seat [m] (None: the bearing's width)

    @property
    def catches_axially(self) -> bool:
        """True when a collar meets the race face."""
        return self.axial_clearance is not None

    @property
    def unit(self) -> BearingGeometry | DuplexSet:
        """The touchdown bearing as one unit: the matched set, or the single bearing."""
        return self.bearing if self.bearing_set is None else self.bearing_set

    @property
    def rows(self) -> int:
        """Rows of balls in the plane: 2 for a matched pair, else 1."""
        return 1 if self.bearing_set is None else 2

    @property
    def set_viscous_factor(self) -> float:
        """Palmgren's f_0 of the plane's bearings together [-]: M_0 is a bearing's, and a matched pair has two."""
        return self.viscous_factor * self.rows


@dataclass(frozen=True)
class MachineRotor:
    """The rotor (SI)."""

    mass: float
    polar_inertia: float
    transverse_inertia: float | None
    speed: float
    unbalance: float = 0.0
    unbalance_phase: float = 0.0
    couple_unbalance: float = 0.0
    couple_unbalance_phase: float = 0.0
    axial_force: float = 0.0
    side_force_x: float = 0.0
    side_force_y: float = 0.0
    start_x: float = 0.0
    start_y: float = 0.0
    max_mode_frequency: float = 3000.0  #: [Hz] elastic modes kept (with a structure)
    modal_damping: float = 0.01  #: damping ratio added to each elastic mode
    #: how the structure is reduced: the kept modes and the static correction at the stations, or the modes alone
    reduction: str = "static_correction"
    #: the rotor as matrices (:mod:`auxbearing.machine.structure`); None: the rigid rotor of mass and inertias
    structure: RotorStructure | None = None
    #: unbalance planes (axial position from the mass centre [m], U = m e [kg m], phase [rad]); when given they are
    #: the static and couple unbalance (:func:`unbalance_of_planes`) and load the elastic modes
    unbalance_planes: tuple = ()

    def __post_init__(self) -> None:
        if self.reduction not in REDUCTIONS:
            raise InputError.for_field("rotor.reduction", self.reduction, f"must be one of {', '.join(REDUCTIONS)}")
        if self.structure is None and self.transverse_inertia is not None:
            _check_inertia_pair(self.polar_inertia, self.transverse_inertia, f"{self.polar_inertia:g} kg*m**2",
                                f"{self.transverse_inertia:g} kg*m**2")
        if self.unbalance_planes:
            if self.unbalance or self.couple_unbalance:
                raise InputError.for_field("rotor.unbalance", f"{self.unbalance * 1e6:g} um", "give the unbalance "
                                           "either as [[unbalance]] planes or as rotor.unbalance/couple_unbalance")
            e, phase, chi, couple = unbalance_of_planes(self.unbalance_planes, self.mass,
                                                        self.transverse_inertia or 0.0, self.polar_inertia)
            for key, value in (("unbalance", e), ("unbalance_phase", phase), ("couple_unbalance", chi),
                               ("couple_unbalance_phase", couple)):
                object.__setattr__(self, key, value)
        if self.structure is None:
            return
        body = modal_rotor(self.structure)
        check_spinning(self.structure, body)
        for key, value, own in (("mass", self.mass, body.mass), ("polar_inertia", self.polar_inertia,
                                                                    body.polar_inertia),
                                ("transverse_inertia", self.transverse_inertia, body.transverse_inertia)):
            if value is None or not math.isclose(value, own, rel_tol=1e-9):
                raise InputError.for_field(f"rotor.{key}", value, f"must be the matrices' own value {own:.9g} (SI); "
                                           "build the rotor with MachineRotor.from_structure")

    @classmethod
    def from_structure(cls, structure: RotorStructure, speed: float, **values) -> MachineRotor:
        """The rotor of a structure: its mass and inertias from the matrices, the rest as given (SI)."""
        body = modal_rotor(structure)
        return cls(mass=body.mass, polar_inertia=body.polar_inertia, transverse_inertia=body.transverse_inertia,
                   speed=speed, structure=structure, **values)

    def modal(self, positions=()) -> ModalRotor | None:
        """The structure's rigid body and kept elastic modes (None: a rigid rotor).

        ``positions`` (from the mass centre [m], each on a node) are where the stations push: with the
        ``static_correction`` reduction the kept modes are followed by the static correction's vectors for forces
        there (:func:`auxbearing.machine.structure.modal_rotor`); a machine passes its own (:meth:`Machine.modal`).
        """
        if self.structure is None:
            return None
        nodes = ()
        if self.reduction == "static_correction" and len(self.structure.nodes) > 1:
            nodes = self.structure.nodes_at(positions)  # each on a node: Machine checks them first
        return modal_rotor(self.structure, 2.0 * math.pi * self.max_mode_frequency, self.modal_damping, nodes)


def _check_inertia_pair(jp: float, jt: float, jp_written: object, jt_written: object) -> None:
    """Refuse a polar inertia above twice the transverse one (the values as written name them in the message).

    The perpendicular-axis theorem: with the spin axis z, J_p = int(x^2 + y^2) dm, and a rotor's transverse moments
    about x and y are int(y^2 + z^2) dm and int(x^2 + z^2) dm, so 2 J_t = J_p + 2 int z^2 dm >= J_p: no body of any
    length has J_p > 2 J_t, and a flat disc (z = 0 throughout) has J_p = 2 J_t exactly. The margin of 1e-9 lets a
    disc's pair written as 0.02 and 0.01 through.
    """
    if jt > 0.0 and jp > 2.0 * jt * (1.0 + 1e-9):
        raise InputError.for_field("rotor.polar_inertia", jp_written, f"is {jp / jt:.4g} times "
                                   f"rotor.transverse_inertia = {jt_written!r}; no body has a polar moment above twice "
                                   "its transverse one (the perpendicular-axis theorem: J_p = 2 J_t - 2 int z^2 dm, "
                                   "equal for a flat disc)")


def unbalance_of_planes(planes, mass: float, transverse_inertia: float, polar_inertia: float
                        ) -> tuple[float, float, float, float]:
    """Static and couple unbalance of a rigid rotor from unbalance planes (position a_i, U_i, phase beta_i).

    Static: the mass centre's offset e = |S| / m with S = sum U_i e^(i beta_i), at arg S. Couple: the point masses'
    products of inertia about the mass centre, sum U_i a_i e^(i beta_i), tilt the principal axis by chi =
    |C| / |J_t - J_p| towards arg C at +z (towards arg C + pi when J_p > J_t), the small-angle rotation of the
    inertia tensor (Friswell et al. 2010, Sec. 3.5). Returns (e, its phase, chi, its phase relative to e's), as
    the rotor's keys take them. The planes' own mass is taken as part of the rotor's.
    """
    static = sum(u * complex(math.cos(b), math.sin(b)) for _, u, b in planes)
    couple = sum(u * a * complex(math.cos(b), math.sin(b)) for a, u, b in planes)
    if abs(static) <= 1e-12 * sum(abs(u) for _, u, _ in planes):
        static = 0.0  # planes that balance each other: no static unbalance, not a round-off's worth at some phase
    e = abs(static) / mass
    phase = math.atan2(static.imag, static.real) if e > 0.0 else 0.0
    arm = transverse_inertia - polar_inertia
    if couple == 0.0:
        return e, phase, 0.0, 0.0
    if arm == 0.0:
        raise InputError.for_field("unbalance", "a couple", "a rotor with J_t = J_p has no principal axis to tilt")
    lean = couple / arm
    return e, phase, abs(lean), math.atan2(lean.imag, lean.real) - phase


@dataclass(frozen=True)
class Simulation:
    """How a run is made: time, output, tolerances, budgets and range limits (SI)."""

    duration: float = default("drop", "duration")
    output_step: float = default("drop", "output_step")
    rtol: float = default("drop", "rtol")
    atol: float = default("drop", "atol")
    max_step: float = default("drop", "max_step")
    gravity: float = default("drop", "gravity")
    max_steps: float = default("drop", "max_steps")
    max_wall_time: float = default("drop", "max_wall_time")
    max_output_points: float = default("drop", "max_output_points")
    whirl_window: float = default("drop", "whirl_window")
    ball_stress_limit: float = default("drop", "ball_stress_limit")
    energy_tolerance: float = default("drop", "energy_tolerance")

    def __post_init__(self) -> None:
        for p in SIMULATION:
            object.__setattr__(self, p.key, accept(p, getattr(self, p.key)))
        if self.output_step > self.duration:  # either may be the one given: name both
            raise InputError.for_field("drop.duration", f"{self.duration:g} s",
                                       f"shorter than drop.output_step = {self.output_step:g} s: give a longer "
                                       "duration or a shorter output_step")
        if self.max_output_points < 2:  # a run's output holds its start and its end at least
            raise InputError.for_field("drop.max_output_points", int(self.max_output_points), "must be 2 or more")


@dataclass(frozen=True)
class Coastdown:
    """The coast-down's drag, process torque, thermal surroundings, budgets and limits (SI)."""

    drag_torque: float = default("coastdown", "drag_torque")
    viscous_drag: float = default("coastdown", "viscous_drag")
    windage_drag: float = default("coastdown", "windage_drag")
    process_torque: float = default("coastdown", "process_torque")
    ambient_temperature: float = default("coastdown", "ambient_temperature")
    max_time: float = default("coastdown", "max_time")
    stop_speed: float = default("coastdown", "stop_speed")
    max_temperature: float = default("coastdown", "max_temperature")
    speed_step: float = default("coastdown", "speed_step")
    max_steps: float = default("coastdown", "max_steps")
    check_window: float = default("coastdown", "check_window")
    settle_time: float = default("coastdown", "settle_time")
    tail_temperature_rise: float = default("coastdown", "tail_temperature_rise")
    vacuum: bool = False

    def __post_init__(self) -> None:
        for p in COASTDOWN:
            object.__setattr__(self, p.key, accept(p, getattr(self, p.key)))
        if not isinstance(self.vacuum, bool):
            raise InputError.for_field("coastdown.vacuum", self.vacuum, "must be true or false")


@dataclass(frozen=True)
class Life:
    """What the bearings must survive."""

    required_drops: float = default("life", "required_drops")
    #: how the dents of successive drops add up (:data:`auxbearing.machine.params.DENT_ACCUMULATION`)
    dent_accumulation: str = "same_spot"
    #: the keys the machine file gives (the rest are auxbearing's assumptions), for what the outputs say of them
    given: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        for p in LIFE:
            object.__setattr__(self, p.key, accept(p, getattr(self, p.key)))
        if self.dent_accumulation not in DENT_ACCUMULATION:
            raise InputError.for_field("life.dent_accumulation", self.dent_accumulation,
                                       "must be " + " or ".join(f"'{k}'" for k in DENT_ACCUMULATION))


@dataclass(frozen=True)
class Machine:
    """A machine: rotor, its touchdown planes (one or more), orientation and run settings."""

    name: str
    rotor: MachineRotor
    planes: tuple[TouchdownPlane, ...]
    orientation: str = "horizontal"
    simulation: Simulation = field(default_factory=Simulation)
    source: str = "user input"
    coastdown: Coastdown = field(default_factory=Coastdown)
    life: Life = field(default_factory=Life)
    #: stations beside the touchdown planes, of the kinds of :mod:`auxbearing.machine.stations`
    stations: tuple = ()
    #: what fails the magnetic bearings (``[[scenario]]``), and the one this run takes (None: they fail at the drop)
    scenarios: tuple = ()
    scenario: str | None = None

    def __post_init__(self) -> None:
        if self.orientation not in ORIENTATIONS:
            raise InputError.for_field("machine.orientation", self.orientation, "must be horizontal or vertical")
        if not self.planes:
            raise InputError.for_field("touchdown", 0, "give at least one [[touchdown]] table")
        if self.tilt_free and self.rotor.transverse_inertia is None:
            raise InputError("rotor.transverse_inertia: missing; a rotor on two or more touchdown planes needs it")
        if self.orientation == "vertical" and not any(p.catches_axially for p in self.planes):
            raise InputError.for_field("machine.orientation", "vertical",
                                       "a vertical rotor rests on an axial touchdown: give axial_clearance on a plane")
        if not self.tilt_free and self.rotor.couple_unbalance > 0.0:
            raise InputError.for_field("rotor.couple_unbalance", f"{self.rotor.couple_unbalance * 1e3:g} mrad",
                                       "needs two touchdown planes (one plane locks the tilt)")
        for j, plane in enumerate(self.planes):
            if any(abs(other.position - plane.position) < 1e-6 for other in self.planes[:j]):
                raise InputError.for_field(f"touchdown.{j}.position", f"{plane.position * 1e3:g} mm",
                                           "touchdown planes must sit at different axial positions")
            if any(other.name == plane.name for other in self.planes[:j]):
                # results and reports tell the planes apart by name
                raise InputError.for_field(f"touchdown.{j}.name", plane.name, "touchdown planes must have "
                                           "different names")
        modal = self.rotor.modal()
        if modal is not None and modal.n_modes:  # a rigid structure's planes may sit anywhere
            for j, plane in enumerate(self.planes):
                modal.node_at(plane.position, f"touchdown.{j}.position")
            for kind in station_kinds():
                for i, station in enumerate(of_kind(self.stations, kind.KIND)):
                    if getattr(station, "on_rotor", True):
                        modal.node_at(station.position, f"{kind.KIND}.{i}.position")
            for i, scenario in enumerate(self.scenarios):
                if scenario.load is not None and scenario.load.on_rotor:
                    modal.node_at(scenario.load.position, f"scenario.{i}.position")
            for i, (position, _, _) in enumerate(self.rotor.unbalance_planes):
                modal.node_at(position, f"unbalance.{i}.position")

    def modal(self) -> ModalRotor | None:
        """The rotor's modal model with the static correction at this machine's stations (None: rigid rotor)."""
        return self._modal

    @cached_property
    def _modal(self) -> ModalRotor | None:
        return self.rotor.modal(self.force_positions())

    def force_positions(self) -> tuple[float, ...]:
        """Where forces act on the rotor, from the mass centre [m]: planes, stations, loads, unbalance planes."""
        positions = [p.position for p in self.planes]
        positions += [s.position for s in self.stations if getattr(s, "on_rotor", True)]
        positions += [s.load.position for s in self.scenarios if s.load is not None and s.load.on_rotor]
        positions += [a for a, _, _ in self.rotor.unbalance_planes]
        return tuple(positions)

    @property
    def tilt_free(self) -> bool:
        """Two planes or more: the rotor tilts (one plane is the planar rotor of the source paper)."""
        return len(self.planes) >= 2

    def rest_share(self, k: int) -> float:
        """Share of the rotor's weight plane k carries at rest, horizontal (estimates of contact sizes and modes).

        Two planes share it by the lever rule (an overhung rotor loads the near plane by more than its weight).
        With more, the rotor rests on the two planes that bracket its mass centre (or the two nearest it, when
        all lie on one side), by the lever rule; the others carry none (the statically indeterminate split is
        not these estimates' business).
        """
        planes = self.planes
        if len(planes) == 1:
            return 1.0
        below = [j for j, p in enumerate(planes) if p.position <= 0.0]
        above = [j for j, p in enumerate(planes) if p.position > 0.0]
        if below and above:
            pair = (max(below, key=lambda j: planes[j].position), min(above, key=lambda j: planes[j].position))
        else:
            pair = tuple(sorted(range(len(planes)), key=lambda j: abs(planes[j].position))[:2])
        if k not in pair:
            return 0.0
        other = pair[1] if k == pair[0] else pair[0]
        return abs(planes[other].position) / abs(planes[pair[1]].position - planes[pair[0]].position)

    def active_scenario(self):
        """The scenario this run takes: the named one, or the magnetic bearings failing at the drop."""
        from auxbearing.machine.scenario import AT_THE_DROP

        for s in self.scenarios:
            if s.name == self.scenario:
                return s
        return AT_THE_DROP

    def with_scenario(self, name: str | None, field: str = "scenario") -> Machine:
        """A copy that runs the scenario ``name`` (``field`` names the input in an error)."""
        if name is None:
            return replace(self, scenario=None)
        names = [s.name for s in self.scenarios]
        if name not in names:
            raise InputError.for_field(field, name, f"no such [[scenario]] in {self.name} (it has: "
                                       f"{', '.join(names) or 'none'})")
        return replace(self, scenario=name)

    @property
    def axial_free(self) -> bool:
        """The rotor moves axially when a plane catches axially."""
        return any(p.catches_axially for p in self.planes)

    def with_simulation(self, **changes) -> Machine:
        """A copy with some run settings changed (values with units or SI)."""
        return replace(self, simulation=replace(self.simulation, **changes))

    def for_batch(self) -> Machine:
        """A copy without the wall-time guard: verify and campaigns bound their work by steps alone.

        The guard (``drop.max_wall_time``) protects an interactive run from a hang; a verdict that rests on
        it would change with how busy the computer is, so the jobs that give verdicts drop it.
        """
        simulation = copy.copy(self.simulation)
        object.__setattr__(simulation, "max_wall_time", math.inf)  # not a user input: past the file's checks
        return replace(self, simulation=simulation)

    def describe(self) -> dict:
        """Inputs with units in the keys, for files and reports."""
        r = self.rotor
        out = {"name": self.name, "orientation": self.orientation, "source": self.source,
               "rotor": {"mass_kg": r.mass, "polar_inertia_kg_m2": r.polar_inertia,
                         "transverse_inertia_kg_m2": r.transverse_inertia, "speed_rpm": r.speed * 30.0 / math.pi,
                         "unbalance_um": r.unbalance * 1e6, "unbalance_phase_deg": math.degrees(r.unbalance_phase),
                         "couple_unbalance_mrad": r.couple_unbalance * 1e3,
                         "couple_unbalance_phase_deg": math.degrees(r.couple_unbalance_phase),
                         "axial_force_N": r.axial_force, "side_force_N": [r.side_force_x, r.side_force_y]},
               "structure": _describe_structure(r),
               "planes": [_describe_plane(p) for p in self.planes],
               "stations": [kind.describe(s) for kind in station_kinds() for s in of_kind(self.stations, kind.KIND)],
               # the file's keys with the values as its reader would type them, unit included ("25 degC")
               "drop": {p.key: display_value(p, getattr(self.simulation, p.key)) for p in SIMULATION},
               "coastdown": {**{p.key: display_value(p, getattr(self.coastdown, p.key)) for p in COASTDOWN},
                             "vacuum": self.coastdown.vacuum},
               "life": {**{p.key: display_value(p, getattr(self.life, p.key)) for p in LIFE},
                        "dent_accumulation": self.life.dent_accumulation}}
        return out


def _describe_plane(p: TouchdownPlane) -> dict:
    out = {"name": p.name, "bearing": p.unit.describe(), "position_mm": p.position * 1e3,
           "radial_clearance_mm": p.radial_clearance * 1e3, "journal_radius_mm": p.journal_radius * 1e3,
           "race_mass_kg": p.race_mass, "race_inertia_kg_m2": p.race_inertia,
           "line_stiffness_N_per_m10_9": p.line_stiffness, "line_damping_N_s_per_m": p.line_damping,
           "ball_damping_N_s_per_m": p.ball_damping, "ball_constant_N_per_m1_5": p.ball_constant,
           "sliding_friction": p.sliding_friction, "rolling_friction": p.rolling_friction,
           "slip_velocity_m_per_s": p.slip_velocity, "shoulder_height_mm": p.shoulder_height * 1e3,
           "misalignment_um": [p.misalignment[0] * 1e6, p.misalignment[1] * 1e6], "from_defaults": list(p.defaults)}
    if p.axial_room is not None:
        out["axial_room_mm"] = p.axial_room * 1e3
    if p.catches_axially:
        out.update(axial_clearance_mm=p.axial_clearance * 1e3, axial_direction=p.axial_direction,
                   face_stiffness_N_per_m=p.face_stiffness, face_damping_N_s_per_m=p.face_damping,
                   face_friction=p.face_friction, face_radius_mm=p.face_radius * 1e3)
    if p.mount is not None:
        m = p.mount
        # the file's own key names (mount_stiffness, ...) with the unit after them: one name from file to report
        out["mount"] = {"mount_stiffness_N_per_m": m.mount_stiffness, "mount_damping_N_s_per_m": m.mount_damping,
                        "mount_mass_kg": m.mount_mass, "mount_deadband_um": m.mount_deadband * 1e6,
                        "mount_stop_um": None if m.mount_stop is None else m.mount_stop * 1e6,
                        "stop_stiffness_N_per_m": m.stop_stiffness, "stop_damping_N_s_per_m": m.stop_damping,
                        "mount_travel_mm": m.mount_travel * 1e3}
    return out


# ----------------------------------------------------------------------------- building planes
def _density(bearing: BearingGeometry) -> float:
    return bearing.ring_material.density or STEEL_DENSITY


def make_plane(bearing: BearingGeometry | DuplexSet, values: dict, name: str, index: int) -> TouchdownPlane:
    """A plane from SI values of a ``[[touchdown]]`` table, every missing value derived (see the table).

    A matched pair's rows are each the one bearing its geometry comes from; the race (both inner rings and
    the spacer between them, on one journal) is as wide as the set.
    """
    where = f"touchdown.{index}."
    bearing_set = None
    if isinstance(bearing, DuplexSet):
        bearing_set, bearing = bearing, bearing.row
    given = dict(values)
    filled: list[str] = []

    def value(key):
        if given.get(key) is not None:
            return given[key]
        filled.append(key)
        return default("touchdown", key)

    s = values["radial_clearance"]
    r = given.get("journal_radius")
    if r is None:
        if bearing.bore is None:
            raise InputError(f"{where}journal_radius: missing; bearing {bearing.name} has no bore to derive it from")
        r = 0.5 * bearing.bore - s
        filled.append("journal_radius")
        if r <= 0.0:
            raise InputError.for_field(where + "radial_clearance", f"{s * 1e3:g} mm",
                                       f"must be below the race bore radius {0.5e3 * bearing.bore:g} mm")
    bore_radius = r + s
    if bore_radius >= 0.5 * bearing.inner_raceway_diameter:
        raise InputError.for_field(where + "journal_radius", f"{r * 1e3:g} mm",
                                   f"journal_radius + radial_clearance = {bore_radius * 1e3:g} mm must be below the "
                                   f"inner raceway radius {0.5e3 * bearing.inner_raceway_diameter:g} mm")
    width = bearing.width if bearing_set is None else bearing_set.width
    race_mass, race_inertia = given.get("race_mass"), given.get("race_inertia")
    if race_mass is None or race_inertia is None:
        if width is None:
            raise InputError(f"{where}race_mass: missing; bearing {bearing.name} has no width to derive it from")
        m_ring, j_ring = hollow_cylinder(_density(bearing), bore_radius, 0.5 * bearing.inner_raceway_diameter, width)
        if race_mass is None:
            race_mass = m_ring
            filled.append("race_mass")
        if race_inertia is None:
            race_inertia = j_ring if "race_mass" in filled else race_mass * 0.5 * (
                bore_radius**2 + (0.5 * bearing.inner_raceway_diameter) ** 2)
            filled.append("race_inertia")
    k_l = given.get("line_stiffness")
    if k_l is None:
        if width is None:
            raise InputError(f"{where}line_stiffness: missing; bearing {bearing.name} has no width for Palmgren's K_l")
        k_l = float(line_contact_constant(width, bearing.ring_material.compliance + JOURNAL_COMPLIANCE))
        filled.append("line_stiffness")
    axial = given.get("axial_clearance")
    direction = str(values.get("axial_direction", "both"))
    face = {}
    if axial is not None:
        if direction not in AXIAL_DIRECTIONS:
            raise InputError.for_field(where + "axial_direction", direction, "must be both, +z or -z")
        face_radius = given.get("face_radius")
        if face_radius is None:
            face_radius = 0.5 * (bore_radius + 0.5 * bearing.inner_raceway_diameter)
            filled.append("face_radius")
        elif not bore_radius <= face_radius <= 0.5 * bearing.inner_raceway_diameter:
            # the axial contact is the inner ring's side face against its shoulder: between the bore and the raceway
            raise InputError.for_field(where + "face_radius", values.get("face_radius"),
                                       f"must lie on the inner ring's face of {bearing.name}, between its bore radius "
                                       f"{bore_radius * 1e3:g} mm and its raceway radius "
                                       f"{0.5 * bearing.inner_raceway_diameter * 1e3:g} mm")
        face_k = given.get("face_stiffness")
        if face_k is None:
            area = math.pi * ((0.5 * bearing.inner_raceway_diameter) ** 2 - bore_radius**2)
            face_k = steel_column_stiffness(bearing.ring_material.elastic_modulus, area, width or bearing.ball_diameter)
            filled.append("face_stiffness")
        friction = given.get("face_friction")
        face = {"axial_clearance": axial, "axial_direction": direction, "face_stiffness": face_k,
                "face_damping": value("face_damping"),
                "face_friction": value("sliding_friction") if friction is None else friction,
                "face_radius": face_radius}
    mount = None
    if given.get("mount_stiffness") is not None:
        m_mass = given.get("mount_mass")
        if m_mass is None:
            if bearing.outside_diameter is None or width is None:
                raise InputError(f"{where}mount_mass: missing; bearing {bearing.name} has no outside diameter/width")
            m_mass = hollow_cylinder(_density(bearing), 0.5 * bearing.outer_raceway_diameter,
                                     0.5 * bearing.outside_diameter, width)[0]
            filled.append("mount_mass")
        stop = given.get("mount_stop")
        stop_k = given.get("stop_stiffness") or 100.0 * given["mount_stiffness"]
        deadband = value("mount_deadband")
        travel = given.get("mount_travel") or (2.0 * stop if stop is not None else max(10.0 * s, 2.0 * deadband))
        mount = Mount(given["mount_stiffness"], value("mount_damping"), m_mass, deadband, stop, stop_k,
                      value("stop_damping"), travel)
    shoulder = given.get("shoulder_height")
    if shoulder is None:
        shoulder = SHOULDER_FRACTION * bearing.ball_diameter
        filled.append("shoulder_height")
    elif shoulder >= 0.5 * bearing.ball_diameter:
        # a land at or past the ball's centre could not let the ball in: a typing slip that would switch off the
        # contact ellipse's shoulder limit
        raise InputError.for_field(where + "shoulder_height", values.get("shoulder_height"),
                                   f"must be below the ball radius of {bearing.name}, "
                                   f"{0.5 * bearing.ball_diameter * 1e3:g} mm")
    return TouchdownPlane(
        name=name, bearing=bearing, position=value("position"), radial_clearance=s, journal_radius=r,
        race_mass=race_mass, race_inertia=race_inertia, line_stiffness=k_l, line_damping=value("line_damping"),
        ball_damping=value("ball_damping"), ball_constant=given.get("ball_constant"),
        sliding_friction=value("sliding_friction"), rolling_friction=value("rolling_friction"),
        slip_velocity=value("slip_velocity"), mount=mount,
        misalignment=(value("misalignment_x"), value("misalignment_y")), shoulder_height=shoulder,
        lubricant_viscosity=value("lubricant_viscosity"), viscous_factor=value("viscous_factor"),
        housing_mass=given.get("housing_mass"), housing_to_ambient=given.get("housing_to_ambient"),
        journal_to_ambient=given.get("journal_to_ambient"), emissivity=value("emissivity"),
        journal_pressure_limit=value("journal_pressure_limit"), defaults=tuple(dict.fromkeys(filled)),
        bearing_set=bearing_set, axial_room=given.get("axial_room"), **face)


# ----------------------------------------------------------------------------- reading files
def _text(table: dict, key: str, where: str, fallback: str) -> str:
    value = table.get(key, fallback)
    if not isinstance(value, str) or not value.strip():
        raise InputError.for_field(where + key, value, "must be a non-empty text")
    return value.strip()


def _inline_pair(row: BearingGeometry, arrangement: object, field: str) -> DuplexSet:
    """A matched pair of an inline bearing table's row (its ``arrangement`` key; the preload is the plane's key)."""
    from auxbearing.bearings.duplex import ARRANGEMENTS, duplex_set

    text = str(arrangement).strip().upper()
    if text not in ARRANGEMENTS:
        raise InputError.for_field(field, arrangement, "must be one of " + ", ".join(ARRANGEMENTS))
    if row.type != "angular_contact":
        raise InputError.for_field(field, arrangement, f"a matched pair needs an angular-contact row; this row is "
                                   f"{row.label}")
    return duplex_set(row, text, name=f"{row.name} {text}")


def with_preload(bearing, preload, field: str) -> DuplexSet:
    """A matched pair with its preload given apart from its name (a class, a force or an axial offset)."""
    from auxbearing.bearings.duplex import duplex_set

    if not isinstance(bearing, DuplexSet):
        raise InputError.for_field(field, preload, f"only a matched pair takes a preload ({bearing.name} is one "
                                   "bearing; name a pair such as '7208 DB')")
    text = str(preload).strip()
    try:
        return duplex_set(bearing.row, bearing.arrangement, preload=text, spacer=bearing.spacer,
                          name=f"{bearing.row.name} {bearing.arrangement} {text}")
    except InputError as err:
        raise InputError(f"{field} = {preload!r}: {str(err).split(': ', 1)[-1]}") from None


def _describe_structure(rotor: MachineRotor) -> dict | None:
    """The rotor's matrices as the reports name them (None: a rigid rotor)."""
    modal = rotor.modal()
    if modal is None:
        return None
    return {"source": rotor.structure.source, "nodes": len(modal.nodes), "mass_centre_mm": modal.centre * 1e3,
            "max_mode_frequency_Hz": rotor.max_mode_frequency, "modal_damping_ratio": rotor.modal_damping,
            "reduction": rotor.reduction,
            "free_free_modes_Hz": [float(f) / (2.0 * math.pi) for f in modal.frequencies]}


def _ross_rotor(rotor_table: dict, base: Path | None) -> tuple:
    """``rotor.ross_file`` (and ``rotor.ross_bearings``): the structure and, kept, the ROSS rotor's bearings.

    From Python, ``ross_file`` may also be a ``ross.Rotor`` itself (the rotor a script built, never saved).
    """
    from auxbearing.machine.ross_rotor import BEARINGS, read_ross_file, structure_from_ross, supports_from_ross

    given = rotor_table["ross_file"]
    keep = rotor_table.pop("ross_bearings", "keep")
    if keep not in BEARINGS:
        raise InputError.for_field("rotor.ross_bearings", keep, f"must be one of {', '.join(BEARINGS)}")
    if hasattr(given, "shaft_elements") and hasattr(given, "disk_elements"):  # a ross.Rotor
        rotor, spec = given, f"{type(given).__name__} given from Python"
    else:
        spec = _text(rotor_table, "ross_file", "rotor.", "")
        rotor = read_ross_file(spec, base, "rotor.ross_file")
    del rotor_table["ross_file"]
    speed = accept(TABLES["rotor"]["speed"], rotor_table.get("speed"), "rotor.speed") if "speed" in rotor_table \
        else 0.0
    supports = supports_from_ross(rotor, speed or 0.0) if keep == "keep" else ()
    source = Path(spec).name
    try:
        structure = structure_from_ross(rotor, source)
    except InputError as err:  # its checks name rotor.matrices, the key of a .npz: this rotor is rotor.ross_file
        text, prefix = str(err), f"rotor.matrices = {source!r}: "
        if not text.startswith(prefix):
            raise
        raise InputError.for_field("rotor.ross_file", spec, text[len(prefix):]) from None
    return structure.with_key("rotor.ross_file", spec), supports


def _shifted(station, centre: float):
    """A station read from a file with rotor.matrices: its positions from the mass centre inside."""
    if not centre:
        return station
    changes = {"position": station.position - centre}
    if getattr(station, "sensor_position", None) is not None:
        changes["sensor_position"] = station.sensor_position - centre
    return replace(station, **changes)


def _read_unbalance(tables) -> tuple:
    """The ``[[unbalance]]`` planes: (position [m], U [kg m], phase [rad]) each."""
    if tables is None:
        return ()
    if not isinstance(tables, list) or not all(isinstance(t, dict) for t in tables):
        raise InputError.for_field("unbalance", tables, "give one [[unbalance]] table per plane")
    planes = []
    for i, table in enumerate(tables):
        values = read_table(table, TABLES["unbalance"], f"unbalance.{i}.")
        for key in ("position", "amount"):
            if key not in values:
                raise InputError(f"unbalance.{i}.{key}: missing; every [[unbalance]] needs position and amount")
        planes.append((values["position"], values["amount"], values.get("phase", 0.0)))
    return tuple(planes)


#: ``[rotor]`` keys of an elastic rotor alone (its modes and their reduction).
ELASTIC_ONLY = ("max_mode_frequency", "modal_damping", "reduction")


def machine_from_mapping(data: dict, name: str = "machine", base: Path | None = None) -> Machine:
    """A machine from the tables of a machine TOML file (values with units); every key checked first.

    The machine's own tables are read here, with the values no machine can have together
    (:func:`auxbearing.machine.combinations.check_combinations`); a whole file, its ``[criteria]``, ``[verify]``,
    ``[[candidate]]`` and ``[campaign]`` tables too, is checked by
    :func:`auxbearing.machine.check.check_machine_document` (what :func:`read_machine` does).
    """
    from auxbearing.machine.combinations import check_combinations

    allowed = ("machine", "rotor", "unbalance", "touchdown", *STATION_TABLES, "scenario", "drop", "coastdown", "life",
               *OTHER_TABLES)
    for key in data:
        if key not in allowed:
            raise unknown(f"[{key}]", "table", key, allowed, "table")
    head = data.get("machine", {})
    if not isinstance(head, dict):
        raise InputError.for_field("machine", head, "must be a table")
    for key in head:
        if key not in MACHINE_KEYS:
            raise unknown(f"machine.{key}", head[key], key, MACHINE_KEYS)
    rotor_table = data.get("rotor")
    structure = None
    ross_supports: tuple = ()
    if isinstance(rotor_table, dict):  # every key, text ones included, before any is taken out of the table
        for key in rotor_table:
            if key not in TABLES["rotor"] and key not in ROTOR_TEXT:
                raise unknown(f"rotor.{key}", rotor_table[key], key, [*TABLES["rotor"], *ROTOR_TEXT])
        if "ross_bearings" in rotor_table and "ross_file" not in rotor_table:
            raise InputError.for_field("rotor.ross_bearings", rotor_table["ross_bearings"], "applies to a rotor "
                                       "given by rotor.ross_file (its bearings and seals); this rotor has none")
    if isinstance(rotor_table, dict) and "matrices" in rotor_table and "ross_file" in rotor_table:
        raise InputError.for_field("rotor.ross_file", rotor_table["ross_file"], "give rotor.matrices or "
                                   "rotor.ross_file, not both")
    if isinstance(rotor_table, dict) and "matrices" in rotor_table:
        rotor_table = dict(rotor_table)
        structure = read_structure(_text(rotor_table, "matrices", "rotor.", ""), base, "rotor.matrices")
        del rotor_table["matrices"]
    elif isinstance(rotor_table, dict) and "ross_file" in rotor_table:
        rotor_table = dict(rotor_table)
        structure, ross_supports = _ross_rotor(rotor_table, base)
    reduction = "static_correction"  # text, not a number: MachineRotor checks it
    if isinstance(rotor_table, dict) and "reduction" in rotor_table and structure is not None:
        rotor_table = dict(rotor_table)
        reduction = rotor_table.pop("reduction")
    rotor_values = read_table({k: v for k, v in rotor_table.items() if k != "reduction"}
                              if isinstance(rotor_table, dict) else rotor_table, TABLES["rotor"], "rotor.")
    if structure is None:  # what only an elastic rotor reads would be quietly dropped on a rigid one
        for key in ELASTIC_ONLY:
            if isinstance(rotor_table, dict) and key in rotor_table:
                raise InputError.for_field(f"rotor.{key}", rotor_table[key], "applies to a rotor given by its "
                                           "matrices (rotor.matrices or rotor.ross_file); this rotor is rigid")
    if structure is None and "polar_inertia" in rotor_values and rotor_values.get("transverse_inertia"):
        _check_inertia_pair(rotor_values["polar_inertia"], rotor_values["transverse_inertia"],
                            rotor_table["polar_inertia"], rotor_table["transverse_inertia"])
    if structure is not None:
        for key in ("mass", "polar_inertia", "transverse_inertia"):
            if key in rotor_values:
                raise InputError.for_field(f"rotor.{key}", rotor_table[key],
                                           "comes from the rotor's matrices (rotor.matrices or rotor.ross_file); "
                                           "give one or the other")
        body = modal_rotor(structure)
        check_spinning(structure, body)  # before the rotor is built: its unbalance planes divide by J_t - J_p
        rotor_values.update(mass=body.mass, polar_inertia=body.polar_inertia,
                            transverse_inertia=body.transverse_inertia)
    for key in ("mass", "polar_inertia", "speed"):
        if key not in rotor_values:
            raise InputError(f"rotor.{key}: missing; a machine's [rotor] needs mass, polar_inertia and speed "
                             "(or rotor.matrices and speed)")
    # with rotor.matrices every position in the file is a coordinate of its nodes; inside, from the mass centre
    centre = 0.0 if structure is None else modal_rotor(structure).centre
    planes_of_unbalance = tuple((a - centre, u, b) for a, u, b in _read_unbalance(data.get("unbalance")))
    if planes_of_unbalance:
        for key in ("unbalance", "unbalance_phase", "couple_unbalance", "couple_unbalance_phase"):
            if key in rotor_values:
                raise InputError.for_field(f"rotor.{key}", rotor_table[key], "comes from the [[unbalance]] planes; "
                                           "give one or the other")
    rotor = MachineRotor(**{k: rotor_values.get(k, default("rotor", k)) for k in TABLES["rotor"]},
                         structure=structure, unbalance_planes=planes_of_unbalance, reduction=reduction)
    tables = data.get("touchdown")
    if not isinstance(tables, list) or not tables or not all(isinstance(t, dict) for t in tables):
        raise InputError.for_field("touchdown", tables, "give one or more [[touchdown]] tables")
    planes = []
    positions: list[float] = []  # in the file's own frame, as written: an error quotes the user's text
    names: dict[str, int] = {}
    for k, table in enumerate(tables):
        where = f"touchdown.{k}."
        for key in table:
            if key not in TABLES["touchdown"] and key not in TOUCHDOWN_TEXT:
                raise unknown(where + key, table[key], key, [*TOUCHDOWN_TEXT, *TABLES["touchdown"]])
        numbers = {key: v for key, v in table.items() if key not in TOUCHDOWN_TEXT}
        values = read_table(numbers, TABLES["touchdown"], where)
        if "radial_clearance" not in values:
            raise InputError(f"{where}radial_clearance: missing; every [[touchdown]] needs it")
        if isinstance(table.get("bearing"), dict):  # an inline [touchdown.bearing] table
            inline = dict(table["bearing"])
            arrangement = inline.pop("arrangement", None)  # a matched pair of this row
            try:
                bearing = bearing_from_mapping(inline, name=f"plane {k} bearing", prefix=where + "bearing.")
            except InputError as err:
                raise InputError(str(err)) from None
            if arrangement is not None:
                bearing = _inline_pair(bearing, arrangement, where + "bearing.arrangement")
        else:
            bearing = read_bearing_spec(_text(table, "bearing", where, ""), base, where + "bearing")
        if "preload" in table:
            from auxbearing.bearings.catalogue import split_name

            named = (split_name(table["bearing"], where + "bearing").preload
                     if isinstance(table.get("bearing"), str) else None)
            if named is not None:  # two preloads for one pair: neither may quietly win
                raise InputError.for_field(where + "preload", table["preload"], f"the bearing's name gives its "
                                           f"preload already ({table['bearing']!r}); give it once")
            bearing = with_preload(bearing, table["preload"], where + "preload")
        values["axial_direction"] = _text(table, "axial_direction", where, "both")
        if "position" not in values and len(tables) >= 2:
            raise InputError(f"{where}position: missing; required with two planes or more")
        if "position" in values:
            for j, other in enumerate(positions):
                if abs(other - values["position"]) < 1e-6:
                    raise InputError.for_field(where + "position", table["position"], "touchdown planes must sit at "
                                               f"different axial positions (touchdown.{j} sits there too)")
            positions.append(values["position"])
        name = _text(table, "name", where, f"plane {k}")
        if name in names:
            # blame the name the user wrote, not the default an unnamed plane took
            j = names[name]
            written, other = (k, j) if "name" in table else (j, k)
            raise InputError.for_field(f"touchdown.{written}.name", name, f"touchdown.{other} has this name too"
                                       + ("" if "name" in tables[other] else ", the default of a plane without one")
                                       + "; give each plane its own name")
        names[name] = k
        if structure is not None:  # the file's node coordinates, from the mass centre inside
            if "position" not in values:
                raise InputError(f"{where}position: missing; with rotor.matrices every plane sits on a node")
            values["position"] -= centre
        try:
            planes.append(make_plane(bearing, values, name, k))
        except InputError as err:  # its checks are made on SI values: tell them with the values as the file wrote them
            raise as_typed(err, table, where) from None
    sim_values = read_table(data.get("drop"), TABLES["drop"], "drop.")
    if not isinstance(data.get("coastdown") or {}, dict):
        raise InputError.for_field("coastdown", data["coastdown"], "must be a table of keys")
    coast = dict(data.get("coastdown") or {})
    for key in coast:  # the text keys too: read_table's own list would leave them out
        if key not in TABLES["coastdown"] and key not in COASTDOWN_TEXT:
            raise unknown(f"coastdown.{key}", coast[key], key, [*TABLES["coastdown"], *COASTDOWN_TEXT])
    vacuum = coast.pop("vacuum", False)
    if not isinstance(vacuum, bool):
        raise InputError.for_field("coastdown.vacuum", vacuum, "must be true or false")
    coast_values = read_table(coast, TABLES["coastdown"], "coastdown.")
    life_table = dict(data.get("life") or {}) if isinstance(data.get("life") or {}, dict) else data.get("life")
    accumulation = life_table.pop("dent_accumulation", "same_spot") if isinstance(life_table, dict) else "same_spot"
    life_values = read_table(life_table, TABLES["life"], "life.")
    stations = tuple(_shifted(s, centre) for s in ross_supports) + tuple(
        _shifted(s, centre) for kind in station_kinds() for s in kind.read(data.get(kind.KIND)))
    machine = Machine(name=_text(head, "name", "machine.", name), rotor=rotor, planes=tuple(planes),
                      orientation=_text(head, "orientation", "machine.", "horizontal"),
                      simulation=Simulation(**sim_values), source=str(head.get("source", "user input")),
                      coastdown=Coastdown(**coast_values, vacuum=vacuum),
                      life=Life(**life_values, dent_accumulation=accumulation, given=tuple(life_values)),
                      stations=stations, scenarios=tuple(s.shifted(centre) for s in read_scenarios(
                          data.get("scenario"), of_kind(stations, "amb"))))
    check_combinations(data, machine)
    return machine


def read_bearing_spec(spec: str, base: Path | None, field: str) -> BearingGeometry:
    """A bearing named in a machine file: a catalogue name, or a bearing TOML file (relative to ``base``).

    ``field`` names it in an error (``touchdown.0.bearing``, ``candidate.1.bearing``).
    """
    from auxbearing.bearings.catalogue import get_bearing
    from auxbearing.common.io import read_toml

    path = Path(spec) if base is None or Path(spec).is_absolute() else base / spec
    if spec.lower().endswith(".toml") or path.is_file():
        table = read_toml(path, field)
        if "bearing" not in table:
            raise InputError.for_field(field, spec, "this file has no [bearing] table")
        return bearing_from_mapping(table["bearing"], name=path.stem)
    return get_bearing(spec, field)


__all__ = ["G0", "Coastdown", "Life", "Machine", "MachineRotor", "Mount", "Simulation", "TouchdownPlane",
           "machine_from_mapping", "make_plane", "read_bearing_spec"]
