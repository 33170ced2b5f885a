"""docs/machine_file.md is the generated reference of the machine file and must match the reader's tables."""

import tomllib
from importlib import resources
from pathlib import Path

from auxbearing.report.machine_file import markdown

DOC = Path(__file__).resolve().parents[2] / "docs" / "machine_file.md"


def test_the_machine_file_reference_is_up_to_date():
    regenerate = "python -m auxbearing.report.machine_file > docs/machine_file.md"
    assert DOC.read_text(encoding="utf-8") == markdown(), f"stale: run {regenerate}"


def test_every_key_of_the_shipped_machines_is_documented():
    text = markdown()
    folder = resources.files("auxbearing.catalog").joinpath("machines")
    for item in folder.iterdir():
        if not item.name.endswith(".toml"):
            continue  # the data files machines name (an elastic rotor's matrices)
        data = tomllib.loads(item.read_text())
        for station in data.get("linear_support", []):
            for key in station:
                assert key == "name" or f"| `{key}` |" in text, (item.name, key)
        for table in ("rotor", "drop", "coastdown", "life", "criteria", "verify"):
            for key in data.get(table, {}):
                assert f"| `{key}` |" in text, (item.name, table, key)
        for plane in data.get("touchdown", []):
            for key in plane:
                if key not in ("name", "bearing"):
                    assert f"| `{key}` |" in text, (item.name, key)
