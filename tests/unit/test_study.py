"""``auxbearing study``: config, output folder, claims, errors."""

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from auxbearing.cli.main import cli
from auxbearing.common.errors import InputError
from auxbearing.common.io import atomic_output_dir
from auxbearing.paper.study_config import load_study_config
from auxbearing.report.claims import VERDICTS
from tests.browser import CHROMIUM, probe_report, unreadable_numbers

EXAMPLE = Path(__file__).parents[2] / "examples" / "my_study.toml"


def test_example_config_reads():
    config = load_study_config(EXAMPLE)
    assert config.bearing.name == "TD15 four-point, 25 deg"
    assert config.comparison.name == "TD15 angular contact, 40 deg"
    assert config.ball_load == pytest.approx(1000.0)
    assert config.own_bearings and not config.paper_comparison


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("[stduy]\n", "[stduy] = 'table': unknown section; allowed: study, bearing"),
        ("[study]\nball_lod = '1 kN'\n", "study.ball_lod = '1 kN': unknown key"),
        ("[study]\nball_load = '1 kg'\n", "study.ball_load = '1 kg': unit kilogram is not a force"),
        ("[study]\ncontact_angles = ['10 deg', '95 deg', '1 deg']\n", "study.contact_angles"),
        ("[study]\ngroove_ratios = [0.5, 0.6]\n", "must be a list [start, stop, step]"),
        ("[bearing]\ncatalogue = 'QJ999'\n", "bearing.catalogue = 'QJ999': unknown"),
        ("[bearing]\ntype = 'four_point'\n", "bearing.ball_diameter: missing"),
    ],
)
def test_config_mistakes(tmp_path, text, message):
    path = tmp_path / "s.toml"
    path.write_text(text)
    with pytest.raises(InputError) as info:
        load_study_config(path)
    assert message in str(info.value)


def test_cli_user_mistake_exits_2_and_leaves_no_folder(tmp_path):
    path = tmp_path / "s.toml"
    path.write_text("[study]\nball_load = 'lots'\n")
    out = tmp_path / "out"
    result = CliRunner().invoke(cli, ["study", "--config", str(path), "--out", str(out), "--quiet"])
    assert result.exit_code == 2
    assert result.output.startswith("error: study.ball_load = 'lots'")
    assert not out.exists()
    missing = CliRunner().invoke(cli, ["study", "--config", str(tmp_path / "none.toml"), "--out", str(out)])
    assert missing.exit_code == 2 and "not found" in missing.output


@pytest.mark.slow
def test_contact_stage_writes_report_and_results(tmp_path):
    out = tmp_path / "study"
    result = CliRunner().invoke(cli, ["study", "--stage", "contact", "--out", str(out), "--quiet", "--json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.output)
    assert data["claims_total"] >= 9
    assert all(c["verdict"] in VERDICTS for c in data["claims"])
    results = json.loads((out / "results.json").read_text())
    assert results["provenance"]["auxbearing_version"]
    for name in ("report.html", "contact_map.nc", "fig2_contact_angle.png", "fig2_contact_angle.pdf"):
        assert (out / name).stat().st_size > 0
    html = (out / "report.html").read_text()
    assert "Claims of the paper" in html and "Parameters the paper does not give" in html
    # the inputs a person reads carry no unit-conversion noise (25.500000000000004 mm) and no bare SI value
    assert unreadable_numbers(html) == []
    if CHROMIUM is not None:  # as a browser renders it: every figure loads, no section is empty
        seen = probe_report(html, tmp_path)
        assert seen["loaded"] == seen["images"] >= 1 and seen["empty"] == []


def test_bearings_lists_catalogue():
    result = CliRunner().invoke(cli, ["bearings", "--json"])
    names = {b["name"] for b in json.loads(result.output)["bearings"]}
    assert {"QJ202", "7202", "7202-40"} <= names


# The group loads its commands lazily (cli.commands is empty): list them the way `auxbearing --help` does.
@pytest.mark.parametrize("command", sorted(cli.list_commands(None)))
def test_every_subcommand_has_help(command):
    result = CliRunner().invoke(cli, [command, "--help"])
    assert result.exit_code == 0
    assert "Usage" in result.output and "Options:" in result.output
    assert len(cli.get_command(None, command).help or "") > 40  # a real description, not a stub


def test_output_folder_that_cannot_be_made_is_one_line_exit_2(tmp_path):
    blocker = tmp_path / "a_file"
    blocker.write_text("not a folder")
    # A parent that is a file: the folder cannot be created; said while the options are read.
    result = CliRunner().invoke(cli, ["study", "--stage", "contact", "--out", str(blocker / "out"), "--quiet"])
    assert result.exit_code == 2
    assert result.output.startswith(f"error: --out = '{blocker / 'out'}': '{blocker}' is a file")
    assert "Traceback" not in result.output
    # The target itself is a file (the CLI's option type says so first; the API says it too).
    with pytest.raises(InputError, match="exists and is not a folder"):
        with atomic_output_dir(blocker):
            pass


@pytest.mark.parametrize("command", [["contact-sweep"], ["static-study"], ["drop-compare"], ["drop"],
                                     ["experiment", "--measured", "x.csv"]])
def test_every_out_option_is_checked_before_work(tmp_path, command):
    blocker = tmp_path / "a_file"
    blocker.write_text("")
    result = CliRunner().invoke(cli, [*command, "--out", str(blocker / "out")])
    assert result.exit_code == 2
    assert result.output.count("\n") == 1 and "is a file, so no folder can be made" in result.output


def test_output_folder_the_system_refuses_is_one_line(tmp_path, monkeypatch):
    import tempfile

    def refuse(*args, **kwargs):
        raise PermissionError(13, "Permission denied")

    monkeypatch.setattr(tempfile, "mkdtemp", refuse)
    with pytest.raises(InputError, match="cannot create the output folder here \\(Permission denied\\)"):
        with atomic_output_dir(tmp_path / "out"):
            pass
