"""The Python API takes what the command line takes, and refuses what it refuses, under the argument's own name:
speeds with units for a Campbell diagram, and a verification's campaign size and workers (issue: 'samples=-1'
ran, 'samples="8"' ended in a TypeError, 'workers=-3' hung, and campbell took no unit strings)."""

import pytest

from auxbearing.analysis.modes import campbell
from auxbearing.common.errors import InputError
from auxbearing.machine.files import read_machine
from auxbearing.verify.run import verify


def test_campbell_takes_speeds_with_units_as_the_command_line_does():
    machine = read_machine("blower")
    text = campbell(machine, "0, 18000 rpm")
    listed = campbell(machine, ["0 rpm", "18000 rpm"])
    numbers = campbell(machine, [0.0, 18000 * 3.141592653589793 / 30])
    assert text.speeds.tolist() == listed.speeds.tolist() == pytest.approx(numbers.speeds.tolist())
    assert text.frequencies.ravel().tolist() == pytest.approx(numbers.frequencies.ravel().tolist())


@pytest.mark.parametrize(("speeds", "message"), [
    ([], r"^speeds = \[\]: give 1 to 1000 speeds"), (-5, "at least 0"), ("0, 9000 m", "not an angular speed"),
    ([float("nan")], "finite"),
])
def test_campbell_refuses_bad_speeds_in_one_line(speeds, message):
    with pytest.raises(InputError, match=message):
        campbell(read_machine("blower"), speeds)


@pytest.mark.parametrize(("kwargs", "message"), [
    ({"samples": -1}, r"^samples = -1: must be a whole number in \[0, 100000\]"),
    ({"samples": "8"}, r"^samples = '8': must be a whole number"),
    ({"workers": 0}, r"^workers = 0: must be a whole number in \[1, 256\]"),
    ({"workers": -3}, r"^workers = -3: must be"),
])
def test_verify_refuses_a_bad_campaign_size_or_worker_count_before_any_work(tmp_path, kwargs, message):
    with pytest.raises(InputError, match=message):
        verify("blower", tmp_path, quick=True, **kwargs)
    assert not any(tmp_path.iterdir())
