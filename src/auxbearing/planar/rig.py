"""The source paper's drop rig as a machine: one plane at the mass centre, tilt and axial motion locked.

The paper (Sec. II.D, Table II; corrected per docs/paper_notes.md) drops a rigid rotor into one four-point
bearing; :func:`planar_machine` builds that rig from its drop parameters (:mod:`auxbearing.planar.params`)
as an ordinary machine, and :func:`run_drop` runs it with the summary keys the paper's figures use.
"""

from __future__ import annotations

import functools
import json
from collections.abc import Callable

import xarray as xr

from auxbearing.analysis.drop import planar_view, run_machine
from auxbearing.bearings.catalogue import load_bearing
from auxbearing.bearings.geometry import BearingGeometry
from auxbearing.common.errors import InputError
from auxbearing.common.io import to_jsonable
from auxbearing.machine.model import Machine, MachineRotor, Simulation, make_plane
from auxbearing.planar.params import DropCase, Rotor


def planar_machine(bearing: BearingGeometry, rotor, case) -> Machine:
    """The source paper's drop as a machine: one plane at the mass centre, tilt and axial motion locked.

    ``rotor`` and ``case`` are :class:`auxbearing.planar.params.Rotor` and ``DropCase``.
    """
    values = {"radial_clearance": case.clearance, "race_mass": case.race_mass, "race_inertia": case.race_inertia,
              "line_stiffness": case.line_stiffness, "line_damping": case.line_damping,
              "ball_damping": case.ball_damping, "ball_constant": case.ball_constant,
              "sliding_friction": case.sliding_friction, "rolling_friction": case.rolling_friction,
              "slip_velocity": case.slip_velocity, "journal_radius": rotor.radius}
    if rotor.radius is not None and bearing.bore is not None and abs(rotor.radius + case.clearance
                                                                      - 0.5 * bearing.bore) > 1e-9:
        raise InputError.for_field(
            "rotor.radius", f"{rotor.radius * 1e3:g} mm",
            f"rotor.radius + drop.clearance = {(rotor.radius + case.clearance) * 1e3:g} mm must equal the race bore "
            f"radius {bearing.bore * 500:g} mm (bore {bearing.bore * 1e3:g} mm); leave rotor.radius unset to derive it")
    plane = make_plane(bearing, values, bearing.name, 0)
    machine_rotor = MachineRotor(rotor.mass, rotor.polar_inertia, None, case.speed, rotor.eccentricity,
                                 case.unbalance_phase, start_x=case.start_x, start_y=case.start_y)
    sim = Simulation(duration=case.duration, output_step=case.output_step, rtol=case.rtol, atol=case.atol,
                     max_step=case.max_step, gravity=case.gravity)
    return Machine(f"paper drop on {bearing.name}", machine_rotor, (plane,), "horizontal", sim,
                   "source paper Sec. II.D, Table II")


def paper_rig() -> Machine:
    """The source paper's QJ202 drop with Table II and our stated defaults (a doctest helper)."""
    from auxbearing.bearings.catalogue import get_bearing
    from auxbearing.planar.params import DropCase, Rotor

    return planar_machine(get_bearing("QJ202"), Rotor(), DropCase())



def run_drop(bearing: str | BearingGeometry = "QJ202", rotor: Rotor | None = None, case: DropCase | None = None,
             progress: Callable[[float], None] | None = None) -> tuple[xr.Dataset, dict]:
    """The source paper's rotor drop (Sec. II.D, corrected per docs/paper_notes.md) as a one-plane machine.

    Returns the machine run's Dataset in its planar view (:func:`planar_view`) and a flat summary with the
    paper-drop keys:
    ``peak_contact_force_N``, ``peak_ball_stress_MPa`` (exact maxima: golden-section search on the
    dense output), ``s0``, ``first_impact_ms``, ``impacts``, ``largest_bounce_um``, ``whirl``,
    ``final_rotor_speed_rad_s``, ``final_race_speed_rad_s``, ``race_spin_up_ms``,
    ``contact_fraction``, ``steps``, ``wall_time_s`` and the run's ``verdict``.

    Examples
    --------
    >>> ds, s = run_drop("QJ202", case=DropCase(duration="20 ms"))
    >>> s["verdict"], round(s["peak_contact_force_N"], 1)
    ('ok', 657.1)
    """
    bearing = load_bearing(bearing)
    rotor = rotor or Rotor()
    case = case or DropCase()
    machine = planar_machine(bearing, rotor, case)
    run = run_machine(machine, progress=None if progress is None else (lambda f, _: progress(f)))
    plane = run.summary["planes"][0]
    keep = ("peak_contact_force_N", "peak_ball_stress_MPa", "s0", "first_impact_ms", "impacts", "largest_bounce_um",
            "whirl", "whirl_frequency_Hz", "backward_whirl_onset_ms", "final_race_speed_rad_s", "race_spin_up_ms",
            "contact_fraction", "peak_force_time_ms", "peak_stress_time_ms", "peak_ball_load_N")
    summary = {"bearing": bearing.name, "type": bearing.type, "verdict": run.summary["verdict"],
               "reason": run.summary["reason"], **{k: plane[k] for k in keep},
               "final_rotor_speed_rad_s": run.summary["final_rotor_speed_rad_s"],
               **{k: run.summary[k] for k in ("steps", "wall_time_s", "rejected_steps", "rhs_evaluations",
                                               "compile_or_cache_load_s", "energy_balance_error")},
               "rotor_radius_mm": machine.planes[0].journal_radius * 1e3, "clearance_mm": case.clearance * 1e3,
               "line_stiffness_N_per_m10_9": machine.planes[0].line_stiffness,
               "ball_constant_N_per_m1_5": _nominal_ball_constant(bearing, case),
               "ball_constant_source": "override" if case.ball_constant is not None else "Hertz (Eq. 15)",
               "sliding_friction": case.sliding_friction, "rtol": case.rtol}
    ds = planar_view(run.dataset)
    ds.attrs["summary"] = json.dumps(to_jsonable(summary))
    return ds, summary


def _nominal_ball_constant(bearing: BearingGeometry, case: DropCase) -> float:
    return case.ball_constant if case.ball_constant is not None else _hertz_ball_constant(bearing)


@functools.lru_cache(maxsize=64)
def _hertz_ball_constant(bearing: BearingGeometry) -> float:
    # exact elliptic integrals at the nominal angle: 15 ms, a tenth of a drop, so once per bearing
    from auxbearing.analysis.contact import ball_constant

    return float(ball_constant(bearing))
