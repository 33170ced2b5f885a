"""How far the convergence re-run of a coast-down goes when the verdict rests on an extreme over time.

The peak temperature is reached long before standstill (the blower's hottest part at 153 s of 215 s), so the
tighter run goes to a little past that time, not to standstill; when its own extreme is still coming there,
the whole run is made after all. The runs here are stand-ins: what is checked is what gets submitted.
"""

from types import SimpleNamespace

import numpy as np
import pytest
import xarray as xr

from auxbearing.machine.files import read_machine
from auxbearing.verify.cases import Cases
from auxbearing.verify.convergence import EXTREME_MARGIN, convergence_started
from auxbearing.verify.criteria import Criterion

HOTTEST = "peak bearing temperature"


def _run(peak_at: float, end: float, peak: float = 121.5, until_stop: bool = True):
    """A coast-down stand-in whose hottest part peaks at ``peak_at`` [s] on a run of ``end`` seconds."""
    time = np.linspace(0.0, end, 401)
    rise = (peak - 20.0) * np.exp(-(((time - peak_at) / (0.3 * end)) ** 2))
    temperature = np.stack([20.0 + rise, 20.0 + 0.5 * rise], axis=1)[:, :, None] * np.ones((1, 1, 3))
    history = xr.Dataset({"temperature": (("time", "plane", "node"), temperature)}, coords={"time": time})
    planes = [{"max_temperature_C": {"race": float(temperature[:, k].max())}} for k in range(2)]
    return SimpleNamespace(history=history, summary={"planes": planes, "until_stop": until_stop,
                                                     "simulated_s": end, "verdict": "ok"})


class Recorder:
    """An executor that answers each submission with the next prepared run and keeps what it was asked."""

    def __init__(self, *answers):
        self.answers = list(answers)
        self.asked = []

    def submit(self, fn, *args):
        self.asked.append(args[1:])
        answer = self.answers.pop(0)
        return SimpleNamespace(result=lambda: answer)


def _failing_hottest() -> list:
    return [Criterion(HOTTEST, 120.0, 121.5, -0.01, False, "degC", "upper", "given", "coast-down, drive end")]


def test_the_tighter_run_stops_a_little_past_the_first_runs_peak():
    machine = read_machine("blower").for_batch()
    cases = Cases(machine=machine, coastdown=_run(peak_at=150.0, end=215.0))
    executor = Recorder(_run(peak_at=151.0, end=165.0, peak=121.6))
    found = convergence_started(cases, _failing_hottest(), executor)()
    span = 150.0 * (1.0 + EXTREME_MARGIN)
    assert executor.asked == [(False, pytest.approx(span, abs=0.6))]  # not to standstill
    assert f"past the first run's extreme at {150.0:.1f} s" in found["case"]
    ambient = machine.coastdown.ambient_temperature - 273.15
    assert found["change"] == pytest.approx((121.6 - 121.5) / (121.5 - ambient), rel=1e-3)


def test_an_extreme_still_coming_at_the_end_of_the_tighter_run_asks_for_the_whole_run():
    cases = Cases(machine=read_machine("blower").for_batch(), coastdown=_run(peak_at=150.0, end=215.0))
    executor = Recorder(_run(peak_at=165.0, end=165.0), _run(peak_at=170.0, end=215.0, peak=121.7))
    found = convergence_started(cases, _failing_hottest(), executor)()
    assert executor.asked[1] == (True, None)  # the whole tighter coast-down, to standstill as the first ran
    assert found["case"] == "the coast-down (speed step halved too)"
    assert found["tightened"] > found["as_run"]


def test_a_peak_near_the_end_of_the_first_run_runs_the_whole_coastdown_at_once():
    cases = Cases(machine=read_machine("blower").for_batch(), coastdown=_run(peak_at=210.0, end=215.0))
    executor = Recorder(_run(peak_at=210.0, end=215.0))
    convergence_started(cases, _failing_hottest(), executor)()
    assert executor.asked == [(True, None)]


def _clearance_run(opening: float, peak_at: float = 150.0, end: float = 215.0):
    """A coast-down stand-in whose drive-end clearance opens by ``opening`` [m] at ``peak_at`` over the blower's."""
    time = np.linspace(0.0, end, 401)
    shape = np.exp(-(((time - peak_at) / (0.3 * end)) ** 2))
    given = read_machine("blower").planes[0].radial_clearance
    clearance = given + np.stack([opening * shape, 0.5 * opening * shape], axis=1)
    history = xr.Dataset({"radial_clearance": (("time", "plane"), clearance)}, coords={"time": time})
    # its own drop: the journals stop at the clearance (the travel past it: tests/consistency/test_verify_signable.py)
    drop = SimpleNamespace(summary={"planes": [{"max_excursion_um": given * 1e6}] * 2})
    return SimpleNamespace(history=history, drop=drop, summary={"planes": [], "until_stop": True, "simulated_s": end,
                                                                "verdict": "ok"})


def test_the_air_gap_compares_the_thermal_opening_not_the_clearance_it_is_added_to():
    """The clearance as given (0.15 mm) and its tolerance are inputs: a 10 % change of a 22.5 um opening is a 10 %
    change, not the 1.3 % it makes of the whole clearance."""
    gap = [Criterion("touchdown clearance against the magnetic air gap", 0.2, 0.1805, 0.0975, True, "mm", "upper",
                     "given", "largest radial travel of the rotor: coast-down, drive end: 0.15 mm as given")]
    cases = Cases(machine=read_machine("blower").for_batch(), coastdown=_clearance_run(22.5e-6))
    found = convergence_started(cases, gap, Recorder(_clearance_run(24.75e-6)))()
    assert found["quantity"].startswith("largest thermal opening of a touchdown clearance")
    assert found["as_run"] == pytest.approx(0.0225, rel=1e-3) and found["change"] == pytest.approx(0.1, rel=1e-2)
    assert found["settled"] is False


def _drop_run(planes_um, bearing_um):
    """A drop stand-in: the journals' and the radial magnetic bearing's largest excursions [um]."""
    return SimpleNamespace(summary={"largest_excursion_m": max(planes_um) * 1e-6, "verdict": "ok",
                                    "amb": [{"name": "impeller-end AMB", "max_excursion_um": bearing_um},
                                            {"name": "thrust AMB", "max_excursion_um": None}]})


def test_a_bending_rotors_travel_is_compared_at_the_magnetic_bearing_its_evidence_names():
    """The compressor bends: its air gap is judged where a case drop recorded the rotor at a magnetic bearing
    (judge._air_gap), so the tighter drop is compared there too, not at the journals."""
    machine = read_machine("compressor").for_batch()
    case = "drop at the maximum speed"
    gap = [Criterion("touchdown clearance against the magnetic air gap", 0.5, 0.286, 0.43, True, "mm", "upper",
                     "given", f"largest radial travel of the rotor: {case}, impeller-end AMB: the rotor 0.278 mm")]
    cases = Cases(machine=machine, drops={case: _drop_run((271.0, 249.0), 278.0)}, machines={case: machine})
    found = convergence_started(cases, gap, Recorder(_drop_run((271.0, 249.0), 280.78)))()
    assert found["case"] == case and "magnetic bearings" in found["quantity"]
    assert found["as_run"] == pytest.approx(0.278) and found["change"] == pytest.approx(0.01, rel=1e-6)
