"""Bad machine inputs a review found: each one line naming the key, status 2, nothing written, no traceback.

An elastic rotor's matrices that no rotor can have (a mass matrix that is not positive definite, a negative
stiffness or damping), an .npz file that cannot be read, matrices that disagree with their nodes, touchdown
planes that share a position or a name or lack a position; and a ROSS rotor whose import must keep stdout
clean for ``--json``. Every refusal comes before any simulated step.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from importlib import resources
from pathlib import Path

import numpy as np
import pytest

from auxbearing.machine.structure import RotorStructure
from tests.cli.test_fuzz_harness import case, check_case

MACHINES = resources.files("auxbearing.catalog").joinpath("machines")
ROOT = Path(__file__).parents[2]


def _arrays() -> dict[str, np.ndarray]:
    with resources.as_file(MACHINES.joinpath("compressor.npz")) as path, np.load(path) as data:
        return {name: data[name] for name in data.files}


def _machine(*changes: tuple[str, str]) -> str:
    """The shipped compressor naming ``rotor.npz``, with text replaced."""
    text = MACHINES.joinpath("compressor.toml").read_text().replace('"compressor.npz"', '"rotor.npz"')
    for old, new in changes:
        assert old in text, old
        text = text.replace(old, new)
    return text


def _npz(**changes):
    """A writer of the compressor's arrays with some replaced (None: left out)."""
    def write(path: Path) -> None:
        data = {**_arrays(), **changes}
        np.savez(path, **{name: value for name, value in data.items() if value is not None})
    return write


def _refused(tmp_path, npz=None, *names: str, machine: str | None = None, avoid: tuple[str, ...] = ()) -> None:
    files = {"m.toml": machine or _machine(), "rotor.npz": npz if npz is not None else _npz()}
    check_case(case("defect", "drop --machine m.toml --duration 0.01", *names, files=files, avoid=avoid), tmp_path)


# ----------------------------------------------------------------------------- 1, 2: definiteness
def test_a_mass_matrix_that_is_not_positive_definite_is_one_line(tmp_path):
    m = _arrays()["M"].copy()
    m[0, 0] = -abs(m[0, 0])
    _refused(tmp_path, _npz(M=m), "rotor.matrices = 'rotor.npz'", "its array 'M'",
             "must be symmetric positive definite")


def test_a_negative_stiffness_matrix_is_refused(tmp_path):
    _refused(tmp_path, _npz(K=-_arrays()["K"]), "rotor.matrices = 'rotor.npz'", "its array 'K'",
             "must be symmetric positive semi-definite")


def test_a_damping_matrix_with_a_negative_symmetric_part_is_refused(tmp_path):
    c = np.zeros_like(_arrays()["M"])
    c[0, 0] = -50.0
    _refused(tmp_path, _npz(C=c), "rotor.matrices = 'rotor.npz'", "its array 'C'", "must be positive semi-definite")


def test_round_off_in_k_and_a_skew_damping_part_are_accepted():
    # a free-free K exported in single precision has rigid-motion eigenvalues of about -4e-11 of its largest;
    # a skew part of C does no work, so only the symmetric part has to be semi-definite
    a = _arrays()
    k = a["K"].astype(np.float32).astype(float)
    c = np.zeros_like(a["M"])
    c[0, 1], c[1, 0] = 5.0, -5.0
    RotorStructure(a["M"], 0.5 * (k + k.T), a["G"], a["nodes"], c)


# ----------------------------------------------------------------------------- 3: files that are no .npz
@pytest.mark.parametrize(("npz", "names"), [
    (b"", ("cannot be read as an .npz file", "empty")),
    (b"not a zip archive at all\n", ("cannot be read as an .npz file",)),
    (lambda path: path.write_bytes(_npz_bytes()[:3000]), ("cannot be read as an .npz file",)),
    (lambda path: path.write_bytes(_npz_bytes(corrupt=True)), ("cannot be read as an .npz file",)),
    (_npz(G=None), ("has no array 'G'",)),
], ids=["empty", "text", "truncated", "corrupt", "no-G"])
def test_an_unreadable_npz_names_the_file_key(tmp_path, npz, names):
    _refused(tmp_path, npz, "rotor.matrices = 'rotor.npz'", *names)


