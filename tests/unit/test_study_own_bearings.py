"""A study of the user's own bearings reports on those bearings, not on the paper (issue 10, item 6).

The quick tests check the config and the captions; every test that runs a study stage (contact and static
on coarse grids, the drop on short runs) is marked slow; the paper's own study keeps its 18/3/6 claims.
"""

import html
import json
import re
from dataclasses import replace
from pathlib import Path

import pytest
from click.testing import CliRunner

from auxbearing.cli.main import cli
from auxbearing.common.errors import InputError
from auxbearing.paper.study import run_study
from auxbearing.paper.study_config import default_config, load_study_config
from auxbearing.report.model import OWN_STUDY, OWN_WITH_PAPER, PAPER_STUDY

#: Text of the paper's study that must not reach a report on other bearings.
PAPER_TEXT = ("Paper says", "Claims of the paper", "QJ202", "7202", "2616", "618 N", "1483", "1.48 kg",
              "Parameters the paper does not give", "Fig. ")

OWN = """
[study]
title = "QJ208 touchdown bearing of a blower"
ball_load = "2 kN"
contact_angles = ["10 deg", "70 deg", "10 deg"]
groove_ratios = [0.505, 0.6, 0.015]
{extra}
[bearing]
catalogue = "QJ208"
[comparison_bearing]
catalogue = "7208"
[rotor]
mass = "12 kg"
polar_inertia = "0.02 kg*m**2"
eccentricity = "5 um"
[drop]
speed = "12000 rpm"
clearance = "0.25 mm"
duration = "{duration}"
"""


@pytest.fixture
def no_figure_files(monkeypatch):
    """Figure files as empty placeholders: the quick tests read the report, whose figures are embedded anyway."""
    import auxbearing.paper.study as study

    def touch(fig, stem, formats=("png",)):
        return [Path(f"{stem}.{fmt}").touch() for fmt in formats]

    monkeypatch.setattr(study, "save_figure", touch)


def _config(tmp_path, extra: str = "", duration: str = "20 ms"):
    path = tmp_path / "own.toml"
    path.write_text(OWN.format(extra=extra, duration=duration))
    return load_study_config(path)


def _text(out) -> str:
    """report.html without its embedded images (base64 text can hold any digits), entities decoded."""
    return html.unescape(re.sub(r"data:image/png;base64,[A-Za-z0-9+/=]+", "", (out / "report.html").read_text()))


def _paper_text_in(text: str) -> list[str]:
    return [s for s in PAPER_TEXT if s in text]


@pytest.mark.parametrize(
    ("text", "own"),
    [
        ("", False),
        ("[bearing]\ncatalogue = 'QJ202'\n[comparison_bearing]\ncatalogue = '7202'\n", False),
        ("[drop]\nspeed = '6000 rpm'\nclearance = '0.2 mm'\n[rotor]\nmass = '1.48 kg'\n", False),
        ("[study]\nball_load = '1.5 kN'\n", False),  # the contact load is not the bearings, rotor or drop
        ("[bearing]\ncatalogue = 'QJ208'\n", True),
        ("[comparison_bearing]\ncatalogue = '7202-40'\n", True),
        ("[rotor]\nmass = '2 kg'\n", True),
        ("[drop]\nspeed = '9000 rpm'\n", True),
    ],
)
def test_own_bearings_is_any_change_of_bearing_rotor_or_drop(tmp_path, text, own):
    path = tmp_path / "s.toml"
    path.write_text(text)
    config = load_study_config(path)
    assert config.own_bearings is own
    assert config.framing() == (OWN_STUDY if own else PAPER_STUDY)
    assert replace(config, paper_comparison=True).framing() == (OWN_WITH_PAPER if own else PAPER_STUDY)


def test_paper_comparison_must_be_a_boolean(tmp_path):
    path = tmp_path / "s.toml"
    path.write_text("[study]\npaper_comparison = 'yes'\n")
    with pytest.raises(InputError, match=r"study\.paper_comparison = 'yes': must be true or false"):
        load_study_config(path)


@pytest.mark.slow
def test_own_study_report_has_nothing_of_the_paper(tmp_path, no_figure_files):
    out = tmp_path / "out"
    results = run_study(_config(tmp_path), out, stages=["contact", "static"])
    text = _text(out)
    assert _paper_text_in(text) == []
    assert results["claims_total"] == 0 and results["study_of"] == "own bearings"
    # captions, titles and the summary name the user's bearings
    assert "A study of QJ208 (four-point contact) against 7208 (angular contact)" in text
    assert "QJ208: elastic approach (a) and max stress (b) against contact angle" in text
    assert "Max contact stress against radial load: QJ208 (four-point) and 7208 (angular contact)" in text
    assert "<th>QJ208 (four-point)</th><th>7208 (angular contact)</th>" in text
    assert "Hertz max contact stress at 2000 N ball load [MPa]" in text
    assert "Assumptions and defaults used" in text
    # no paper figure numbers in the file names either
    assert not [p.name for p in out.iterdir() if p.name.startswith("fig")]


