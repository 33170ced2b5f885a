"""A Ctrl-C inside a block that must not be interrupted halfway (writing a result file) waits for its end."""

import os
import signal

import pytest

from auxbearing.common import interrupt


def test_an_interrupt_inside_is_raised_when_the_block_ends():
    finished = []
    with pytest.raises(KeyboardInterrupt), interrupt.watching():
        with interrupt.deferred():
            os.kill(os.getpid(), signal.SIGINT)
            finished.append(True)  # reached: the interrupt did not cut the block
    assert finished == [True]


def test_no_interrupt_no_exception_and_the_handler_is_restored():
    before = signal.getsignal(signal.SIGINT)
    with interrupt.deferred():
        pass
    assert signal.getsignal(signal.SIGINT) is before