def _npz_bytes(corrupt: bool = False) -> bytes:
    with resources.as_file(MACHINES.joinpath("compressor.npz")) as path:
        data = bytearray(path.read_bytes())
    if corrupt:  # inside the first array's data: the archive's directory stays whole
        data[200:400] = bytes(200)
    return bytes(data)


# ----------------------------------------------------------------------------- 4: which matrix, which key
@pytest.mark.parametrize("name", ["M", "K"])
def test_asymmetry_names_the_matrix(tmp_path, name):
    matrix = _arrays()[name].copy()
    matrix[0, 5] += 0.1 * np.abs(matrix).max()
    _refused(tmp_path, _npz(**{name: matrix}), "rotor.matrices = 'rotor.npz'", f"its array '{name}'",
             "must be symmetric", avoid=("M or K",))


def test_a_node_list_one_short_is_blamed_not_the_mass_matrix(tmp_path):
    _refused(tmp_path, _npz(nodes=_arrays()["nodes"][:-1]), "rotor.matrices = 'rotor.npz'",
             "its array 'nodes' holds 15 nodes", "64 x 64", "disagree", avoid=("its array 'M'",))


def test_one_matrix_of_another_size_is_the_one_blamed(tmp_path):
    _refused(tmp_path, _npz(G=np.zeros((60, 60))), "rotor.matrices = 'rotor.npz'", "its array 'G'", "(60, 60)",
             "64 x 64")


# ----------------------------------------------------------------------------- 5, 6, 7: the planes
def test_a_duplicate_plane_quotes_the_position_as_written(tmp_path):
    _refused(tmp_path, None, "touchdown.1.position = '120 mm'", "different axial positions", "touchdown.0",
             machine=_machine(('position = "800 mm"', 'position = "120 mm"')), avoid=("-275",))


def test_a_missing_position_with_two_planes_is_refused(tmp_path):
    _refused(tmp_path, None, "touchdown.1.position: missing; required with two planes or more",
             machine=_machine(('position = "800 mm"\n', "")))


def test_a_missing_position_on_a_rigid_rotor_with_two_planes_is_refused(tmp_path):
    text = MACHINES.joinpath("paper_rig_two_planes.toml").read_text()
    assert 'position = "80 mm"\n' in text
    check_case(case("defect", "drop --machine m.toml --duration 0.01", "touchdown.1.position: missing",
                    files={"m.toml": text.replace('position = "80 mm"\n', "")}), tmp_path)


def test_two_planes_of_one_name_are_refused(tmp_path):
    _refused(tmp_path, None, "touchdown.1.name = 'impeller end'", "touchdown.0",
             machine=_machine(('name = "coupling end"', 'name = "impeller end"')))


def test_a_name_that_another_plane_takes_by_default_is_refused(tmp_path):
    _refused(tmp_path, None, "touchdown.0.name = 'plane 1'", "touchdown.1",
             machine=_machine(('name = "impeller end"', 'name = "plane 1"'), ('name = "coupling end"\n', "")))


# ----------------------------------------------------------------------------- 8: ROSS keeps stdout clean
@pytest.mark.slow  # a drop of the ROSS compressor in its own process: about 20 s
def test_a_ross_rotor_leaves_json_on_stdout_alone(tmp_path):
    pytest.importorskip("ross")
    folder = tmp_path / "ross"
    shutil.copytree(ROOT / "examples" / "compressor_ross", folder)
    env = {**os.environ, "MPLBACKEND": "Agg"}
    run = subprocess.run([sys.executable, "-m", "auxbearing.cli.main", "drop", "--machine", "compressor.toml",
                          "--duration", "0.01", "--json"], cwd=folder, env=env, capture_output=True, text=True,
                         timeout=600)
    assert run.returncode == 0, run.stderr[-2000:]
    assert "REFPROP" not in run.stdout
    assert json.loads(run.stdout)["machine"] == "compressor from ROSS"
