"""How a machine file's rotor and bearings are read: inputs no rotor or bearing has are refused in one line.

A gyroscopic matrix whose polar inertia is not positive, a stiffness matrix with a mechanism, a polar inertia
above twice the transverse one (the perpendicular-axis theorem), a bearing name with a digit too many; and the
messages name the keys as the user wrote them: the .npz file and the array in it, every allowed key of [rotor]
and [coastdown] with the closest one suggested.
"""

from __future__ import annotations

import tomllib
from importlib import resources
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from auxbearing.analysis.plausibility import inertia_notes
from auxbearing.bearings.catalogue import get_bearing
from auxbearing.common.errors import InputError
from auxbearing.machine.files import read_machine
from auxbearing.machine.model import MachineRotor, machine_from_mapping
from auxbearing.machine.structure import RotorStructure, beam_structure, modal_rotor
from tests.cli.test_fuzz_harness import case, check_case

MACHINES = resources.files("auxbearing.catalog").joinpath("machines")
DOC = Path(__file__).resolve().parents[2] / "docs" / "machine_file.md"


def _arrays() -> dict[str, np.ndarray]:
    with resources.as_file(MACHINES.joinpath("compressor.npz")) as path, np.load(path) as data:
        return {name: data[name] for name in data.files}


def _compressor(folder: Path, npz: str = "compressor.npz", text_changes=(), **arrays) -> Path:
    """The shipped compressor in ``folder``, its matrices written to ``npz`` with some arrays replaced."""
    text = MACHINES.joinpath("compressor.toml").read_text()
    text = text.replace('matrices = "compressor.npz"', f'matrices = "{npz}"')
    for old, new in text_changes:
        assert old in text, old
        text = text.replace(old, new)
    (folder / npz).parent.mkdir(parents=True, exist_ok=True)
    np.savez(folder / npz, **{**_arrays(), **arrays})
    (folder / "m.toml").write_text(text)
    return folder / "m.toml"


def _refusal(path: Path) -> str:
    with pytest.raises(InputError) as err:
        read_machine(path)
    message = str(err.value)
    assert "\n" not in message
    return message


def _blower() -> dict:
    return tomllib.loads(MACHINES.joinpath("blower.toml").read_text())


# ----------------------------------------------------------------------------- 11: G with J_p <= 0
@pytest.mark.parametrize(("name", "scale", "jp"), [("neg_G.npz", -1.0, "-0.08348"), ("zero_G.npz", 0.0, "0")])
def test_a_gyroscopic_matrix_without_a_positive_polar_inertia_is_refused(tmp_path, name, scale, jp):
    path = _compressor(tmp_path, name, G=scale * _arrays()["G"])
    message = _refusal(path)
    assert message.startswith(f"rotor.matrices = '{name}': its array 'G' gives a polar inertia <= 0 "
                              f"(J_p = {jp} kg*m**2")
    assert "polar_inertia" not in message  # a key the file does not have


def test_the_shipped_compressor_has_the_polar_inertia_the_negated_one_lost():
    structure = RotorStructure(*(_arrays()[k] for k in ("M", "K", "G", "nodes")))
    assert modal_rotor(structure).polar_inertia == pytest.approx(0.08348, rel=1e-4)


def test_drop_of_a_negated_g_is_one_line_exit_2_nothing_written(tmp_path):
    files = {"m.toml": MACHINES.joinpath("compressor.toml").read_text().replace('"compressor.npz"', '"neg_G.npz"'),
             "neg_G.npz": lambda p: np.savez(p, **{**_arrays(), "G": -_arrays()["G"]})}
    check_case(case("defect 11", "drop --machine m.toml --duration 0.01", "rotor.matrices = 'neg_G.npz'",
                    "its array 'G' gives a polar inertia <= 0", files=files, avoid=("rotor.polar_inertia",)),
               tmp_path)


@pytest.mark.parametrize("jp", [-0.1, 0.0])
def test_inertia_notes_refuse_a_polar_inertia_that_is_not_positive(jp):
    rotor = SimpleNamespace(mass=40.0, polar_inertia=jp, transverse_inertia=2.0)
    with pytest.raises(InputError, match=rf"^J_p: a mass of 40 kg and a polar inertia of {jp:.4g} kg\*m\*\*2: "):
        inertia_notes(rotor, [SimpleNamespace(journal_radius=0.02)], "J_p")


