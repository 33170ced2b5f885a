"""A matched pair in a touchdown plane: the drop's kernel against the pair's own statics (consistency checks).

The machine kernel (auxbearing.core.machine) puts both rows of a duplex set on one race through the rows' maps
of auxbearing.bearings.duplex with the race tilt neglected; at any race displacement its ball-set force on
the race must be the statics' set reaction (auxbearing.bearings.duplex_statics.set_reaction) at the same
displacement with no tilt, preload included. A drop and a short coast-down of the blower on 7208 DB pairs
run through, with both rows' ball states and damage.
"""

import copy

import numpy as np
import pytest

from auxbearing import get_bearing
from auxbearing.analysis.coastdown import run_coastdown
from auxbearing.analysis.drop import run_machine
from auxbearing.bearings.duplex_statics import set_reaction
from auxbearing.core import machine as cm
from auxbearing.core.probes import plane_diagnostics
from auxbearing.machine.files import machine_table
from auxbearing.machine.model import machine_from_mapping
from auxbearing.machine.pack import pack


def _blower(bearing: str, duration: str = "0.05 s"):
    data, _, base = machine_table("blower")
    data = copy.deepcopy(data)
    for key in ("criteria", "candidate"):
        data.pop(key)
    data["drop"]["duration"] = duration
    for table in data["touchdown"]:
        table["bearing"] = bearing
    return machine_from_mapping(data, "blower", base)


@pytest.mark.parametrize("name", ["7208 DB", "7208 DF", "7208 DT", "7208 DB heavy"])
@pytest.mark.parametrize("u", [(0.0, 0.0, 0.0), (12e-6, 0.0, 0.0), (-9e-6, 4e-6, -7e-6), (2e-6, -15e-6, 3e-6)])
def test_kernel_force_on_the_race_is_the_pair_reaction(name, u):
    machine = _blower(name)
    model = pack(machine)
    y = model.y0.copy()
    b = cm.N_ROTOR  # plane 0, the drive end, which catches axially
    y[b + cm.RZ], y[b + cm.RX], y[b + cm.RY] = u
    y[cm.Y] = -1e-3  # the journal well away from the race: only the balls act on it
    diag = plane_diagnostics(y, model.machine, 0)
    pair = get_bearing(name)
    expected, _, _ = set_reaction(pair, np.array([u[0], u[1], u[2], 0.0, 0.0]), with_jac=False)
    scale = max(1.0, float(np.abs(expected[:3]).max()))
    assert diag[cm.D_BFZ] == pytest.approx(expected[0], abs=1e-9 * scale)
    assert diag[cm.D_BFX] == pytest.approx(expected[1], abs=1e-9 * scale)
    assert diag[cm.D_BFY] == pytest.approx(expected[2], abs=1e-9 * scale)


def test_a_pair_plane_is_described_as_the_pair():
    plane = _blower("7208 DB").planes[0]
    assert plane.rows == 2 and plane.unit.name == "7208 DB" and plane.bearing.name == "7208"
    assert plane.unit.width == pytest.approx(2.0 * plane.bearing.width)


@pytest.mark.slow
def test_drop_and_coastdown_on_pairs():
    drop = run_machine(_blower("7208 DB"))
    assert drop.summary["verdict"] == "ok"
    single = run_machine(_blower("7208")).summary["planes"][0]
    pair = drop.summary["planes"][0]
    assert pair["bearing"] == "7208 DB"
    # both rows' contacts in the ball arrays: one 7208 row has 15 balls and one pair of contacts per ball
    assert drop.dataset["stress_inner"].sizes["ball"] == 15 and drop.dataset["stress_inner"].sizes["pair"] == 2
    assert pair["peak_ball_stress_MPa"] > 0.0 and single["peak_ball_stress_MPa"] > 0.0
    run = run_coastdown(_blower("7208 DB"), duration=0.5)
    assert run.summary["verdict"] == "ok"
    life = run.life[0]
    assert life["damage_per_drop"] > 0.0 and 0 <= life["worst_contact"]["row"] <= 1


def test_preload_given_as_a_key_of_the_plane_or_the_candidate():
    from auxbearing.common.errors import InputError
    from auxbearing.machine.judging import candidate_tables

    data, _, base = machine_table("blower")
    data = copy.deepcopy(data)
    for table in data["touchdown"]:
        table.update(bearing="7208 DB", preload="500 N")
    plane = machine_from_mapping(data, "blower", base).planes[0]
    assert plane.unit.preload_force == pytest.approx(500.0) and plane.unit.name == "7208 DB 500 N"
    data["touchdown"][0]["preload"] = "lite"
    with pytest.raises(InputError, match=r"^touchdown.0.preload = 'lite': cannot read it"):
        machine_from_mapping(data, "blower", base)
    data["touchdown"][0].update(bearing="QJ208", preload="light")
    with pytest.raises(InputError, match=r"^touchdown.0.preload = 'light': only a matched pair takes a preload"):
        machine_from_mapping(data, "blower", base)
    (label, tables), = candidate_tables(data, [{"name": "pair", "bearing": "7208 DB", "preload": "heavy"}])
    assert label == "pair" and {t["preload"] for t in tables["touchdown"]} == {"heavy"}
    assert machine_from_mapping(tables, "blower", base).planes[1].unit.preload == "heavy"


def test_ball_arrays_of_planes_with_different_bearings_share_one_grid():
    """A plane dimension for the ball arrays: a QJ208 plane (11 balls x 2 pairs) beside a 6208 plane (9 x 1),
    the smaller one padded with NaN and cut back to its own size by plane_ball_arrays."""
    from auxbearing.analysis.drop import plane_ball_arrays

    data, _, base = machine_table("blower")
    data = copy.deepcopy(data)
    for key in ("criteria", "candidate"):
        data.pop(key)
    data["drop"]["duration"] = "5 ms"
    data["touchdown"][1]["bearing"] = "6208"
    ds = run_machine(machine_from_mapping(data, "blower", base)).dataset
    assert ds.stress_inner.dims == ("time", "plane", "ball", "pair")
    assert (ds.sizes["ball"], ds.sizes["pair"]) == (11, 2)
    own = plane_ball_arrays(ds, 1, 9, 1)
    assert own["stress_outer"].shape == (ds.sizes["time"], 9, 1) and np.isfinite(own["stress_outer"]).all()
    assert np.isnan(ds.stress_inner.values[:, 1, 9:, :]).all() and np.isnan(ds.stress_inner.values[:, 1, :, 1]).all()
