"""The coast-down's reduced model against full dynamics, on every shipped example and verify candidate.

The reduced model (auxbearing.core.spin, states chosen by auxbearing.analysis.coastdown_phases) must reproduce full
dynamics where it runs: over the same simulated time, the rotor's speed within 2 % (of the speed lost) and
every part's peak temperature within 2 K, the smallest clearances within 2 % of their change, the damage per
drop within 2 % (over these 4 s the rattling non-drive ends of the blower and its candidates within 6 %, the
scatter of their chaotic rattle: :data:`DAMAGE_TOLERANCE`). Full dynamics costs 1-3 s of computing per
simulated second on these machines, so the comparison runs the first seconds here: 4 s, of which the reduced
model carries 1.2-2.9 s once the journals' motion after the drop has stopped changing
(coastdown_phases.motion_steady), none on the paper rigs (:data:`IN_PASSAGE`); the closing note of the coast-down
issue gives the same table to standstill, made by this module's `compare`.
"""

import copy
import math

import pytest

from auxbearing.analysis.coastdown import run_coastdown
from auxbearing.machine.files import machine_table, read_machine
from auxbearing.machine.judging import candidate_tables
from auxbearing.machine.model import machine_from_mapping

#: Simulated seconds of the comparison in the test suite.
HORIZON = 4.0
#: Longer where the handover comes later: the 7208 DB pair's races turn two rows of oil (Palmgren's M_0 of both),
#: which spins its non-drive end's race up to rolling only 3.8 s after the failure (0.99 of the rolling speed).
HORIZONS = {"blower:7208 DB light": 8.0}


def _machine(case: str):
    spec, _, candidate = case.partition(":")
    if not candidate:
        return read_machine(spec)
    data, name, base = machine_table(spec)
    (label, tables), = candidate_tables(data, [candidate])
    return machine_from_mapping(tables, f"{name} with {label}", base)


def compare(machine, duration: float | None) -> dict:
    """Auto against full dynamics over ``duration`` seconds (None: to standstill); both summaries."""
    until_stop = duration is None
    auto = run_coastdown(machine, until_stop=until_stop, duration=duration, mode="auto").summary
    full = run_coastdown(machine, until_stop=until_stop, duration=duration, mode="full").summary
    return {"auto": auto, "full": full}


#: Every shipped example whose drop ends in range (the heavy rotor's drop runs a ball over its groove shoulder, so it
#: has no coast-down) and the blower's verify candidates (7208 DB light, QJ208 hybrid, 6208), with the 7208.
CASES = ["paper_rig", "paper_rig_two_planes", "blower", "blower:7208", "blower:6208", "blower:7208 DB light",
         "blower:QJ208 hybrid", "vertical", "compressor"]