# ----------------------------------------------------------------------------- 12: K with a mechanism
def test_a_stiffness_matrix_of_zeros_is_a_mechanism(tmp_path):
    path = _compressor(tmp_path, "zero_K.npz", K=np.zeros((64, 64)))
    message = _refusal(path)
    assert message.startswith("rotor.matrices = 'zero_K.npz': its array 'K' has 64 zero eigenvalues (rigid motions): "
                              "a free-free lateral rotor has four (two translations, two tilts), so 60 more are a "
                              "mechanism")


def test_a_node_left_unconnected_is_a_mechanism_of_four_more_zero_eigenvalues():
    shaft = beam_structure(np.linspace(-0.3, 0.3, 7), 0.04, 7850.0, 2.1e11)
    k = shaft.stiffness.copy()
    # the last element's stiffness taken out: the end node floats free, its own two translations and two tilts
    k[-8:, -8:] -= beam_structure(np.array([0.2, 0.3]), 0.04, 7850.0, 2.1e11).stiffness
    loose = RotorStructure(shaft.mass, k, shaft.gyroscopic, shaft.nodes)
    with pytest.raises(InputError, match=r"its array 'K' has 8 zero eigenvalues .* so 4 more are a mechanism"):
        modal_rotor(loose)


@pytest.mark.slow
def test_round_off_of_a_float32_export_and_a_fine_mesh_are_no_mechanism():
    a = _arrays()
    k = a["K"].astype(np.float32).astype(float)
    exported = modal_rotor(RotorStructure(a["M"], 0.5 * (k + k.T), a["G"], a["nodes"]))
    exact = modal_rotor(RotorStructure(a["M"], a["K"], a["G"], a["nodes"]))
    assert exported.n_modes == exact.n_modes == 60
    assert exported.frequencies[0] == pytest.approx(exact.frequencies[0], rel=1e-5)
    fine = modal_rotor(beam_structure(np.linspace(0.0, 1.0, 200), 0.05, 7850.0, 2.1e11))
    assert fine.n_modes == 4 * 200 - 4


# ----------------------------------------------------------------------------- 14: a digit too many
@pytest.mark.parametrize(("name", "read_as", "extra"), [
    ("QJ2088", "QJ208", "8"), ("62080", "6208", "0"), ("QJ 2088", "QJ 208", "8"), ("72089", "7208", "9"),
])
def test_a_bore_code_with_a_digit_too_many_is_refused(name, read_as, extra):
    with pytest.raises(InputError) as err:
        get_bearing(name, "touchdown.0.bearing")
    assert str(err.value).startswith(f"touchdown.0.bearing = '{name}': unknown (a bore code has two digits, and "
                                     f"{read_as} is followed by '{extra}'")


@pytest.mark.parametrize(("name", "bearing"), [
    ("7208 BECBP", "7208"), ("QJ 208 N2MA", "QJ208"), ("6208-2RS1", "6208"), ("6208 2RS1", "6208"),
    ("6208-2Z", "6208"), ("6208N", "6208"), ("7202-40", "7202-40"),
])
def test_maker_suffixes_still_read(name, bearing):
    assert get_bearing(name).name == bearing


# ----------------------------------------------------------------------------- 15: J_p > 2 J_t
def test_a_polar_inertia_above_twice_the_transverse_is_refused_as_written():
    data = _blower()
    data["rotor"]["transverse_inertia"] = "0.005 kg*m^2"
    with pytest.raises(InputError) as err:
        machine_from_mapping(data, "blower")
    assert str(err.value).startswith("rotor.polar_inertia = '0.015 kg*m^2': is 3 times rotor.transverse_inertia = "
                                     "'0.005 kg*m^2'; no body has a polar moment above twice its transverse one "
                                     "(the perpendicular-axis theorem")


