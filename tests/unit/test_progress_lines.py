"""Progress off a terminal names what is being done at least every few seconds (cli.common.ProgressReporter)."""

import time

from auxbearing.cli.common import ProgressReporter


def test_a_long_step_is_named_again_while_it_reports_nothing(capsys):
    reporter = ProgressReporter("verify demo")
    reporter.every = 0.05
    with reporter:
        reporter(0.25, "design: campaign of 128 drops")
        time.sleep(0.4)
    lines = [ln for ln in capsys.readouterr().err.splitlines() if ln]
    assert len(lines) >= 3, lines
    assert all(ln.startswith("verify demo: 25 % design: campaign of 128 drops (") and ln.endswith(" s left)")
               for ln in lines), lines


def test_time_left_is_the_pace_so_far_once_a_twentieth_is_done():
    from auxbearing.cli.common import _time_left

    assert _time_left(0.25, 30.0) == ", about 90 s left"
    assert _time_left(0.1, 60.0) == ", about 9 min left"
    assert _time_left(0.01, 60.0) == "" and _time_left(1.0, 60.0) == ""


def test_quiet_prints_nothing(capsys):
    with ProgressReporter("verify demo", quiet=True) as reporter:
        reporter(0.5, "anything")
    assert capsys.readouterr().err == ""


def test_a_reporter_of_stages_gives_no_time_left_and_no_percentage(capsys):
    reporter = ProgressReporter("verify demo", time_left=False)
    reporter.every = 0.0
    with reporter:
        reporter(0.99, "convergence of the governing case")
    lines = [ln for ln in capsys.readouterr().err.splitlines() if ln]
    assert lines and all(ln.startswith("verify demo: convergence of the governing case (") for ln in lines), lines
    assert all("left" not in ln and "%" not in ln for ln in lines), lines