#: Damage per drop over the first 4 s where the few windows after the handover set the load of most of the
#: reduced revolutions (1.2-1.7 s of them) and a rattle's windows scatter. A rattle is chaotic: the last bits of
#: the arithmetic move it. Measured over five runs of each blower case whose unbalance phase differed by 0 to
#: 4e-9 rad, auto against full dynamics: the drive ends within 1.6 % in every run; the non-drive ends, loaded at
#: 0.4 of their drive ends and rattling, by run the blower +1.2 / -1.5 / +0.6 / -2.4 / +1.8 %, the 6208 -1.9 /
#: +0.5 / -3.0 / -3.8 / -1.9 %, the 7208 -4.6 / +2.4 / -5.1 / -0.3 / -0.9 % (full dynamics alone moved by 5 %),
#: the hybrid +2.4 / -2.7 / +0.7 / +1.6 / -1.5 %, the 7208 DB pair +1.9 to +2.3 %. So the suite holds these
#: planes, over 4 s, to 6 %; the 2 % over 30 s, where the rattle averages out, is the comparison this module's
#: `compare` makes for the closing notes (and, from an earlier version, 7208's drive end -2.0 % here).
#: The DB pair's journals have two rattles at these speeds, a small one (mean square orbit
#: speed about 4e-5 m^2/s^2) and a large one (1.5e-4 at the drive end, 2.7e-4 at the non-drive end, 2-4 % more
#: load). Between about 17 000 and 15 000 rpm the small one is unstable: full dynamics leaves it 4-8 s after the
#: failure (the time moves with the window length) and keeps the large one until about 16 s; started from the
#: reduced run's state at 8 s, full dynamics grew to the large rattle within 5 s, from its state at 18 s it did
#: not. The reduced run stays on the small rattle, whose windows (30 ms of motion per stretch) grow too slowly to
#: leave it: -3.3 / -5.6 % over 30 s against full dynamics converged in its tolerances (at the default
#: tolerances full dynamics' own damage is 1.2 / 2.4 % low; tolerances 3.3 and 10 times tighter agree within 0.04 %).
#: To standstill at phase 0, in 1000 rpm bands of over-rolling: the non-drive end's whole deficit (-3.9 %) lies
#: between 17 000 and 14 000 rpm, where the reduced run carries 94.5-99.7 N against full dynamics' 97.2-102.3 N;
#: below, the bands agree within 0.5 N. No test on the windows catches the growth: a first-versus-last span trend
#: of 5 % or 3 % instead of 10 % gave -2.67 / -3.07 % (four phases), and the motion confirmed steady again over
#: 0.9 s after every stretch (7538 windows instead of 545) still -3.21 +- 0.75 %. Only holding the first stretch
#: until 8 s after the failure catches the transient (+0.26 +- 2.60 %), at twice the windows of every coast-down
#: (about 540 -> 1100) and with the 6208's non-drive end at +2.11 %.
#: What grows is the journals' swing along the bore (the square of a window's mean whirl speed times the radius):
#: in full dynamics it falls after the drop to about 2e-6 m^2/s^2 at 1.5-2 s, then doubles every 0.6-0.8 s to a
#: level it keeps from 6.6 s on (about 1.4e-4 at the drive end, 7e-5 at the non-drive end); with tolerances ten
#: times tighter it starts twice as high and saturates 1.5 s sooner at the same level, so the growth is the
#: model's and its start the numerics'. The reduced run's first stretch comes at that minimum (span means 3.0, 2.3,
#: 2.2e-6 m^2/s^2), where nothing grows yet. Tried, four phases: no first stretch while the swing's last span
#: exceeds its first by the trend allowance (non-drive end unchanged, -2.96 %; the hybrid's windows doubled); the
#: same and the motion confirmed again after the first stretch (the large rattle caught, then held too long:
#: non-drive end +8.13 %, the 6208's drive end -4.14 %).
#: Since a stretch hands a spin-locked journal back at the new speed's pace
#: (auxbearing.analysis.coastdown_phases.spin_locked), every drive end is within 1.2 % here (the QJ208 hybrid's
#: +0.71 %, before -2.2 %; the 7208's -0.74 %) and held to the 2 %; the non-drive ends were -2.01 to +1.17 %.
#: With both rows' oil and heat in the pair's plane, its load falls from 99 to 70 N within 250 rpm near 13 600 rpm
#: instead, and the stretch across that step is measured inside (coastdown_phases.StretchEnd): to standstill over
#: four phases its drive end +1.30 +- 0.13 %, its non-drive end +3.09 +- 0.27 % (+4.82 % charged linearly).
#: With a rattle's first 0.1 s after each stretch left unjudged, the blower's drive end was +2.18 % here (held to 3 %
#: then); with those windows judged and the next stretch started where they agree (coastdown.RATTLE_SETTLE), over
#: these 4 s at phase 0: blower -0.53 / -0.23 %, DB pair +0.13 / +0.46 %, hybrid +0.71 / -1.61 %, 6208 +0.52 / -0.22 %,
#: 7208 -0.74 / -0.26 %, compressor +0.17 / -0.14 %.
DAMAGE_TOLERANCE = {(case, 1): 0.06 for case in ("blower", "blower:7208", "blower:6208", "blower:7208 DB light",
                                                 "blower:QJ208 hybrid")}