def test_a_flat_disc_has_exactly_twice_and_is_accepted():
    data = _blower()
    data["rotor"]["transverse_inertia"] = "0.0075 kg*m^2"
    rotor = machine_from_mapping(data, "blower").rotor
    assert (rotor.polar_inertia, rotor.transverse_inertia) == (pytest.approx(0.015), pytest.approx(0.0075))


def test_the_api_refuses_the_pair_in_si():
    with pytest.raises(InputError, match=r"^rotor.polar_inertia = '0.5 kg\*m\*\*2': is 2.5 times "
                                         r"rotor.transverse_inertia = '0.2 kg\*m\*\*2'"):
        MachineRotor(mass=10.0, polar_inertia=0.5, transverse_inertia=0.2, speed=100.0)


def test_matrices_whose_g_outgrows_twice_the_transverse_inertia_are_refused(tmp_path):
    path = _compressor(tmp_path, "big_G.npz", G=100.0 * _arrays()["G"])
    assert "its array 'G' gives a polar inertia J_p = 8.348 kg*m**2, 3." in _refusal(path)


def test_drop_with_the_impossible_pair_is_one_line_exit_2(tmp_path):
    text = MACHINES.joinpath("blower.toml").read_text()
    assert 'transverse_inertia = "0.2 kg*m^2"' in text
    files = {"m.toml": text.replace('transverse_inertia = "0.2 kg*m^2"', 'transverse_inertia = "0.005 kg*m^2"')}
    check_case(case("defect 15", "drop --machine m.toml --duration 0.001", "rotor.polar_inertia = '0.015 kg*m^2'",
                    "rotor.transverse_inertia = '0.005 kg*m^2'", "perpendicular-axis theorem", files=files), tmp_path)


def test_an_inertia_in_the_wrong_unit_is_still_only_warned_of():
    planes = [SimpleNamespace(journal_radius=0.01985)]
    notes = inertia_notes(SimpleNamespace(mass=10.0, polar_inertia=1.5e-6, transverse_inertia=0.2), planes, "J_p")
    assert len(notes) == 1 and "radius of gyration of 0.3873 mm against a journal radius of 19.85 mm" in notes[0]


# ----------------------------------------------------------------------------- 17, 18: every allowed key listed
ROTOR_KEYS = ("mass, polar_inertia, transverse_inertia, speed, unbalance, unbalance_phase, couple_unbalance, "
              "couple_unbalance_phase, axial_force, side_force_x, side_force_y, start_x, start_y, max_mode_frequency, "
              "modal_damping, matrices, ross_file, ross_bearings, reduction")


def test_a_mistyped_matrices_key_lists_every_rotor_key_and_suggests_it(tmp_path):
    path = _compressor(tmp_path, text_changes=[('matrices = "compressor.npz"', 'matrix = "compressor.npz"')])
    assert _refusal(path) == (f"rotor.matrix = 'compressor.npz': unknown key; allowed keys: {ROTOR_KEYS}; "
                              "did you mean matrices?")


def test_ross_bearings_without_ross_file_is_named_as_real(tmp_path):
    path = _compressor(tmp_path, text_changes=[('speed = "15000 rpm"', 'speed = "15000 rpm"\nross_bearings = "drop"')])
    assert _refusal(path).startswith("rotor.ross_bearings = 'drop': applies to a rotor given by rotor.ross_file")


def test_a_mistyped_vacuum_is_suggested():
    data = _blower()
    data["coastdown"]["vacum"] = True
    with pytest.raises(InputError) as err:
        machine_from_mapping(data, "blower")
    message = str(err.value)
    assert message.startswith("coastdown.vacum = True: unknown key; allowed keys: drag_torque, ")
    assert message.endswith(", settle_time, vacuum; did you mean vacuum?")


def test_the_reference_documents_axial_direction_and_vacuum():
    text = DOC.read_text(encoding="utf-8")
    touchdown = text.split("## `[[touchdown]]`")[1].split("\n## ")[0]
    coastdown = text.split("## `[coastdown]`")[1].split("\n## ")[0]
    assert "| `axial_direction` | - | `both` | With `axial_clearance`:" in touchdown
    assert "`+z` (only moving towards +z) or `-z` (only towards -z)" in touchdown
    assert "| `vacuum` | - | `false` | `true`: the machine runs in vacuum" in coastdown


