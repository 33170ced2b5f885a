"""A campaign says nothing absurd: a whole-number input cannot be drawn from a continuous distribution (every sample
broke its rule and the run still ended 0), and statistics no run gave are '-', not 'nan'."""

import math

import pytest

from auxbearing.campaign.config import campaign_from_mapping
from auxbearing.cli.campaign_cmd import _print
from auxbearing.common.errors import InputError


def _config(distribution: dict) -> dict:
    return {"campaign": {"machine": "paper_rig", "samples": 4, "seed": 1,
                         "input": [{"key": "drop.max_steps", **distribution}]}}


def test_a_whole_number_input_needs_a_list_of_whole_numbers():
    with pytest.raises(InputError, match=r"^campaign.input.0.distribution = 'uniform': drop.max_steps is a whole "
                                         r"number: give distribution = \"list\" with its values"):
        campaign_from_mapping(_config({"distribution": "uniform", "low": 20000, "high": 40000}))
    with pytest.raises(InputError, match=r"^campaign.input.0.values.1 = 40000.5: must be a whole number"):
        campaign_from_mapping(_config({"distribution": "list", "values": [20000, 40000.5]}))
    campaign_from_mapping(_config({"distribution": "list", "values": [20000, 40000]}))


def test_statistics_no_run_gave_print_as_a_dash(capsys):
    nan = math.nan
    p = {"value": nan, "low": nan, "high": nan}
    stats = {"required_s0": 1.0, "p_backward_whirl": p, "p_out_of_range": p, "p_s0_below_required": p,
             "quantiles": {"peak_ball_stress_MPa": {"p50": nan, "p95": nan, "p99": nan,
                                                    "interval": {t: [nan, nan] for t in ("p50", "p95", "p99")}}}}
    out = {"campaign": "c", "completed": 4, "samples": 4, "sampler": "random", "seed": 1, "ok": 0,
           "out_of_range": 0, "failed": 0, "drops_per_second": None, "new": 4, "wall_time_s": 1.0, "workers": 1,
           "store": "s.zarr"}
    _print(out, stats)
    text = capsys.readouterr().out
    assert "nan" not in text.lower()
    assert "No run ended ok, so there is nothing to estimate" in text


def test_a_coast_down_input_in_a_campaign_of_drops_is_refused():
    # it was accepted and changed nothing: a drop campaign runs no coast-down
    config = {"campaign": {"machine": "paper_rig", "samples": 4, "seed": 1,
                           "input": [{"key": "coastdown.ambient_temperature", "distribution": "uniform",
                                      "low": "20 degC", "high": "40 degC"}]}}
    with pytest.raises(InputError, match=r"^campaign.input.0.key = 'coastdown.ambient_temperature': names nothing "
                                         r"here: a campaign of drops runs no coast-down"):
        campaign_from_mapping(config)
    config["campaign"]["analysis"] = "coastdown"
    campaign_from_mapping(config)


def test_a_whirl_map_of_one_input_against_itself_is_refused():
    config = {"campaign": {"machine": "paper_rig", "samples": 4, "seed": 1, "whirl_map": ["rotor.speed"] * 2,
                           "input": [{"key": "rotor.speed", "distribution": "uniform", "low": "5000 rpm",
                                      "high": "7000 rpm"}]}}
    with pytest.raises(InputError, match=r"^campaign.whirl_map = \['rotor.speed', 'rotor.speed'\]: give two "
                                         r"different input keys"):
        campaign_from_mapping(config)


@pytest.mark.parametrize("workers", ["1", -1, 0, 1.5, True])
def test_run_campaign_refuses_a_bad_worker_count_before_the_store_is_made(tmp_path, workers):
    # issue: '1' raised a TypeError after the store was made; -1 waited 60 s for workers that never came
    from auxbearing.campaign.run import run_campaign

    path = tmp_path / "c.toml"
    path.write_text('[campaign]\nmachine = "paper_rig"\nsamples = 2\nseed = 1\n[[campaign.input]]\n'
                    'key = "rotor.unbalance_phase"\ndistribution = "uniform"\nlow = "0 deg"\nhigh = "360 deg"\n')
    with pytest.raises(InputError, match=r"^workers = .*: must be a whole number from 1 to 1024"):
        run_campaign(path, tmp_path / "s.zarr", workers=workers)  # a file's path, as the command line takes it
    assert not (tmp_path / "s.zarr").exists()
