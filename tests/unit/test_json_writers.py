"""Every JSON text a user reads goes through auxbearing.common.io: an infinity is "inf", never bare Infinity.

Bare ``Infinity`` is no JSON (a strict reader, a browser's JSON.parse or jq, refuses the whole text), and a
reader that takes the text with ``json.loads`` alone gets the string "inf" where a number is meant; the
writers here and their readers were the ones that bypassed the shared encoder and ``common.io.loads``.
"""

from __future__ import annotations

import dataclasses
import json
import math
from types import SimpleNamespace

import numpy as np
import pytest
import xarray as xr
from matplotlib.figure import Figure

from auxbearing.campaign.config import Campaign, campaign_from_mapping
from auxbearing.common.io import to_jsonable


def _strict(text: str):
    """JSON as the standard has it: a bare Infinity or NaN is an error, not a number."""
    def refuse(token):
        raise ValueError(f"not JSON: {token}")

    return json.loads(text, parse_constant=refuse)


def _campaign(**tables):
    """A campaign whose description holds ``tables``, made directly: the machine checks refuse an infinite
    input, and what the store must do with one is the question here, not how a file could carry it."""
    return Campaign(name="t", tables={"machine": {"name": "paper_rig"}, **tables}, base=None, sampler="sobol",
                    samples=4, seed=1, analysis="drop", inputs=(), batch_size=2, plane_names=("QJ202",))


def test_a_campaign_store_holds_its_description_as_json():
    from auxbearing.campaign.store import described

    c = _campaign(extra={"limit": math.inf, "floor": -math.inf, "count": np.int64(3)})
    stored = _strict(described(c))["tables"]["extra"]
    assert stored == {"limit": "inf", "floor": "-inf", "count": 3}


def test_a_store_read_back_has_its_infinities_as_numbers():
    from auxbearing.campaign.store import MARK, _differences

    c = _campaign(extra={"limit": math.inf})
    attrs = {MARK: "0" * 16, "campaign": json.dumps(to_jsonable(c.describe()))}
    # the same campaign but its seed: only the seed differs, the infinity read back equals the file's
    assert _differences(attrs, dataclasses.replace(c, seed=2)) == "it differs in seed"


def test_a_number_numpy_holds_fingerprints_as_the_number():
    assert _campaign(extra={"count": np.int64(3)}).fingerprint() == _campaign(extra={"count": 3}).fingerprint()
    assert _campaign(extra={"count": 3}).fingerprint() != _campaign(extra={"count": 4}).fingerprint()


@pytest.mark.slow  # 1-4 s: imports dask.array and makes a Zarr store
def test_the_stores_metadata_file_is_json(tmp_path):
    from auxbearing.campaign.sampling import design
    from auxbearing.campaign.store import prepare_store, read_attrs

    checked = campaign_from_mapping({
        "campaign": {"machine": "paper_rig", "samples": 4, "seed": 1, "batch_size": 2, "input": [
            {"key": "rotor.unbalance_phase", "distribution": "uniform", "low": "0 deg", "high": "360 deg"}]},
        "drop": {"duration": "2 ms"}})
    c = dataclasses.replace(checked, tables={**checked.tables, "extra": {"limit": math.inf}})
    path = tmp_path / "s.zarr"
    prepare_store(path, c, design(c))
    attrs = _strict((path / ".zattrs").read_text())
    assert _strict(attrs["campaign"])["tables"]["extra"] == {"limit": "inf"}
    assert prepare_store(path, c, design(c)) is False  # the store is found again: same fingerprint
    assert read_attrs(path)["campaign"] == attrs["campaign"]


def test_the_campaign_page_reads_the_stored_description_with_its_infinities():
    from auxbearing.report.campaign import PROBABILITIES, _page

    spec = {"key": "rotor.unbalance", "unit": "", "distribution": "uniform", "low": 0.5, "high": math.inf}
    # the page reads only the store's attributes here: a stand-in spares making a store
    ds = SimpleNamespace(attrs={"campaign": json.dumps(to_jsonable({"name": "t", "inputs": [spec]}))}, coords={})
    chance = {"value": 0.0, "low": 0.0, "high": 0.1, "successes": 0, "trials": 4, "among": "all"}
    stats = {"samples": 4, "completed": 4, "ok": 4, "out_of_range": 0, "failed": 0, "planes": {}, "quantiles": {},
             "sensitivity": {}, **{p: chance for p in PROBABILITIES}}
    assert "low 0.5, high inf" in _page(ds, stats, [], None)