def test_own_study_leaves_out_the_experiment_on_the_papers_synthetic_drops(tmp_path, no_figure_files):
    out = tmp_path / "out"
    results = run_study(_config(tmp_path), out, stages=["experiment"])
    assert "SYNTHETIC drop records made for the source paper's" in results["skipped_stages"]["experiment"]
    assert results["results"] == {}
    assert "Stage <code>experiment</code> not run" in (out / "report.html").read_text()


@pytest.mark.slow
def test_paper_comparison_sets_the_papers_claims_beside_labelled(tmp_path, no_figure_files):
    out = tmp_path / "out"
    results = run_study(_config(tmp_path, extra="paper_comparison = true"), out, stages=["contact", "static"])
    text = _text(out)
    assert results["claims_total"] == 14  # 9 contact + 5 static claims of the paper
    assert "The paper's claims, its QJ202/7202 numbers" in text
    assert "Paper (its QJ202/7202) says:" in text
    assert "<th>paper (its QJ202/7202)</th>" in text
    assert "2616" in text  # the paper's theory value, in the labelled comparison rows
    assert "Paper (its QJ202/7202), theory, inner race [MPa]" in text


@pytest.mark.slow
def test_paper_comparison_flag_on_the_command_line(tmp_path, no_figure_files):
    path = tmp_path / "own.toml"
    path.write_text(OWN.format(extra="", duration="20 ms"))
    args = ["study", "--config", str(path), "--stage", "contact", "--quiet", "--json"]
    plain = CliRunner().invoke(cli, [*args, "--out", str(tmp_path / "a")])
    asked = CliRunner().invoke(cli, [*args, "--out", str(tmp_path / "b"), "--paper-comparison"])
    assert plain.exit_code == 0 and asked.exit_code == 0, plain.output + asked.output
    assert json.loads(plain.output)["claims_total"] == 0
    assert json.loads(asked.output)["claims_total"] == 9


@pytest.mark.slow
def test_stress_beyond_iso76_is_a_warning_box_at_the_top(tmp_path, no_figure_files):
    out = tmp_path / "out"
    config = replace(_config(tmp_path), ball_load=40000.0)
    results = run_study(config, out, stages=["contact"])
    text = _text(out)
    assert text.index("Results outside the model's range") < text.index("<h2 id='summary'>")
    assert re.search(r"Contact analysis: QJ208 and 7208:</strong> QJ208 at 40000 N radial ball load: max contact "
                     r"stress \d+ MPa exceeds the 4200 MPa of ISO 76 \(s0 = 0\.\d+ < 1\)", text)
    assert any("7208 at 40000 N" in w for w in results["warnings"])


@pytest.mark.slow
def test_paper_study_has_no_warning_box_for_its_contact_stage(tmp_path, no_figure_files):
    out = tmp_path / "out"
    run_study(replace(default_config(), contact_angles_deg=(10.0, 70.0, 10.0), groove_ratios=(0.505, 0.6, 0.015)),
              out, stages=["contact"])
    text = _text(out)
    assert "Results outside the model's range" not in text
    assert "Claims of the paper" in text and "Paper says" in text


@pytest.mark.slow
def test_own_study_with_the_drop_names_the_users_rotor_and_nothing_of_the_paper(tmp_path):
    out = tmp_path / "out"
    results = run_study(_config(tmp_path), out)
    text = _text(out)
    assert _paper_text_in(text) == []
    assert "Rotor drop: 12 kg rotor at 12000 rpm, clearance 0.25 mm onto QJ208 and 7208" in text
    assert "QJ208 (four-point): orbit (a) and collision force (b), 12 kg rotor at 12000 rpm" in text
    assert "Drop: peak ball stress [MPa]" in text
    assert "paper_ball_constant" not in results["results"]["drop"]
    assert set(results["stage_times_s"]) == {"contact", "static", "drop"}


@pytest.mark.slow
def test_own_study_of_the_example_file_has_no_paper_caption(tmp_path):
    example = Path(__file__).parents[2] / "examples" / "my_study.toml"
    config = load_study_config(example)
    drop = {**config.sections["drop"], "duration": "20 ms"}  # the captions, not the drop's length, are at stake
    config = replace(config, contact_angles_deg=(10.0, 70.0, 10.0), groove_ratios=(0.505, 0.6, 0.015),
                     sections={**config.sections, "drop": drop})
    out = tmp_path / "out"
    run_study(config, out)
    text = _text(out)
    assert _paper_text_in(text) == []
    assert "A study of TD15 four-point, 25 deg (four-point contact) against TD15 angular contact, 40 deg" in text
    assert "2.2 kg rotor at 9000 rpm" in text


@pytest.mark.slow
def test_own_study_with_paper_comparison_has_every_stage_claim_labelled(tmp_path):
    out = tmp_path / "out"
    results = run_study(_config(tmp_path, extra="paper_comparison = true"), out)
    assert results["claims_total"] == 9 + 5 + 9
    text = _text(out)
    assert "618 (QJ202)" in text and "Paper (its QJ202/7202): peak force [N]" in text

