"""A measured record the pipeline cannot use is refused, and a fit that explains nothing says so (a review's finds)."""

import math

import numpy as np
import pytest

from auxbearing.common.errors import InputError
from auxbearing.experiment import io
from auxbearing.experiment.fit import FIT_PARAMETERS, POOR_FIT, fit_quality


def _record(rate=50e3, n=5000, x=None, y=None):
    t = np.arange(n) / rate
    rng = np.random.default_rng(1)
    orbit = 1e-4 * np.sin(2 * math.pi * 40.0 * t)
    return {"time": t, "x": orbit + 1e-7 * rng.standard_normal(n) if x is None else x,
            "y": orbit[::-1] + 1e-7 * rng.standard_normal(n) if y is None else y}


def _check(data):
    return io._checked(data, [f"row {i}" for i in range(data["time"].size)], "m.csv",
                       {"time": "time [ms]", "x": "x [um]", "y": "y [um]"}, {})


def test_a_record_faster_than_any_probe_is_a_time_unit_slip():
    """Seconds under a 'ms' header: 50 kHz read as 50 MHz."""
    with pytest.raises(InputError, match=r"^m.csv: column 'time \[ms\]': sampling rate 5e\+07 Hz"):
        _check(_record(rate=50e6))


def test_a_dead_probe_is_refused():
    data = _record()
    data["x"] = np.full(data["time"].size, 31.7e-6)
    with pytest.raises(InputError, match=r"column 'x \[um\]' moves over 0 um .* a dead or disconnected probe"):
        _check(data)


def test_a_clipped_probe_is_refused():
    data = _record()
    data["x"] = np.clip(data["x"], -6e-5, 6e-5)
    with pytest.raises(InputError, match=r"column 'x \[um\]' holds 60 um for \d+ samples in a row .* clipped"):
        _check(data)


def test_a_live_record_passes():
    assert _check(_record()).attrs["sampling_rate_Hz"] == pytest.approx(50e3)


def test_a_fit_on_its_bounds_or_far_above_the_noise_says_so():
    n = len(FIT_PARAMETERS)
    lower, upper, scale = np.zeros(n), np.ones(n), np.full(n, 0.1)
    inside = fit_quality(np.full(n, 0.5), lower, upper, 50.0, scale)
    assert inside == []  # the reference records fit at a reduced chi-square of about 50
    notes = fit_quality(np.r_[0.0, np.full(n - 1, 0.5)], lower, upper, 4.0 * POOR_FIT, scale)
    assert notes[0].startswith(f"{FIT_PARAMETERS[0][0]} stopped on its lower bound")
    assert "the residual is 63.2 times the noise" in notes[1]
