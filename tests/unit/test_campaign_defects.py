"""Campaign defects found by a review: display offsets, what a resume compares, where files are found, refusals."""

import shutil
from pathlib import Path

import numpy as np
import pytest

from auxbearing.campaign.config import campaign_from_mapping, read_campaign
from auxbearing.campaign.sampling import design
from auxbearing.campaign.store import input_display, load_results, prepare_store, read_attrs
from auxbearing.common.errors import InputError

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _config(**head):
    return {"campaign": {"machine": "paper_rig", "samples": 4, "seed": 1, "input": [
        {"key": "rotor.unbalance_phase", "distribution": "uniform", "low": "0 deg", "high": "360 deg"}], **head},
        "drop": {"duration": "2 ms"}}


@pytest.mark.slow
def test_a_temperature_input_is_shown_with_its_offset(tmp_path):
    """300 K is 26.85 degC: the store held a factor of -272.15 (1 K in degC) and showed 300 K as -81 645 degC."""
    c = campaign_from_mapping({"campaign": {"machine": "paper_rig", "samples": 2, "analysis": "coastdown", "input": [
        {"key": "coastdown.ambient_temperature", "distribution": "uniform", "low": "15 degC", "high": "35 degC"}]},
        "drop": {"duration": "2 ms"}})
    prepare_store(tmp_path / "s.zarr", c, design(c))
    ds = load_results(tmp_path / "s.zarr")
    unit, scale, offset = input_display(ds, 0)
    assert unit == "degC" and scale == pytest.approx(1.0) and offset == pytest.approx(-273.15)
    shown = ds["value"].values[:, 0] * scale + offset
    assert ((15.0 <= shown) & (shown <= 35.0)).all()


def _with_bearing_file(tmp_path):
    shutil.copy(EXAMPLES / "my_bearing.toml", tmp_path / "brg.toml")
    text = "\n".join(['[campaign]', 'machine = "paper_rig"', 'samples = 4', '[[campaign.input]]',
                      'key = "rotor.unbalance_phase"', 'distribution = "uniform"', 'low = "0 deg"', 'high = "360 deg"',
                      '[[touchdown]]', 'bearing = "brg.toml"', '[drop]', 'duration = "2 ms"'])
    (tmp_path / "c.toml").write_text(text)
    return tmp_path / "c.toml"


def test_a_bearing_file_beside_the_campaign_file_is_found_there(tmp_path):
    campaign = read_campaign(_with_bearing_file(tmp_path))
    assert campaign.tables["touchdown"][0]["bearing"] == str((tmp_path / "brg.toml").resolve())


@pytest.mark.slow
def test_an_edited_bearing_file_is_another_campaign(tmp_path):
    """Before, the fingerprint held the file's name only: a resume after an edit mixed two bearings in one store."""
    config = _with_bearing_file(tmp_path)
    before = read_campaign(config)
    prepare_store(tmp_path / "s.zarr", before, design(before))
    text = (tmp_path / "brg.toml").read_text()
    (tmp_path / "brg.toml").write_text(text.replace("ball_count = 11", "ball_count = 10"))
    after = read_campaign(config)
    if after.named_files() == before.named_files():
        pytest.skip("the example bearing file has no 'ball_count = 11' line to edit")
    assert after.fingerprint() != before.fingerprint()
    with pytest.raises(InputError, match=r"holds another campaign .*files"):
        prepare_store(tmp_path / "s.zarr", after, design(after))


@pytest.mark.slow
def test_a_resume_judges_with_the_file_s_required_s0(tmp_path):
    first = campaign_from_mapping(_config())
    prepare_store(tmp_path / "s.zarr", first, design(first))
    again = campaign_from_mapping(_config(required_s0=30))
    assert again.fingerprint() == first.fingerprint()  # it changes no run
    prepare_store(tmp_path / "s.zarr", again, design(again))
    assert read_attrs(tmp_path / "s.zarr")["required_s0"] == 30


def test_second_order_needs_saltelli():
    with pytest.raises(InputError, match=r"^campaign.second_order = True: second-order Sobol' indices need"):
        campaign_from_mapping(_config(second_order=True))


def test_a_count_given_as_true_is_quoted_as_the_file_spells_it():
    with pytest.raises(InputError, match=r"^campaign.samples = true: must be a whole number"):
        campaign_from_mapping(_config(samples=True))


@pytest.mark.slow
def test_a_whirl_map_of_one_input_against_itself_is_refused(tmp_path):
    from auxbearing.report.campaign import whirl_map_keys

    c = campaign_from_mapping(_config())
    prepare_store(tmp_path / "s.zarr", c, design(c))
    ds = load_results(tmp_path / "s.zarr")
    with pytest.raises(InputError, match="give two different inputs"):
        whirl_map_keys(ds, ("rotor.unbalance_phase", "rotor.unbalance_phase"))


def test_a_store_that_does_not_exist_is_said_so(tmp_path):
    with pytest.raises(InputError, match="does not exist"):
        load_results(tmp_path / "nowhere.zarr")


def test_the_share_outside_a_rule_reads_as_a_percentage():
    c = campaign_from_mapping({"campaign": {"machine": "paper_rig", "samples": 4, "input": [
        {"key": "touchdown.0.sliding_friction", "distribution": "normal", "mean": 0.5, "std": 100}]},
        "drop": {"duration": "2 ms"}})
    assert any("% of the samples fall outside" in note for note in c.notes)
    assert np.isfinite(design(c).values).all()
