"""A coast-down carried on without the magnetic bearings that failed for good runs as it did with them.

Self-consistency of :mod:`auxbearing.analysis.dead_bearings`: the shipped blower's bearings fail at the drop
with no decay time, so from then on they neither push nor change; the coast-down leaves their states out of
its windows, and every figure of the run comes out as with the bearings kept in the state vector, to the bit.
"""

import numpy as np
import pytest

from auxbearing.analysis import coastdown as cd
from auxbearing.analysis.dead_bearings import dead_for_good, without_dead_bearings
from auxbearing.analysis.drop import integrate_machine
from auxbearing.core import amb
from auxbearing.core import machine as cm
from auxbearing.machine.files import read_machine


@pytest.fixture(scope="module")
def blower():
    return read_machine("blower")


@pytest.fixture(scope="module")
def dropped(blower):
    return integrate_machine(blower, 0.02, None, None)


def test_the_state_moves_across_by_name_and_the_slope_with_it(blower, dropped):
    t = float(dropped.memory.t[0])
    model, y, memory, e0 = without_dead_bearings(blower, dropped.model, dropped.y, dropped.memory,
                                                    dropped.model.energy0, t)
    assert model.layout.size == dropped.model.layout.size - 18  # 15 controller states and 3 ledger entries
    assert not any(name.startswith("amb_") for name in model.layout.names)
    old = {name: i for i, name in enumerate(dropped.model.layout.names)}
    slope_before, slope_after = np.zeros(dropped.y.size), np.zeros(y.size)
    cm.rhs(t, dropped.y, dropped.model.machine, slope_before)
    cm.rhs(t, y, model.machine, slope_after)
    for j, name in enumerate(model.layout.names):
        assert y[j] == dropped.y[old[name]] and slope_after[j] == slope_before[old[name]], name
    # the error norm counts the same states (the failed bearings' were out of it already): the same tolerances
    assert model.settings.rtol == dropped.model.settings.rtol
    assert memory.t[0] == t and memory.evaluations[0] == dropped.memory.evaluations[0]
    assert np.array_equal(memory.derivative, [dropped.memory.derivative[old[name]] for name in model.layout.names])
    before = cm.energy_balance(dropped.y, dropped.model.machine, dropped.model.energy0)
    after = cm.energy_balance(y, model.machine, e0)
    assert after[1] - after[0] == pytest.approx(before[1] - before[0], abs=1e-12 * before[2])


def test_bearings_that_may_still_act_stay(blower, dropped):
    t = float(dropped.memory.t[0])
    assert dead_for_good(dropped.model, t)
    # power that comes back at 1 s: the bearings may act again
    kind = cm.STATION_KINDS.index(cm.amb)
    values = dropped.model.stations[kind].values.copy()
    values[:, amb.P_RESTORE] = 1.0
    stations = tuple(p._replace(values=values) if k == kind else p for k, p in enumerate(dropped.model.stations))
    assert not dead_for_good(dropped.model._replace(stations=stations), t)
    # a machine without magnetic bearings has nothing to leave out
    rig = read_machine("paper_rig")
    plain = integrate_machine(rig, 0.002, None, None)
    assert without_dead_bearings(rig, plain.model, plain.y, plain.memory, plain.model.energy0, 0.002) is None


@pytest.mark.slow
def test_a_coastdown_without_its_dead_bearings_is_the_one_with_them(blower, monkeypatch):
    lighter = cd.run_coastdown(blower, False, 5.0)
    monkeypatch.setattr(cd._Session, "forget_dead_bearings", lambda self: None)
    kept = cd.run_coastdown(blower, False, 5.0)
    assert lighter.summary["windows"] == kept.summary["windows"]
    assert np.array_equal(lighter.history["rotor_speed"].values, kept.history["rotor_speed"].values)
    for a, b in zip(lighter.summary["planes"], kept.summary["planes"], strict=True):
        assert a["damage_per_drop"] == b["damage_per_drop"] and a["max_temperature_C"] == b["max_temperature_C"]
    assert lighter.summary["energy_balance_error"] == pytest.approx(kept.summary["energy_balance_error"], abs=1e-12)


def test_an_elastic_rotor_keeps_the_modal_basis_it_ran_with():
    # the compressor's basis carries static corrections at its bearings' nodes (18 modes; rebuilt without the
    # bearings, 12): the lighter machine keeps it, and its slopes are the same state by state
    compressor = read_machine("compressor")
    dropped = integrate_machine(compressor, 0.002, None, None)
    model, y, _, _ = without_dead_bearings(compressor, dropped.model, dropped.y, dropped.memory,
                                              dropped.model.energy0, 0.002)
    assert model.layout.modes == dropped.model.layout.modes == 18
    old = {name: i for i, name in enumerate(dropped.model.layout.names)}
    slope_before, slope_after = np.zeros(dropped.y.size), np.zeros(y.size)
    cm.rhs(0.002, dropped.y, dropped.model.machine, slope_before)
    cm.rhs(0.002, y, model.machine, slope_after)
    assert all(slope_after[j] == slope_before[old[name]] for j, name in enumerate(model.layout.names))


@pytest.mark.parametrize("name", ["blower", "compressor"])
def test_a_drop_whose_bearings_fail_at_the_start_runs_without_them_to_the_same_bits(name, monkeypatch):
    from auxbearing.analysis import drop

    machine = read_machine(name)
    lighter = drop.integrate_machine(machine, 0.02, None, None)
    monkeypatch.setattr(drop, "lighter_model", lambda *args: None)  # the bearings kept in the state vector
    kept = drop.integrate_machine(machine, 0.02, None, None)
    assert lighter.model.layout.names == kept.model.layout.names  # handed back in the machine's own layout
    assert np.array_equal(lighter.grid, kept.grid) and np.array_equal(lighter.y, kept.y)
    assert np.array_equal(lighter.memory.derivative, kept.memory.derivative)
    assert int(lighter.memory.steps[0]) == int(kept.memory.steps[0])
    assert np.array_equal(lighter.watch.peak, kept.watch.peak)