def test_axial_direction_reaches_the_plane():
    data = _blower()
    data["touchdown"][0]["axial_direction"] = "-z"
    assert machine_from_mapping(data, "blower").planes[0].axial_direction == "-z"


# ----------------------------------------------------------------------------- 19: the file and the array named
def test_a_bad_damping_matrix_names_the_file_as_written_and_its_array(tmp_path):
    c = np.zeros((64, 64))
    c[0, 0] = -50.0
    path = _compressor(tmp_path, "rotors/negC.npz", C=c)
    message = _refusal(path)
    assert message.startswith("rotor.matrices = 'rotors/negC.npz': its array 'C' must be positive semi-definite "
                              "(eigenvalues from -50 to 0 for (C + C^T) / 2)")
    assert "rotor.matrices.damping" not in message


@pytest.mark.parametrize(("arrays", "said"), [
    ({"M": np.diag(np.r_[-1.0, np.ones(63)])}, "its array 'M' must be symmetric positive definite"),
    ({"G": np.zeros((60, 60))}, "its array 'G' has shape (60, 60): it must be 64 x 64"),
    ({"nodes": np.arange(15.0)}, "its array 'nodes' holds 15 nodes: the node list and the matrices disagree, the "
                                 "matrices are 64 x 64"),
])
def test_every_array_check_names_the_file(tmp_path, arrays, said):
    message = _refusal(_compressor(tmp_path, "r.npz", **arrays))
    assert message.startswith(f"rotor.matrices = 'r.npz': {said}"), message


def test_a_ross_rotor_is_named_by_its_own_key(tmp_path, monkeypatch):
    from auxbearing.machine import ross_rotor

    a = _arrays()
    monkeypatch.setattr(ross_rotor, "read_ross_file", lambda spec, base, field: object())
    text = MACHINES.joinpath("compressor.toml").read_text().replace(
        'matrices = "compressor.npz"', 'ross_file = "ross/rotor.toml"\nross_bearings = "drop"')
    (tmp_path / "m.toml").write_text(text)
    monkeypatch.setattr(ross_rotor, "structure_from_ross",
                        lambda rotor, source: RotorStructure(a["M"], a["K"], -a["G"], a["nodes"], source=source))
    assert _refusal(tmp_path / "m.toml").startswith("rotor.ross_file = 'ross/rotor.toml': its array 'G' gives a polar "
                                                    "inertia <= 0")
    c = np.zeros((64, 64))
    c[3, 3] = -1.0
    monkeypatch.setattr(ross_rotor, "structure_from_ross",
                        lambda rotor, source: RotorStructure(a["M"], a["K"], a["G"], a["nodes"], c, source=source))
    assert _refusal(tmp_path / "m.toml").startswith("rotor.ross_file = 'ross/rotor.toml': its array 'C' must be "
                                                    "positive semi-definite")


def test_the_shipped_machines_still_load():
    for item in MACHINES.iterdir():
        if item.name.endswith(".toml"):
            with resources.as_file(item) as path:
                assert read_machine(path).rotor.mass > 0.0, item.name


def test_an_unusual_inertia_of_matrices_is_warned_of_under_the_key_written(tmp_path):
    from auxbearing.analysis.plausibility import plausibility

    data = tomllib.loads(_compressor(tmp_path, "small_G.npz", G=1e-4 * _arrays()["G"]).read_text())
    for table in ("amb", "scenario", "load", "linear_support"):  # the rotor and its planes are what is judged
        data.pop(table, None)
    machine = machine_from_mapping(data, "compressor", tmp_path)
    names = {"unbalance": "m.toml: rotor.unbalance", "clearance": "m.toml: radial_clearance",
             "line_stiffness": "m.toml: line_stiffness", "polar_inertia": "m.toml: rotor.polar_inertia"}
    notes = [n for n in plausibility(machine, names) if "radius of gyration" in n]
    assert len(notes) == 1
    assert notes[0].startswith("m.toml: rotor.matrices = 'small_G.npz': 8.348e-06 kg*m**2 with 40")
