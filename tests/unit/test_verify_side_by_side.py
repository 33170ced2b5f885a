"""The verification's jobs run side by side in threads: their results in order, the first error raised at once."""

import threading
import time

import pytest

from auxbearing.verify.run import _side_by_side


def test_results_in_the_order_of_the_jobs_whatever_order_they_finish_in():
    def job(value, delay):
        def run():
            time.sleep(delay)
            return value
        return run

    assert _side_by_side([job("a", 0.05), job("b", 0.0), job("c", 0.02)]) == ["a", "b", "c"]


def test_jobs_run_at_once_not_one_after_another():
    barrier = threading.Barrier(3, timeout=5)  # each job waits for the other two: one at a time would time out
    assert _side_by_side([barrier.wait] * 3) is not None


def test_the_first_error_is_raised_without_waiting_for_the_jobs_still_running():
    release, finished = threading.Event(), threading.Event()

    def fails():
        raise ValueError("bad candidate")

    def slow():
        release.wait(10)
        finished.set()

    with pytest.raises(ValueError, match="bad candidate"):
        _side_by_side([fails, slow])
    assert not finished.is_set()  # raised while the slow job still ran
    release.set()
