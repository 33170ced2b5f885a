"""Campaign files: parsing, distributions with units, sampling reproducibility, one-line errors."""

import copy
import math

import numpy as np
import pytest

from auxbearing.campaign.config import apply_sample, campaign_from_mapping
from auxbearing.campaign.distributions import Distribution
from auxbearing.campaign.sampling import design, unit_design
from auxbearing.common.errors import InputError
from auxbearing.machine.model import machine_from_mapping


def base(**campaign):
    head = {"machine": "paper_rig", "sampler": "sobol", "samples": 16, "seed": 1, "analysis": "drop",
            "input": [{"key": "rotor.unbalance_phase", "distribution": "uniform", "low": "0 deg", "high": "360 deg"},
                      {"key": "touchdown.0.sliding_friction", "distribution": "normal", "mean": 0.2, "std": 0.03}]}
    head.update(campaign)
    return {"campaign": head, "drop": {"duration": "20 ms"}}


def with_input(**table):
    data = base()
    data["campaign"]["input"].append(table)
    return data


def test_issue_form_is_read_with_units_in_si():
    c = campaign_from_mapping(base())
    assert c.runs == 16 and c.keys == ("rotor.unbalance_phase", "touchdown.0.sliding_friction")
    phase, friction = c.inputs
    assert phase.distribution.kind == "uniform"
    assert phase.distribution.params == pytest.approx((0.0, 2.0 * math.pi))
    assert phase.unit == "rad" and friction.unit == ""
    assert friction.distribution.params == (0.2, 0.03)
    assert c.tables["drop"]["duration"] == "20 ms"  # the file's table laid over the catalogue machine
    assert c.tables["rotor"]["mass"] == "1.48 kg"
    assert c.plane_names == ("QJ202",)


def test_same_seed_same_samples_other_seed_other_samples():
    for sampler in ("sobol", "lhs", "random"):
        a = design(campaign_from_mapping(base(sampler=sampler)))
        b = design(campaign_from_mapping(base(sampler=sampler)))
        c = design(campaign_from_mapping(base(sampler=sampler, seed=2)))
        assert np.array_equal(a.values, b.values) and np.array_equal(a.unit, b.unit)
        assert not np.allclose(a.unit, c.unit)
        assert a.unit.shape == (16, 2) and ((a.unit >= 0) & (a.unit < 1)).all()


def test_saltelli_design_size_and_blocks():
    c = campaign_from_mapping(base(sampler="saltelli", samples=8))
    d = design(c)
    assert c.runs == d.unit.shape[0] == 8 * (2 + 2)
    # rows A, AB_1, AB_2, B: AB_i takes column i from B and the others from A
    a, ab1, ab2, b = d.unit[0], d.unit[1], d.unit[2], d.unit[3]
    assert ab1[0] == b[0] and ab1[1] == a[1] and ab2[1] == b[1] and ab2[0] == a[0]
    second = campaign_from_mapping(base(sampler="saltelli", samples=8, second_order=True))
    assert second.runs == 8 * (2 * 2 + 2)


def test_sobol_first_points_are_balanced():
    u = unit_design("sobol", 16, 3, seed=5)
    for j in range(3):  # a (0, m, s)-net in base 2: one point in each of the 16 equal intervals
        assert sorted(np.floor(u[:, j] * 16).astype(int).tolist()) == list(range(16))


def test_distributions_in_units_and_their_quantiles():
    c = campaign_from_mapping(with_input(key="touchdown.0.radial_clearance", distribution="truncated normal",
                                         mean="0.2 mm", std="10 um", low="0.18 mm", high="0.22 mm"))
    d = c.inputs[2].distribution
    assert d.kind == "truncated_normal" and d.params == pytest.approx((2e-4, 1e-5, 1.8e-4, 2.2e-4))
    u = np.linspace(0.0, 1.0, 101)
    v = d.ppf(u)
    assert v.min() >= 1.8e-4 and v.max() <= 2.2e-4 and np.all(np.diff(v) >= 0)
    assert d.median() == pytest.approx(2e-4)
    lognormal = Distribution("lognormal", (10e-6, 3e-6))
    x = lognormal.ppf((np.arange(200_000) + 0.5) / 200_000)
    assert x.mean() == pytest.approx(10e-6, rel=1e-3) and x.std() == pytest.approx(3e-6, rel=1e-2)
    listed = campaign_from_mapping(with_input(key="rotor.speed", distribution="list",
                                              values=["5000 rpm", "6000 rpm"])).inputs[2].distribution
    assert listed.params == pytest.approx((5000 * math.pi / 30, 6000 * math.pi / 30))
    assert listed.ppf(np.array([0.2, 0.7])).tolist() == list(listed.params)


