"""A campaign over an elastic rotor (the shipped compressor, its matrices next to its machine file): each sample's
record is the drop of the machine that sample makes, run as the drop command runs it."""

from pathlib import Path

import numpy as np
import pytest

from auxbearing.analysis.drop import run_machine
from auxbearing.campaign.config import apply_sample, campaign_from_mapping
from auxbearing.campaign.evaluate import VERDICTS, _prepared, evaluate_batch
from auxbearing.machine.model import machine_from_mapping


@pytest.mark.slow
def test_each_sample_of_the_compressor_is_its_own_elastic_drop():
    campaign = campaign_from_mapping({"campaign": {"machine": "compressor", "samples": 2, "input": [
        {"key": "touchdown.0.sliding_friction", "distribution": "uniform", "low": 0.1, "high": 0.3}]},
        "drop": {"duration": "10 ms"}})
    values = np.array([[0.12], [0.28]])
    records = evaluate_batch(campaign, values)
    assert [VERDICTS[v] for v in records["verdict"]] == ["ok", "ok"]
    for row, peaks in zip(values, records["peak_contact_force"], strict=True):
        tables = apply_sample(_prepared(campaign), campaign.inputs, row, as_quantity=True)
        machine = machine_from_mapping(tables, campaign.name, Path(campaign.base))
        assert machine.modal().natural == 8  # the elastic rotor, not a rigid stand-in
        direct = [p["peak_contact_force_N"] for p in run_machine(machine, lean=True).summary["planes"]]
        assert list(peaks) == pytest.approx(direct, rel=1e-12)
    assert not np.allclose(records["peak_contact_force"][0], records["peak_contact_force"][1])
