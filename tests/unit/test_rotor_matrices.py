"""`[rotor] matrices`: a rotor's matrices from a .npz file; every bad file or value is one line naming the key."""

import numpy as np
import pytest

from auxbearing.common.errors import InputError
from auxbearing.machine.files import read_machine
from auxbearing.machine.structure import beam_structure

BASE = """
[rotor]
matrices = "shaft.npz"
speed = "3000 rpm"
{extra}
[[touchdown]]
position = "{left}"
bearing = "QJ208"
radial_clearance = "0.15 mm"
[[touchdown]]
position = "0.3 m"
bearing = "QJ208"
radial_clearance = "0.15 mm"
"""


def _write(folder, extra="", left="-0.3 m", **arrays):
    shaft = beam_structure(np.linspace(-0.3, 0.3, 7), 0.04, 7850.0, 2.1e11)
    data = {"M": shaft.mass, "K": shaft.stiffness, "G": shaft.gyroscopic, "nodes": shaft.nodes}
    data.update(arrays)
    np.savez(folder / "shaft.npz", **{k: v for k, v in data.items() if v is not None})
    (folder / "m.toml").write_text(BASE.format(extra=extra, left=left))
    return folder / "m.toml"


def test_mass_and_inertias_come_from_the_matrices(tmp_path):
    machine = read_machine(_write(tmp_path))
    assert machine.rotor.mass == pytest.approx(7850.0 * np.pi / 4 * 0.04**2 * 0.6, rel=1e-12)
    assert machine.rotor.structure.source == "shaft.npz"
    assert machine.modal().natural == 6  # three bending pairs below the 3 kHz default (508, 1392, 2710 Hz)


@pytest.mark.parametrize(("kwargs", "names"), [
    ({"extra": 'mass = "5 kg"'}, ("rotor.mass", "comes from the rotor's matrices")),
    ({"left": "-0.25 m"}, ("touchdown.0.position", "-250 mm", "must sit on a node")),
    ({"K": None}, ("rotor.matrices", "has no array 'K'")),
    ({"nodes": np.zeros(7)}, ("rotor.matrices", "strictly increasing")),
    ({"M": np.eye(3)}, ("rotor.matrices = 'shaft.npz'", "its array 'M' has shape (3, 3)", "28 x 28")),
    ({"K": np.eye(28)}, ("rotor.matrices = 'shaft.npz'", "its array 'K' ties the rotor to the ground")),
    ({"G": np.eye(28)}, ("rotor.matrices = 'shaft.npz'", "its array 'G' must be skew-symmetric")),
    ({"extra": 'max_mode_frequency = "-1 Hz"'}, ("rotor.max_mode_frequency",)),
])
def test_bad_matrices_are_one_line_naming_the_key(tmp_path, kwargs, names):
    path = _write(tmp_path, **kwargs)
    with pytest.raises(InputError) as err:
        read_machine(path)
    message = str(err.value)
    assert "\n" not in message
    for name in names:
        assert name in message


def test_a_missing_file_names_the_key(tmp_path):
    path = _write(tmp_path)
    (tmp_path / "shaft.npz").unlink()
    with pytest.raises(InputError, match=r"rotor.matrices = 'shaft.npz': no such file"):
        read_machine(path)