def test_apply_sample_writes_si_text_and_the_machine_takes_it():
    c = campaign_from_mapping(with_input(key="touchdown.*.radial_clearance", distribution="uniform",
                                         low="0.19 mm", high="0.21 mm"))
    tables = copy.deepcopy(c.tables)
    out = apply_sample(c.tables, c.inputs, [1.0, 0.25, 2.05e-4])
    assert c.tables == tables  # the campaign's tables are not touched
    assert out["rotor"]["unbalance_phase"] == "1.0 rad"
    assert out["touchdown"][0]["sliding_friction"] == 0.25
    assert out["touchdown"][0]["radial_clearance"] == "0.000205 m"
    m = machine_from_mapping(out)
    assert m.rotor.unbalance_phase == 1.0 and m.planes[0].sliding_friction == 0.25
    assert m.planes[0].radial_clearance == pytest.approx(2.05e-4, rel=1e-15)


def test_catalogue_machine_two_planes_and_star_key():
    data = base(machine="paper_rig_two_planes")
    data["campaign"]["input"][1]["key"] = "touchdown.*.sliding_friction"
    c = campaign_from_mapping(data)
    assert c.inputs[1].planes == (0, 1) and len(c.plane_names) == 2


BAD = [
    (base(sampler="halton"), "campaign.sampler"),
    (base(colour="red"), "campaign.colour = 'red': unknown key"),
    (base(samples=0), "campaign.samples"),
    (base(samples=2.5), "campaign.samples"),
    (base(input=[]), "campaign.input"),
    (with_input(key="rotor.unbalance_phaze", distribution="uniform", low="0 deg", high="1 deg"),
     "campaign.input.2.key = 'rotor.unbalance_phaze': unknown key"),
    (with_input(key="touchdown.1.sliding_friction", distribution="uniform", low=0.1, high=0.3),
     "names nothing: the machine has 1 touchdown plane"),
    (with_input(key="touchdown.sliding_friction", distribution="uniform", low=0.1, high=0.3), "names nothing"),
    (with_input(key="machine.orientation", distribution="list", values=[1]), "names nothing"),
    (with_input(key="rotor", distribution="uniform", low=0.1, high=0.3), "names nothing"),
    (with_input(key="touchdown.0.bearing", distribution="list", values=[1]), "names a text"),
    (with_input(key="rotor.unbalance", distribution="normal", mean="10 um", std="-1 um"),
     ".std = '-1 um': must be > 0"),
    (with_input(key="rotor.unbalance", distribution="uniform", low="10 um", high="5 um"),
     ".high = '5 um': must be above"),
    (with_input(key="rotor.unbalance", distribution="lognormal", mean="0 um", std="1 um"), ".mean = '0 um'"),
    (with_input(key="rotor.unbalance", distribution="list", values=[]), ".values = []"),
    (with_input(key="rotor.unbalance", distribution="uniform", low=1, high=2), "needs a unit"),
    (with_input(key="rotor.unbalance", distribution="uniform", low="1 kg", high="2 kg"), "is not a length"),
    (with_input(key="rotor.unbalance", distribution="weibull", shape=2), "unknown distribution"),
    (with_input(key="rotor.unbalance", distribution="uniform", low="1 um"), ".high: missing"),
    (with_input(key="rotor.unbalance", distribution="uniform", low="1 um", high="2 um", mean="1 um"),
     ".mean = '1 um': unknown key for a uniform"),
    (with_input(key="touchdown.0.sliding_friction", distribution="uniform", low=0.5, high=1.5), "must lie in [0, 1]"),
    (with_input(key="rotor.unbalance_phase", distribution="uniform", low="0 deg", high="1 deg"), "sets the same value"),
    (with_input(key="touchdown.0.radial_clearance", distribution="uniform", low="8 mm", high="9 mm"),
     "central sample"),
    (with_input(key="touchdown.0.mount_damping", distribution="uniform", low="1 N*s/m", high="2 N*s/m"),
     "has no mount"),
    (with_input(key="touchdown.0.face_friction", distribution="uniform", low=0.1, high=0.2), "does not catch axially"),
    ({"campaign": base()["campaign"], "bearing": {}}, "[bearing] = 'table': unknown table"),
    ({"rotor": {"mass": "1 kg"}}, "campaign: missing"),
    (base(machine="no_such_machine"), "neither a file nor a catalogue machine"),
]


