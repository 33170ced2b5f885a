"""An infinite value in a JSON output is written "inf" (or "-inf"), never null, which reads as "missing".

A life of infinitely many drops, a margin against a limit of zero or an amplifier without a current limit are
findings; the files hold them as text (JSON has no number for infinity, and bare ``Infinity`` is no JSON),
NaN stays null, and :func:`auxbearing.common.io.loads` reads the text back as the number.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from auxbearing.common.io import dumps, from_jsonable, loads, provenance, to_jsonable, write_json


def _strict(text: str):
    """JSON as the standard has it: a bare Infinity or NaN is an error, not a number."""
    def refuse(token):
        raise ValueError(f"not JSON: {token}")

    return json.loads(text, parse_constant=refuse)


RESULT = {"drops_to_failure": math.inf, "margin": np.float64(-np.inf), "s0": math.nan,
          "series": np.array([1.5, np.inf, -np.inf, np.nan]), "count": np.int64(3), "name": "drive end"}


def test_an_infinity_is_text_and_nan_is_null(tmp_path):
    path = write_json(RESULT, tmp_path / "summary.json")
    data = _strict(path.read_text())
    assert data["drops_to_failure"] == "inf" and data["margin"] == "-inf" and data["s0"] is None
    assert data["series"] == [1.5, "inf", "-inf", None] and data["count"] == 3
    assert _strict(dumps({"x": math.inf})) == {"x": "inf"}


def test_what_is_written_reads_back_as_the_numbers():
    back = loads(dumps(RESULT))
    assert back["drops_to_failure"] == math.inf and back["margin"] == -math.inf and back["s0"] is None
    assert back["series"][:3] == [1.5, math.inf, -math.inf] and back["series"][3] is None
    assert back["name"] == "drive end"
    assert from_jsonable(to_jsonable({"life": [math.inf]})) == {"life": [math.inf]}
    # the text is also what float() reads, for a reader that does not use loads
    assert float(_strict(dumps({"x": -math.inf}))["x"]) == -math.inf


def test_a_file_attribute_and_the_run_inputs_keep_an_infinity():
    inputs = provenance({"max_current_A": math.inf})["inputs"]
    assert _strict(inputs) == {"max_current_A": "inf"}


@pytest.mark.slow  # 0.4 s alone, importing the magnetic bearing's kernel
def test_a_magnetic_bearing_without_limits_says_so_in_its_description():
    from auxbearing.machine.stations.amb import MagneticBearing, describe

    bearing = MagneticBearing("drive-end AMB", position=-0.1, current_stiffness=100.0, kp=5000.0, kd=5.0)
    written = _strict(dumps(describe(bearing)))
    # a limit not given reads as words in a file and on a report page (tests/browser.py: no "inf" for a person)
    assert written["max_current_A"] == "unlimited (no max_current)"
    assert written["slew_rate_A_per_s"] == "unlimited (no max_voltage)"


@pytest.mark.slow  # up to 1 s alone, importing the load's kernel
def test_a_step_load_to_the_end_of_the_run_says_so():
    from auxbearing.machine.stations.load import Load, describe

    written = _strict(dumps(describe(Load("surge", "force", 0.0, -100.0, position=0.05))))
    assert written["duration_s"] == "to the end of the run"


@pytest.mark.parametrize("value", [math.inf, -math.inf, math.nan])
def test_no_bare_infinity_or_nan_ever_reaches_the_text(value):
    text = dumps({"a": [value, {"b": np.float32(value)}]})
    assert "Infinity" not in text and "NaN" not in text
    _strict(text)
