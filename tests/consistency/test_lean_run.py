"""A lean run (what campaigns take) summarises a drop exactly as a full one: the same numbers, fewer arrays."""

import numpy as np
import pytest

from auxbearing.analysis.drop import LEAN_AT_END, LEAN_SERIES, integrate_machine, run_machine
from auxbearing.core import machine as cm
from auxbearing.core import probes
from auxbearing.machine.files import read_machine


def _without_timing(summary: dict) -> dict:
    return {k: v for k, v in summary.items() if k not in ("wall_time_s", "compile_or_cache_load_s")}


@pytest.mark.parametrize("name", ["paper_rig", "blower", "compressor"])
def test_the_lean_summary_is_the_full_one(name):
    machine = read_machine(name).with_simulation(duration=0.03)
    full, lean = run_machine(machine), run_machine(machine, lean=True)
    assert _without_timing(lean.summary) == _without_timing(full.summary)
    for variable in LEAN_SERIES:
        np.testing.assert_array_equal(lean.dataset[variable].values, full.dataset[variable].values)
    for variable in LEAN_AT_END:
        np.testing.assert_array_equal(lean.dataset[f"{variable}_at_end"].values, full.dataset[variable].values[-1])
        assert variable not in lean.dataset  # no series that is not one


@pytest.mark.parametrize("scenario", ["supply dip", "surge"])
def test_a_scenario_from_levitation_summarises_lean_as_in_full(scenario):
    """A verification's candidates run their scenarios lean (auxbearing.verify.cases.submit_cases): the outcome
    (touchdown, re-levitation), the magnetic bearings' currents and the drop's peaks are the full run's."""
    machine = read_machine("blower").with_scenario(scenario).with_simulation(duration=0.06)
    full, lean = run_machine(machine), run_machine(machine, lean=True)
    assert "outcome" in full.summary["scenario"]
    assert _without_timing(lean.summary) == _without_timing(full.summary)


def test_the_contact_geometry_series_equals_the_diagnostics_to_the_bit():
    machine = read_machine("paper_rig_two_planes").with_simulation(duration=0.02)
    run = integrate_machine(machine, 0.02, None, None)
    geometry = probes.contact_series(run.grid, run.model.machine)
    diag = probes.series(run.grid, run.model.machine, False)
    for i, name in enumerate(LEAN_SERIES):
        np.testing.assert_array_equal(geometry[:, :2, i], diag[:, :2, cm.DIAG_FIELDS.index(name)])
    assert (geometry[:, :, 0] > 0.0).any()  # the journals touched: the comparison covers contact