@pytest.mark.parametrize(("data", "message"), BAD, ids=[m for _, m in BAD])
def test_bad_campaign_files_give_one_line(data, message):
    with pytest.raises(InputError) as err:
        campaign_from_mapping(data)
    text = str(err.value)
    assert message in text and "\n" not in text


def test_coastdown_analysis_adds_its_outputs():
    from auxbearing.campaign.evaluate import output_variables

    c = campaign_from_mapping(base(analysis="coastdown"))
    assert c.analysis == "coastdown"
    sample, plane = output_variables(c.analysis)
    assert "coastdown_time" in sample and {"max_temperature", "allowed_drops", "drops_to_failure"} <= set(plane)
    drop_sample, drop_plane = output_variables("drop")
    assert "coastdown_time" not in drop_sample and "allowed_drops" not in drop_plane


def test_normal_reaching_outside_the_rule_is_noted():
    c = campaign_from_mapping(with_input(key="rotor.unbalance", distribution="normal", mean="2 um", std="2 um"))
    assert any("rotor.unbalance" in n and "invalid_input" in n for n in c.notes)
    assert not campaign_from_mapping(base()).notes  # 0.2 +- 0.03 leaves [0, 1] with ~1e-11


def test_a_temperature_spilling_out_of_the_service_range_is_noted():
    # 40 degC +- 60 K puts ~4 % below -73 degC; those samples would be refused one by one
    spill = base(analysis="coastdown")
    spill["campaign"]["input"].append({"key": "coastdown.ambient_temperature", "distribution": "normal",
                                       "mean": "40 degC", "std": "60 K"})
    notes = campaign_from_mapping(spill).notes
    assert any("coastdown.ambient_temperature" in n and "service_temperature" in n for n in notes)
    # a uniform spread over the whole range, typed at its ends in degC, is inside it (no note)
    edge = base(analysis="coastdown")
    edge["campaign"]["input"].append({"key": "coastdown.ambient_temperature", "distribution": "uniform",
                                      "low": "-73 degC", "high": "100 degC"})
    assert not campaign_from_mapping(edge).notes
    # the coast-down's settling threshold has a range of its own, 0 to 10 K
    rise = base(analysis="coastdown")
    rise["campaign"]["input"].append({"key": "coastdown.tail_temperature_rise", "distribution": "normal",
                                      "mean": "0.05 K", "std": "0.05 K"})
    assert any("tail_temperature_rise" in n and "temperature_rise" in n for n in campaign_from_mapping(rise).notes)


def test_fingerprint_follows_what_fixes_the_results():
    a = campaign_from_mapping(base())
    assert a.fingerprint() == campaign_from_mapping(base()).fingerprint()
    assert a.fingerprint() != campaign_from_mapping(base(seed=2)).fingerprint()
    other = base()
    other["drop"]["duration"] = "30 ms"
    assert a.fingerprint() != campaign_from_mapping(other).fingerprint()
    assert a.fingerprint() == campaign_from_mapping(base(required_s0=2.0)).fingerprint()  # analysis only


def test_a_renamed_or_moved_campaign_keeps_its_fingerprint(tmp_path):
    from auxbearing.campaign.config import read_campaign

    text = "\n".join(['[campaign]', 'machine = "paper_rig"', 'samples = 4',
                      '[[campaign.input]]', 'key = "rotor.unbalance_phase"', 'distribution = "uniform"',
                      'low = "0 deg"', 'high = "360 deg"'])
    (tmp_path / "a").mkdir()
    (tmp_path / "a" / "one.toml").write_text(text)
    (tmp_path / "two.toml").write_text(text)
    moved = read_campaign(tmp_path / "a" / "one.toml")
    assert moved.fingerprint() == read_campaign(tmp_path / "two.toml").fingerprint()
