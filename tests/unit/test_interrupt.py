"""A Ctrl-C that a library swallowed still stops the run at its next safe point (auxbearing.common.interrupt)."""

import signal

import pytest

from auxbearing.analysis.drop import run_machine
from auxbearing.common import interrupt
from auxbearing.machine.files import read_machine


def test_a_swallowed_interrupt_stops_the_drop_at_its_next_chunk():
    machine = read_machine("paper_rig").with_simulation(duration=2e-3)
    with interrupt.watching():
        try:  # what a finaliser or a catch-all library does with the KeyboardInterrupt
            interrupt.handler(signal.SIGINT, None)
        except KeyboardInterrupt:
            pass
        with pytest.raises(KeyboardInterrupt):
            run_machine(machine, progress=lambda *_: None)
    interrupt.check()  # leaving the watch forgets the request: the next command starts clean


def test_without_a_request_check_lets_the_run_go_on():
    with interrupt.watching():
        interrupt.check()
        run = run_machine(read_machine("paper_rig").with_simulation(duration=1e-4))
    assert run.summary["verdict"] == "ok"
