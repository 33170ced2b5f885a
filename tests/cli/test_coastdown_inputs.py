"""A coast-down shorter than its drop's record can be, and one with neither a duration nor a standstill to run to:
one line naming the input, exit 2, nothing written (the first gave a traceback from the drop's damage count)."""

import pytest
from click.testing import CliRunner

from auxbearing.analysis.coastdown import run_coastdown
from auxbearing.cli.main import cli
from auxbearing.common.errors import InputError


def test_a_duration_below_two_output_steps_is_one_line_on_the_command_line(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    done = CliRunner().invoke(cli, ["coastdown", "--machine", "blower", "--duration", "5 us", "--out", "o"])
    assert done.exit_code == 2
    assert done.output.strip().splitlines() == [
        "error: --duration = '5 us': must be at least 20 us (two of the drop's output steps, the shortest record "
        "a coast-down starts from)"]
    assert not any(tmp_path.iterdir())


@pytest.mark.parametrize(("kwargs", "message"), [
    ({"duration": "1 us"}, r"^duration = '1 us': must be at least 20 us"),
    ({"until_stop": False}, r"^until_stop = False: needs a duration"),
])
def test_the_python_api_refuses_them_as_the_command_line_does(kwargs, message):
    with pytest.raises(InputError, match=message):
        run_coastdown("blower", **kwargs)