#: The paper rigs' journals rest in their bores from the drop's end on (in contact all of every window), swinging
#: with about 60 % of the energy that lifts them off, in the passage through three times their rolling pendulum
#: (4440-6020 rpm, their first 12.6 s): no stretch may carry that swing
#: (auxbearing.analysis.coastdown_phases.pendulum_swinging), so over these 4 s the reduced run is full dynamics, to
#: the last digit.
IN_PASSAGE = ("paper_rig", "paper_rig_two_planes")


@pytest.mark.slow
@pytest.mark.parametrize("case", CASES)
def test_reduced_model_agrees_with_full_dynamics(case):
    machine = _machine(case)
    both = compare(machine, HORIZONS.get(case, HORIZON))
    auto, full = both["auto"], both["full"]
    assert auto["verdict"] == full["verdict"] == "ok"
    if case in IN_PASSAGE:
        assert auto["reduced_model_s"] == 0.0
        assert auto["planes"] == full["planes"]
    else:
        assert auto["reduced_model_s"] > 0.0  # the comparison reaches past the handover
    start = abs(machine.rotor.speed) * 30.0 / math.pi
    lost_auto = start - abs(auto["final_rotor_speed_rpm"])
    lost_full = start - abs(full["final_rotor_speed_rpm"])
    assert lost_auto == pytest.approx(lost_full, rel=0.02)
    for k, (pa, pf, plane) in enumerate(zip(auto["planes"], full["planes"], machine.planes, strict=True)):
        for node, value in pa["max_temperature_C"].items():
            assert value == pytest.approx(pf["max_temperature_C"][node], abs=2.0), (plane.name, node)
        closing = plane.bearing.diametral_clearance * 1e6 - pf["min_internal_clearance_um"]
        assert pa["min_internal_clearance_um"] == pytest.approx(pf["min_internal_clearance_um"],
                                                                abs=max(0.02 * abs(closing), 0.05))
        # abs=0: damages of 1e-13 to 1e-10 per drop lie below pytest.approx's own absolute tolerance of 1e-12
        tolerance = DAMAGE_TOLERANCE.get((case, k), 0.02)
        assert pa["damage_per_drop"] == pytest.approx(pf["damage_per_drop"], rel=tolerance, abs=0.0), (plane.name,)


def _blower_with_drop(duration: str):
    """The blower braked harder (0.2 N m of drag), run to 500 rpm in reduced stretches of up to 30 % of the speed:
    the same handover after the drop window, at 37 s of computing for the pair instead of three minutes."""
    data, _, base = machine_table("blower")
    data = copy.deepcopy(data)
    data["drop"]["duration"] = duration
    data["coastdown"].update(drag_torque="0.2 N*m", stop_speed="500 rpm", speed_step=0.3)
    for key in ("criteria", "candidate"):
        data.pop(key)
    return machine_from_mapping(data, "blower", base)


@pytest.mark.slow
def test_time_to_standstill_does_not_depend_on_the_drop_window():
    """The drop window's length only moves where full dynamics hands over. Measured here: 79.413 s with 0.1 s and
    79.428 s with 0.3 s; the shipped blower to 1 rpm 223.43 s (0.1 s) and 223.32 s (0.4 s), to 200 rpm 212.16 s and
    212.03 s. Before the reduced model waited for the races to roll, a machine braked by rolling resistance
    alone moved its standstill time by a factor of 2.4 between windows of 0.1 s and 0.5 s."""
    short = run_coastdown(_blower_with_drop("0.1 s")).summary
    long = run_coastdown(_blower_with_drop("0.3 s")).summary
    assert short["reached_standstill"] and long["reached_standstill"]
    assert short["coastdown_time_s"] == pytest.approx(long["coastdown_time_s"], rel=0.01)

