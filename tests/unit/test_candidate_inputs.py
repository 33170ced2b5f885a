"""How verification candidates are named: a bearing file given on the command line is read where the user is, and a
[[candidate]] table takes the preload its documentation lists (docs/machine_file.md)."""

import json

import pytest

from auxbearing import get_bearing
from auxbearing.common.errors import InputError
from auxbearing.machine.check import check_candidates
from auxbearing.machine.files import machine_table
from auxbearing.machine.judging import candidate_tables
from auxbearing.machine.model import machine_from_mapping


def _bearing_file(path):
    table = get_bearing("QJ208").to_table()
    table.pop("source")
    path.write_text("[bearing]\n" + "".join(f"{k} = {json.dumps(v)}\n" for k, v in table.items()))


def test_a_bearing_file_on_the_command_line_is_read_from_the_working_folder(tmp_path, monkeypatch):
    # issue: 'verify --machine blower --candidates b40.toml' looked for b40.toml in the catalogue's machines folder
    monkeypatch.chdir(tmp_path)
    _bearing_file(tmp_path / "b40.toml")
    data, name, base = machine_table("blower")
    ((label, tables),) = candidate_tables(data, ["b40.toml"])
    assert label == "b40.toml"
    machine = machine_from_mapping(tables, name, base)
    assert machine.planes[0].bearing.ball_count == 11


def test_a_missing_bearing_file_on_the_command_line_is_one_line_naming_it(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    data, _, _ = machine_table("blower")
    with pytest.raises(InputError, match=r"^--candidates = 'b41.toml': no such bearing file"):
        candidate_tables(data, ["b41.toml"])


def test_a_candidate_table_takes_a_preload():
    # issue: the documented key was refused ("unknown key; allowed keys: name, bearing")
    data, name, base = machine_table("blower")
    data["candidate"] = [{"name": "pair", "bearing": "7208 DB", "preload": "medium"}]
    data["touchdown"] = [dict(p, axial_room="40 mm") for p in data["touchdown"]]
    design = machine_from_mapping({k: v for k, v in data.items() if k != "candidate"}, name, base)
    check_candidates(data, design, name, base)
    ((_, tables),) = candidate_tables(data, data["candidate"])
    assert machine_from_mapping(tables, name, base).planes[0].bearing_set.preload == "medium"