def test_the_study_page_shows_its_inputs_as_the_files_hold_them():
    from auxbearing.report.html import render_report

    page = render_report([], [], {"amb": {"max_current_A": math.inf, "floor": -math.inf}}, "t", 0.0)
    shown = page[page.rindex("<pre"):]
    assert "&quot;max_current_A&quot;: &quot;inf&quot;" in shown and "&quot;-inf&quot;" in shown
    assert "Infinity" not in shown


@pytest.fixture
def bearing_with_infinity(monkeypatch):
    """QJ202 whose description holds an infinity and a numpy count, as a derived rating or limit might."""
    from auxbearing import get_bearing
    from auxbearing.bearings.geometry import BearingGeometry

    plain = BearingGeometry.describe
    monkeypatch.setattr(BearingGeometry, "describe",
                        lambda self: {**plain(self), "limiting_speed_rpm": math.inf, "rows": np.int64(1)})
    return get_bearing("QJ202")


@pytest.mark.slow  # 0.8 s alone: the first call loads the compiled Hertz kernels
def test_a_contact_map_file_describes_its_bearing_in_json(bearing_with_infinity):
    from auxbearing.analysis.contact import contact_map

    ds = contact_map(bearing_with_infinity, 1000.0, np.array([20.0, 30.0]), np.array([0.52, 0.53]))
    described = _strict(ds.attrs["bearing"])
    assert described["limiting_speed_rpm"] == "inf" and described["rows"] == 1


@pytest.mark.slow  # 0.5 s alone: the first call loads the compiled load-distribution kernels
def test_a_load_distribution_file_describes_its_bearing_in_json(bearing_with_infinity):
    from auxbearing.analysis.statics import load_distribution

    ds = load_distribution(bearing_with_infinity, axial=500.0, radial=1000.0)
    described = _strict(ds.attrs["bearing"])
    assert described["limiting_speed_rpm"] == "inf" and described["rows"] == 1


def _levitated_run(summary: dict) -> xr.Dataset:
    t = np.linspace(0.0, 0.01, 50)
    current = np.column_stack([np.sin(400.0 * t), np.cos(400.0 * t)])
    return xr.Dataset({"amb_current_x": (("time", "amb"), current), "amb_force_x": (("time", "amb"), 10.0 * current),
                       "normal_force": ("time", np.zeros_like(t))},
                      coords={"time": t, "amb": ["drive end", "non-drive end"]},
                      attrs={"summary": json.dumps(to_jsonable(summary)), "plane_name": "QJ202"})


def test_a_drop_figure_reads_the_run_summary_with_its_infinities():
    from auxbearing.plots.drop import _summary

    ds = _levitated_run({"amb": [{"name": "drive end", "max_current_A": math.inf}]})
    assert _summary(ds)["amb"][0]["max_current_A"] == math.inf


@pytest.mark.parametrize("unlimited", [math.inf, "inf", None])
def test_a_current_limit_is_drawn_only_where_there_is_one(unlimited):
    from auxbearing.plots.drop import plot_magnetic_bearings

    summary = {"amb": [{"name": "drive end", "max_current_A": unlimited},
                       {"name": "non-drive end", "max_current_A": 5.0}]}
    fig = plot_magnetic_bearings(_levitated_run(summary), summary)
    assert isinstance(fig, Figure)
    currents = fig.axes[0]
    dashed = sorted(float(line.get_ydata()[0]) for line in currents.get_lines() if line.get_linestyle() == "--")
    assert dashed == [-5.0, 5.0]
    fig.canvas.draw()  # the limits leave the axis numeric: it still draws


def test_the_verification_page_shows_its_inputs_as_verify_json_holds_them():
    from auxbearing.report.verify_html import render

    result = {"machine": "m", "verdict": "pass", "margins": {}, "assumptions": [], "wall_time_s": 0.0,
              "design": {"criteria": [], "drop_rows": [], "coastdown_rows": []},
              "inputs": {"machine": {"stations": [{"kind": "amb", "max_current_A": math.inf}]}}}
    page = render(result, {})
    shown = page[page.rindex("<pre"):]
    assert "&quot;max_current_A&quot;: &quot;inf&quot;" in shown and "Infinity" not in shown
